#!/usr/bin/env bash
# roughness_command.sh IWB SCENE: `iwb dem roughness` on a scene whose wall and plate are sawtooths
# of pitch p = 2 d50 (data/scenes/smoke.toml: heights h 0.5 and 1 d50) reports, in JSON and in
# text, the descriptors a triangle wave has in closed form (within 1 %, the sampling's share):
#   R_n = R_max over one d50 window = h (a window is half a period: one flank's full rise)
#   R_n over the mean window = 3/4 h (a window across a crest spans h max(s, 1 - s), s uniform)
#   R_a = h/4, R_q = h/sqrt(12) (a triangle wave's mean absolute and RMS deviation)
#   mean |dz/dx| = 2 h / p
set -euo pipefail
iwb=$1 scene=$2
json=$("$iwb" dem roughness "$scene" --format json)
text=$("$iwb" dem roughness "$scene")
/usr/bin/python3 - "$json" <<'PY'
import json, math, sys
d = json.loads(sys.argv[1])
failed = []
for side, h in (("wall", 0.5), ("plate", 1.0)):
    want = {"R_n": h, "R_n_mean": 0.75 * h, "R_a_d50": h / 4, "R_q_d50": h / math.sqrt(12),
            "mean_abs_slope": 2 * h / 2.0}
    for key, value in want.items():
        got = d[side][key]
        ok = abs(got - value) <= 0.01 * value
        print(f"{side} {key}: {got:.5g}, closed form {value:.5g} {'ok' if ok else 'WRONG'}")
        if not ok:
            failed.append(f"{side} {key}")
sys.exit(f"roughness_command.sh: {', '.join(failed)} off the closed form" if failed else 0)
PY
grep -Eq "R_n = R_max\(d50\)/d50 +0\.5 \(largest\), 0\.375 \(mean over windows\)" <<<"$text" ||
  { echo "$text"; echo "roughness_command.sh: the text report lacks the wall's R_n line"; exit 1; }
echo "roughness_command.sh: JSON and text agree with the closed forms"
