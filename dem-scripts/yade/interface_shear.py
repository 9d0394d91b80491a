# iwb YADE runner: one stage of an interface-shear scene (DEM.md), driven by the parameters that
# `iwb dem run --engine yade` derives from the scene file (yade_params.json, SI units).
# Run headless from the stage's work directory:  yade -n -x -jN interface_shear.py PARAMS STAGE
#   STAGE consolidate: generate, settle, consolidate to sigma_n0 under the servo plate, save.
#   STAGE shear:       load, switch to test friction, relax, shear the bottom wall, write raw outputs.
#   STAGE oedometer:   a soil cell's (`iwb dem soiltest --engine yade`): load, test friction, relax,
#                      then ramp and hold the plate's target at each level, a row per level.
# Lines starting IWB_ are read by the runner (progress, stage ends, failures, cost), exactly as
# from the LIGGGHTS templates; the raw files have the LIGGGHTS runner's columns so that one C++
# routine turns either engine's output into the contract.
import json
import math
import random
import sys
import time

from yade import export, ymport

P = json.load(open(sys.argv[1]))
STAGE = sys.argv[2]
# YADE's cell is periodic in z as well and starts at 0: the scene is lifted so that its lowest
# point sits one d_max above 0, and the cell is two d_max taller than the scene, so nothing meets
# its own image across z.
ZS = P["d_max"] - P["zlo"]
LZ = (P["zhi"] - P["zlo"]) + 2.0 * P["d_max"]


def say(line):
    print(line, flush=True)


def fail(reason):
    say("IWB_FAIL " + reason)
    sys.exit(3)


# --- scene construction (stage 1) -------------------------------------------------------------

def material(friction, label):
    return O.materials.append(FrictMat(young=P["E"], poisson=P["nu"], density=P["density"],
                                       frictionAngle=math.atan(friction), label=label))


def diameters(n, sizes, rng):
    # Counts per class from mass fractions (number ~ mass / d^3), then shuffled.
    weights = [f / d ** 3 for d, f in sizes]
    total = sum(weights)
    counts = [int(round(n * w / total)) for w in weights]
    counts[-1] += n - sum(counts)
    out = [d for (d, _), c in zip(sizes, counts) for _ in range(max(c, 0))]
    rng.shuffle(out)
    return out


def random_cloud(n, rng, z0, z1, periodic_z=False):
    """Non-overlapping spheres at random between heights z0 and z1, periodic in x and y (and in z
    over z1 - z0 with periodic_z: the periodic cell): random sequential addition, largest first,
    on a hash grid. Fails with the counts if it cannot."""
    ds = sorted(diameters(n, P["sizes"], rng), reverse=True)
    lx, ly = P["Lx"], P["Ly"]
    cell = P["d_max"]
    nz = max(1, int((z1 - z0) / cell))
    grid = {}
    placed = []
    for d in ds:
        r = 0.5 * d
        for _ in range(2000):
            zr = (z0, z1) if periodic_z else (z0 + r, z1 - r)
            p = (rng.uniform(0, lx), rng.uniform(0, ly), rng.uniform(*zr))
            key = (int(p[0] / cell), int(p[1] / cell), int((p[2] - z0) / cell))
            ok = True
            for i in (-1, 0, 1):
                for j in (-1, 0, 1):
                    for k in (-1, 0, 1):
                        kz = (key[2] + k) % nz if periodic_z else key[2] + k
                        kk = ((key[0] + i) % max(1, int(lx / cell)), (key[1] + j) % max(1, int(ly / cell)), kz)
                        for q, rq in grid.get(kk, ()):
                            dx = abs(p[0] - q[0]); dx = min(dx, lx - dx)
                            dy = abs(p[1] - q[1]); dy = min(dy, ly - dy)
                            dz = abs(p[2] - q[2])
                            if periodic_z:
                                dz = min(dz, (z1 - z0) - dz)
                            if dx * dx + dy * dy + dz * dz < (r + rq) ** 2:
                                ok = False
                                break
                        if not ok: break
                    if not ok: break
                if not ok: break
            if ok:
                key = (key[0] % max(1, int(lx / cell)), key[1] % max(1, int(ly / cell)), key[2] % nz if periodic_z else key[2])
                grid.setdefault(key, []).append((p, r))
                placed.append((p, r))
                break
        else:
            break
    return placed


