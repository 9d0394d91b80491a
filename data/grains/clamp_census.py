#!/usr/bin/python3
"""How often does the clamp keep the band at the wall? (issue 36 item 4; README.md here, "A deeper
clamp"). Every committed DEM run (data/**/runs/*/summary.json with the scene it ran in its
manifest), counted by engine, monotonic or cyclic, the plate's clamp depth (plate.clamp_d50; 0 = no
clamp) and the preparation (specimen.consolidation_friction: 0.1 dense, 0.3 medium, 1.0 loose), with
where each sheared (summary.json's shear_mode). Then, per preparation, the monotonic LIGGGHTS runs
that left the wall with 9 d50 clamped against 6 d50: Fisher's exact test (one-sided: is the deeper
clamp's rate lower?) and the 95 % upper bound of its rate. A census of whatever campaigns ran, not a
designed comparison: walls, gradings, stresses and travels differ between the runs counted. Run from
the repository root:

    /usr/bin/python3 data/grains/clamp_census.py
"""
import collections
import glob
import json
import tomllib

from scipy import stats

AT_WALL = "localised at the wall"


def census():
    cells = collections.defaultdict(collections.Counter)
    for path in glob.glob("data/**/runs/*/summary.json", recursive=True):
        run = path.rsplit("/", 1)[0]
        try:
            manifest = json.load(open(f"{run}/manifest.json"))
            scene = tomllib.loads(manifest["scene"]["text"])
        except (OSError, KeyError, ValueError):
            continue  # no manifest or no scene text (runs older than the scene record)
        engine = manifest.get("engine")
        engine = engine.get("name") if isinstance(engine, dict) else engine
        kind = "cyclic" if "cycles" in scene.get("shear", {}) else "monotonic"
        clamp = float(scene.get("plate", {}).get("clamp_d50", 0))
        friction = float(scene.get("specimen", {}).get("consolidation_friction", 0.1))
        cells[(engine, kind, clamp, friction)][json.load(open(path)).get("shear_mode")] += 1
    return cells


def main():
    cells = census()
    print("| engine | kind | clamp (d50) | consolidation friction | runs | at the wall | elsewhere (where) |")
    print("|---|---|---|---|---|---|---|")
    for (engine, kind, clamp, friction), modes in sorted(cells.items(), key=str):
        n, wall = sum(modes.values()), modes[AT_WALL]
        other = ", ".join(f"{m} {k}" for m, k in sorted(modes.items()) if m != AT_WALL)
        print(f"| {engine} | {kind} | {clamp:g} | {friction:g} | {n} | {wall} | {other or '-'} |")
    print("\nMonotonic LIGGGHTS runs, 9 d50 clamped against 6 d50 (left the wall / runs):")
    frictions = sorted({k[3] for k in cells})
    for label, chosen in [(f"consolidation friction {f:g}", [f]) for f in frictions] + [("all", frictions)]:
        deep, shallow = (sum((cells.get(("liggghts", "monotonic", c, f), collections.Counter()) for f in chosen),
                             collections.Counter()) for c in (9.0, 6.0))
        if deep and shallow:
            compare(label, deep, shallow)


def compare(label, deep, shallow):
    a, b = sum(deep.values()), sum(shallow.values())
    fa, fb = a - deep[AT_WALL], b - shallow[AT_WALL]
    p = stats.fisher_exact([[fa, a - fa], [fb, b - fb]], alternative="less").pvalue
    upper = stats.beta.ppf(0.95, fa + 1, a - fa)  # Clopper-Pearson, one-sided 95 %
    print(f"  {label}: {fa} of {a} against {fb} of {b} ({100 * fb / b:.0f} %); "
          f"the deeper clamp's rate below {100 * upper:.0f} % (95 %); Fisher's p {p:.3f}")


if __name__ == "__main__":
    main()
