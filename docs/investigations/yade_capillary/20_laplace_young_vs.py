# Suction <-> bridge volume for two touching equal spheres (theta = 0), from YADE's own Laplace-Young
# solver (examples/capillaryLaplaceYoung/solveLiqBridge.py, Lian's finite-difference profile), against
# the small-bridge toroidal approximation V = 2 pi gamma^2 R / s^2.  Run with /usr/bin/python3.
import sys, time, math, numpy
from math import sin, cos, tan, pi, radians, sqrt
sys.path.insert(0, '/usr/share/doc/yade/examples/capillaryLaplaceYoung')
src = open('/usr/share/doc/yade/examples/capillaryLaplaceYoung/solveLiqBridge.py').read()
g = dict(numpy=numpy, sin=sin, cos=cos, tan=tan, pi=pi, radians=radians, sqrt=sqrt, degrees=math.degrees)
exec(compile(src, 'solveLiqBridge.py', 'exec'), g)
solve = g['solveLiqBridge']
R = 1e-3; gamma = 0.073
for s in [float(x) for x in sys.argv[1:]] or [1000., 3000., 10000.]:
    u = s * R / gamma
    t = time.time()
    rows = []
    for d1 in numpy.linspace(0.5, 40, 80):
        dz = 2e-5
        out = solve(1.0, 0.0, u, d1, dz, 0, 0, 0)
        while out[-1] == 0 and dz > 1e-7:
            dz /= 2; out = solve(1.0, 0.0, u, d1, dz, 0, 0, 0)
        rows.append(out[:4])
    rows = numpy.array(rows)  # dist*, V*, F*, delta1
    # stable branch at D* = 0: the largest-volume solution with dist closest to 0
    phys = rows[(rows[:, 0] >= -1e-3) & (rows[:, 1] > 0)]
    i = numpy.argmin(abs(phys[:, 0]))
    Vs, Fs, d1 = phys[i, 1], phys[i, 2], phys[i, 3]
    Vapprox = 2 * pi * gamma ** 2 * R / s ** 2 / R ** 3
    print("suction %.0f Pa  u*=%.2f  D*=%.4f  V*=%.4e (toroidal small-bridge 2 pi gamma^2/(s^2 R^2) = %.4e)  F*=%.4f  F=%.4e N  delta=%.2f deg  (%.1f s)" % (
        s, u, phys[i, 0], Vs, Vapprox, Fs, Fs * 2 * pi * gamma * R, d1, time.time() - t))
    numpy.savetxt('20_ly_s%.0f.txt' % s, rows, header='dist* V* F* delta1(deg); R=1mm gamma=0.073 theta=0 suction %.0f Pa' % s)
