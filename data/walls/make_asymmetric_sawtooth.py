#!/usr/bin/python3
"""Writes asymmetric_sawtooth.csv and its mirror, asymmetric_sawtooth_mirrored.csv (README.md).

An asymmetric sawtooth (issue 56: a wall whose direction matters, sheared both ways): pitch 4 mm
(2 d50 of the truth's 2 mm grains, as the truth's sawtooth), height 1 mm, each tooth rising over
3.5 mm (slope 0.29) and falling over 0.5 mm (slope 2.0). Its R_max over any 2 mm window is the full
height (the steep face fits in a window), so R_n is 0.5 as the truth's symmetric sawtooth; its mean
|slope| is 2 x 1 / 4 = 0.5, also the symmetric one's; R_a and R_q are those of any sawtooth of that
height (R_q = h / sqrt(12)). Every descriptor `iwb dem roughness` reports is the same for the two
files; only the direction differs. The wall moves in +x (../../../shared/spec/DEM.md), so the soil
passes over it in -x: on asymmetric_sawtooth.csv (rising gently in +x) the steep faces lead and
push the grains; on the mirror the gentle ramps lead and the grains ride up them.
120 mm at 0.1 mm (0.05 d50: the resampling default, so no sample is averaged away and every ridge is a sample), starting in a valley; 12 teeth fill the truth's 48 mm box exactly (periodic).
"""
import numpy as np

pitch, height, rise = 4.0, 1.0, 3.5  # mm
dx, length = 0.1, 120.0
x = np.round(np.arange(0.0, length + dx / 2, dx), 6)
phase = np.mod(x, pitch)
z = np.where(phase <= rise, height * phase / rise, height * (pitch - phase) / (pitch - rise))
for name, heights in [("asymmetric_sawtooth.csv", z), ("asymmetric_sawtooth_mirrored.csv", z[::-1])]:
    with open(name, "w") as f:
        f.write(f"# an asymmetric sawtooth (pitch {pitch} mm, height {height} mm, rise over {rise} mm"
                f"{', mirrored' if 'mirrored' in name else ''}), written by make_asymmetric_sawtooth.py\n")
        f.write("x_mm,z_mm\n")
        for xi, zi in zip(x, heights):
            f.write(f"{xi:.3f},{zi:.5f}\n")
