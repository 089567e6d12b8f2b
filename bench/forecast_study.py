#!/usr/bin/python3
"""Convergence and method studies of `linerlife forecast` (issue 5 §3,
docs/validation/forecast.md).

Each study varies one key of the bundled Qiu mill (or a config given with
--config) and runs a whole-life forecast per value. Results are cached in
OUT/results.json (a rerun only runs what is missing); the script prints the
markdown tables of docs/validation/forecast.md and draws its charts into
docs/validation/img/.

    /usr/bin/python3 bench/forecast_study.py [--only rtol,euler] [--out /tmp/fstudy]

Needs build/app/linerlife (scripts/setup.sh builds it), matplotlib and h5py.
"""
import argparse
import json
import math
import os
import subprocess
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from toml_edit import set_key  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# (study, section, key, values, extra settings, what it shows)
STUDIES = [
    ("rtol", "forecast", "rtol", [1e-3, 1e-4, 1e-5, 1e-6], {}, "CVODE relative tolerance"),
    ("refresh", "forecast", "refresh_tol_m", [0.008, 0.004, 0.002, 0.001], {}, "charge re-drive tolerance [m]"),
    ("element", "liner", "element_size_m", [0.02, 0.01, 0.005, 0.0025, 0.0015], {}, "surface element size [m]"),
    ("revolutions", "forecast", "revolutions_per_drive", [2.5, 5, 10, 20], {}, "revolutions averaged per drive"),
    ("secant", "forecast", "refresh_tol_m", [0.004, 0.002, 0.001], {"rate_model": '"secant"'},
     "charge re-drive tolerance [m] with secant rates"),
    ("amplify", "forecast", "amplification", [1e5, 1e6, 1e7, 1e8], {"method": '"amplify"'},
     "amplification factor A (method amplify)"),
    ("euler", "forecast", "euler_step_h", [800, 400, 200, 100, 50], {"method": '"euler"'},
     "Euler step [h] (method euler)"),
]


def run_case(binary, base_text, section, key, value, extra, out_dir):
    text = set_key(base_text, section, key, value)
    for k, v in extra.items():
        text = set_key(text, "forecast", k, v)
    os.makedirs(out_dir, exist_ok=True)
    cfg = os.path.join(out_dir, "config.toml")
    with open(cfg, "w") as f:
        f.write(text)
    p = subprocess.run([binary, "forecast", cfg, "--json", "--quiet", "--out", os.path.join(out_dir, "run")],
                       capture_output=True, text=True)
    if p.returncode != 0:
        return {"exit": p.returncode, "error": p.stderr.strip()}
    j = json.loads(p.stdout)
    with h5py.File(os.path.join(out_dir, "run", "forecast.h5"), "r") as h5:
        pr = h5["forecast/profiles"]
        nodes, off = np.asarray(pr["nodes"]), np.asarray(pr["offset"])
        R = float(h5["surface"].attrs["shell_radius_m"])
        last = nodes[off[-2]:off[-1]]
        hist = h5["forecast/history"]
        power = np.asarray(hist["net_power_kw"])
    # final profile in the lifter frame: x along the shell, y above it
    th = np.arctan2(last[:, 1], last[:, 0])
    r = np.hypot(last[:, 0], last[:, 1])
    j_out = {k: j[k] for k in ("operating_hours", "criterion", "lifter_height_m_final", "face_angle_leading_deg_final",
                               "charge_redrives", "cvode_steps", "rhs_evals", "wall_s") if k in j}
    j_out.update({"exit": 0, "x": (R * th).tolist(), "y": (R - r).tolist(), "mean_power_kw": float(np.mean(power)),
                  "power_hist": power.tolist(), "hours_hist": j["history"]["hours"]})
    return j_out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--config", default=os.path.join(ROOT, "data/mills/qiu2001_sag.toml"))
    ap.add_argument("--binary", default=os.path.join(ROOT, "build/app/linerlife"))
    ap.add_argument("--out", default="/tmp/linerlife_forecast_study")
    ap.add_argument("--only", default="")
    ap.add_argument("--img", default=os.path.join(ROOT, "docs/validation/img"))
    a = ap.parse_args()
    base = open(a.config).read()
    os.makedirs(a.out, exist_ok=True)
    cache_path = os.path.join(a.out, "results.json")
    cache = json.load(open(cache_path)) if os.path.exists(cache_path) else {}
    only = set(filter(None, a.only.split(",")))
    for name, section, key, values, extra, label in STUDIES:
        if only and name not in only:
            continue
        for v in values:
            tag = f"{name}:{v}"
            if tag not in cache:
                print(f"running {tag}", file=sys.stderr, flush=True)
                cache[tag] = run_case(a.binary, base, section, key, v, extra, os.path.join(a.out, f"{name}_{v}"))
                with open(cache_path + ".tmp", "w") as f:
                    json.dump(cache, f)
                os.replace(cache_path + ".tmp", cache_path)
        report(name, key, values, label, cache, a.img)


def report(name, key, values, label, cache, img):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = [(v, cache[f"{name}:{v}"]) for v in values]
    ok = [(v, r) for v, r in rows if r.get("exit") == 0]
    ref = ok[-1][1]["operating_hours"] if ok else float("nan")
    ode = cache.get("rtol:0.0001", {})
    if name in ("amplify", "euler") and ode.get("exit") == 0:
        ref = ode["operating_hours"]  # the reference methods against the default ODE forecast
    print(f"\n#### {label}\n")
    print(f"| `{key}` | life [h] | {'vs ODE default' if name in ('amplify', 'euler') else 'vs last row'} | criterion | lifter end [m] | lead face end [deg] | mean power [kW] "
          "| drives | CVODE steps | wall [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for v, r in rows:
        if r.get("exit") != 0:
            print(f"| {v} | exit {r.get('exit')} | | {r.get('error', '')[:80]} | | | | | | |")
            continue
        d = 100 * (r["operating_hours"] - ref) / ref
        print(f"| {v:g} | {r['operating_hours']:.0f} | {d:+.2f} % | {r['criterion']} | {r['lifter_height_m_final']:.4f} "
              f"| {r['face_angle_leading_deg_final']:.1f} | {r['mean_power_kw']:.0f} | {r['charge_redrives']} "
              f"| {r.get('cvode_steps', 0)} | {r['wall_s']:.1f} |")
    if not ok:
        return
    fig, ax = plt.subplots(1, 3, figsize=(13, 3.8))
    xs = [v for v, _ in ok]
    ax[0].plot(xs, [r["operating_hours"] for _, r in ok], "o-")
    ax[0].set_xscale("log")
    ax[0].set_xlabel(label)
    ax[0].set_ylabel("operating hours to relining")
    cmap = plt.cm.viridis
    for i, (v, r) in enumerate(ok):
        c = cmap(i / max(1, len(ok) - 1))
        ax[1].plot(r["x"], 1000 * np.asarray(r["y"]), "-", color=c, lw=1, label=f"{v:g}")
        ax[2].plot(r["hours_hist"], r["power_hist"], "-", color=c, lw=1, label=f"{v:g}")
    ax[1].set_xlabel("arc length from the lifter centre [m]")
    ax[1].set_ylabel("final profile height [mm]")
    ax[1].legend(fontsize=7)
    ax[2].set_xlabel("operating hours")
    ax[2].set_ylabel("net power [kW]")
    fig.suptitle(f"Forecast of the Qiu mill against {label}")
    fig.tight_layout()
    os.makedirs(img, exist_ok=True)
    fig.savefig(os.path.join(img, f"forecast_{name}.png"), dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
