#!/usr/bin/python3
"""Where the liner's normal load goes: plate, leading and trailing faces, for
the DEM and the layer model with `[model] pocket_loads` off and on
(docs/models/layer.md §7, "Pocket loads", the table under "Why").

Runs `linerlife charge CONFIG --model M --out DIR` for each and sums the
time-averaged loads of the HDF5 output per metre of mill, as the test
"pocket loads put the charge's tangential weight on the lifter faces, not the
plate" does (tests/charge/test_layer_pocket.cpp, parts()): the plate is the
elements whose normal is within 2 deg of the radial at the shell's largest
radius (not the lifter tops), the faces those whose normal is turned more than
30 deg towards the tangent, leading if it faces the rotation.

    /usr/bin/python3 bench/pocket_forces.py [--linerlife BIN] [--config FILE] [--out DIR]

Prints the Markdown table of the doc page.
"""
import argparse
import math
import os
import subprocess
import sys
import tomllib

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from toml_edit import set_key  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

RUNS = [
    ("DEM (default settings)", "dem", None),
    ("layer, pocket loads off (the thesis)", "layer", "off"),
    ("layer, pocket loads on", "layer", "on"),
]


def parts(h5, ccw):
    """Plate normal and shear, leading and trailing faces' normal, all normal [N/m]."""
    with h5py.File(h5, "r") as f:
        nodes = f["surface/nodes"][:]
        normal = f["surface/normal"][:]
        fn = f["loads/normal_force_n_per_m"][:]
        fs = f["loads/shear_force_n_per_m"][:]
    # the surface is one closed ring: element e joins node e to node e + 1 (the last to node 0)
    mid = 0.5 * (nodes + np.roll(nodes, -1, axis=0))
    r = np.linalg.norm(mid, axis=1)
    er = mid / r[:, None]
    et = (1.0 if ccw else -1.0) * np.stack([-er[:, 1], er[:, 0]], axis=1)
    radial = -(normal * er).sum(axis=1)  # the normal points into the mill
    plate = (radial > math.cos(math.radians(2.0))) & (r > r.max() - 0.002)
    face = ~plate & (radial < math.cos(math.radians(30.0)))
    lead = face & ((normal * et).sum(axis=1) > 0)
    trail = face & ~lead
    return fn[plate].sum(), fs[plate].sum(), fn[lead].sum(), fn[trail].sum(), fn.sum()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--linerlife", default=os.path.join(ROOT, "build/app/linerlife"))
    ap.add_argument("--config", default=os.path.join(ROOT, "data/mills/ball_mill_5m.toml"))
    ap.add_argument("--out", default="/tmp/pocket_forces")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    base = open(a.config).read()
    ccw = tomllib.loads(base)["mill"].get("rotation", "ccw") == "ccw"
    print("| run | plate: normal [kN/m] | plate: shear [kN/m] | leading faces: normal | trailing faces: normal "
          "| all: normal |")
    print("|---|---|---|---|---|---|")
    for label, model, pocket in RUNS:
        text = base if pocket is None else set_key(base, "model", "pocket_loads", f'"{pocket}"')
        tag = model + ("" if pocket is None else "_pocket_" + pocket)
        cfg = os.path.join(a.out, tag + ".toml")
        open(cfg, "w").write(text)
        out = os.path.join(a.out, tag)
        subprocess.run([a.linerlife, "charge", cfg, "--model", model, "--out", out, "--json"], check=True,
                       stdout=subprocess.DEVNULL)
        pn, ps, ln, tn, an = (x / 1000.0 for x in parts(os.path.join(out, "charge.h5"), ccw))
        print(f"| {label} | {pn:.1f} ({100 * pn / an:.0f} %) | {ps:.1f} | {ln:.1f} ({100 * ln / an:.0f} %) | "
              f"{tn:.1f} ({100 * tn / an:.0f} %) | {an:.1f} |", flush=True)


if __name__ == "__main__":
    main()
