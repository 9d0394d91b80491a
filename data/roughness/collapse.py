"""Which roughness descriptor collapses the wall shapes best (issue 36, item 3; README.md here,
"Which descriptor collapses the shapes?"). Every complete run of table.py's cells is one point:
quantity Q (peak friction, residual friction, total dilation) against descriptor D of its wall
(R_n, the mean R_max over d50 windows R_n_mean, R_a/d50, R_q/d50, the mean slope |dz/dx|), one
curve Q = a + b ln D through all runs. The scatter left about the curve is split into the seeds'
own (pure error: runs of one cell about their mean, which no descriptor can remove) and the lack of
fit (cell means about the curve: the shape differences the descriptor leaves unexplained). Per
descriptor: the residual SD about the curve, its ratio to the pure error's SD (1: the descriptor
collapses the shapes to the seeds' scatter) and the lack-of-fit F test's p-value (small: the cells
differ beyond the seeds' scatter at equal D). Descriptors from each run's manifest (`roughness`),
or from `iwb dem roughness` on its scene text where the manifest predates them (the sawtooth cells).
Run from the repository root:  /usr/bin/python3 data/roughness/collapse.py   (IWB: build/iwb)"""
import json
import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path

from scipy import stats

sys.path.insert(0, str(Path(__file__).parent))  # table.py beside this file
from table import CELLS, complete  # noqa: E402

IWB = os.environ.get("IWB", "build/iwb")
DESCRIPTORS = [("R_n", "R_n"), ("R_n_mean", "R_n (mean window)"), ("R_a_d50", "R_a/d50"),
               ("R_q_d50", "R_q/d50"), ("mean_abs_slope", "mean slope")]
QUANTITIES = [("peak_friction", "peak friction"), ("residual_friction", "residual friction"),
              ("dilation_mm", "total dilation")]


def wall_descriptors(run):
    manifest = json.loads((run / "manifest.json").read_text())
    if "roughness" in manifest:
        return manifest["roughness"]["wall"]
    with tempfile.NamedTemporaryFile("w", suffix=".toml", dir=run, delete=False) as f:
        f.write(manifest["scene"]["text"])
    try:
        out = subprocess.run([IWB, "dem", "roughness", f.name, "--format", "json"],
                             capture_output=True, text=True, check=True).stdout
    finally:
        os.unlink(f.name)
    return json.loads(out)["wall"]


def lack_of_fit(cells, key, quantity):
    """(residual SD, pure-error SD, F, p) of Q = a + b ln D over the runs of `cells`."""
    x, y, groups = [], [], []
    for c in cells:
        for s in c["summaries"]:
            if s.get(quantity) is None:
                continue
            x.append(math.log(c["descriptors"][key])), y.append(s[quantity]), groups.append(c["name"])
    n, k = len(x), len(set(groups))
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((a - mx) ** 2 for a in x)
    b = sum((a - mx) * (v - my) for a, v in zip(x, y)) / sxx if sxx > 0 else 0.0
    a0 = my - b * mx
    ss_resid = sum((v - a0 - b * a) ** 2 for a, v in zip(x, y))
    means = {g: sum(v for v, h in zip(y, groups) if h == g) / groups.count(g) for g in set(groups)}
    ss_pure = sum((v - means[g]) ** 2 for v, g in zip(y, groups))
    ss_lof = ss_resid - ss_pure
    df_lof, df_pure = k - 2, n - k
    f = (ss_lof / df_lof) / (ss_pure / df_pure) if df_lof > 0 and ss_pure > 0 else float("nan")
    p = 1.0 - stats.f.cdf(f, df_lof, df_pure) if math.isfinite(f) else float("nan")
    return math.sqrt(ss_resid / (n - 2)), math.sqrt(ss_pure / df_pure), f, p, n, k


def main():
    cells = []
    for label, rn, runs in CELLS:
        done = [r for r in runs if complete(r)]
        if not done:
            continue
        cells.append({"name": f"{label} R_n {rn}",
                      "descriptors": wall_descriptors(done[0]),
                      "summaries": [json.loads((r / "summary.json").read_text()) for r in done]})
    runs = sum(len(c["summaries"]) for c in cells)
    print(f"{len(cells)} cells, {runs} runs\n")
    print("| cell | R_n | R_n (mean window) | R_a/d50 | R_q/d50 | mean slope |")
    print("|---|---|---|---|---|---|")
    for c in cells:
        print(f"| {c['name']} | " + " | ".join(f"{c['descriptors'][k]:.3f}" for k, _ in DESCRIPTORS) + " |")
    print("\n| quantity | descriptor | SD about the curve | / seeds' SD | lack of fit F | p |")
    print("|---|---|---|---|---|---|")
    for q, qname in QUANTITIES:
        for key, dname in DESCRIPTORS:
            sd, pure, f, p, n, k = lack_of_fit(cells, key, q)
            print(f"| {qname} | {dname} | {sd:.4f} | {sd / pure:.2f} | {f:.2f} ({k - 2}, {n - k}) | {p:.3f} |")


if __name__ == "__main__":
    main()
