# V*(u*) and F*(u*) at contact (D* = 0) for equal spheres, theta = 0, from YADE's Laplace-Young solver
# (solveLiqBridge.py), interpolated in D* along the stable branch. Writes 20_vstar_table.json.
import json, math, numpy
from math import sin, cos, tan, pi, radians, sqrt
src = open('/usr/share/doc/yade/examples/capillaryLaplaceYoung/solveLiqBridge.py').read()
G = dict(numpy=numpy, sin=sin, cos=cos, tan=tan, pi=pi, radians=radians, sqrt=sqrt, degrees=math.degrees)
exec(compile(src, 'solveLiqBridge.py', 'exec'), G)
solve = G['solveLiqBridge']
us, vs, fs, ds, drs = [], [], [], [], []
for u in numpy.geomspace(1.0, 1000.0, 16):
    rows = []
    for d1 in numpy.arange(0.2, 60, 0.2):
        z = 1e-5
        o = solve(1.0, 0.0, u, d1, z, 0, 0, 0)
        while o[-1] == 0 and z > 1e-7:
            z /= 2; o = solve(1.0, 0.0, u, d1, z, 0, 0, 0)
        rows.append(o[:5])
    a = numpy.array(rows)
    a = a[a[:, 1] > 0]
    drupt = a[:, 0].max(); vr = a[a[:, 0] == drupt, 1].max()
    st = a[a[:, 1] >= vr]; st = st[numpy.argsort(st[:, 0])]
    # interpolate at dist = 0 (the two rows straddling 0)
    k = numpy.searchsorted(st[:, 0], 0.0)
    lo, hi = st[k - 1], st[k]
    t = (0 - lo[0]) / (hi[0] - lo[0])
    row = lo + t * (hi - lo)
    us.append(float(u)); vs.append(float(row[1])); fs.append(float(row[2])); ds.append(float(row[3])); drs.append(float(drupt))
    print("u* %8.3f  V* %.4e  F* %.4f  delta %.2f deg  D*_rupture %.4f   (small-bridge 2 pi/u*^2 = %.4e)" % (u, row[1], row[2], row[3], drupt, 2 * pi / u ** 2), flush=True)
json.dump(dict(u_star=us, V_star=vs, F_star=fs, delta_deg=ds, D_rupture=drs,
               note="equal spheres, theta=0, D*=0; u*=s R/gamma, V*=V/R^3, F*=F/(2 pi R gamma)"), open("20_vstar_table.json", "w"), indent=1)
