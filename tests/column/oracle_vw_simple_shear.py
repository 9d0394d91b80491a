"""The oracle of tests/column/test_column.cpp, written outside the workbench's code (by a helper
session from the numgeo documentation of von Wolffersdorff's law, 2026-12-02) and run by hand:
    /usr/bin/python3 tests/column/oracle_vw_simple_shear.py

Homogeneous simple shear under constant normal stress with the plain
von Wolffersdorff (1996) hypoplastic model (compression negative).

This is the non-polar limit of micro-polar hypoplasticity: if the Cosserat
rotation follows the continuum rotation (omega_c = -gamma/2, k = 0, m = 0),
D^c = D and the polar law reduces to this one.  Used only as an independent
check value for a 1D polar column (homogeneous branch before localisation).
"""
import math, sys

def vw_rate(T, e, D, P):
    phi, hs, n, ed0, ec0, ei0, alpha, beta = P
    tr = T[0][0] + T[1][1] + T[2][2]
    p = -tr / 3.0
    Th = [[T[i][j] / tr for j in range(3)] for i in range(3)]
    Ts = [[Th[i][j] - (1.0 / 3.0 if i == j else 0.0) for j in range(3)] for i in range(3)]
    ThTh = sum(Th[i][j] * Th[i][j] for i in range(3) for j in range(3))
    nTs2 = sum(Ts[i][j] * Ts[i][j] for i in range(3) for j in range(3))
    tanpsi = math.sqrt(3.0) * math.sqrt(nTs2)
    if nTs2 > 1e-30:
        Ts3 = sum(Ts[i][j] * Ts[j][k] * Ts[k][i] for i in range(3) for j in range(3) for k in range(3))
        c3t = -math.sqrt(6.0) * Ts3 / nTs2 ** 1.5
        c3t = max(-1.0, min(1.0, c3t))
    else:
        c3t = 1.0
    F = math.sqrt(tanpsi ** 2 / 8.0 + (2.0 - tanpsi ** 2) / (2.0 + math.sqrt(2.0) * tanpsi * c3t)) \
        - tanpsi / (2.0 * math.sqrt(2.0))
    sphi = math.sin(math.radians(phi))
    a = math.sqrt(3.0) * (3.0 - sphi) / (2.0 * math.sqrt(2.0) * sphi)
    x = (3.0 * p / hs) ** n
    ei, ec, ed = ei0 * math.exp(-x), ec0 * math.exp(-x), ed0 * math.exp(-x)
    fb = (hs / n) * (ei0 / ec0) ** beta * (1.0 + ei) / ei * (3.0 * p / hs) ** (1.0 - n) \
        / (3.0 + a * a - a * math.sqrt(3.0) * ((ei0 - ed0) / (ec0 - ed0)) ** alpha)
    fe = (ec / e) ** beta
    fd = ((e - ed) / (ec - ed)) ** alpha if e > ed else 0.0
    ThD = sum(Th[i][j] * D[i][j] for i in range(3) for j in range(3))
    nD = math.sqrt(sum(D[i][j] ** 2 for i in range(3) for j in range(3)))
    fac = fb * fe / ThTh
    return [[fac * (F * F * D[i][j] + a * a * Th[i][j] * ThD + fd * a * F * (Th[i][j] + Ts[i][j]) * nD)
             for j in range(3)] for i in range(3)], (ed, ec, ei)


def stress_rate(T, e, epsn, P):
    # velocity gradient: v1,2 = 1 (unit shear rate), v2,2 = epsn
    L = [[0, 1.0, 0], [0, epsn, 0], [0, 0, 0]]
    D = [[0.5 * (L[i][j] + L[j][i]) for j in range(3)] for i in range(3)]
    W = [[0.5 * (L[i][j] - L[j][i]) for j in range(3)] for i in range(3)]
    To, lim = vw_rate(T, e, D, P)
    WT = [[sum(W[i][k] * T[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    TW = [[sum(T[i][k] * W[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    Td = [[To[i][j] + WT[i][j] - TW[i][j] for j in range(3)] for i in range(3)]
    return Td, lim


def run(P, e0, sn, K0=0.5, dg=2e-4, gmax=1.0):
    T = [[-K0 * sn, 0, 0], [0, -sn, 0], [0, 0, -K0 * sn]]
    e, g, en = e0, 0.0, 0.0
    out = []
    peak = (0.0, 0.0)
    while g < gmax - 1e-12:
        # solve Tdot22(epsn) = 0 by secant
        x0, x1 = 0.0, 0.1
        f0 = stress_rate(T, e, x0, P)[0][1][1]
        f1 = stress_rate(T, e, x1, P)[0][1][1]
        for _ in range(30):
            if abs(f1 - f0) < 1e-300:
                break
            x2 = x1 - f1 * (x1 - x0) / (f1 - f0)
            x0, f0 = x1, f1
            x1 = x2
            f1 = stress_rate(T, e, x1, P)[0][1][1]
            if abs(f1) < 1e-10 * sn:
                break
        epsn = x1
        Td, lim = stress_rate(T, e, epsn, P)
        T = [[T[i][j] + dg * Td[i][j] for j in range(3)] for i in range(3)]
        e += dg * (1.0 + e) * epsn
        en += dg * epsn
        g += dg
        ratio = T[0][1] / (-T[1][1])
        if ratio > peak[0]:
            peak = (ratio, g)
        out.append((g, ratio, en, e, lim[1]))
    return out, peak


if __name__ == "__main__":
    sets = {
        # Herle & Gudehus (1999) Karlsruhe sand, as quoted in jtorreci/tochnog docs
        "HG99_Karlsruhe": (30.0, 5.8e6, 0.28, 0.53, 0.84, 1.00, 0.13, 1.05),
        # set recalled from Tejchman's papers (UNVERIFIED recollection)
        "Tejchman_recalled": (30.0, 190e3, 0.5, 0.51, 0.82, 1.30, 0.30, 1.0),
    }
    for name, P in sets.items():
        for sn in (50.0, 100.0, 200.0):
            for e0 in (0.60, 0.70, 0.90):
                out, peak = run(P, e0, sn)
                g, r, en, e, ec = out[-1]
                # gamma where dilation rate vanishes approx: report at gamma 0.1,0.3,1
                def at(gq):
                    for row in out:
                        if row[0] >= gq - 1e-9:
                            return row
                    return out[-1]
                r01 = at(0.1); r03 = at(0.3)
                print(f"{name:18s} sn={sn:5.0f}kPa e0={e0:.2f}: peak tau/sn={peak[0]:.3f} "
                      f"(phi={math.degrees(math.atan(peak[0])):.1f}deg at gamma={peak[1]:.3f}); "
                      f"gamma=1: tau/sn={r:.3f} (phi={math.degrees(math.atan(r)):.1f}), e={e:.3f}, ec(p)={ec:.3f}, "
                      f"eps_n(total)={en:+.4f}; eps_n@0.1={r01[2]:+.4f} @0.3={r03[2]:+.4f}")
