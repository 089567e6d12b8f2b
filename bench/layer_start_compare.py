#!/usr/bin/env python3
"""The recommended layer-model start against the default on the 17 bundled
mills (docs/models/layer.md §Settling): `linerlife charge CONFIG --json` with
[model] initial_phases = "aligned" and settle_revolutions = 3 (the defaults)
against "staggered" and 1, default averaging (2 revolutions). Prints one
Markdown row per mill and a summary line.

    /usr/bin/python3 bench/layer_start_compare.py [BUILD_DIR=build]
"""
import glob
import json
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from toml_edit import set_key  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build")
LL = os.path.join(BUILD, "app", "linerlife")
STARTS = (("aligned", 3), ("staggered", 1))


def angle_diff(a, b):
    return (b - a + 180.0) % 360.0 - 180.0


def run(config_text, tmp):
    path = os.path.join(tmp, "mill.toml")
    with open(path, "w") as f:
        f.write(config_text)
    out = subprocess.run([LL, "charge", path, "--json"], capture_output=True, text=True, check=True).stdout
    return json.loads(out)


def main():
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        # the 16 pilot tests and the Qiu mill, in file-name order (the study's 17;
        # not the later example ball mill)
        mills = sorted(glob.glob(os.path.join(ROOT, "data", "mills", "pilot_test_*.toml")))
        mills.append(os.path.join(ROOT, "data", "mills", "qiu2001_sag.toml"))
        for f in mills:
            text = open(f).read()
            res = []
            for phases, settle in STARTS:
                t = set_key(text, "model", "initial_phases", f'"{phases}"')
                res.append(run(set_key(t, "model", "settle_revolutions", str(settle)), tmp))
            a, b = res
            rows.append((os.path.basename(f)[:-5], a["net_power_kw"], 100 * (b["net_power_kw"] / a["net_power_kw"] - 1),
                         angle_diff(a["toe_deg"], b["toe_deg"]), angle_diff(a["shoulder_deg"], b["shoulder_deg"]),
                         a["wall_s"], b["wall_s"]))
    print("| mill | net power, aligned + 3 [kW] | power, staggered + 1 [%] | toe [deg] | shoulder [deg] "
          "| wall aligned + 3 [s] | wall staggered + 1 [s] |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r[0]} | {r[1]:.4g} | {r[2]:+.1f} | {r[3]:+.1f} | {r[4]:+.1f} | {r[5]:.3f} | {r[6]:.3f} |")
    print(f"mean |power| {statistics.mean(abs(r[2]) for r in rows):.2f} %, max {max(abs(r[2]) for r in rows):.1f} %; "
          f"mean |toe| {statistics.mean(abs(r[3]) for r in rows):.2f}, max {max(abs(r[3]) for r in rows):.1f} deg; "
          f"mean |shoulder| {statistics.mean(abs(r[4]) for r in rows):.2f}, "
          f"max {max(abs(r[4]) for r in rows):.1f} deg; "
          f"wall, sum over the mills {sum(r[5] for r in rows):.2f} -> {sum(r[6] for r in rows):.2f} s")


if __name__ == "__main__":
    main()
