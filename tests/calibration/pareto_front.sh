#!/usr/bin/env bash
# pareto_front.sh IWB SCRATCH: `iwb calibrate --pareto` on synthetic soil tests whose oedometer
# and shear tests come from different h_s (1 and 4 MPa, Table 5.2 Hostun otherwise), with h_s and
# n free: writes the parameter file of the given weights, calibration.json, pareto.csv/.json/.svg
# and a parameter file per point (4 and the given); the front's table has one row per point in order of share, the
# oedometer's RMS falling and the shear's rising along it, and each point's file holds the values
# of its row. The trade's physics is asserted in tests/calibration/test_pareto.cpp; this checks
# the command's files agree with each other.
set -euo pipefail
IWB=$1 SCRATCH=$2
REPO=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$SCRATCH" && mkdir -p "$SCRATCH" && cd "$SCRATCH"
sed 's/^hs_kPa *=.*/hs_kPa = 4e6/' "$REPO/data/params/table_5_2_hostun.toml" > stiffer.toml
grep -q '^hs_kPa = 4e6' stiffer.toml
"$IWB" soiltest synthetic --params "$REPO/data/params/table_5_2_hostun.toml" --test oedometer \
  --e0 0.85 --sigma 10 --rows 20 -o soil/oedometer > /dev/null
for bc_e0 in CNL:0.65 CNL:0.90 CV:0.70; do
  "$IWB" soiltest synthetic --params stiffer.toml --test simpleshear --bc "${bc_e0%:*}" \
    --e0 "${bc_e0#*:}" --rows 40 -o "soil/shear-${bc_e0%:*}-${bc_e0#*:}" > /dev/null
done
fix=()
for kv in phi_c_deg=31 ec0=0.96 ed0=0.61 ei0=1.09 alpha=0.13 beta=2; do fix+=(--fix "$kv"); done
"$IWB" calibrate soil/* "${fix[@]}" --weight shear=1e-5 --pareto oedometer,shear --points 4 \
  -o out/hostun.toml > calibrate.txt
cat calibrate.txt
for f in hostun.toml calibration.json pareto.csv pareto.json pareto.svg pareto.png pareto.gp \
  pareto/point-1.toml pareto/point-5.toml; do
  [ -s "out/$f" ] || { echo "pareto_front.sh: out/$f missing or empty"; exit 1; }
done
[ ! -e out/pareto/point-6.toml ] || { echo "pareto_front.sh: more points than 4 and the given"; exit 1; }
/usr/bin/python3 - out <<'PY'
import csv, json, sys, tomllib
out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/pareto.csv")))
front = json.load(open(f"{out}/pareto.json"))
assert len(rows) == 5 == len(front["points"]), (len(rows), len(front["points"]))
shares = [float(r["share"]) for r in rows]
assert shares == sorted(shares), shares
oed = [float(r["rms_oedometer"]) for r in rows]
shear = [float(r["rms_shear"]) for r in rows]
assert all(b <= a * (1 + 1e-6) for a, b in zip(oed, oed[1:])), oed
assert all(b >= a * (1 - 1e-6) for a, b in zip(shear, shear[1:])), shear
assert oed[-1] < 0.5 * oed[0] and shear[0] < 0.5 * shear[-1], (oed, shear)
given = [k for k, r in enumerate(rows) if r["given"] == "1"]
assert len(given) == 1, given
for k, r in enumerate(rows):
    p = tomllib.load(open(f"{out}/pareto/point-{k + 1}.toml", "rb"))["hypoplastic"]
    for key in ("hs_kPa", "n", "phi_c_deg"):
        assert abs(p[key] - float(r[key])) <= 1e-6 * abs(p[key]), (k, key, p[key], r[key])
    assert p["phi_c_deg"] == 31.0
main = tomllib.load(open(f"{out}/hostun.toml", "rb"))["hypoplastic"]
assert abs(main["hs_kPa"] - float(rows[given[0]]["hs_kPa"])) <= 1e-6 * main["hs_kPa"]
cal = json.load(open(f"{out}/calibration.json"))
assert cal["objectives"]["shear"]["weight"] == 1e-5, cal["objectives"]
print("pareto_front.sh: 5 points, oedometer RMS", [round(x, 3) for x in oed], "shear RMS", [round(x, 3) for x in shear])
PY
