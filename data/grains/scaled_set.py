#!/usr/bin/python3
"""A hypoplastic set for a wider grading from the uniform grains' calibrated one (README.md here,
"The models on the graded cells"): what a user does who has the graded sand's index void ratios
and no soil tests of it. Herle & Gudehus (1999) tie the limit void ratios to the grain assembly
(e_d0 ~ e_min, e_c0 ~ e_max, e_i0 ~ 1.2 e_max), and a wider grading packs denser at every state;
here e_d0, e_c0 and e_i0 are scaled by one ratio, the graded specimens' void ratio over the uniform
ones' after the same dense preparation (consolidation friction 0.1 at 50 kPa: the DEM's e_min
test). phi_c, h_s, n, alpha and beta are kept: an assumption, said in the file it writes. Reads
the first row of each run's timeseries.csv. Run from the repository root:

    /usr/bin/python3 data/grains/scaled_set.py BASE_SET "UNIFORM_GLOB" "GRADED_GLOB" OUT_SET
"""
import csv
import glob
import os
import re
import statistics as st
import sys
import tempfile

LIMIT_VOID_RATIOS = ("ec0", "ed0", "ei0")


def first_void_ratios(pattern):
    files = sorted(glob.glob(f"{pattern}/timeseries.csv"))
    if not files:
        sys.exit(f"scaled_set: no run matches {pattern}")
    return [float(next(csv.DictReader(open(f)))["e_specimen"]) for f in files]


def main(base, uniform_glob, graded_glob, out):
    uniform, graded = first_void_ratios(uniform_glob), first_void_ratios(graded_glob)
    ratio = st.mean(graded) / st.mean(uniform)
    lines = [f"# {os.path.basename(base)} with its limit void ratios (ec0, ed0, ei0) times {ratio:.4f}:",
             f"# the mean specimen void ratio after the dense preparation of {len(graded)} runs of",
             f"# {graded_glob} ({st.mean(graded):.4f}) over that of {len(uniform)} runs of",
             f"# {uniform_glob} ({st.mean(uniform):.4f}). phi_c, hs, n, alpha and beta are the",
             "# uniform grains' (an assumption). Written by data/grains/scaled_set.py."]
    scaled = 0
    for line in open(base):
        if line.startswith("#"):
            continue
        m = re.match(r"\s*(\w+)\s*=\s*([-+0-9.eE]+)", line)
        if m and m.group(1) in LIMIT_VOID_RATIOS:
            line = f"{m.group(1)} = {float(m.group(2)) * ratio:.6f}  # {m.group(2)} x {ratio:.4f}\n"
            scaled += 1
        lines.append(line.rstrip("\n"))
    if scaled != len(LIMIT_VOID_RATIOS):
        sys.exit(f"scaled_set: {base} holds {scaled} of ec0, ed0, ei0")
    with tempfile.NamedTemporaryFile("w", dir=os.path.dirname(out) or ".", delete=False) as f:
        f.write("\n".join(lines) + "\n")
    os.replace(f.name, out)
    print(f"{out}: limit void ratios x {ratio:.4f} ({st.mean(graded):.4f} / {st.mean(uniform):.4f})")


if __name__ == "__main__":
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    main(*sys.argv[1:])
