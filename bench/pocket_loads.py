#!/usr/bin/python3
"""Pocket loads (docs/models/layer.md §7, "Pocket loads"): where the layer
model wears a new liner, with `[model] pocket_loads` off (the thesis' loads)
and on, against the DEM.

For six mills (the bundled ball mill, the same with steep low lifters, the Qiu
SAG mill and three pilot tests) it runs build/bench/bench_speed_accuracy once
per model: the DEM at the reference settings of bench/speed_accuracy.py (the
media size, 16 steps a collision, 12 revolutions averaged, two threads) and
the layer model V-1.2 with pocket_loads off and on. It prints the wear shape
error of each layer run (the total-variation distance between the wear
distributions along one liner segment, 20 bins, as in speed_accuracy.py) and
how pocket loads change the mass-loss rate, and with --bins the binned
distributions. Results are cached in OUT/results.json (a rerun only runs
what is missing).

    /usr/bin/python3 bench/pocket_loads.py --out /tmp/pocket_loads [--bins]
"""
import argparse
import json
import os
import subprocess
import sys
import time
import tomllib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ball_mill import save  # noqa: E402
from speed_accuracy import NBINS, REF, binned, wear_shape_err  # noqa: E402
from toml_edit import set_key  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# (label, configuration, [(section, key, value)])
MILLS = [
    ("ball mill (bundled)", "data/mills/ball_mill_5m.toml", []),
    ("ball mill, 45 deg faces, 0.09 m lifters", "data/mills/ball_mill_5m.toml",
     [("liner", "face_angle_leading_deg", "45.0"), ("liner", "lifter_height_m", "0.09")]),
    ("Qiu SAG mill", "data/mills/qiu2001_sag.toml", []),
    ("pilot test 1", "data/mills/pilot_test_01.toml", []),
    ("pilot test 6", "data/mills/pilot_test_06.toml", []),
    ("pilot test 12", "data/mills/pilot_test_12.toml", []),
]
RUNS = [
    ("dem ref", REF[1] + ["threads=2"], "off"),
    ("layer, pocket loads off", ["model=layer", "variant=1.2"], "off"),
    ("layer, pocket loads on", ["model=layer", "variant=1.2"], "on"),
]


def slug(s):
    return "".join(ch if ch.isalnum() else "_" for ch in s)


def run(binary, cfg, args):
    t0 = time.time()
    p = subprocess.run([binary, cfg] + args, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"{cfg} {' '.join(args)}: exit {p.returncode}\n{p.stderr}")
    r = json.loads(p.stdout.strip().splitlines()[-1])
    r["wall_s"] = time.time() - t0
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=os.path.join(ROOT, "build/bench/bench_speed_accuracy"))
    ap.add_argument("--out", default="/tmp/pocket_loads")
    ap.add_argument("--bins", action="store_true", help="print the binned wear distributions too")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    path = os.path.join(a.out, "results.json")
    cache = json.load(open(path)) if os.path.exists(path) else {}
    for mill, cfg, edits in MILLS:
        text = open(os.path.join(ROOT, cfg)).read()
        for section, key, value in edits:
            text = set_key(text, section, key, value)
        for label, args, pocket in RUNS:
            name = f"{mill}/{label}"
            if name in cache:
                continue
            f = os.path.join(a.out, slug(mill) + f"_pocket_{pocket}.toml")
            open(f, "w").write(set_key(text, "model", "pocket_loads", f'"{pocket}"'))
            print(f"running {name} ...", file=sys.stderr, flush=True)
            cache[name] = run(a.binary, f, args)
            save(cache, path)

    print("| mill | lifter height / ball diameter | wear shape error, pocket loads off [%] | on [%] | "
          "mass-loss rate on / off | impact share of the wear, off / on | DEM impact share |")
    print("|---|---|---|---|---|---|---|")
    err_off, err_on = [], []
    for mill, cfg, edits in MILLS:
        ref, off, on = (cache[f"{mill}/{label}"] for label, _, _ in RUNS)
        t = tomllib.loads(open(os.path.join(a.out, slug(mill) + "_pocket_off.toml")).read())
        h_d = t["liner"]["lifter_height_m"] / t["charge"]["ball_diameter_m"]
        eo, en = wear_shape_err(off, ref), wear_shape_err(on, ref)
        err_off.append(eo)
        err_on.append(en)
        print(f"| {mill} | {h_d:.2f} | {eo:.1f} | {en:.1f} | "
              f"{on['mass_rate_kg_s_per_m'] / off['mass_rate_kg_s_per_m']:.3f} | "
              f"{off['impact_share']:.2f} / {on['impact_share']:.2f} | {ref['impact_share']:.2f} |")
    n = len(err_off)
    print(f"\nMean wear shape error: off {sum(err_off) / n:.1f} %, on {sum(err_on) / n:.1f} % ({n} mills).")
    if a.bins:
        for mill, _, _ in MILLS:
            print(f"\n{mill}: share of the segment's wear per bin [%] ({NBINS} bins along the segment)")
            for label, _, _ in RUNS:
                b = binned(cache[f"{mill}/{label}"], NBINS)
                print(f"  {label:26s} " + " ".join(f"{100 * x:4.1f}" for x in b))


if __name__ == "__main__":
    main()
