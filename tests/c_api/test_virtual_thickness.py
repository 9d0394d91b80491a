#!/usr/bin/python3
"""Seed 7.2 without Abaqus (tests/c_api): the direct interface shear test of 7.2.1 through the C
interface's Python module, the pressure held by a Newton iteration on the normal displacement with
the consistent tangent (the FRIC scheme of 7.1), for the granular and the clay set of Table 7.1 at
the seed's pressures, with virtual thicknesses d_s^v of 1, 5 and 20 mm. A rate-independent model
sees only u / d_s^v: the responses of two thicknesses at the same u / d_s^v agree to round-off, so
d_s^v stretches the displacement axis and leaves every stress alone (peak, residual; the seed's
"calibrate the shear stress evolution"). Prints the table of src/c_api/README.md.
Usage: test_virtual_thickness.py PARAMS_DIR (PYTHONPATH holds the module)."""
import os, sys

import numpy as np
import iwb_interface

U_END_MM = 50.0  # the seed's u_t = 5 cm
STEPS = 500


def direct_shear(material, initial, p_n, d_s):
    state = material.initial_state(sigma_n_kPa=p_n, **initial)
    rows = []
    du = U_END_MM * d_s / 20.0 / STEPS  # the same strain per step for every d_s^v (u / d_s to 2.5)
    for k in range(STEPS):
        u_n = 0.0
        for _ in range(30):
            out, t, tangent = material.update(state, [u_n, du, 0.0], thickness=d_s)
            r = t[0] - p_n
            if abs(r) < 1e-12 * p_n:
                break
            u_n -= r / tangent[0, 0]
        state = out
        rows.append([(k + 1) * du, t[0], t[1]])
    return np.array(rows)


def main():
    params = os.path.join(sys.argv[1], "table_7_1_verification.toml")
    cases = (("hvwe", {"e0": 0.75}, (100.0, 200.0, 300.0)), ("hce", {"OCR": 1.0}, (50.0, 100.0, 200.0)))
    failed = False
    print("model,p_n_kPa,d_s_mm,peak_tau_over_sigma,u_at_peak_mm,end_tau_over_sigma,largest_difference_vs_1mm")
    for model, initial, pressures in cases:
        m = iwb_interface.Material(model, params)
        for p_n in pressures:
            base = direct_shear(m, initial, p_n, 1.0)
            for d_s in (1.0, 5.0, 20.0):
                r = base if d_s == 1.0 else direct_shear(m, initial, p_n, d_s)
                worst = np.max(np.abs(r[:, 1:] - base[:, 1:])) / np.max(np.abs(base[:, 1:]))
                k = int(np.argmax(r[:, 2]))
                print(f"{model},{p_n:g},{d_s:g},{r[k, 2] / r[k, 1]:.4f},{r[k, 0]:.3g},{r[-1, 2] / r[-1, 1]:.4f},{worst:.1e}")
                failed |= not worst <= 1e-12
    sys.exit(1 if failed else 0)


main()
