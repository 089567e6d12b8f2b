#!/usr/bin/python3
"""The bundled example ball mill (data/mills/ball_mill_5m.toml) through every
charge model and a whole-life forecast per model (docs/validation/ball-mill.md).

The charge runs use build/bench/bench_speed_accuracy and the error measures
of bench/speed_accuracy.py (against the finest DEM run: media size, 16 steps a
collision, 12 revolutions averaged); the forecasts use `linerlife forecast`,
the DEM's wear calibration scaled as in that script's Qiu forecasts (its
three factors times the ratio of the layer V-1.2's new-liner mass-loss rate
to the DEM reference's, so that the lives differ by where the wear goes and
how it feeds back, not by its amount). Results are cached in OUT/results.json
(a rerun only runs what is missing; --rerun LABEL,.. forces some).

    /usr/bin/python3 bench/ball_mill.py --out /tmp/ball_mill [--rerun "layer 1.2"]

One thread for every charge run; the DEM forecast uses two.
"""
import argparse
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from speed_accuracy import REF, errors, f, forecast_rows, run  # noqa: E402
from toml_edit import set_key  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CONFIG = "data/mills/ball_mill_5m.toml"

CHARGE_RUNS = [
    ("empirical", ["model=empirical"]),
    ("layer 1.0", ["model=layer", "variant=1.0"]),
    ("layer 1.1", ["model=layer", "variant=1.1"]),
    ("layer 1.2", ["model=layer", "variant=1.2"]),
    ("dem", ["model=dem"]),
    (REF[0], REF[1]),
]

DEM_DRIVE = {"model": {"charge": '"dem"'}, "dem": {"threads": "2"},
             "forecast": {"revolutions_per_drive": "2", "refresh_tol_m": "0.008"}}
# (label, keys, whether the DEM's wear calibration is scaled to the layer V-1.2's rate)
FORECASTS = [
    ("layer 1.0", {"model": {"charge": '"layer"', "variant": '"1.0"'}}, False),
    ("layer 1.1", {"model": {"charge": '"layer"', "variant": '"1.1"'}}, False),
    ("layer 1.2", {"model": {"charge": '"layer"', "variant": '"1.2"'}}, False),
    ("layer 1.2, 2 revolutions, 8 mm", {"model": {"charge": '"layer"', "variant": '"1.2"'},
                                         "forecast": {"revolutions_per_drive": "2", "refresh_tol_m": "0.008"}}, False),
    ("dem, 2 revolutions, 8 mm", DEM_DRIVE, True),
    ("dem, 2 revolutions, 8 mm, the thesis' constants", DEM_DRIVE, False),
    # the DEM forecast's own convergence in the revolutions a drive
    ("dem, 6 revolutions, 8 mm", {**DEM_DRIVE, "forecast": {"revolutions_per_drive": "6", "refresh_tol_m": "0.008"}},
     True),
    # and in the refresh tolerance
    ("dem, 2 revolutions, 4 mm", {**DEM_DRIVE, "forecast": {"revolutions_per_drive": "2", "refresh_tol_m": "0.004"}},
     True),
    ("dem, 2 revolutions, 16 mm", {**DEM_DRIVE, "forecast": {"revolutions_per_drive": "2", "refresh_tol_m": "0.016"}},
     True),
]


def save(cache, path):
    tmp = path + ".tmp"
    json.dump(cache, open(tmp, "w"), indent=1)
    os.replace(tmp, path)