def build_scene():
    O.periodic = True
    O.cell.setBox(P["Lx"], P["Ly"], LZ)
    O.dt = P["dt"]
    grains_mat = material(P["mu_consolidation"], "grains")
    wall_mat = material(P["mu_consolidation"], "walls")
    shift = Vector3(0, 0, ZS)
    wall = O.bodies.append(ymport.stl(P["wall_stl"], material=wall_mat, shift=shift, fixed=True))
    glued = O.bodies.append([sphere((x, y, z + ZS), 0.5 * d, material=wall_mat, fixed=True)
                             for x, y, z, d in P["glued"]])
    plate = O.bodies.append(ymport.stl(P["plate_stl"], material=wall_mat, shift=shift, fixed=True))
    rng = random.Random(P["seed"])
    cloud = random_cloud(P["n_particles"], rng, P["ins_zlo"], P["ins_zhi"])
    grains = O.bodies.append([sphere((p[0], p[1], p[2] + ZS), r, material=grains_mat) for p, r in cloud])
    O.tags["iwb_ids"] = json.dumps({"wall": wall + glued, "plate": plate, "grains": grains})
    say("IWB_PARTICLES %d requested %d" % (len(grains), P["n_particles"]))
    if len(grains) < P["n_particles"]:
        fail("particle count short: %d of %d placed (random placement could not fit them in the "
             "insertion region; lower specimen.solid_fraction_estimate or particles)" % (len(grains), P["n_particles"]))


WET = P.get("capillary") is not None


def engines(facets=True, gravity=-9.81, control="control()"):
    # Hertz-Mindlin with restitution damping and a rolling-resistance moment capped at
    # eta * R_mean * F_n, its stiffness krot that of the LIGGGHTS model it stands in for (cdt or
    # epsd2; dem-scripts/README.md, "Contact-law mapping"). Wet
    # scenes add pendular liquid bridges at the scene's suction between grains (not facets):
    # Law2_ScGeom_CapillaryPhys_Capillarity over the same contacts, which then outlive contact
    # (neverErase) until their bridge breaks; it reads the tables M(r=...) the runner writes.
    ip2 = Ip2_FrictMat_FrictMat_MindlinCapillaryPhys if WET else Ip2_FrictMat_FrictMat_MindlinPhys
    out = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb()] + ([Bo1_Facet_Aabb()] if facets else []),
                              allowBiggerThanPeriod=True, verletDist=P["skin"], label="collider"),
        InteractionLoop(
            [Ig2_Sphere_Sphere_ScGeom()] + ([Ig2_Facet_Sphere_ScGeom()] if facets else []),
            [ip2(en=P["restitution"], es=P["restitution"], krot=P["rolling"]["krot"], eta=P["rolling"]["eta"])],
            [Law2_ScGeom_MindlinPhys_Mindlin(includeMoment=P["rolling"]["eta"] > 0, neverErase=WET)]),
    ]
    if WET:
        out.append(Law2_ScGeom_CapillaryPhys_Capillarity(capillaryPressure=P["capillary"]["suction_Pa"],
                                                         surfaceTension=P["capillary"]["surface_tension_N_m"]))
    return out + [
        PyRunner(iterPeriod=P["servo"]["every"], command=control, label="controller"),
        NewtonIntegrator(gravity=(0, 0, gravity), damping=0.0),
    ]


def report_liquid_bridges():
    """How many liquid bridges the specimen holds, and how many across a gap (wet scenes)."""
    if WET:
        bridges = [i for i in O.interactions if i.isReal and i.phys.meniscus]
        say("IWB_FACT liquid_bridges %d" % len(bridges))
        say("IWB_FACT liquid_bridges_across_gaps %d" % sum(1 for i in bridges if i.geom.penetrationDepth < 0))


def touching(c):
    """A contact, not a liquid bridge across a gap (wet scenes keep those as interactions)."""
    return c.isReal and (not WET or c.geom.penetrationDepth > 0)


def capillary_force_on_2(c):
    """The bridge's force on id2: fCap (and -fCap on id1; checked on two touching spheres, where the
    pull on each is fCap's size less the Hertz push); 0 when dry."""
    return c.phys.fCap if WET and c.isReal and c.phys.meniscus else Vector3(0, 0, 0)


# --- measurements -----------------------------------------------------------------------------

IDS = {}
REF = {}


def ids_from_tags():
    IDS.update(json.loads(O.tags["iwb_ids"]))
    SPHERES[0] = sum(1 for b in O.bodies if isinstance(b.shape, Sphere))
    REF["plate_z"] = O.bodies[IDS["plate"][0]].state.pos[2]
    REF["wall_x"] = O.bodies[IDS["wall"][0]].state.pos[0]


def zplate():
    # The plate's reference height in scene coordinates (LIGGGHTS: the servo mesh's com).
    return P["plate_z"] + (O.bodies[IDS["plate"][0]].state.pos[2] - P["plate_ref_z"])


def plate_force():
    return sumForces(IDS["plate"], (0, 0, 1))  # grains push the plate up: positive


def wall_forces():
    return -sumForces(IDS["wall"], (0, 0, 1)), -sumForces(IDS["wall"], (1, 0, 0))


def kinetic_energy():
    return sum(0.5 * b.state.mass * b.state.vel.squaredNorm() for b in (O.bodies[i] for i in IDS["grains"]))


