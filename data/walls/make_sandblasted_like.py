#!/usr/bin/python3
"""Writes sandblasted_like.csv: a measured-LIKE line profile (synthesised, not measured; see README.md).

A self-affine profile (Hurst exponent 0.8, the value reported for sand-blasted surfaces by
Persson et al. 2005, J. Phys.: Condens. Matter 17 R1) with a roll-off at 0.5 mm, scaled so that its
R_max over a 2 mm gauge is about 0.2 mm (R_n ~ 0.1 for the truth grains: a rough pile at the
bottom of the range the issue asks for), on top of what a profilometer trace carries and a DEM
wall must not: a tilt (form, 0.3 mm over the trace) and sensor noise (RMS 2 um). 8001 samples,
0.015 mm apart: 120 mm, enough for a 48 d50 box of 2 mm grains. Deterministic (seed 20261127).
"""
import numpy as np

rng = np.random.default_rng(20261127)
n, dx = 8001, 0.015  # samples, mm
L = (n - 1) * dx
q = 2 * np.pi * np.fft.rfftfreq(n, dx)  # rad/mm
H, xi = 0.8, 0.5 / (2 * np.pi)
psd = np.zeros_like(q)
psd[1:] = (1 + (q[1:] * xi) ** 2) ** (-(1 + 2 * H) / 2)  # a line scan: PSD ~ q^-(1+2H)
spectrum = np.sqrt(psd) * np.exp(1j * rng.uniform(0, 2 * np.pi, q.size))
z = np.fft.irfft(spectrum, n)
x = np.arange(n) * dx
window = int(round(2.0 / dx))
r_max = max(z[i:i + window + 1].max() - z[i:i + window + 1].min() for i in range(0, n - window, 7))
z *= 0.2 / r_max
z += 0.3 * x / L + rng.normal(0, 0.002, n)
with open("sandblasted_like.csv", "w") as f:
    f.write("# measured-like line profile, synthesised by make_sandblasted_like.py (README.md): not a measurement\n")
    f.write("x_mm,z_mm\n")
    for xi_, zi in zip(x, z):
        f.write(f"{xi_:.3f},{zi:.5f}\n")
