#!/usr/bin/python3
"""Scatter of one layer-model charge run (one forecast drive) against the
number of revolutions averaged, over realisations of its sampling
(docs/validation/forecast.md, "Scatter over realisations: rtol and revolutions
per drive").

A realisation is a start (`[model] initial_phases`) and a number of settling
revolutions (`[model] settle_revolutions`), as in bench/forecast_scatter.py.
For each N in --revs it runs `linerlife charge CONFIG --revolutions N --json
--out DIR` per realisation on one liner (the bundled new liner, or a profile
CSV such as a worn profile from a forecast, --profile) and prints, over the
realisations, the relative standard deviation of the net power, of the total
shear work rate and impact energy rate on the liner, and the median over the
elements of one segment of the relative standard deviation of the shear work
rate and impact energy rate folded onto one segment, load-weighted over its
elements (what one drive hands the forecast, before its rate smoothing).

    /usr/bin/python3 bench/charge_scatter.py --binary BIN --out DIR [--revs 10,20,40,80] [--profile CSV]
"""
import argparse
import json
import os
import subprocess
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from toml_edit import set_key  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REALS = [("staggered", s) for s in (1, 1.25, 1.5, 1.75, 2, 2.5, 3)] + [("aligned", s) for s in (2, 2.5, 3)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--config", default=os.path.join(ROOT, "data/mills/qiu2001_sag.toml"))
    ap.add_argument("--binary", default=os.path.join(ROOT, "build/app/linerlife"))
    ap.add_argument("--out", default="/tmp/linerlife_charge_scatter")
    ap.add_argument("--revs", default="10,20,40,80")
    ap.add_argument("--profile", default="")
    a = ap.parse_args()
    base = open(a.config).read()
    if a.profile:
        base = set_key(base, "liner", "profile_csv", json.dumps(os.path.abspath(a.profile)))
    os.makedirs(a.out, exist_ok=True)
    cache_path = os.path.join(a.out, "results.json")
    cache = json.load(open(cache_path)) if os.path.exists(cache_path) else {}
    print("| revolutions | n | net power: mean [kW] | net power: std [%] | shear work rate (sum): mean [kW/m] "
          "| shear work rate (sum): std [%] | impact energy rate (sum): mean [kW/m] | impact energy rate (sum): std [%] "
          "| folded shear work rate: element std [%] | folded impact energy rate: element std [%] "
          "| wall per run [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for n_rev in [float(x) for x in a.revs.split(",")]:
        rows = []
        for phases, settle in REALS:
            k = f"{n_rev:g}_{phases}_{settle:g}"
            d = os.path.join(a.out, k)
            if k not in cache:
                text = set_key(set_key(base, "model", "initial_phases", f'"{phases}"'), "model", "settle_revolutions", settle)
                os.makedirs(d, exist_ok=True)
                cfg = os.path.join(d, "config.toml")
                open(cfg, "w").write(text)
                p = subprocess.run([a.binary, "charge", cfg, "--revolutions", f"{n_rev:g}", "--json", "--out", d],
                                   capture_output=True, text=True, check=True)
                j = json.loads(p.stdout)
                cache[k] = {"power": j["net_power_kw"], "wall": j["wall_s"]}
                json.dump(cache, open(cache_path, "w"))
            rows.append(dict(cache[k], **loads(os.path.join(d, "charge.h5"))))
        P = np.array([r["power"] for r in rows])
        S = np.array([np.sum(r["shear"]) for r in rows])
        E = np.array([np.sum(r["impact"]) for r in rows])
        rel = lambda x: 100 * np.std(x, ddof=1) / np.mean(x)
        w = np.median([r["wall"] for r in rows])
        print(f"| {n_rev:g} | {len(rows)} | {np.mean(P):.0f} | {rel(P):.2f} | {np.mean(S) / 1e3:.2f} | {rel(S):.2f} "
              f"| {np.mean(E) / 1e3:.3f} | {rel(E):.2f} "
              f"| {folded_std([r['shear'] for r in rows]):.2f} | {folded_std([r['impact'] for r in rows]):.1f} "
              f"| {w:.1f} |")


def loads(h5_path):
    """Shear work rate and impact energy rate (sum of m v_n^2 / 2 x rate) per element position of one
    segment, summed over the segments (the liner is the same in every segment) [W/m]."""
    with h5py.File(h5_path, "r") as h5:
        sb = np.asarray(h5["surface/segment_begin"])
        per = int(sb[1] - sb[0])
        if sb[0] != 0 or np.any(np.diff(sb) != per):
            raise RuntimeError(f"{h5_path}: segments of unequal element counts")
        sw = np.asarray(h5["loads/shear_work_rate_w_per_m"])
        im = h5["loads/impacts"]
        e = 0.5 * np.asarray(im["mass_kg"]) * np.asarray(im["normal_speed_m_s"]) ** 2 * np.asarray(im["rate_per_s"])
        el = np.asarray(im["element"])
    return {"shear": sw.reshape(-1, per).sum(axis=0), "impact": np.bincount(el % per, weights=e, minlength=per)}


def folded_std(fields):
    """Relative standard deviation over the realisations of each element's load, averaged over the
    elements weighted by their mean load [%]: the scatter of the rate field one drive hands the forecast."""
    F = np.array(fields)
    m, sd = F.mean(axis=0), F.std(axis=0, ddof=1)
    ok = m > 0
    return float(100 * np.sum(m[ok] * sd[ok] / m[ok]) / np.sum(m[ok]))


if __name__ == "__main__":
    main()
