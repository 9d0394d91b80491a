"""The form limits of data/reference/form_limit/ (form_limit.sh) as one table (README.md here, "Form
or calibration"): per model and wall, the fit's RMS, per quantity how the soil-test set's
prediction fares and why it breaks (form or calibration, over the runs it breaks on), the form
limit's own verdicts, the parameters that moved most (in the soil-test set's sigmas; without a
soil-test calibration every parameter's start and end) with those left on a bound of their box,
and what the form limit costs the soil tests. Run from the repository root:
  /usr/bin/python3 data/reference/form_limit_table.py"""
import collections
import glob
import json


def main():
    print("| model, wall | RMS | quantity: predicted breaks (form / calibration) of runs; form limit holds, within scatter, breaks | moved most (soil-test sigmas) | soil tests' RMS, soil-test set -> form limit |")
    print("|---|---|---|---|---|")
    for f in sorted(glob.glob("data/reference/form_limit/*/form_limit.json")):
        j = json.load(open(f))
        name = f.split("/")[-2]
        per = collections.defaultdict(lambda: collections.Counter())
        for r in j["runs"]:
            for key, q in r["quantities"].items():
                c = per[key]
                c["runs"] += 1
                if q["soil_test_predicted"]["verdict"] == "breaks":
                    c["breaks_" + q.get("cause", "?")] += 1
                c["limit_" + q["form_limit"]["verdict"]] += 1
        cells = []
        for key, c in sorted(per.items()):
            breaks = c["breaks_form"] + c["breaks_calibration"]
            cells.append(f"{key}: {breaks} ({c['breaks_form']} / {c['breaks_calibration']}) of {c['runs']}; "
                         f"{c['limit_holds']}, {c['limit_within DEM scatter']}, {c['limit_breaks']}")
        moved = sorted((p for p in j["parameters"] if "moved_in_soil_test_sigmas" in p),
                       key=lambda p: -abs(p["moved_in_soil_test_sigmas"]))[:3]
        moves = ", ".join(f"{p['name']} {p['moved_in_soil_test_sigmas']:+.0f}" for p in moved)
        # without a soil-test calibration (mc, lashkari: the seed's tables) no sigmas: the values
        if not moved:
            moves = "no soil-test sigmas; " + ", ".join(
                f"{p['name']} {p['soil_test_value']:.3g} -> {p['value']:.3g}" for p in j["parameters"])
        bound = [p["name"] for p in j["parameters"] if p.get("at_bound")]
        if bound:
            moves += "; on a bound: " + ", ".join(bound)
        costs = "; ".join(f"{e['what'].split(': ')[-1]} {e['soil_test']:.2f}{e.get('soil_test_note', '')} -> "
                          f"{e['form_limit']:.2f}{e.get('form_limit_note', '')}"
                          for e in j.get("elsewhere", []))
        print(f"| {j['model']}, {j['walls'][0]} | {j['rms_scaled']:.2f} | " + "<br>".join(cells)
              + f" | {moves} | {costs} |")


main()