def stiffness_on(ids):
    s = 0.0
    for i in ids:
        for c in O.interactions.withBody(i):
            if touching(c):
                s += c.phys.kn
    return s


# --- the servo plate ----------------------------------------------------------------------------
# Every `every` steps: v = g (F - F_target) / (sum k_n * every * dt), i.e. each update closes the
# fraction g of the force error (DEM.md), clamped to vel_max; sum k_n of the plate's contacts is
# refreshed every tenth update. Without contacts the plate approaches at vel_max. g = 0.3 per step
# made the plate chatter against rattling grains and settle 40 % below target (the clamp is
# one-sided while approaching); g = 0.02 per step converges on the smoke scene. While shearing,
# vel_max is capped at 20 wall speeds: dilation is slower than the wall, and a cap near it keeps
# one rattling contact from kicking the plate.

SERVO = {"on": False, "kn": 0.0, "z0": None, "shear": False, "t0": 0.0, "updates": 0, "integral": 0.0,
         "vel_max": P["servo"]["vel_max"], "ramp": None, "integrate": False,
         "layers": 1.0}


def target_force():
    if SERVO["ramp"] is not None:  # oedometer: (first step, steps, from, to), then held at `to`
        i0, n, f0, f1 = SERVO["ramp"]
        return f0 + (f1 - f0) * min(1.0, (O.iter - i0) / float(n))
    if P["bc"] == "CNS" and SERVO["z0"] is not None:
        return P["F0"] + P["K_Pa_per_m"] * P["area"] * (zplate() - SERVO["z0"])
    return P["F0"]


def set_velocity(ids, v):
    for i in ids:
        O.bodies[i].state.vel = v


def control():
    every = P["servo"]["every"]
    v = 0.0
    if SERVO["on"]:
        if SERVO["updates"] % 10 == 0:
            SERVO["kn"] = stiffness_on(IDS["plate"])
        SERVO["updates"] += 1
        err = plate_force() - target_force()
        vmax = SERVO["vel_max"]
        if SERVO["kn"] <= 0.0:
            v = -vmax
        else:
            # the velocity that closes the error in one update, the plate's contacts in series with
            # `layers` grain layers (1: the contacts alone)
            closing = err * SERVO["layers"] / (SERVO["kn"] * every * O.dt)
            if SERVO["integrate"]:  # the integral follows steady dilation or creep, which a P servo only trails
                SERVO["integral"] = max(-vmax, min(vmax, SERVO["integral"] + P["servo"]["integral_gain"] * closing))
            v = P["servo"]["gain"] * closing + SERVO["integral"]
        v = max(-vmax, min(vmax, v))
    set_velocity(IDS["plate"], Vector3(0, 0, v))
    if SERVO["shear"]:
        set_velocity(IDS["wall"], Vector3(wall_velocity(O.time - SERVO["t0"]), 0, 0))


def wall_displacement(t):
    """The wall's displacement t after shear starts (Shear::displacement_at): monotonic, v t after
    a linear ramp of the speed over ramp_s (0: an instant start); cyclic, the triangle wave
    0 -> +A -> -A -> 0 of the LIGGGHTS runner, then the post-cyclic shear from 0 at v."""
    sh = P["shear"]
    v, ramp = sh["velocity"], sh["ramp_s"]
    if sh["cyclic"]:
        a = sh["amplitude"]
        if v * t >= sh["cycles_travel"]:
            return v * t - sh["cycles_travel"]
        phase = v * t / a  # in quarter cycles
        return a * (abs(math.fmod(phase + 3.0, 4.0) - 2.0) - 1.0)
    if t < ramp:
        return 0.5 * v * t * t / ramp
    return v * (t - 0.5 * ramp)


def wall_velocity(t):
    """Set at every servo update: the mean speed until the next update, so the wall is exactly at
    wall_displacement() at every update (rows and snapshots fall on them), through the ramp and
    across the reversals of a cycle (a reversal between two updates would otherwise shift the
    whole wave by up to two updates' travel)."""
    sh = P["shear"]
    if not sh["cyclic"] and t >= sh["ramp_s"]:
        return sh["velocity"]
    span = P["servo"]["every"] * O.dt
    return (wall_displacement(t + span) - wall_displacement(t)) / span


COST = {"seconds": 0.0, "particle_steps": 0.0}
SPHERES = [0]


def run(steps):
    # O.step() in this thread, not O.run(steps, True): O.run starts the loop in YADE's own thread
    # and O.wait() polls it, which cost ~40 ms a call, idle; the shear loop's chunks of 10 steps
    # then spent most of their time waiting (3000 steps of the smoke scene: 14.6 s, 3.4 s of CPU).
    # The same engines in the same order: the smoke scene's timeseries and profiles came out
    # bit-identical both ways (2026-11-27); the YADE smoke runs went from 240 s to 100 s summed.
    t = time.time()
    for _ in range(int(steps)):
        O.step()
    COST["seconds"] += time.time() - t
    COST["particle_steps"] += float(steps) * SPHERES[0]  # grains and glued spheres, as LIGGGHTS counts atoms


