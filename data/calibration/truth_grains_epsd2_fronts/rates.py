"""Each point of a committed calibration front against the DEM soil cells of data/dilatancy/: vw3d
with the point's set, CNL 50 kPa from the cells' mean e0 at the three densities (as-scene 0.675,
dense 0.584, loose 0.835), its peak friction and peak dilatancy rate d u_n / d u_x measured as
data/dilatancy/table.py measures them (its model_run), beside the point's RMS per objective group.
Run from the repository root after building:
  /usr/bin/python3 data/calibration/truth_grains_epsd2_fronts/rates.py [FRONT_DIR...]"""
import csv
import glob
import sys

SOURCE = open("data/dilatancy/table.py").read().replace('if __name__ == "__main__":\n    main()', "")
TABLE = {"__name__": "rates"}
exec(compile(SOURCE, "data/dilatancy/table.py", "exec"), TABLE)
DENSITIES = [("as-scene", 0.675, 0.668, 0.273), ("dense", 0.584, 0.855, 0.446), ("loose", 0.835, 0.541, 0.109)]


def rows(front):
    out = []
    for k, r in enumerate(csv.DictReader(open(f"{front}/pareto.csv"))):
        TABLE["PARAMS"] = f"{front}/pareto/point-{k + 1}.toml"
        cells = [TABLE["model_run"](e0) for _, e0, _, _ in DENSITIES]
        out.append((r, cells))
    return out


def main(fronts):
    print("DEM soil cells (data/dilatancy/table.md): " + "; ".join(
        f"{n} e0 {e0}: peak {mu}, rate {rate}" for n, e0, mu, rate in DENSITIES) + "\n")
    for front in fronts:
        first = next(csv.DictReader(open(f"{front}/pareto.csv")))
        pair = [c[len("weight_"):] for c in first if c.startswith("weight_")]
        print(f"## {front}\n")
        print(f"| share on {pair[0]} | given | RMS oedometer | RMS shear | RMS dilatancy | "
              + " | ".join(f"{n}: peak, rate" for n, _, _, _ in DENSITIES) + " | phi_c | alpha |")
        print("|---|---|---|---|---|" + "---|" * len(DENSITIES) + "---|---|")
        for r, cells in rows(front):
            print(f"| {float(r['share']):.4g} | {'yes' if r['given'] == '1' else ''} | {float(r['rms_oedometer']):.2f} | "
                  f"{float(r['rms_shear']):.2f} | {float(r['rms_dilatancy']):.2f} | "
                  + " | ".join(f"{mu:.3f}, {rate:.3f}" for mu, rate in cells)
                  + f" | {float(r['phi_c_deg']):.1f} | {float(r['alpha']):.3f} |")
        print()


main(sys.argv[1:] or sorted(glob.glob("data/calibration/truth_grains_epsd2_fronts/*/")))
