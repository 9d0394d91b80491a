# Builds YADE capillary files M(r=1) ... M(r=10) (theta = 0) for Law2_ScGeom_CapillaryPhys_Capillarity,
# which Debian's yade does not ship (yade-data). Python port of the logic of
# /usr/share/doc/yade/examples/capillaryLaplaceYoung/writesCapFile.m, using that folder's own
# Laplace-Young solver solveLiqBridge.py, at reduced resolution (fewer u* values, a coarser deltaZ):
#   file = R ratio, n_D, then per distance D* (=D/R2, increasing, first 0) a block "n 0 0 0 0 0 0 0"
#   followed by n rows [D*, u*, V*, F*, delta1, delta2, nn11, nn33], u* (= suction R2/gamma) increasing;
#   only the u* for which a stable bridge exists at that D* are listed (absent -> V = 0 -> rupture).
# Usage: /usr/bin/python3 make_capillary_tables.py OUTDIR FINE_UP_TO [r ...]
#   ratios up to FINE_UP_TO get the fine resolution (37 u* up to 600, dz 1e-5: ~8 min a table), the
#   others a coarse one (15 u* up to 400, dz 4e-5: ~30 s). The shipped tables: FINE_UP_TO 1.25.
import sys, time, math, numpy
from math import sin, cos, tan, pi, radians, sqrt
src = open('/usr/share/doc/yade/examples/capillaryLaplaceYoung/solveLiqBridge.py').read()
G = dict(numpy=numpy, sin=sin, cos=cos, tan=tan, pi=pi, radians=radians, sqrt=sqrt, degrees=math.degrees)
exec(compile(src, 'solveLiqBridge.py', 'exec'), G)
solve = G['solveLiqBridge']
THETA = 0.0
outdir = sys.argv[1]
fine_up_to = float(sys.argv[2])
rlist = [float(x) for x in sys.argv[3:]] or [1, 1.1, 1.25, 1.5, 1.75, 2, 3, 4, 5, 10]

def bridges(r, u, d1s, dz):
    """Stable physical bridges at (r, u*): rows [D, u, V, F, d1, d2, nn11, nn33] (solveLaplace_uc.py)."""
    rows = []
    for d1 in d1s:
        if d1 <= 0 or d1 + THETA > 90: continue
        z = dz
        try:
            o = solve(r, THETA, u, d1, z, 0, 0, 0)
            while o[-1] == 0 and z > dz / 17:
                z /= 2; o = solve(r, THETA, u, d1, z, 0, 0, 0)
        except BaseException:
            continue
        dist, vol, force, dd1, dd2, e, n11, n33, ok = o
        rows.append([dist, u, vol, force, dd1, dd2, n11, n33])
    a = numpy.array(rows)
    if len(a) == 0: return a
    a = a[(a[:, 0] >= 0) & (a[:, 2] >= 0)]
    if len(a) == 0: return a
    vr = a[a[:, 0] == a[:, 0].max(), 2].max()
    a = a[a[:, 2] >= vr]
    return a[numpy.argsort(a[:, 0])]

def interp_at(dist, data_uc):
    """writesCapFile.m's interpolate(): linear in D*, extrapolated below the smallest computed D*."""
    if len(data_uc) < 2 or dist > data_uc[:, 0].max(): return None
    if dist < data_uc[0, 0]:
        a, b = data_uc[0], data_uc[1]
        return a + (b - a) / (b[0] - a[0]) * (dist - a[0])
    lo = data_uc[data_uc[:, 0] <= dist][-1]; hi = data_uc[data_uc[:, 0] >= dist][0]
    if hi[0] == lo[0]: return lo.copy()
    return lo + (hi - lo) / (hi[0] - lo[0]) * (dist - lo[0])

for r in rlist:
    t0 = time.time()
    fine = r <= fine_up_to
    dz = 1e-5 if fine else 4e-5
    dd1 = 0.3 if fine else 1.0
    n_uc = 36 if fine else 14
    uc_max = 600.0 if fine else 400.0
    ucs = [0.0] + list(numpy.geomspace(0.01, uc_max, n_uc))
    per_uc = {}
    d1max = 90 - THETA
    for u in ucs:
        d1s = numpy.arange(dd1, d1max + 1e-9, dd1)
        a = bridges(r, u, d1s, dz)
        if len(a) >= 2:
            per_uc[u] = a
            d1max = min(90 - THETA, a[:, 4].max() + 2 * dd1)
    maxD = max(a[:, 0].max() for a in per_uc.values())
    ds = numpy.concatenate([[0.0], numpy.geomspace(2e-5, maxD, 49)])
    blocks = []
    for D in ds:
        rows = []
        for u in ucs:
            if u not in per_uc: continue
            x = interp_at(D, per_uc[u])
            if x is None: continue
            x[0], x[1] = D, u
            if x[2] <= 0 or x[3] <= 0: continue
            rows.append(x)
        if not rows: break
        blocks.append(rows)
    name = "%s/M(r=%g)" % (outdir, r)
    with open(name, "w") as f:
        f.write("%g\n%d\n" % (r, len(blocks)))
        for rows in blocks:
            f.write("%d 0 0 0 0 0 0 0\n" % len(rows))
            for x in rows:
                f.write("\t".join("%.8g" % v for v in x) + "\n")
    print("r=%g: %d u* values with bridges, maxD*=%.4f, %d D* blocks, %.0f s" % (r, len(per_uc), maxD, len(blocks), time.time() - t0), flush=True)
    a0 = per_uc.get(ucs[1]); 
