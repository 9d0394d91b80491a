"""The runs of the re-run reference campaign on the converged truth, for the table scripts here:
the committed sweeps data/reference/truth2_* and the convergence study's CNL runs at R_n 0.5 and
0.25 (data/convergence/truth_clamped*, the same scene), each with its group: wall, d50, boundary."""
import glob, json, tomllib

DIRS = ["data/reference/truth2_*/runs/*", "data/convergence/truth_clamped/runs/*",
        "data/convergence/truth_clamped_rn025/runs/*"]


def group_of(manifest):
    """(wall, boundary) of a run, readable and sortable."""
    scene = tomllib.loads(manifest["scene"]["text"])
    w, b, d50 = scene["wall"], scene["boundary"], scene["particles"]["d50_mm"]
    wall = "flat" if w["profile"] == "flat" else f"R_n {manifest['R_n']:g}"
    if d50 != 2.0:
        wall += f", d50 {d50:g} mm"
    bc = f"{b['type']} {b.get('sigma_n_kPa', 50):g} kPa"
    if b["type"] == "CNS":
        bc += f", K {b['K_kPa_per_mm']:g} kPa/mm"
    return wall, bc


def campaign_runs():
    """Sorted (group, run directory, summary) of every complete run."""
    out = []
    for pattern in DIRS:
        for d in glob.glob(pattern):
            m = json.load(open(f"{d}/manifest.json"))
            if m.get("status") != "complete":
                continue
            scene = tomllib.loads(m["scene"]["text"])
            order = (scene["boundary"]["type"], scene["boundary"].get("sigma_n_kPa", 50),
                     -scene["particles"]["d50_mm"], m["R_n"])
            out.append((order, group_of(m), d, json.load(open(f"{d}/summary.json"))))
    # CNL before CNS, 50 before 200 kPa, 2 mm before 1 mm, flat to rough
    out.sort(key=lambda r: (r[0], r[2]))
    return [r[1:] for r in out]