def report_cost():
    say("IWB_COST seconds %.6g particle_steps %.0f" % (COST["seconds"], COST["particle_steps"]))


# --- stage 1 ----------------------------------------------------------------------------------

def approach(sigma, what="the plate did not reach the grains"):
    """Windows until the grains bear the load (sigma() above approach_sigma), at most
    approach_windows, apart from the acceptance windows: as the LIGGGHTS template does."""
    for a in range(1, P["approach_windows"] + 1):
        run(P["window_steps"])
        s = sigma()
        say("IWB_APPROACH %d sigma_Pa %.8g" % (a, s))
        if s > P["approach_sigma"]:
            return
    report_cost()
    fail("servo did not converge: %s in %d windows" % (what, P["approach_windows"]))


def still_windows(tag, sigma, height, held=lambda s: True):
    """Windows until windows_required consecutive ones have held(sigma()), a height() that has
    stopped and a small kinetic energy (DEM.md), each printed as `tag`; at most max_windows.
    Returns (windows, height, sigma) of the last one, or None if the specimen never held still."""
    good, zprev = 0, height()
    for w in range(1, P["max_windows"] + 1):
        run(P["window_steps"])
        s, zp = sigma(), height()
        dz, ke = abs(zp - zprev), kinetic_energy()
        good = good + 1 if held(s) and dz < P["plate_tol"] and ke < P["ke_tol"] else 0
        say("%s %d sigma_Pa %.8g dz_m %.6g ke_J %.6g good %d" % (tag, w, s, dz, ke, good))
        if good >= P["windows_required"]:
            return w, zp, s
        zprev = zp
    return None


def accept(sigma, height, before_save=lambda: None):
    """Consolidation's windows: sigma() within tolerance of sigma_n0 besides a still specimen;
    then the specimen is saved."""
    done = still_windows("IWB_WINDOW", sigma, height,
                        lambda s: abs(s - P["sigma_n0"]) < P["sigma_tol"] * P["sigma_n0"])
    report_cost()
    if done is None:
        fail("servo did not converge: consolidation not accepted after %d windows" % P["max_windows"])
    before_save()
    O.save("consolidated.yade.gz")
    report_liquid_bridges()
    say("IWB_STAGE_DONE consolidate zplate_m %.10g sigma_Pa %.8g" % done[1:])


def settle(zrelax):
    """A specimen prepared looser than the test's contacts hold collapses when they take over
    (the LIGGGHTS template's lesson: 1-1.7 mm within the first 0.14 mm of a shear that did not
    wait). Shear starts once the plate has come to rest under the servo's sigma_n0; a specimen
    whose plate did not move over the relaxation starts at once. The plate's stress is not asked:
    the servo holds it wherever the plate rests."""
    windows = 0
    if abs(zplate() - zrelax) >= P["plate_tol"] or kinetic_energy() >= P["ke_tol"]:
        done = still_windows("IWB_SETTLE", plate_sigma, zplate)
        if done is None:
            report_cost()
            fail("the specimen did not settle at the test's contacts in %d windows" % P["max_windows"])
        windows = done[0]
    say("IWB_FACT settle_windows %d" % windows)


def plate_sigma():
    return plate_force() / P["area"]


def consolidate():
    build_scene()
    O.engines = engines()
    ids_from_tags()
    P["plate_ref_z"] = REF["plate_z"]
    O.tags["iwb_plate_ref_z"] = repr(REF["plate_z"])
    run(P["settle_steps"])  # settle under gravity with the plate held
    SERVO["on"] = True
    approach(plate_sigma)
    accept(plate_sigma, zplate)


# --- stage 2 ----------------------------------------------------------------------------------

def set_friction(mu):
    # Existing contacts keep the friction their Ip2 computed: change both (DEM.md pitfall).
    for m in O.materials:
        m.frictionAngle = math.atan(mu)
    for c in O.interactions:
        if c.isReal:
            c.phys.tangensOfFrictionAngle = mu


def coordination(grain_set):
    # Grain-grain contacts per grain (LIGGGHTS's contact/atom averaged).
    n = sum(1 for c in O.interactions if touching(c) and c.id1 in grain_set and c.id2 in grain_set)
    return 2.0 * n / max(1, len(grain_set))


def grain_volumes():
    return [(4.0 / 3.0) * math.pi * O.bodies[i].shape.radius ** 3 for i in IDS["grains"]]


