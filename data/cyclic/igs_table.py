"""Does intergranular strain improve the cyclic verdicts over the plain model? (issue 34, item 5;
README.md here.) Each argument is the OUT of one `iwb compare RUN --seeds ... --model A,B -o OUT`
(OUT/<model>/compare.json); the cell is OUT's name, and several OUTs of one cell (one per model
pair) merge. Per cell and model, the cyclic verdicts of compare.json counted, predicted and
fitted (holds / within DEM scatter / breaks; "not reached" added where any); then per quantity
the predicted variant's median relative error over the judged cycles, per amplitude (cells named
small_* and a1_*, as models_compare.sh names them). Run from the repository root:
  /usr/bin/python3 data/cyclic/igs_table.py runs/igs_vs_plain/*/
  /usr/bin/python3 data/cyclic/igs_table.py --models hvwe,hvwe-igs,ahe,ahe-igs,vw3d,vw3d-igs \\
      runs/models53/*/*/
(models_compare.sh makes the comparisons of the six R_n 0.5 cells for any pair.)"""
import argparse
import collections
import json
import statistics as st
from pathlib import Path


def verdicts(cmp, which):
    return cmp["variants"][cmp["verdicts"][which]]["cyclic"]["verdicts"]


def counts(vs):
    c = collections.Counter(v["verdict"] for v in vs)
    s = f"{c['holds']} / {c['within DEM scatter']} / {c['breaks']}"
    return s + (f" ({c['not reached']} not reached)" if c["not reached"] else "")


def load(dirs, models):
    """(cell, model) -> compare.json, for every model of `models` some OUT of the cell holds."""
    found = {}
    for d in dirs:
        for m in models:
            f = Path(d) / m / "compare.json"
            if f.is_file():
                found[(Path(d).name, m)] = json.loads(f.read_text())
    return found


def count_table(found, cells, models, which):
    print("| cell | " + " | ".join(models) + " |")
    print("|---|" + "---|" * len(models))
    for cell in cells:
        row = [counts(verdicts(found[(cell, m)], which)) if (cell, m) in found else "-" for m in models]
        print(f"| {cell} | " + " | ".join(row) + " |")


def error_table(found, cells, models):
    errors = collections.defaultdict(lambda: collections.defaultdict(list))
    for (cell, m), cmp in found.items():
        amplitude = cell.split("_")[0]
        for v in verdicts(cmp, "predicted_variant"):
            if v.get("relative_error") is not None:
                errors[(v["quantity"], amplitude)][m].append(abs(v["relative_error"]))
    print("| quantity | cells | " + " | ".join(models) + " |")
    print("|---|---|" + "---|" * len(models))
    for (q, amplitude), by_model in sorted(errors.items()):
        row = [f"{100 * st.median(by_model[m]):.0f} %" if by_model[m] else "-" for m in models]
        print(f"| {q} | {amplitude} | " + " | ".join(row) + " |")


def main(dirs, models):
    found = load(dirs, models)
    cells = sorted({cell for cell, _ in found})
    print("Predicted (holds / within DEM scatter / breaks):\n")
    count_table(found, cells, models, "predicted_variant")
    print("\nFitted (kappa_r, d_s fitted to the cell):\n")
    count_table(found, cells, models, "fitted_variant")
    print("\nPredicted, median |relative error| over the judged cycles and the cells of one amplitude:\n")
    error_table(found, cells, models)


parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("--models", default="hvwe,hvwe-igs", help="comma-separated, in column order")
parser.add_argument("dirs", nargs="+", help="OUT directories of iwb compare --model A,B")
args = parser.parse_args()
main(args.dirs, args.models.split(","))
