# Two-sphere and sphere-facet test of Law2_ScGeom_ViscElCapPhys_Basic (all CapillarType's) in a
# PERIODIC cell, d = 2 mm grains. Bridge formed at contact, then the pair is pulled apart
# quasi-statically (positions set, fixed bodies) and the capillary force is read from O.forces.
# Analytical reference (touching equal spheres, small volume, toroidal/Derjaguin):
#   F0 = 2 pi R gamma cos(theta)  (sphere-sphere),   4 pi R gamma cos(theta) (sphere-plane)
import math, json, sys
R = 1e-3; gamma = 0.073; theta_deg = 0.0
types = ["Willett_numeric", "Willett_analytic", "Weigert", "Rabinovich", "Lambert", "Soulie"]
Vstars = [1e-4, 1e-3, 1e-2]
res = {}
def run_pair(ctype, Vb, facet=False):
    O.reset()
    O.periodic = True
    O.cell.setBox(0.01, 0.01, 0.01)
    O.dt = 1e-7
    m = O.materials.append(ViscElCapMat(kn=1e4, cn=0, ks=1e4, cs=0, frictionAngle=0.5, density=2650,
                                        Vb=Vb, gamma=gamma, theta=theta_deg, Capillar=True, CapillarType=ctype))
    z0 = 0.003
    a = O.bodies.append(sphere((0.005, 0.005, z0 + R), R, material=m, fixed=True))
    if facet:
        b = O.bodies.append(facet_((0.003, 0.003, z0), (0.008, 0.003, z0), (0.005, 0.008, z0), m))
    else:
        b = O.bodies.append(sphere((0.005, 0.005, z0 - R), R, material=m, fixed=True))
    O.engines = [ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()], allowBiggerThanPeriod=True, verletDist=0.5 * R),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()],
                        [Ip2_ViscElCapMat_ViscElCapMat_ViscElCapPhys()], [Law2_ScGeom_ViscElCapPhys_Basic(label='law')]),
        NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
    # first contact (tiny overlap) to create the bridge
    O.bodies[a].state.pos = Vector3(0.005, 0.005, z0 + R - 1e-9)
    O.step()
    out = []
    for s_over_R in [0.0, 1e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.2, 0.3, 0.5]:
        O.bodies[a].state.pos = Vector3(0.005, 0.005, z0 + R + s_over_R * R + 1e-12)
        O.step()
        f = O.forces.f(a)[2]  # attractive: pulls a (upper) down -> negative
        ninter = len([i for i in O.interactions if i.isReal])
        out.append((s_over_R, -f, ninter))
    return out
def facet_(p1, p2, p3, m):
    return facet((Vector3(*p1), Vector3(*p2), Vector3(*p3)), material=m, fixed=True)
F_ss = 2 * math.pi * R * gamma * math.cos(math.radians(theta_deg))
print("analytical touching sphere-sphere F0 = %.4e N, sphere-plane %.4e N" % (F_ss, 2 * F_ss))
for facet_case in (False, True):
    for ct in types:
        for vs in Vstars:
            Vb = vs * R ** 3
            try:
                out = run_pair(ct, Vb, facet_case)
                key = "%s %s V*=%g" % ("sphere-facet" if facet_case else "sphere-sphere", ct, vs)
                res[key] = out
                print(key, " ".join("s/R=%g:F=%.4e(%d)" % (s, f, n) for s, f, n in out), " F(0)/F_ss=%.3f" % (out[0][1] / F_ss))
            except Exception as e:
                print("FAIL", ct, vs, facet_case, type(e).__name__, e)
json.dump(res, open("10_two_sphere_viscelcap.json", "w"), indent=1)
