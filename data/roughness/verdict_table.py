"""Issue 36 item 3: the models against the shapes (README.md here, "The verdicts"). Per cell of
table.py (every wall shape at R_n 0.1 and 0.5, three seeds each) and per model comparison given:
the predicted variant's relative error and verdict on peak friction, residual friction and total
dilation (the median over the cell's runs, each compared with its cell's other seeds, and the
verdicts counted), with each quantity's detection limit; then kappa_r: the joint fit's (mean +-
95 % t over the runs), eq. 5.35 (0.25 log10 D + 1.05, at most 1) with each roughness descriptor D
of the wall in place of R_n, and eq. 5.36 (tan delta_res / tan phi_c, delta_res the DEM's residual
interface friction); and per descriptor the RMS of eq. 5.35 about the fitted kappa_r over the
cells. Arguments: LABEL=DIR, each DIR the OUT of one `iwb compare --runs` over the cells' runs:
  R="data/roughness/roughness_shapes/runs/* data/convergence/truth_clamped/runs/s[123] \\
     data/reference/truth2_rn/runs/sawtooth-2-0.1_s[123]_cnl"
  build/iwb compare --runs $R --model hvwe --params data/params/truth_grains_epsd2.toml -o runs/cmp_shapes
  build/iwb compare --runs $R --model ahe --params data/params/truth_grains_epsd2.toml -o runs/cmp_shapes_ahe
  build/iwb compare --runs $R --model ahe --roughness-scheme arnold-herle \\
      --params data/params/truth_grains_epsd2.toml -o runs/cmp_shapes_ah
  /usr/bin/python3 data/roughness/verdict_table.py hvwe=runs/cmp_shapes ahe=runs/cmp_shapes_ahe \\
      "ahe, A&H scheme"=runs/cmp_shapes_ah
Run from the repository root (IWB: build/iwb, for the descriptors of walls whose manifests
predate them)."""
import collections
import json
import math
import statistics as st
import sys
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))  # table.py, collapse.py beside this file
from collapse import DESCRIPTORS, wall_descriptors  # noqa: E402
from table import CELLS, complete, interval  # noqa: E402

PHI_C_DEG = tomllib.load(open("data/params/truth_grains_epsd2.toml", "rb"))["hypoplastic"]["phi_c_deg"]
QUANTITIES = [("peak_friction", "peak"), ("residual_friction", "residual"), ("total_dilation", "dilation")]
SHORT = {"holds": "H", "within DEM scatter": "S", "breaks": "B", "not reached": "-"}


def comparisons(directory):
    """DEM run directory (resolved) -> compare.json of an `iwb compare --runs` OUT."""
    out = {}
    for f in Path(directory).glob("*/compare.json"):
        c = json.loads(f.read_text())
        out[str(Path(c["dem"]["dir"]).resolve())] = c
    return out


def kappa_535(d):
    return min(1.0, 0.25 * math.log10(d) + 1.05)


def verdict_cell(rows, key):
    vs = [next(v for v in r["variants"][r["verdicts"]["predicted_variant"]]["verdicts"] if v["quantity"] == key)
          for r in rows]
    errors = [v["relative_error"] for v in vs if v.get("relative_error") is not None]
    counts = collections.Counter(SHORT[v["verdict"]] for v in vs)
    word = "".join(f"{n}{k}" for k, n in sorted(counts.items()))
    limit = st.median(v["detection_limit"] for v in vs if v.get("detection_limit") is not None)
    return (f"{100 * st.median(errors):+.0f} % {word}" if errors else "-"), limit


def main(models):
    cmps = {label: comparisons(d) for label, d in models}
    cells = []
    for label, rn, runs in CELLS:
        runs = [r for r in runs if complete(r)]
        per_model = {m: [c[str(r.resolve())] for r in runs if str(r.resolve()) in c] for m, c in cmps.items()}
        residual = [json.loads((r / "summary.json").read_text())["residual_friction"] for r in runs]
        cells.append((f"{label}, R_n {rn}", runs, per_model, wall_descriptors(runs[0]), residual))
    print("Predicted variants: the median relative error over the cell's runs and the verdicts "
          "(H holds, S within DEM scatter, B breaks); detects: the median detection limit\n")
    print("| cell | runs | " + " | ".join(f"{m}: {q}" for m, _ in models for _, q in QUANTITIES) + " | detects (peak, residual, dilation) |")
    print("|---|---|" + "---|" * (len(models) * len(QUANTITIES) + 1))
    for name, runs, per_model, _, _ in cells:
        row, limits = [], []
        for m, _ in models:
            for key, _ in QUANTITIES:
                text, limit = verdict_cell(per_model[m], key) if per_model[m] else ("-", None)
                row.append(text)
                if m == models[0][0]:
                    limits.append(f"{100 * limit:.0f} %" if limit is not None else "-")
        print(f"| {name} | {len(runs)} | " + " | ".join(row) + f" | {', '.join(limits)} |")
    tan_phi = math.tan(math.radians(PHI_C_DEG))
    print(f"\nkappa_r (phi_c {PHI_C_DEG:.2f} deg): fitted jointly (mean +- 95 % t over the runs); "
          "eq. 5.35 with each descriptor in place of R_n; eq. 5.36 from the DEM's residual\n")
    print("| cell | " + " | ".join(f"fitted, {m}" for m, _ in models) + " | "
          + " | ".join(f"5.35 on {label}" for _, label in DESCRIPTORS) + " | 5.36 |")
    print("|---|" + "---|" * (len(models) + len(DESCRIPTORS) + 1))
    misses = collections.defaultdict(list)
    for name, runs, per_model, desc, residual in cells:
        fitted = {m: [r["fit"]["kappa_r"] for r in per_model[m]] for m, _ in models}
        eq = [kappa_535(desc[key]) for key, _ in DESCRIPTORS]
        for m, _ in models:
            if fitted[m]:
                for (key, _), k in zip(DESCRIPTORS, eq):
                    misses[(m, key)].append(k - st.mean(fitted[m]))
        k536 = [min(1.0, r / tan_phi) for r in residual]
        print(f"| {name} | " + " | ".join(interval(fitted[m]) if fitted[m] else "-" for m, _ in models)
              + " | " + " | ".join(f"{k:.3f}" for k in eq) + f" | {interval(k536)} |")
    print("\nEq. 5.35 per descriptor: RMS (and mean) of eq. 5.35 less the fitted kappa_r over the cells\n")
    print("| fitted by | " + " | ".join(label for _, label in DESCRIPTORS) + " |")
    print("|---|" + "---|" * len(DESCRIPTORS))
    for m, _ in models:
        row = []
        for key, _ in DESCRIPTORS:
            d = misses[(m, key)]
            row.append(f"{math.sqrt(sum(x * x for x in d) / len(d)):.3f} ({st.mean(d):+.3f})" if d else "-")
        print(f"| {m} | " + " | ".join(row) + " |")


main([tuple(a.split("=", 1)) for a in sys.argv[1:]])
