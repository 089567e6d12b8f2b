#!/usr/bin/python3
"""Does the fast model rank lifter designs as the DEM does? `linerlife compare`
over a grid of lifter designs with the layer model (the default) and with the
DEM (docs/validation/ball-mill.md and speed-accuracy.md, "Ranking lifter
designs").

The DEM's wear calibration is scaled once, for every design, as in
bench/ball_mill.py and speed_accuracy.py (its three factors times the ratio of
the layer V-1.2's new-liner mass-loss rate to the DEM reference's: read from
ball_mill.py's cache for the ball mill, or given by --scale), so that the two models' lives differ by where the wear goes and how
it feeds back, not by its amount; the same constants serve every design, as a
plant's would. The DEM forecasts use ball_mill.py's drive settings (2
revolutions a drive, 8 mm refresh, two threads); compare runs them one at a
time. Results are cached in OUT/<model>.json with the arguments (a rerun
with the same ones prints the tables without running anything; other
arguments are refused; delete a file to run that model again).

    /usr/bin/python3 bench/design_ranking.py --out /tmp/design_rank \\
        [--vary liner.face_angle_leading_deg=15,30,45 --vary liner.lifter_height_m=0.09,0.15]
    /usr/bin/python3 bench/design_ranking.py --mill data/mills/qiu2001_sag.toml --scale 0.13445 \\
        --out /tmp/design_rank_qiu --vary liner.face_angle_leading_deg=10,15,20

--layer-set SECTION.KEY=VALUE (repeatable) changes the layer model's
configuration only (a layer option against the same DEM runs: copy dem.json
from an earlier --out of the same mill, vary and scale).
"""
import argparse
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from speed_accuracy import REF  # noqa: E402
from toml_edit import set_key  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CONFIG = "data/mills/ball_mill_5m.toml"
DEFAULT_VARY = ["liner.face_angle_leading_deg=15,30,45", "liner.lifter_height_m=0.09,0.15"]


def ranks(values):
    """Rank 1 = the longest life; ties share the mean rank."""
    order = sorted(range(len(values)), key=lambda i: -values[i])
    r = [0.0] * len(values)
    i = 0
    while i < len(order):
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]:
            j += 1
        for k in range(i, j + 1):
            r[order[k]] = (i + j) / 2 + 1
        i = j + 1
    return r


def spearman(a, b):
    ra, rb = ranks(a), ranks(b)
    n = len(a)
    ma, mb = sum(ra) / n, sum(rb) / n
    cov = sum((x - ma) * (y - mb) for x, y in zip(ra, rb))
    va = sum((x - ma) ** 2 for x in ra) ** 0.5
    vb = sum((y - mb) ** 2 for y in rb) ** 0.5
    return cov / (va * vb) if va > 0 and vb > 0 else float("nan")