class Outputs:
    PROFILE_HEADER = "# step z_m count vx_m_s solid_fraction s_zz_Pa s_xz_Pa (stresses: compression negative)\n"

    def __init__(self):
        self.vol = grain_volumes()
        self.vsolid = sum(self.vol)
        self.ts = open("timeseries.raw", "w")
        self.ts.write("# t_s ux_m zplate_m sigma_wall_Pa tau_wall_Pa sigma_plate_Pa vsolid_m3 vband_m3 coordination atoms ke_J\n")
        self.prof = open("profiles.raw", "w")
        self.prof.write(self.PROFILE_HEADER)
        self.samples = []
        self.grain_set = set(IDS["grains"])

    def coordination(self):
        return coordination(self.grain_set)

    def row(self, t, ux, z, sigma_wall, tau_wall, sigma_plate, vband):
        self.ts.write("%.9g %.9g %.10g %.8g %.8g %.8g %.8g %.8g %.6g %d %.6g\n" % (
            t, ux, z, sigma_wall, tau_wall, sigma_plate, self.vsolid, vband,
            self.coordination(), len(IDS["grains"]), kinetic_energy()))

    def timeseries(self, t):
        zlo, zhi = P["band_zlo"] + ZS, P["band_zhi"] + ZS
        vband = sum(v for i, v in zip(IDS["grains"], self.vol) if zlo <= O.bodies[i].state.pos[2] < zhi)
        sw, tw = wall_forces()
        ux = O.bodies[IDS["wall"][0]].state.pos[0] - REF["wall_x"]
        self.row(t, ux, zplate(), sw / P["area"], tw / P["area"], plate_force() / P["area"], vband)
        self.ts.flush()

    def sample_profile(self):
        # One instantaneous binning; profile() averages the samples of a window.
        dz, z0 = P["bin_dz"], P["zlo"]
        nb = int(math.ceil((P["zhi"] - P["zlo"]) / dz))
        bins = [[0, 0.0, 0.0, 0.0, 0.0] for _ in range(nb)]
        stress = bodyStressTensors()
        for i, v in zip(IDS["grains"], self.vol):
            b = O.bodies[i]
            k = int((b.state.pos[2] - ZS - z0) / dz)
            if 0 <= k < nb:
                s = stress[i]
                row = bins[k]
                row[0] += 1; row[1] += b.state.vel[0]; row[2] += v; row[3] += s[2, 2] * v; row[4] += s[0, 2] * v
        self.samples.append(bins)

    def profile(self, step):
        dz, z0 = P["bin_dz"], P["zlo"]
        vbin = P["area"] * dz
        ns = len(self.samples)
        for k in range(len(self.samples[0])):
            count = sum(s[k][0] for s in self.samples)
            if count == 0:
                self.prof.write("%d %.9g 0 0 0 0 0\n" % (step, z0 + (k + 0.5) * dz))
                continue
            vx = sum(s[k][1] for s in self.samples) / count
            solid = sum(s[k][2] for s in self.samples) / (ns * vbin)
            szz = sum(s[k][3] for s in self.samples) / (ns * vbin)
            sxz = sum(s[k][4] for s in self.samples) / (ns * vbin)
            self.prof.write("%d %.9g %.6g %.9g %.9g %.9g %.9g\n" % (step, z0 + (k + 0.5) * dz, count / ns, vx, solid, szz, sxz))
        self.prof.flush()
        self.samples = []


def load_consolidated():
    # Stage 1's specimen at test friction, under the servo plate.
    O.load("consolidated.yade.gz")
    ids_from_tags()
    P["plate_ref_z"] = float(O.tags["iwb_plate_ref_z"])
    O.engines = engines()
    set_friction(P["mu_test"])
    SERVO["on"] = True


def stress_volume_sums(volumes):
    # The grains' summed stress x volume (compression negative), as LIGGGHTS's stress/atom reduced;
    # volumes: grain_volumes(), which do not change during a stage.
    stress = bodyStressTensors()
    sums = [0.0, 0.0, 0.0]
    for i, v in zip(IDS["grains"], volumes):
        for k in range(3):
            sums[k] += stress[i][k, k] * v
    return sums