def forecast(linerlife, text, out_dir, label):
    cfg = os.path.join(out_dir, "forecast_" + label.replace(" ", "_").replace(",", "") + ".toml")
    open(cfg, "w").write(text)
    out = cfg[:-5] + "_out"
    t0 = time.time()
    p = subprocess.run([linerlife, "forecast", cfg, "--json", "--quiet", "--out", out], capture_output=True, text=True)
    wall = time.time() - t0
    if p.returncode != 0:
        return {"error": p.stderr.strip(), "exit": p.returncode, "wall_s": wall}
    j = json.loads(p.stdout)
    r = {k: j[k] for k in ("operating_hours", "calendar_days", "criterion", "charge_redrives", "lifter_height_m_final",
                           "face_angle_leading_deg_final", "min_thickness_m_final", "history")}
    r["wall_s"] = wall
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=os.path.join(ROOT, "build/bench/bench_speed_accuracy"))
    ap.add_argument("--linerlife", default=os.path.join(ROOT, "build/app/linerlife"))
    ap.add_argument("--out", default="/tmp/ball_mill")
    ap.add_argument("--rerun", default="", help="labels to run again (charge runs and forecasts)")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    cache_path = os.path.join(a.out, "results.json")
    cache = json.load(open(cache_path)) if os.path.exists(cache_path) else {}
    rerun = set(x for x in a.rerun.split(",") if x)

    for label, args in CHARGE_RUNS:
        ck = f"charge/{label}"
        if ck in cache and label not in rerun:
            continue
        print(f"running {ck} ...", file=sys.stderr, flush=True)
        cache[ck] = run(a.binary, CONFIG, args)
        save(cache, cache_path)

    base = open(os.path.join(ROOT, CONFIG)).read()
    for label, keys, scaled in FORECASTS:
        ck = f"forecast/{label}"
        if ck in cache and label not in rerun:
            continue
        text, scale = base, None
        if scaled:
            scale = cache["charge/layer 1.2"]["mass_rate_kg_s_per_m"] / cache[f"charge/{REF[0]}"]["mass_rate_kg_s_per_m"]
            for k in ("calibration_centrifugal", "calibration_gravitational", "calibration_impact"):
                text = set_key(text, "wear", k, f"{scale:.6g}")
        for sec, kv in keys.items():
            for k, v in kv.items():
                text = set_key(text, sec, k, v)
        print(f"running {ck} ...", file=sys.stderr, flush=True)
        cache[ck] = forecast(a.linerlife, text, a.out, label)
        cache[ck]["calibration_scale"] = scale
        save(cache, cache_path)

    ref = cache[f"charge/{REF[0]}"]
    print(f"Reference: DEM at the media size, 16 steps a collision, 12 revolutions averaged: {ref['particles']} "
          f"discs, toe {ref['toe_deg']:.1f} deg, shoulder {ref['shoulder_deg']:.1f} deg, CoM "
          f"{ref['com_angle_deg']:.1f} deg, net power {ref['net_power_kw']:.4g} kW, mass-loss rate "
          f"{ref['mass_rate_kg_s_per_m']:.4g} kg/s/m, {ref['simulated_s']:.1f} s simulated in {ref['wall_s']:.1f} s.\n")
    print("| run | elements | wall [s] | toe [deg] | shoulder [deg] | CoM [deg] | net power [kW] | mass-loss rate "
          "[kg/s/m] | error: toe / shoulder / CoM [deg] | error: power / wear rate / wear shape [%] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for label, _ in CHARGE_RUNS:
        r = cache[f"charge/{label}"]
        if "error" in r:
            print(f"| {label} | failed (exit {r['exit']}): {r['error'][:80]} | | | | | | | | |")
            continue
        e = errors(r, ref)
        rate = r.get("mass_rate_kg_s_per_m")
        print(f"| {label} | {r['particles'] if r['model'] != 'empirical' else '-'} | {r['wall_s']:.3g} | "
              f"{r['toe_deg']:.1f} | {r['shoulder_deg']:.1f} | {r['com_angle_deg']:.1f} | {r['net_power_kw']:.0f} | "
              f"{'-' if not rate else f'{rate:.4g}'} | {f(e['toe'])} / {f(e['shoulder'])} / {f(e['com'])} | "
              f"{f(e['power'])} / {f(e['wear_rate'])} / {f(e['wear_shape'])} |")

    print("\n| forecast | life [h] | calendar days | criterion | vs the DEM forecast | at the end: lifter [m], "
          "leading face [deg], thinnest [m] | net power: new, lowest, highest, last [kW] | drives | wall [s] |")
    print("|---|---|---|---|---|---|---|---|---|")
    for label, r, rel in forecast_rows(cache, [label for label, _, _ in FORECASTS], 9):
        p = r["history"]["net_power_kw"]
        cal = f", calibration x {r['calibration_scale']:.4g}" if r.get("calibration_scale") else ""
        print(f"| {label}{cal} | {r['operating_hours']:.0f} | {r['calendar_days']:.0f} | {r['criterion']} | {rel} | "
              f"{r['lifter_height_m_final']:.3f}, {r['face_angle_leading_deg_final']:.1f}, "
              f"{r['min_thickness_m_final']:.3f} | {p[0]:.0f}, {min(p):.0f}, {max(p):.0f}, {p[-1]:.0f} | "
              f"{r['charge_redrives']} | {r['wall_s']:.0f} |")


if __name__ == "__main__":
    main()