def compare(linerlife, text, out_dir, name, vary):
    cfg = os.path.join(out_dir, name + ".toml")
    open(cfg, "w").write(text)
    cmd = [linerlife, "compare", cfg, "--json"]
    for v in vary:
        cmd += ["--vary", v]
    t0 = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.time() - t0
    if p.returncode != 0:
        sys.exit(f"{name}: linerlife compare failed (exit {p.returncode}):\n{p.stderr}")
    return {"cases": json.loads(p.stdout)["cases"], "wall_s": wall, "command": " ".join(cmd[1:]),
            "stderr": p.stderr}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--linerlife", default=os.path.join(ROOT, "build/app/linerlife"))
    ap.add_argument("--ball-mill-cache", default="/tmp/ball_mill/results.json",
                    help="bench/ball_mill.py's results (for the DEM's calibration scale)")
    ap.add_argument("--mill", default=CONFIG)
    ap.add_argument("--scale", type=float, default=0.0,
                    help="the DEM's calibration scale (default: from --ball-mill-cache, for the ball mill)")
    ap.add_argument("--out", default="/tmp/design_rank")
    ap.add_argument("--vary", action="append", help="as compare's --vary (default: %s)" % " ".join(DEFAULT_VARY))
    ap.add_argument("--layer-set", action="append", default=[], metavar="SECTION.KEY=VALUE",
                    help="set a key of the layer model's configuration only, e.g. model.pocket_loads=on")
    a = ap.parse_args()
    vary = a.vary or DEFAULT_VARY
    os.makedirs(a.out, exist_ok=True)
    scale = a.scale
    if not scale > 0:
        if a.mill != CONFIG:
            sys.exit("give --scale for a mill other than " + CONFIG)
        bm = json.load(open(a.ball_mill_cache))
        scale = bm["charge/layer 1.2"]["mass_rate_kg_s_per_m"] / bm[f"charge/{REF[0]}"]["mass_rate_kg_s_per_m"]
    base = open(os.path.join(ROOT, a.mill)).read()
    layer = base
    for kv in a.layer_set:
        key, sep, value = kv.partition("=")
        section, dot, name = key.partition(".")
        if not sep or not dot or not name or not value:
            sys.exit(f"--layer-set {kv}: expected SECTION.KEY=VALUE")
        try:
            float(value)
        except ValueError:
            if not value.startswith('"'):
                value = f'"{value}"'
        layer = set_key(layer, section, name, value)
    dem = set_key(set_key(base, "model", "charge", '"dem"'), "dem", "threads", "2")
    dem = set_key(set_key(dem, "forecast", "revolutions_per_drive", "2"), "forecast", "refresh_tol_m", "0.008")
    for k in ("calibration_centrifugal", "calibration_gravitational", "calibration_impact"):
        dem = set_key(dem, "wear", k, f"{scale:.6g}")
    res = {}
    for name, text in (("layer", layer), ("dem", dem)):
        path = os.path.join(a.out, name + ".json")
        args = [a.mill, vary, scale] + ([sorted(a.layer_set)] if name == "layer" and a.layer_set else [])
        if os.path.exists(path):
            res[name] = json.load(open(path))
            if res[name].get("args") != args:
                sys.exit(f"{path} holds a run of other arguments ({res[name].get('args')}); give another --out")
            continue
        print(f"running {name} ...", file=sys.stderr, flush=True)
        res[name] = compare(a.linerlife, text, a.out, name, vary)
        res[name]["args"] = args
        tmp = path + ".tmp"
        json.dump(res[name], open(tmp, "w"), indent=1)
        os.replace(tmp, path)

    L, D = res["layer"]["cases"], res["dem"]["cases"]
    assert [c["case"] for c in L] == [c["case"] for c in D]
    hl = [c["operating_hours"] for c in L]
    hd = [c["operating_hours"] for c in D]
    rl, rd = ranks(hl), ranks(hd)
    print(f"Mill {a.mill}{' (layer: ' + ', '.join(a.layer_set) + ')' if a.layer_set else ''}; "
          f"the DEM's calibration x {scale:.4g}. Commands (from {a.out}): "
          f"`{res['layer']['command']}` ({res['layer']['wall_s']:.0f} s) and `{res['dem']['command']}` "
          f"({res['dem']['wall_s']:.0f} s).\n")
    print("| design | layer: life [h] | rank | criterion | DEM: life [h] | rank | criterion | layer / DEM |")
    print("|---|---|---|---|---|---|---|---|")
    for i, c in enumerate(L):
        d = D[i]
        print(f"| {c['case']} | {hl[i]:,.0f} | {rl[i]:g} | {c['criterion']} | {hd[i]:,.0f} | {rd[i]:g} | "
              f"{d['criterion']} | {hl[i] / hd[i]:.3f} |")
    print(f"\nSpearman rank correlation of the lives: {spearman(hl, hd):.3f} ({len(hl)} designs).")
    # the pairwise verdicts: which of two designs lasts longer, and by how much
    agree, total, worst = 0, 0, None
    for i in range(len(hl)):
        for j in range(i + 1, len(hl)):
            total += 1
            dl, dd = hl[i] / hl[j] - 1, hd[i] / hd[j] - 1
            if (dl > 0) == (dd > 0):
                agree += 1
            elif worst is None or abs(dd) > abs(worst[2]):
                worst = (L[i]["case"], L[j]["case"], dd, dl)
    print(f"Pairs the two models order the same way: {agree} of {total}.")
    if worst:
        print(f"Largest disagreement: {worst[0]} against {worst[1]}: the DEM {100 * worst[2]:+.1f} %, "
              f"the layer model {100 * worst[3]:+.1f} %.")
    best_l, best_d = max(range(len(hl)), key=lambda i: hl[i]), max(range(len(hd)), key=lambda i: hd[i])
    print(f"Longest life: layer {L[best_l]['case']} ({hl[best_l]:,.0f} h); DEM {D[best_d]['case']} "
          f"({hd[best_d]:,.0f} h; the layer's choice there {hd[best_l]:,.0f} h).")


if __name__ == "__main__":
    main()