def export_snapshot(vtk):
    """Particles, walls and contacts in the raw layout of src/dem/engines/snapshots.hpp (LIGGGHTS's): point
    arrays id, mass, v, omega (radius is VTKExporter's own); contact rows of 15 columns, the force on
    the first body. Positions are YADE's (unwrapped, lifted by ZS): the workbench shifts them."""
    vtk.exportSpheres(ids=IDS["grains"], numLabel=O.iter,
                      what=dict(id="b.id", mass="b.state.mass", v="b.state.vel", omega="b.state.angVel"))
    vtk.exportFacets(ids=[i for i in IDS["wall"] if isinstance(O.bodies[i].shape, Facet)] + IDS["plate"],
                     numLabel=O.iter)
    boundary = set(IDS["wall"]) | set(IDS["plate"])
    fmt = " ".join(["%.9g"] * 15) + "\n"
    with open("dumps/pairs_%d.txt" % O.iter, "w") as pairs, open("dumps/wall_contacts_%d.txt" % O.iter, "w") as walls:
        for i in O.interactions:
            if not i.isReal:
                continue
            # YADE's law adds it to id2 and its negative to id1; a liquid bridge pulls as well
            f2 = i.phys.normalForce + i.phys.shearForce + capillary_force_on_2(i)
            c = i.geom.contactPoint
            if i.id1 in boundary or i.id2 in boundary:
                grain, f = (i.id2, f2) if i.id1 in boundary else (i.id1, -f2)
                x = O.bodies[grain].state.pos
                walls.write(fmt % (c[0], c[1], c[2], x[0], x[1], x[2], 0, 0, grain, f[0], f[1], f[2], 0, 0, 0))
                continue
            x1 = O.bodies[i.id1].state.pos
            x2 = O.bodies[i.id2].state.pos + O.cell.hSize * i.cellDist  # the image in contact
            f = -f2
            pairs.write(fmt % (x1[0], x1[1], x1[2], x2[0], x2[1], x2[2], i.id1, i.id2, 0, f[0], f[1], f[2], c[0], c[1], c[2]))


def clamp_under_plate(z):
    """The grains whose centres lie above z (the clamp's depth below the plate's teeth) held in x
    and y and in rotation, free in z: the upper frame of a direct interface shear test."""
    clamped = 0
    for i in IDS["grains"]:
        b = O.bodies[i]
        if b.state.pos[2] > z:
            b.state.blockedDOFs = "xyXYZ"
            b.state.vel = Vector3(0, 0, b.state.vel[2])
            b.state.angVel = Vector3(0, 0, 0)
            clamped += 1
    say("IWB_FACT clamped_grains %d" % clamped)


