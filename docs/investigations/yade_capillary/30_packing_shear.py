# Small periodic packing (no walls), isotropic compression to SIGMA, then constant-normal-stress
# simple shear (cell velGrad xz, zz servo on the total stress, x and y lengths fixed), dry vs wet.
# Usage: yade -n -x -j1 30_packing_shear.py LAW CASE [SUCTION_Pa] [SEED] [SIGMA_Pa]
#   LAW  viscel   : ViscElCapMat + Ip2_ViscElCapMat_ViscElCapMat_ViscElCapPhys + Law2_ScGeom_ViscElCapPhys_Basic
#                   (CASE dry: Capillar=False; wet: Willett_analytic, Vb from SUCTION via Laplace-Young)
#        mindlin  : FrictMat + Ip2_FrictMat_FrictMat_MindlinCapillaryPhys + Law2_ScGeom_MindlinPhys_Mindlin
#                   (+ Law2_ScGeom_CapillaryPhys_Capillarity(capillaryPressure=SUCTION) when wet,
#                    capillary files from ./capfiles)
import sys, os, math, json, time, random
LAW, CASE = sys.argv[1], sys.argv[2]
SUCTION = float(sys.argv[3]) if len(sys.argv) > 3 else 0.0
SEED = int(sys.argv[4]) if len(sys.argv) > 4 else 1
SIGMA = float(sys.argv[5]) if len(sys.argv) > 5 else 500.0
N = int(os.environ.get("NSPH", "300"))
GAMMA_DOT = float(os.environ.get("GDOT", "0.5"))
STRAIN = float(os.environ.get("STRAIN", "0.3"))
HERE = os.path.dirname(os.path.abspath(sys.argv[0])) if os.path.dirname(sys.argv[0]) else os.getcwd()
tag = "%s_%s_s%g_seed%d_sig%g" % (LAW, CASE, SUCTION, SEED, SIGMA)
d50, gamma, rho = 2e-3, 0.073, 2650.0
mu, mu_r, E, nu, e = 0.5, 0.1, 1e8, 0.25, 0.5
R50 = d50 / 2

def bridge_volume(s, R):
    # Laplace-Young (theta = 0, touching equal spheres), fitted to YADE's solveLiqBridge.py results
    # (20_laplace_young_vs.py): V*(u*) with u* = s R / gamma; table lookup in log-log.
    tab = json.load(open(os.path.join(HERE, "20_vstar_table.json")))
    us, vs = tab["u_star"], tab["V_star"]
    u = s * R / gamma
    import bisect
    i = min(max(1, bisect.bisect_left(us, u)), len(us) - 1)
    t = (math.log(u) - math.log(us[i - 1])) / (math.log(us[i]) - math.log(us[i - 1]))
    return math.exp(math.log(vs[i - 1]) + t * (math.log(vs[i]) - math.log(vs[i - 1]))) * R ** 3

# --- Hertz stiffness at SIGMA (for the linear ViscEl law and the rolling stiffness) ---
Estar = E / (2 * (1 - nu ** 2)); Rstar = R50 / 2
Fc = SIGMA * d50 ** 2
delta = (3 * Fc / (4 * Estar * math.sqrt(Rstar))) ** (2.0 / 3)
kn_hertz = 2 * Estar * math.sqrt(Rstar * delta)
krot = 2.25 * kn_hertz * mu_r ** 2 * Rstar ** 2

O.periodic = True
from yade import pack
sp = pack.SpherePack()
L = (N * math.pi / 6 * d50 ** 3 / 0.25) ** (1.0 / 3)  # loose cloud, solid fraction ~0.25
random.seed(SEED)
sp.makeCloud((0, 0, 0), (L, L, L), psdSizes=[0.8 * d50, 1.0 * d50, 1.2 * d50], psdCumm=[0.0, 0.5, 1.0],
             periodic=True, num=N, seed=SEED, distributeMass=True)
if LAW == "viscel":
    kw = dict(kn=2 * kn_hertz, ks=2 * kn_hertz, frictionAngle=math.atan(mu), density=rho, mR=float(os.environ.get("MR", "0")), mRtype=1)
    m_eff = rho * math.pi / 6 * (0.8 * d50) ** 3 / 2
    zeta = -math.log(e) / math.sqrt(math.pi ** 2 + math.log(e) ** 2)
    kw["cn"] = kw["cs"] = 2 * 2 * zeta * math.sqrt(kn_hertz * m_eff)  # materials combine in series
    if CASE == "wet":
        Vb = bridge_volume(SUCTION, R50)
        kw.update(Capillar=True, CapillarType="Willett_analytic", Vb=Vb, gamma=gamma, theta=0.0)
        print("VISCEL_WET suction %g Pa  Vb %.4e m3  V*=Vb/R50^3 %.4e" % (SUCTION, Vb, Vb / R50 ** 3))
    mat = O.materials.append(ViscElCapMat(**kw))
    ip2 = Ip2_ViscElCapMat_ViscElCapMat_ViscElCapPhys()
    law = Law2_ScGeom_ViscElCapPhys_Basic()
    capeng = []
else:
    mat = O.materials.append(FrictMat(young=E, poisson=nu, frictionAngle=math.atan(mu), density=rho))
    ip2 = Ip2_FrictMat_FrictMat_MindlinCapillaryPhys(en=e, es=e, krot=krot, eta=0.5 * mu_r)
    law = Law2_ScGeom_MindlinPhys_Mindlin(includeMoment=True, neverErase=(CASE == "wet"))
    capeng = []
    if CASE == "wet":
        os.chdir(os.path.join(HERE, "capfiles"))
        capeng = [Law2_ScGeom_CapillaryPhys_Capillarity(capillaryPressure=SUCTION, surfaceTension=gamma, label="cap")]
