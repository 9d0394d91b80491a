# Law2_ScGeom_CapillaryPhys_Capillarity with Hertz-Mindlin (MindlinCapillaryPhys) on 2 spheres and a
# sphere-facet pair in a periodic cell, run from a directory WITHOUT the capillary files M(r=...).
import math, os
print("cwd", os.getcwd(), "capillary files present:", [f for f in os.listdir('.') if f.startswith('M(r=')])
R = 1e-3; gamma = 0.073; suction = float(os.environ.get("SUCTION", "1000"))
O.periodic = True
O.cell.setBox(0.01, 0.01, 0.01)
O.dt = 1e-7
m = O.materials.append(FrictMat(young=1e8, poisson=0.25, frictionAngle=0.5, density=2650))
z0 = 0.003
a = O.bodies.append(sphere((0.005, 0.005, z0 + R - 1e-9), R, material=m, fixed=True))
b = O.bodies.append(sphere((0.005, 0.005, z0 - R), R, material=m, fixed=True))
c = O.bodies.append(sphere((0.002, 0.002, z0 + R - 1e-9), R, material=m, fixed=True))
f = O.bodies.append(facet((Vector3(0.0005, 0.0005, z0), Vector3(0.004, 0.0005, z0), Vector3(0.002, 0.004, z0)), material=m, fixed=True))
O.engines = [ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()], allowBiggerThanPeriod=True, verletDist=0.5 * R),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()],
                    [Ip2_FrictMat_FrictMat_MindlinCapillaryPhys(en=0.5, es=0.5, krot=0.1, eta=0.1)],
                    [Law2_ScGeom_MindlinPhys_Mindlin(includeMoment=True, neverErase=True)]),
    Law2_ScGeom_CapillaryPhys_Capillarity(capillaryPressure=suction, surfaceTension=gamma, label='cap'),
    NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
O.step()
for s_over_R in [0.0, 1e-3, 1e-2, 0.05]:
    O.bodies[a].state.pos = Vector3(0.005, 0.005, z0 + R + s_over_R * R + 1e-12)
    O.bodies[c].state.pos = Vector3(0.002, 0.002, z0 + R + s_over_R * R + 1e-12)
    O.step()
    print("s/R=%g  F_ss=%.4e  F_sf=%.4e  real=%d" % (s_over_R, -O.forces.f(a)[2], -O.forces.f(c)[2], len([i for i in O.interactions if i.isReal])))
    for i in O.interactions:
        if i.isReal: print("   ", i.id1, i.id2, type(i.phys).__name__, "meniscus", i.phys.meniscus, "V", i.phys.vMeniscus, "fCap", i.phys.fCap)
