#!/usr/bin/env python3
"""Issue 56: reads a candidate's fit record (`iwb form-limit --free ... --hold-walls`, form_limit.json)
and applies the criteria README.md fixed before any fit. Prints a markdown report.

Per run, the record holds hvwe's verdict (the start set, chi or beta_w = 0: "soil_test_predicted")
and the candidate's (the fitted set: "form_limit") on each quantity, each run judged against its
cell's seed scatter. A cell is the runs of one scene but seed (the record's cell_runs). A cell holds
(breaks) a quantity when most of its runs do; without a majority it counts as neither. "holds" and
"within DEM scatter" are holds; "breaks" is breaks; every other verdict (not resolved, not steady, an
error) is neither. Usage: judge.py RECORD_DIR [--md OUT]"""
import argparse
import collections
import json
import os
import re
import sys

HOLDS = {"holds", "within DEM scatter"}
# criterion 2's quantities (README: peak friction, residual where steady, u_x at peak, sigma_n
# change, total dilation); "not steady" residuals count as neither, so "where steady" follows
DECIDING = ["peak_friction", "residual_friction", "u_x_at_peak", "sigma_n_change", "total_dilation"]
ROUGH_R_N = 0.25


def r_n_of(wall):
    return float(re.match(r"R_n ([0-9.e+-]+)", wall).group(1))


def majority(verdicts):
    held = sum(v in HOLDS for v in verdicts)
    broke = sum(v == "breaks" for v in verdicts)
    if 2 * held > len(verdicts):
        return "holds"
    if 2 * broke > len(verdicts):
        return "breaks"
    return "neither"


def cells(record):
    """{cell key: {"wall", "boundary", "name", "runs": [run records]}} of the held-out runs."""
    out = collections.OrderedDict()
    for r in record["runs"]:
        if r["role"] != "held out":
            continue
        key = tuple(sorted(r.get("cell_runs") or [r["dir"]]))
        c = out.setdefault(key, {"wall": r["wall"], "boundary": r["boundary"], "runs": []})
        c["runs"].append(r)
    for c in out.values():
        first = c["runs"][0]["dir"]
        parts = [x for x in os.path.basename(first).split("_") if not re.fullmatch(r"s\d+", x)]
        c["name"] = os.path.relpath(os.path.dirname(first), "data").replace("/runs", "") + ":" + (
            "_".join(parts) or "seeds")
    return out


def mean_error(c, key, variant):
    """The cell's mean signed relative error of `variant` on `key`, over the runs that have one."""
    errors = [r["quantities"][key][variant]["error"] for r in c["runs"]
              if key in r["quantities"] and r["quantities"][key][variant]["error"] is not None]
    return f"{100 * sum(errors) / len(errors):+.0f} %" if errors else "-"


def cell_verdicts(c, variant):
    keys = sorted(set().union(*(r["quantities"].keys() for r in c["runs"])))
    return {k: majority([r["quantities"][k][variant]["verdict"] for r in c["runs"] if k in r["quantities"]])
            for k in keys}


def judge(record):
    rows, c1_denominator, c1_held, new_breaks, smooth_changed = [], [], [], [], []
    for c in cells(record).values():
        hvwe, cand = cell_verdicts(c, "soil_test_predicted"), cell_verdicts(c, "form_limit")
        r_n = r_n_of(c["wall"])
        rows.append((c, hvwe, cand))
        if r_n >= ROUGH_R_N and hvwe.get("total_dilation") == "breaks":
            c1_denominator.append(c["name"])
            if cand.get("total_dilation") == "holds":
                c1_held.append(c["name"])
        for k in DECIDING:
            if hvwe.get(k) == "holds" and cand.get(k) == "breaks":
                new_breaks.append(f"{c['name']}: {k}")
        if r_n < ROUGH_R_N and any(hvwe[k] != cand[k] for k in hvwe):
            smooth_changed.append(c["name"] + ": " + ", ".join(k for k in hvwe if hvwe[k] != cand[k]))
    return rows, c1_denominator, c1_held, new_breaks, smooth_changed


def reference_verdicts(reference, c):
    """The reference model's predicted verdicts on cell `c`'s runs (matched by directory)."""
    if reference is None:
        return {}
    by_dir = {r["dir"]: r for r in reference["runs"]}
    runs = [by_dir[r["dir"]] for r in c["runs"] if r["dir"] in by_dir]
    return cell_verdicts({"runs": runs}, "soil_test_predicted") if runs else {}


def report(record, path, reference=None):
    rows, den, held, new, smooth = judge(record)
    ref_name = reference["model"] if reference else None
    params = ", ".join(f"{p['name']} = {p['value']:.4g}" + (f" +- {p['sigma']:.2g}" if p.get("sigma") is not None else "")
                       + (" (on a bound)" if p.get("at_bound") else "") for p in record["parameters"])
    c1 = len(held) >= 2 * len(den) / 3 if den else False
    lines = [f"## {record['model']}: {path}", "",
             f"Fitted ({record.get('fitted', 'every material parameter and each wall')}): {params}; RMS {record['rms_scaled']:.3g} scatter units over "
             f"{len(record['fit_runs'])} training runs.", "",
             f"- Criterion 1 (dilation at held-out rough walls where hvwe's breaks): {len(held)} of {len(den)} cells "
             f"hold -> {'met' if c1 else 'NOT met'}" + (f" (holds: {', '.join(held)})" if held else ""),
             f"- Criterion 2 (no new breaks): {'met' if not new else 'NOT met: ' + '; '.join(new)}",
             f"- Criterion 3 (smooth walls unchanged): {'met' if not smooth else 'NOT met: ' + '; '.join(smooth)}",
             f"- The candidate {'HOLDS' if c1 and not new and not smooth else 'does not hold'} by the criteria fixed before the fit.",
             "", "Each cell's verdict (most of its runs) and mean error against the DEM; a changed verdict in bold.", "",
             f"| cell | wall | boundary | seeds | quantity | hvwe |{' ' + ref_name + ' |' if ref_name else ''} candidate |",
             "|---|---|---|---|---|---|---|" + ("---|" if ref_name else "")]
    for c, hvwe, cand in rows:
        ref = reference_verdicts(reference, c)
        for k in DECIDING + ["dilation_rate"]:
            if k in hvwe:
                ref_cell = f" {ref.get(k, '-')} |" if ref_name else ""
                shown = f"{cand[k]} ({mean_error(c, k, 'form_limit')})"
                lines.append(f"| {c['name']} | {c['wall']} | {c['boundary']} | {len(c['runs'])} | {k} | "
                             f"{hvwe[k]} ({mean_error(c, k, 'soil_test_predicted')}) |{ref_cell} "
                             f"{'**' + shown + '**' if hvwe[k] != cand[k] else shown} |")
    return "\n".join(lines) + "\n"


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("records", nargs="+", help="form-limit output directories")
    p.add_argument("--md", help="also write the report here")
    p.add_argument("--reference", help="a record of another model whose predicted verdicts are shown beside (ahe)")
    a = p.parse_args()
    reference = json.load(open(os.path.join(a.reference, "form_limit.json"))) if a.reference else None
    text = "".join(report(json.load(open(os.path.join(d, "form_limit.json"))), d, reference) + "\n"
                   for d in a.records)
    print(text)
    if a.md:
        with open(a.md, "w") as out:
            out.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