sp.toSimulation(material=mat)
O.cell.setBox(L, L, L)
mmin = min(b.state.mass for b in O.bodies)
if LAW == "viscel":
    O.dt = 0.05 * 2 * math.pi * math.sqrt(0.5 * mmin / kn_hertz)
else:
    rmin = 0.4 * d50; G = E / (2 * (1 + nu))
    O.dt = 0.15 * math.pi * rmin * math.sqrt(rho / G) / (0.1631 * nu + 0.8766)
O.engines = [ForceResetter(),
             InsertionSortCollider([Bo1_Sphere_Aabb()], verletDist=0.05 * d50),
             InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [ip2], [law])] + capeng + [
             PyRunner(iterPeriod=10, command="servo()", label="servoR"),
             NewtonIntegrator(damping=0.0, gravity=(0, 0, 0))]

def total_stress():
    s = getStress()  # interactions' normalForce + shearForce (ViscElCap's bridge force is in normalForce)
    if LAW != "viscel" and CASE == "wet":
        s = s + getCapillaryStress(O.cell.volume, True)  # MindlinCapillaryPhys: fCap is stored apart
    return s  # tension positive

PH = {"phase": "iso", "t0": 0, "rate": 0.5}
def servo():
    s = -total_stress()  # compression positive
    g = Matrix3.Zero
    rmax = PH["rate"]
    if PH["phase"] == "iso":
        for k in range(3):
            err = (SIGMA - s[k, k]) / SIGMA
            g[k, k] = -max(-rmax, min(rmax, 0.5 * rmax * err))
    else:
        err = (SIGMA - s[2, 2]) / SIGMA
        g[2, 2] = -max(-rmax, min(rmax, 0.2 * rmax * err))
        g[0, 2] = GAMMA_DOT
    O.cell.velGrad = g

def run_timed(n):
    t = time.time(); O.run(n, True); return time.time() - t

# isotropic compression to SIGMA: fast then slow, until stress within 2 % and unbalanced force small
t_iso = 0.0
p = 0.0
for it in range(int(os.environ.get("ISO_CHUNKS", "150"))):
    # fast until the packing bears 30 % of SIGMA (schedule of the viscel runs: 15 chunks fast)
    PH["rate"] = 2.0 if (it < 15 if LAW == "viscel" else p < 0.3 * SIGMA) else 0.5
    t_iso += run_timed(1000)
    s = -total_stress()
    p = (s[0, 0] + s[1, 1] + s[2, 2]) / 3
    if it % 5 == 0:
        print("ISO it %d p %.1f szz %.1f unb %.3g %.0f steps/s" % (O.iter, p, s[2, 2], unbalancedForce(), O.iter / t_iso), flush=True)
    if it > 15 and all(abs(s[k, k] - SIGMA) < 0.05 * SIGMA for k in range(3)) and unbalancedForce() < 0.05:
        break
V = O.cell.volume
vs = sum(4 / 3.0 * math.pi * b.shape.radius ** 3 for b in O.bodies)
ncont = sum(1 for i in O.interactions if i.isReal)
print("ISO_DONE iters %d  p %.1f Pa  phi %.4f  Z %.2f  unb %.3g  %.0f steps/s" % (O.iter, p, vs / V, 2.0 * ncont / N, unbalancedForce(), O.iter / t_iso))
# simple shear at constant total normal stress
PH["phase"], PH["rate"] = "shear", 2.0 * GAMMA_DOT
steps = int(STRAIN / GAMMA_DOT / O.dt)
rows = []
t_sh = 0.0
chunk = max(100, steps // 150)
done = 0; hz0 = O.cell.hSize[2, 2]
while done < steps:
    t_sh += run_timed(chunk); done += chunk
    s = -total_stress()
    gam = done * O.dt * GAMMA_DOT
    nb = sum(1 for i in O.interactions if i.isReal and (LAW == "viscel" and i.geom.penetrationDepth < 0 or LAW != "viscel" and CASE == "wet" and i.phys.meniscus and i.geom.penetrationDepth < 0))
    rows.append((gam, s[2, 2], -s[0, 2], (O.cell.hSize[2, 2] - hz0) / hz0, 2.0 * sum(1 for i in O.interactions if i.isReal and i.geom.penetrationDepth >= 0) / N, nb))
ratios = [(r[0], r[2] / r[1]) for r in rows if r[1] > 0]
peak = max(x[1] for x in ratios)
resid = [x[1] for x in ratios if x[0] >= 0.6 * STRAIN]
resid = sum(resid) / len(resid)
sigm = sum(r[1] for r in rows) / len(rows)
out = dict(tag=tag, law=LAW, case=CASE, suction=SUCTION, seed=SEED, sigma=SIGMA, N=N, dt=O.dt, peak=peak, residual=resid,
           sigma_mean=sigm, steps_per_s_shear=done / t_sh, steps_per_s_iso=O.iter and (O.iter - done) / t_iso, rows=rows,
           kn_hertz=kn_hertz, phi0=vs / V)
json.dump(out, open(os.path.join(HERE, "results", tag + ".json"), "w"), indent=1)
print("RESULT %s peak tau/sigma %.4f residual(gamma>=%.2f) %.4f  mean sigma_zz %.1f Pa  dilation %.4f  bridges(dist) %d  shear %.0f steps/s" % (
    tag, peak, 0.6 * STRAIN, resid, sigm, rows[-1][3], rows[-1][5], done / t_sh))
