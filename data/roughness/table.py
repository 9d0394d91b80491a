"""The shapes campaign's cells beside the sawtooth's at the same R_n: per cell the mean over its
seeds +- the 95 % t half-width (Student's t, n - 1 degrees of freedom) of each run's summary.json,
the runs it rests on and where each sheared. Cells with no complete run are left out. Run from the
repository root:  /usr/bin/python3 data/roughness/table.py"""
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # data/seed_stats.py
import seed_stats  # noqa: E402

DATA = Path("data")
SHAPES = DATA / "roughness" / "roughness_shapes" / "runs"
# (label, R_n, run directories): the sawtooth cells are the truth campaign's own; job names are
# the sweep's (random: RMS-xi-H, file: height_scale)
CELLS = [
    ("sawtooth", 0.1, sorted((DATA / "reference/truth2_rn/runs").glob("sawtooth-2-0.1_s*_cnl"))),
    ("sinusoid", 0.1, sorted(SHAPES.glob("sinusoid-2-0.1_s*"))),
    ("random H 0.5", 0.1, sorted(SHAPES.glob("random-0.02185-0.5-0.5_s*"))),
    ("random H 0.8", 0.1, sorted(SHAPES.glob("random-0.02398-0.5-0.8_s*"))),
    ("measured-like file", 0.1, sorted(SHAPES.glob("file-*-1.263_s*"))),
    ("sawtooth", 0.5, sorted((DATA / "convergence/truth_clamped/runs").glob("s[0-9]"))),
    ("sinusoid", 0.5, sorted(SHAPES.glob("sinusoid-2-0.5_s*"))),
    ("glued spheres", 0.5, sorted(SHAPES.glob("glued-*_s*"))),
    ("random H 0.5", 0.5, sorted(SHAPES.glob("random-0.1092-0.5-0.5_s*"))),
    ("random H 0.8", 0.5, sorted(SHAPES.glob("random-0.1199-0.5-0.8_s*"))),
    ("measured-like file", 0.5, sorted(SHAPES.glob("file-*-6.316_s*"))),
]


def interval(values):
    return seed_stats.interval(values, single="{:s} (one run)")


def complete(run):
    manifest = run / "manifest.json"
    return manifest.exists() and json.loads(manifest.read_text()).get("status") == "complete"


def main():
    print("| wall | R_n | runs | peak friction | residual friction | total dilation (mm) | first-layer slip | where it sheared (residual steady?) |")
    print("|---|---|---|---|---|---|---|---|")
    for label, rn, runs in CELLS:
        summaries = [json.loads((r / "summary.json").read_text()) for r in runs if complete(r)]
        if not summaries:
            continue
        q = lambda key: interval([s.get(key) for s in summaries])
        where = "; ".join(f"{s['shear_mode']} ({s['residual_is']})" for s in summaries)
        print(f"| {label} | {rn} | {len(summaries)} | {q('peak_friction')} | {q('residual_friction')} | "
              f"{q('dilation_mm')} | {q('wall_slip')} | {where} |")


if __name__ == "__main__":
    main()
