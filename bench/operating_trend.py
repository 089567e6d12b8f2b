#!/usr/bin/python3
"""How each charge model's power, toe and centre of mass follow an operating
setting (the mill speed or the filling) against the DEM
(docs/validation/charge.md, "Operating trends").

For each value of one key (e.g. mill.speed_fraction_critical) it runs
`linerlife charge CONFIG --json` with the DEM (the configuration's [dem]
settings), Morrell's C-model and the layer model's three versions, and prints
one table per indicator with each model's difference from the DEM. Results are
cached in OUT/results.json (a rerun only runs what is missing).

    /usr/bin/python3 bench/operating_trend.py --out /tmp/operating_trend \\
        --vary mill.speed_fraction_critical=0.66,0.70,0.74,0.78,0.82,0.86,0.90
    /usr/bin/python3 bench/operating_trend.py --out /tmp/operating_trend \\
        --vary charge.filling=0.18,0.24,0.30,0.36
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ball_mill import save  # noqa: E402
from toml_edit import set_key  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MODELS = [
    ("DEM", ["--model", "dem"]),
    ("Morrell", ["--model", "empirical"]),
    ("V-1.0", ["--model", "layer", "--variant", "1.0"]),
    ("V-1.1", ["--model", "layer", "--variant", "1.1"]),
    ("V-1.2", ["--model", "layer", "--variant", "1.2"]),
]
SPEED_KEYS = ("speed_rpm", "speed_fraction_critical")


def case_text(base, section, key, value):
    text = base
    if section == "mill" and key in SPEED_KEYS:  # the speed is one setting: drop the other form
        other = SPEED_KEYS[1 - SPEED_KEYS.index(key)]
        text = re.sub(rf"(?m)^{other}\s*=.*\n", "", text)
    return set_key(text, section, key, value)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True)
    ap.add_argument("--config", default=os.path.join(ROOT, "data/mills/qiu2001_sag.toml"))
    ap.add_argument("--vary", required=True, help="section.key=v1,v2,...")
    ap.add_argument("--linerlife", default=os.path.join(ROOT, "build/app/linerlife"))
    a = ap.parse_args()
    key, values = a.vary.split("=", 1)
    section, name = key.split(".", 1)
    values = values.split(",")
    os.makedirs(a.out, exist_ok=True)
    cache_path = os.path.join(a.out, "results.json")
    cache = json.load(open(cache_path)) if os.path.exists(cache_path) else {}
    base = open(a.config).read()
    rows = {}
    for v in values:
        text = case_text(base, section, name, v)
        cfg = os.path.join(a.out, f"{os.path.basename(a.config)[:-5]}_{section}_{name}_{v}.toml")
        open(cfg, "w").write(text)
        for label, args in MODELS:
            ck = f"{os.path.abspath(a.config)}|{key}={v}|{label}"
            if ck not in cache:
                t0 = time.time()
                p = subprocess.run([a.linerlife, "charge", cfg, "--json"] + args, capture_output=True, text=True)
                if p.returncode != 0:
                    sys.exit(f"{cfg} {' '.join(args)}: exit {p.returncode}\n{p.stderr}")
                j = json.loads(p.stdout)
                cache[ck] = {k: j[k] for k in ("net_power_kw", "toe_deg", "shoulder_deg", "com_angle_deg",
                                               "fraction_critical")}
                cache[ck]["wall_s"] = time.time() - t0
                save(cache, cache_path)
                print(f"  {key}={v} {label}: {cache[ck]['net_power_kw']:.0f} kW ({cache[ck]['wall_s']:.0f} s)",
                      file=sys.stderr)
            rows[(v, label)] = cache[ck]
    labels = [m[0] for m in MODELS]
    print(f"{os.path.relpath(a.config, ROOT)}, {key}\n")
    for ind, unit, rel in (("net_power_kw", "kW", True), ("toe_deg", "deg", False), ("com_angle_deg", "deg", False)):
        print(f"{ind} [{unit}]; in brackets the difference from the DEM ({'%' if rel else 'deg'})\n")
        print("| " + name + " | " + " | ".join(labels) + " |")
        print("|---" * (len(labels) + 1) + "|")
        for v in values:
            ref = rows[(v, "DEM")][ind]
            cells = []
            for m in labels:
                x = rows[(v, m)][ind]
                if m == "DEM":
                    cells.append(f"{x:.0f}" if rel else f"{x:.1f}")
                elif rel:
                    cells.append(f"{x:.0f} ({100 * (x / ref - 1):+.0f})")
                else:
                    cells.append(f"{x:.1f} ({x - ref:+.1f})")
            print(f"| {v} | " + " | ".join(cells) + " |")
        print()
    # the trend: the change from the first value to the last, each model
    first, last = values[0], values[-1]
    print(f"change of net power from {name} = {first} to {last}: " +
          ", ".join(f"{m} {100 * (rows[(last, m)]['net_power_kw'] / rows[(first, m)]['net_power_kw'] - 1):+.0f} %"
                    for m in labels))


if __name__ == "__main__":
    main()