def shear():
    load_consolidated()
    zrelax = zplate()
    run(P["relax_steps"])
    settle(zrelax)
    for axis, value in zip("xyz", stress_volume_sums(grain_volumes())):  # the soil cell's K0 when shear starts
        say("IWB_FACT stress_volume_%s%s_Pa_m3 %.10g" % (axis, axis, value))
    z0 = zplate()
    SERVO["z0"] = z0
    say("IWB_STAGE_DONE relax zplate_m %.10g" % z0)
    if P["bc"] == "CV":
        SERVO["on"] = False  # CV: the plate is held during shear
    if P["clamp"]:
        clamp_under_plate(z0 + ZS - P["plate_clamp"])  # grains sit in YADE's lifted frame
    sh = P["shear"]
    step0 = O.iter
    say("IWB_SHEAR_START step %d zplate_m %.10g" % (step0, z0))
    REF["wall_x"] = O.bodies[IDS["wall"][0]].state.pos[0]
    SERVO["shear"], SERVO["integrate"], SERVO["t0"] = True, True, O.time
    SERVO["vel_max"] = min(SERVO["vel_max"], 20.0 * sh["velocity"])
    out = Outputs()
    # One loop over the shear in chunks of the smallest output period; outputs fall on chunk ends.
    chunk = 10
    sample_every = max(chunk, (sh["profile_every"] // max(1, min(20, sh["profile_repeat"]))) // chunk * chunk)
    vtk = export.VTKExporter("dumps/yade")
    out.timeseries(0.0)  # the state when shear starts (u_x = 0): the relaxation's last step
    export_snapshot(vtk)
    done = 0
    while done < sh["steps"]:
        n = min(chunk, sh["steps"] - done)
        run(n)
        done += n
        step = O.iter - step0
        t = O.time - SERVO["t0"]
        if step % sh["ts_every"] < chunk:
            out.timeseries(t)
        if step % sample_every < chunk:
            out.sample_profile()
        if step % sh["profile_every"] < chunk and out.samples:
            out.profile(O.iter)
        if step % sh["vtk_every"] < chunk:
            export_snapshot(vtk)
        if step % sh["progress_every"] < chunk:
            say("IWB_PROGRESS %.9g %.9g" % (sh["velocity"] * t if sh["cyclic"] else wall_displacement(t), sh["u_total"]))
    ux = O.bodies[IDS["wall"][0]].state.pos[0] - REF["wall_x"]
    report_cost()
    report_liquid_bridges()
    say("IWB_STAGE_DONE shear ux_m %.9g" % ux)


# --- soil cell: oedometer --------------------------------------------------------------------

def oedometer_row(k, steps):
    """Holds for `steps` and prints the row of level k: the mean over the last avg_steps (the
    LIGGGHTS template's ave/time over the last half window: a stiff, dense cell rattles by tens
    of percent around the servo's target). Columns as oedometer.in's: sigma on the bottom wall
    and on the plate (Pa), plate height (m), solid volume (m3), summed stress x volume xx yy zz
    (Pa m3), coordination, kinetic energy (J)."""
    oe = P["oedometer"]
    run(steps - oe["avg_steps"])
    grain_set, volumes = set(IDS["grains"]), grain_volumes()
    vsolid = sum(volumes)
    sums, n = [0.0] * 9, 0
    for _ in range(max(1, oe["avg_steps"] // oe["avg_every"])):
        run(oe["avg_every"])
        row = [wall_forces()[0] / P["area"], plate_force() / P["area"], zplate(), vsolid]
        row += stress_volume_sums(volumes) + [coordination(grain_set), kinetic_energy()]
        sums = [a + b for a, b in zip(sums, row)]
        n += 1
    say("IWB_ROW oedometer %d %s" % (k, " ".join("%.10g" % (v / n) for v in sums)))


def oedometer():
    load_consolidated()
    # The plate's contact stiffness alone is several times the cell's (its grain layers are in
    # series): a 6 d50 cell was held 9 % under a level's target on loading and 24 % over it on
    # unloading. Counting the layers, and the shear stage's integral term for creep, the rows
    # land within ~1 % of their targets.
    SERVO["layers"] = P["oedometer"]["layers"]
    SERVO["integrate"] = True
    oe = P["oedometer"]
    oedometer_row(0, P["relax_steps"])
    levels = oe["levels_Pa"]
    for k in range(1, len(levels)):
        say("IWB_LEVEL %d %d %.10g" % (k, len(levels) - 1, levels[k]))
        SERVO["ramp"] = (O.iter, oe["ramp_steps"], levels[k - 1] * P["area"], levels[k] * P["area"])
        run(oe["ramp_steps"])
        oedometer_row(k, oe["hold_steps"])
    report_cost()
    say("IWB_STAGE_DONE oedometer")


# --- soil cell: the periodic cell (`iwb dem soiltest --cell periodic --engine yade`) -----------
# No walls and no gravity: YADE's cell periodic in x, y and z, consolidated by a servo on its
# height (x and y held), then sheared by its own velocity gradient, the top image moving in +x
# over the bottom one at the wall's speed (velGrad[0][2] = v / H), the height servo-controlled
# (CNL) or held (CV). Every `every` steps the servo sets d H / dt = k (sigma_zz - sigma_n0),
# capped at vel_max, with the gains of dem/scene/periodic_cell.hpp. The raw files have the plate
# cell's columns: u_x is the top image's travel, the "plate" the cell's height, both stresses
# the grains' (getStress: the Love-Weber stress of the whole cell).

PERIODIC = {"gain": 0.0, "hold": False, "shear": False, "t0": 0.0}


def cell_height():
    return O.cell.hSize[2, 2]


def cell_stresses():
    """sigma_zz (compression positive) and tau_zx (positive against a growing tilt), Pa."""
    s = getStress()
    return -s[2, 2], s[0, 2]


def periodic_control():
    g = O.cell.velGrad
    vz = 0.0
    if not PERIODIC["hold"]:
        vmax = P["servo"]["vel_max"]
        vz = max(-vmax, min(vmax, PERIODIC["gain"] * (cell_stresses()[0] - P["sigma_n0"])))
    g[2, 2] = vz / cell_height()
    if PERIODIC["shear"]:
        g[0, 2] = wall_velocity(O.time - PERIODIC["t0"]) / cell_height()
        # a tilt past half the length: the same lattice, flipped to the least skewed cell
        if abs(O.cell.hSize[0, 2]) > 0.5 * O.cell.hSize[0, 0]:
            O.cell.flipCell()
    O.cell.velGrad = g


def periodic_ids():
    IDS.update(json.loads(O.tags["iwb_ids"]))
    SPHERES[0] = len(IDS["grains"])


def periodic_consolidate():
    pc = P["periodic"]
    O.periodic = True
    O.cell.setBox(P["Lx"], P["Ly"], pc["Lz_insert"])
    O.dt = P["dt"]
    grains_mat = material(P["mu_consolidation"], "grains")
    cloud = random_cloud(P["n_particles"], random.Random(P["seed"]), 0.0, pc["Lz_insert"], periodic_z=True)
    grains = O.bodies.append([sphere(p, r, material=grains_mat) for p, r in cloud])
    O.tags["iwb_ids"] = json.dumps({"grains": grains, "wall": [], "plate": []})
    periodic_ids()
    say("IWB_PARTICLES %d requested %d" % (len(grains), P["n_particles"]))
    if len(grains) < P["n_particles"]:
        fail("particle count short: %d of %d placed in the periodic cell" % (len(grains), P["n_particles"]))
    O.engines = engines(facets=False, gravity=0.0, control="periodic_control()")
    PERIODIC["gain"] = pc["gain_consolidation"]
    sigma_zz = lambda: cell_stresses()[0]
    approach(sigma_zz, "the cloud did not reach %g Pa" % P["approach_sigma"])

    def stop_the_cell():
        O.cell.velGrad = Matrix3.Zero

    accept(sigma_zz, cell_height, stop_the_cell)


class PeriodicOutputs(Outputs):
    """timeseries.raw as Outputs writes it (the cell's height for the plate, its stresses for both
    boundaries, the whole cell for the band); profiles.raw rows "step z_m count vx solid szz tau"
    per bin of the cell's height (z wrapped into the cell, vx less one wall speed per period
    wrapped, stresses per bin volume, compression and shear along the tilt positive)."""
    PROFILE_HEADER = "# step z_m count vx_m_s solid_fraction s_zz_Pa tau_zx_Pa (compression and shear along the tilt positive)\n"

    def __init__(self, z0):
        super().__init__()
        self.area = P["Lx"] * P["Ly"]
        self.bins = max(1, int(round(z0 / P["periodic"]["bin_dz"])))

    def timeseries(self, t):
        s, tau = cell_stresses()
        self.row(t, wall_displacement(t), cell_height(), s, tau, s, self.vsolid)
        self.ts.flush()

    def sample_profile(self):
        h, v = cell_height(), P["shear"]["velocity"]
        nb = self.bins
        bins = [[0, 0.0, 0.0, 0.0, 0.0] for _ in range(nb)]
        stress = bodyStressTensors()
        for i, vol in zip(IDS["grains"], self.vol):
            b = O.bodies[i]
            periods = math.floor(b.state.pos[2] / h)
            k = min(nb - 1, int((b.state.pos[2] - periods * h) / h * nb))
            row, st = bins[k], stress[i]
            row[0] += 1; row[1] += b.state.vel[0] - periods * v; row[2] += vol
            row[3] -= st[2, 2] * vol; row[4] += st[0, 2] * vol
        self.samples.append((h, bins))

    def profile(self, step):
        ns, nb = len(self.samples), self.bins
        h = sum(hs for hs, _ in self.samples) / ns
        vbin = self.area * h / nb
        for k in range(nb):
            count = sum(b[k][0] for _, b in self.samples)
            vx = sum(b[k][1] for _, b in self.samples) / count if count else 0.0
            sums = [sum(b[k][j] for _, b in self.samples) / (ns * vbin) for j in (2, 3, 4)]
            self.prof.write("%d %.9g %.6g %.9g %.9g %.9g %.9g\n" % (step, (k + 0.5) * h / nb, count / ns, vx, *sums))
        self.prof.flush()
        self.samples = []


def periodic_shear():
    O.load("consolidated.yade.gz")
    periodic_ids()
    O.engines = engines(facets=False, gravity=0.0, control="periodic_control()")
    set_friction(P["mu_test"])
    PERIODIC["gain"] = P["periodic"]["gain_consolidation"]
    run(P["relax_steps"])
    for axis, value in zip("xyz", stress_volume_sums(grain_volumes())):  # K0 when shear starts
        say("IWB_FACT stress_volume_%s%s_Pa_m3 %.10g" % (axis, axis, value))
    z0 = cell_height()
    say("IWB_STAGE_DONE relax zplate_m %.10g" % z0)
    sh = P["shear"]
    step0 = O.iter
    say("IWB_SHEAR_START step %d zplate_m %.10g" % (step0, z0))
    PERIODIC.update(gain=P["periodic"]["gain_shear"], hold=P["bc"] == "CV", shear=True, t0=O.time)
    out = PeriodicOutputs(z0)
    chunk = P["servo"]["every"]
    # a sample every chunk through the second half of each profile window, as the LIGGGHTS cell
    half = sh["profile_every"] // 2
    out.timeseries(0.0)
    done = 0
    while done < sh["steps"]:
        n = min(chunk, sh["steps"] - done)
        run(n)
        done += n
        step, t = O.iter - step0, O.time - PERIODIC["t0"]
        if step % sh["ts_every"] < chunk:
            out.timeseries(t)
        if step % sh["profile_every"] >= half:
            out.sample_profile()
        if step % sh["profile_every"] < chunk and out.samples:
            out.profile(O.iter)
        if step % sh["progress_every"] < chunk:
            say("IWB_PROGRESS %.9g %.9g" % (sh["velocity"] * t if sh["cyclic"] else wall_displacement(t), sh["u_total"]))
    report_cost()
    say("IWB_STAGE_DONE shear ux_m %.9g" % wall_displacement(O.time - PERIODIC["t0"]))


STAGES = {"consolidate": consolidate, "shear": shear, "oedometer": oedometer,
          "periodic_consolidate": periodic_consolidate, "periodic_shear": periodic_shear}
if STAGE not in STAGES:
    fail("unknown stage " + STAGE)
try:
    STAGES[STAGE]()
except SystemExit:
    raise
except Exception as e:  # the runner shows this line; the traceback stays in the stage log
    import traceback
    traceback.print_exc()
    fail("python error in stage %s: %s: %s" % (STAGE, type(e).__name__, e))
