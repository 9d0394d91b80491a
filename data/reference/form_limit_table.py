"""The form limits of data/reference/form_limit/ (form_limit.sh) as one table (form_limit/README.md):
per model and wall, the free fit's RMS and the joint fit's (over the sets the soil tests accept;
issue 59), per quantity the runs whose soil-test prediction breaks and the cause the form limit
gives each (form_limit.json's own "cause": this script counts, it decides nothing), the joint set's
d_s in grains and its largest moves in the soil-test set's sigmas, and each objective group's RMS on
the soil tests with the soil-test set, the free set and the joint set. Run from the repository root:
  /usr/bin/python3 data/reference/form_limit_table.py"""
import collections
import glob
import json


def quantity_cells(j):
    per = collections.defaultdict(collections.Counter)
    for r in j["runs"]:
        for key, q in r["quantities"].items():
            per[key]["runs"] += 1
            if "cause" in q:
                per[key][q["cause"]] += 1
    cells = []
    for key, c in sorted(per.items()):
        causes = ", ".join(f"{cause} {n}" for cause, n in c.most_common() if cause != "runs")
        if causes:
            cells.append(f"{key}: {causes} of {c['runs']}")
    return "<br>".join(cells) or "nothing breaks"


def joint_cells(j):
    if "joint" not in j:
        return "no soil tests", "-", "-"
    joint = j["joint"]
    d50 = {w: float(w.split("d50 ")[1].split(" ")[0]) for w in j["walls"]}
    d_s = [f"{p['value'] / d50[p['name'].split('(')[1].rstrip(')')]:.1f}"
           for p in joint["parameters"] if p["name"].startswith("d_s_mm")]
    moved = sorted((p for p in joint["parameters"] if "moved_in_soil_test_sigmas" in p),
                   key=lambda p: -abs(p["moved_in_soil_test_sigmas"]))[:3]
    moves = ", ".join(f"{p['name']} {p['moved_in_soil_test_sigmas']:+.0f}" for p in moved)
    def rms(s):  # rows a set cannot start count apart: their RMS is over the others
        return f"{s['rms']:.2f}" + (f" ({s['unreached']} rows unreached)" if s["unreached"] else "")
    soil = "; ".join(f"{g['group']} {rms(g['soil_test'])} -> {rms(g['form_limit'])} "
                     f"/ {rms(g['joint'])} (<= {g['accepted_up_to']:.2f})"
                     for g in j["soil_tests"])
    accepted = "accepted" if joint["accepted"] else "REFUSED"
    return (f"{joint['rms_scaled']:.2f} ({accepted}, {joint['evaluations']} evaluations, "
            f"{joint['seconds']:.0f} s)", f"d_s {', '.join(d_s)} d50; {moves}", soil)


def main():
    print("| model, wall | RMS free | RMS with the soil tests | breaks of the prediction by cause | "
          "joint set | soil tests' RMS: soil-test set -> free / joint (accepted up to) |")
    print("|---|---|---|---|---|---|")
    for f in sorted(glob.glob("data/reference/form_limit/*/form_limit.json")):
        j = json.load(open(f))
        label = f"{j['model']}, {j['walls'][0]}"
        if j.get("soil_acceptance", 1.25) != 1.25:
            label += f" (acceptance {j['soil_acceptance']:g})"
        joint_rms, joint_set, soil = joint_cells(j)
        print(f"| {label} | {j['rms_scaled']:.2f} | {joint_rms} | {quantity_cells(j)} | "
              f"{joint_set} | {soil} |")


main()
