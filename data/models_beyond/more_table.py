#!/usr/bin/python3
"""Issue 56: hvwe and the candidates side by side on the cells the plan reports but does not decide
by (judge_more.sh writes the comparisons). Per cell (the runs of one scene but seed) and quantity,
each model's predicted verdict, the label most of its runs carry ("within DEM scatter" kept apart
from "holds"), with the cell's mean error. Usage: more_table.py NAME=COMPARE_DIR... [--md OUT] [--json OUT]"""
import argparse
import collections
import glob
import json
import os

from judge import DECIDING

MODELS = ["hvwe", "ahe", "hvwe-rd", "hvwe-pg"]
QUANTITIES = DECIDING + ["dilation_rate"]


def predicted(path):
    """{quantity: (verdict, relative error)} of a compare.json's predicted variant, and its DEM."""
    d = json.load(open(path))
    v = d["variants"][d["verdicts"]["predicted_variant"]]
    return d["dem"], d["seeds"]["runs"], {q["quantity"]: (q["verdict"], q.get("relative_error"))
                                          for q in v["verdicts"]}


def cells(directory):
    """{cell: {"dem": the first run's, "runs": {model: [per-run verdicts]}}} of one set, whose
    comparisons are DIRECTORY/<model>/<run>/compare.json."""
    out = collections.OrderedDict()
    for run in sorted(glob.glob(os.path.join(directory, "hvwe", "*", "compare.json"))):
        name = os.path.basename(os.path.dirname(run))
        dem, _, _ = predicted(run)
        # a cell: the runs of one scene but seed (a run's own seed list leaves out its cell's runs
        # at the plate, so it does not name the cell)
        key = name_of(dem)
        cell = out.setdefault(key, {"dem": dem, "runs": collections.defaultdict(list)})
        for m in MODELS:
            path = os.path.join(directory, m, name, "compare.json")
            if os.path.exists(path):
                cell["runs"][m].append(predicted(path)[2])
    return out


def cell_verdict(labels):
    """The label most of a cell's runs carry; "mixed" without a majority. Unlike judge.py, "within
    DEM scatter" stays its own label: a miss the seeds cannot convict is not a hold (issue 59)."""
    label, n = collections.Counter(labels).most_common(1)[0]
    return label if 2 * n > len(labels) else "mixed"


def summary(verdicts):
    """The cell's verdict (most of its runs) and mean error on each quantity."""
    out = {}
    for q in QUANTITIES:
        seen = [r[q] for r in verdicts if q in r]
        if seen:
            errors = [e for _, e in seen if e is not None]
            out[q] = {"verdict": cell_verdict([v for v, _ in seen]),
                      "mean_error": sum(errors) / len(errors) if errors else None}
    return out


def name_of(dem):
    parent = os.path.dirname(os.path.dirname(dem["dir"]))
    leaf = "_".join(p for p in os.path.basename(dem["dir"]).split("_") if not p.startswith("s") or not p[1:].isdigit())
    return os.path.relpath(parent, "data") + ":" + (leaf or "seeds")


def shown(entry):
    error = entry["mean_error"]
    return entry["verdict"] + (f" ({100 * error:+.0f} %)" if error is not None else "")


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("sets", nargs="+", help="NAME=DIR")
    p.add_argument("--md")
    p.add_argument("--json")
    a = p.parse_args()
    records, lines = [], []
    changed = collections.Counter()
    lines += ["| set | cell | R_n | boundary | runs | quantity | " + " | ".join(MODELS) + " |",
              "|---|---|---|---|---|---|" + "---|" * len(MODELS)]
    for item in a.sets:
        name, directory = item.split("=", 1)
        for cell in cells(directory).values():
            per_model = {m: summary(cell["runs"][m]) for m in MODELS}
            refused = {m for m in MODELS if os.path.exists(os.path.join(directory, m + ".refused"))}
            dem = cell["dem"]
            records.append({"set": name, "cell": name_of(dem), "R_n": dem["R_n"], "boundary": dem["boundary"],
                            "runs": len(cell["runs"]["hvwe"]), "models": per_model,
                            "cannot_start": sorted(refused)})
            for q in QUANTITIES:
                if q not in per_model["hvwe"]:
                    continue
                base = per_model["hvwe"][q]["verdict"]
                row = [shown(per_model[m][q]) if q in per_model[m] else
                       ("cannot start" if m in refused else "-") for m in MODELS]
                for m in MODELS[1:]:
                    v = per_model[m].get(q, {}).get("verdict")
                    if v == "holds" and base != "holds":
                        changed[(m, "holds where hvwe does not")] += 1
                    if v == "breaks" and base != "breaks":
                        changed[(m, "breaks where hvwe does not")] += 1
                row = [row[0]] + [f"**{t}**" if t == "cannot start" or
                                  per_model[m].get(q, {}).get("verdict") != base else t
                                  for m, t in zip(MODELS[1:], row[1:])]
                lines.append(f"| {name} | {name_of(dem)} | {dem['R_n']:g} | {dem['boundary']} | "
                             f"{len(cell['runs']['hvwe'])} | {q} | " + " | ".join(row) + " |")
    head = ["Predicted verdicts (no fit on these cells), each cell's by most of its runs, with its mean "
            "error; a verdict other than hvwe's in bold; 'cannot start': the model refused the set's first "
            "states (its reason in judge_more.sh's WORK/<set>/<model>.refused). Against hvwe, counted over "
            "cells and quantities:", ""]
    head += [f"- {m}: " + (", ".join(f"{k} {n}" for (mm, k), n in sorted(changed.items()) if mm == m) or "none")
             for m in MODELS[1:]]
    text = "\n".join(head + [""] + lines) + "\n"
    print(text)
    if a.md:
        open(a.md, "w").write(text)
    if a.json:
        json.dump(records, open(a.json, "w"), indent=1)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
