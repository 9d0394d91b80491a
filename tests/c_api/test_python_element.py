#!/usr/bin/python3
"""The Python caller of the C interface (module iwb_interface, pybind11; tests/c_api): an element
test written in Python reproduces `iwb element` - to round-off under CV (the same operations:
explicit Euler, 4 substeps), to the Newton tolerance under CNL (its own Newton on eps_n with the
consistent tangent). Usage: test_python_element.py IWB TESTS_DIR (PYTHONPATH holds the module)."""
import csv, os, subprocess, sys, tempfile

import numpy as np
import iwb_interface


def history(iwb, toml):
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([iwb, "element", toml, "-o", out + "/run"], check=True, capture_output=True)
        with open(out + "/run/history.csv") as f:
            rows = list(csv.DictReader(f))
    return np.array([[float(r["sigma_n_kPa"]), float(r["tau_x_kPa"])] for r in rows[1:]])


def python_element(normal_load):
    params = os.path.join(os.path.dirname(__file__), "../../data/params/table_5_1_evaluation.toml")
    m = iwb_interface.Material("hvwe", params, integration='scheme = "euler"\nsubsteps = 4')
    state = m.initial_state(sigma_n_kPa=100.0, e0=0.7)
    rows = []
    for _ in range(100):
        eps_n = 0.0
        for _ in range(20):  # CNL: Newton on eps_n with the tangent's d sigma_n / d eps_n
            out, traction, tangent = m.update(state, [eps_n, 0.05 / 100, 0.0])
            residual = traction[0] - 100.0
            if not normal_load or abs(residual) < 1e-12 * 100.0:
                break
            eps_n -= residual / tangent[0, 0]
        state = out
        rows.append(traction[:2])
    return np.array(rows)


def main():
    iwb, tests = sys.argv[1], sys.argv[2]
    failed = False
    for name, normal_load, rtol in (("cv_hvwe_euler.toml", False, 1e-13), ("cnl_hvwe_euler.toml", True, 1e-9)):
        expected, got = history(iwb, os.path.join(tests, name)), python_element(normal_load)
        worst = np.max(np.abs(got - expected)) / np.max(np.abs(expected))
        print(f"{name}: largest difference {worst:.2e} of the largest stress (allowed {rtol:g})")
        failed |= not worst <= rtol
    try:  # errors arrive as exceptions with the library's status
        iwb_interface.Material("nonesuch", "x.toml")
        failed = True
    except iwb_interface.MaterialError as e:
        print(f"unknown model: status {e.status}: {str(e)[:60]}...")
        failed |= e.status != 1
    sys.exit(1 if failed else 0)


main()
