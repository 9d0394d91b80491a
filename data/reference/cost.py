"""The share of engine time spent shearing in the reference campaign on the converged truth (issue
20 item 2): per committed run, the consolidate and shear stages' wall seconds from manifest.json (a
run whose consolidation was reused from the cache spends ~0 s there). The machine was shared with
builds and tests and the engines ran at nice 19, so the seconds are an upper bound of an idle run's.
Run from the repository root:  /usr/bin/python3 data/reference/cost.py"""
import glob, json

runs = sorted(glob.glob("data/reference/truth2_*/runs/*/manifest.json"))
consolidate = shear = 0.0
fresh = reused = 0
for f in runs:
    stages = json.load(open(f))["stages"]
    c = stages["consolidate"]
    consolidate += c["wall_seconds"]
    if c.get("consolidation", {}).get("reused"):
        reused += 1
    else:
        fresh += 1
    shear += stages["shear"]["wall_seconds"]
total = consolidate + shear
print(f"{len(runs)} runs: {fresh} consolidations ({consolidate:.0f} s), {reused} reused; "
      f"shearing {shear:.0f} s: {100 * shear / total:.0f} % of the engine time shearing")
