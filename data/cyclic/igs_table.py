"""Does intergranular strain improve the cyclic verdicts over the plain model? (issue 34, item 5;
README.md here.) Each argument is the OUT of one `iwb compare RUN --seeds ... --model hvwe-igs,hvwe
-o OUT` (OUT/hvwe-igs and OUT/hvwe). Per cell and model, the per-cycle verdicts of compare.json
counted: predicted and fitted, holds / within DEM scatter / breaks / not reached; then per quantity
the predicted variant's median relative error over the judged cycles. Run from the repository root:
  /usr/bin/python3 data/cyclic/igs_table.py runs/igs_vs_plain/*/"""
import collections
import json
import statistics as st
import sys
from pathlib import Path

MODELS = ["hvwe", "hvwe-igs"]


def verdicts(cmp, which):
    return cmp["variants"][cmp["verdicts"][which]]["cyclic"]["verdicts"]


def counts(vs):
    c = collections.Counter(v["verdict"] for v in vs)
    return f"{c['holds']} / {c['within DEM scatter']} / {c['breaks']} / {c['not reached']}"


def main(dirs):
    print("| cell | model | predicted: holds / within scatter / breaks / not reached | fitted: the same |")
    print("|---|---|---|---|")
    errors = collections.defaultdict(lambda: collections.defaultdict(list))
    for d in dirs:
        cell = Path(d).name
        for m in MODELS:
            cmp = json.loads((Path(d) / m / "compare.json").read_text())
            pred, fit = verdicts(cmp, "predicted_variant"), verdicts(cmp, "fitted_variant")
            print(f"| {cell} | {m} | {counts(pred)} | {counts(fit)} |")
            for v in pred:
                if v.get("relative_error") is not None:
                    errors[(cell, v["quantity"])][m].append(abs(v["relative_error"]))
    print("\n| cell | quantity | median |error| predicted, hvwe | hvwe-igs |")
    print("|---|---|---|---|")
    for (cell, q), by_model in sorted(errors.items()):
        cells = [f"{100 * st.median(by_model[m]):.0f} %" if by_model[m] else "-" for m in MODELS]
        print(f"| {cell} | {q} | " + " | ".join(cells) + " |")


main(sys.argv[1:])
