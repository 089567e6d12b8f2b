#!/usr/bin/python3
"""Sampling scatter of `linerlife forecast` against revolutions_per_drive and
rtol, over several realisations of the layer model's sampling
(docs/validation/forecast.md, "Scatter over realisations: rtol and revolutions
per drive").

The layer model is deterministic, so one forecast is one draw of its
noise. A realisation here changes which revolutions each charge drive
averages, not the physics: the layer model's start (`[model]
initial_phases`) and how many settling revolutions it runs before it averages
(`[model] settle_revolutions`; docs/models/layer.md §Settling: the staggered
start settles in 1 revolution, the aligned one needs 2-3, so aligned is only
used with 2 or 3). Every (revolutions, rtol) cell runs every realisation.

    /usr/bin/python3 bench/forecast_scatter.py --binary BIN --out DIR \
        [--revs 10,20,40] [--rtols 1e-4,1e-5] [--real s1,s2,s3,a2,a3] [--report] [--wall-real ...]
    /usr/bin/python3 bench/forecast_scatter.py --out DIR --diverge "TAG_A,TAG_B"
    /usr/bin/python3 bench/forecast_scatter.py --out DIR --export-profile "TAG,HOURS,CSV"

Runs one forecast at a time, cheapest first (all 10- and 20-revolution cells
of one realisation, then the next realisation, then the 40-revolution cells),
caching every finished run in DIR/results.json (a rerun only runs what is
missing) and appending it to DIR/results.csv; at the end (or with --report)
prints the markdown tables of the doc page.
"""
import argparse
import csv
import datetime
import json
import math
import os
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from toml_edit import set_key  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# realisation tag -> (initial_phases, settle_revolutions)
REALISATIONS = {
    "s1": ("staggered", 1),  # the default start
    "s2": ("staggered", 2),
    "s3": ("staggered", 3),
    "a2": ("aligned", 2),
    "a3": ("aligned", 3),
    "s1.5": ("staggered", 1.5),
    "s2.5": ("staggered", 2.5),
    "s1.25": ("staggered", 1.25),
    "s1.75": ("staggered", 1.75),
    "a2.5": ("aligned", 2.5),
}

FIELDS = ["revs", "rtol", "real", "operating_hours", "criterion", "lifter_height_m_final",
          "face_angle_leading_deg_final", "charge_redrives", "cvode_steps", "rhs_evals", "wall_s",
          "start", "end", "load_before", "load_after"]


def tag(revs, rtol, real):
    return f"{revs:g}|{rtol:g}|{real}"


def run_case(binary, base_text, revs, rtol, real, out_dir):
    phases, settle = REALISATIONS[real]
    text = set_key(base_text, "forecast", "revolutions_per_drive", revs)
    text = set_key(text, "forecast", "rtol", rtol)
    text = set_key(text, "model", "initial_phases", f'"{phases}"')
    text = set_key(text, "model", "settle_revolutions", settle)
    os.makedirs(out_dir, exist_ok=True)
    cfg = os.path.join(out_dir, "config.toml")
    with open(cfg, "w") as f:
        f.write(text)
    load0 = os.getloadavg()[0]
    t0 = datetime.datetime.now().strftime("%Y-%m-%d %H:%M:%S")
    p = subprocess.run([binary, "forecast", cfg, "--json", "--quiet", "--out", os.path.join(out_dir, "run")],
                       capture_output=True, text=True)
    r = {"revs": revs, "rtol": rtol, "real": real, "start": t0,
         "end": datetime.datetime.now().strftime("%Y-%m-%d %H:%M:%S"),
         "load_before": load0, "load_after": os.getloadavg()[0]}
    if p.returncode != 0:
        r.update({"exit": p.returncode, "error": p.stderr.strip()[-400:]})
        return r
    j = json.loads(p.stdout)
    r.update({k: j.get(k) for k in FIELDS if k in j})
    r["exit"] = 0
    return r


def plan(revs_list, rtols, reals):
    cheap = [v for v in revs_list if v < 40]
    dear = [v for v in revs_list if v >= 40]
    out = []
    for real in reals:
        for v in cheap:
            for rt in rtols:
                out.append((v, rt, real))
    for rt in rtols:
        for real in reals:
            for v in dear:
                out.append((v, rt, real))
    return out


def stats(xs):
    n = len(xs)
    m = sum(xs) / n
    sd = statistics.stdev(xs) if n > 1 else float("nan")
    return m, min(xs), max(xs), sd


def power_noise(h5_path):
    """Drive-to-drive scatter of the net power along one forecast [% of its mean]: the history records the
    last drive's power every 100 h; the second difference of a smooth trend is about 0 and that of
    independent noise of standard deviation s has standard deviation s sqrt(6). 500-8500 h."""
    try:
        import h5py
        import numpy as np
        with h5py.File(h5_path, "r") as f:
            P = np.asarray(f["forecast/history/net_power_kw"])
            h = np.asarray(f["forecast/history/hours"])
    except (OSError, KeyError, ImportError):
        return float("nan")
    P = P[(h > 500) & (h < 8500) & np.isfinite(P)]
    d2 = P[2:] - 2 * P[1:-1] + P[:-2]
    return float(100 * np.std(d2) / math.sqrt(6) / np.mean(P))


def impact_share(h5_path):
    """The forecast's impact share of the mass loss (history, every 100 h): its mean and largest record."""
    try:
        import h5py
        import numpy as np
        with h5py.File(h5_path, "r") as f:
            x = np.asarray(f["forecast/history/impact_fraction"])
    except (OSError, KeyError, ImportError):
        return (float("nan"), float("nan"))
    return (float(np.nanmean(x)), float(np.nanmax(x)))


def report(cache, revs_list, rtols, reals, wall_reals=None, out=None):
    ok = {k: r for k, r in cache.items() if r.get("exit") == 0}

    def life(v, rt, real):
        r = ok.get(tag(v, rt, real))
        return r["operating_hours"] if r else None

    print("\n#### Life per realisation [h]\n")
    print("| revs | rtol | " + " | ".join(f"{x} ({REALISATIONS[x][0]}, settle {REALISATIONS[x][1]:g})" for x in reals)
          + " |")
    print("|---|---|" + "---|" * len(reals))
    for v in revs_list:
        for rt in rtols:
            cells = [life(v, rt, x) for x in reals]
            print(f"| {v:g} | {rt:g} | " + " | ".join("-" if c is None else f"{c:.0f}" for c in cells) + " |")

    # reference: the mean of the 40-revolution runs at rtol 1e-4 (or the largest revs present)
    ref_v = max(revs_list)
    ref_list = [life(ref_v, rtols[0], x) for x in reals if life(ref_v, rtols[0], x) is not None]
    ref = sum(ref_list) / len(ref_list) if ref_list else float("nan")

    print(f"\n#### Mean and spread over realisations (reference: the {ref_v:g}-revolution mean at rtol "
          f"{rtols[0]:g}, {ref:.0f} h, n = {len(ref_list)})\n")
    print("| revs | rtol | n | mean life [h] | min [h] | max [h] | max-min [%] | std [h] | std [%] "
          "| mean vs ref [%] | std err of mean [%] | median wall [s] | drives (range) | CVODE steps (range) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for v in revs_list:
        for rt in rtols:
            rs = [ok[tag(v, rt, x)] for x in reals if tag(v, rt, x) in ok]
            if not rs:
                continue
            ls = [r["operating_hours"] for r in rs]
            m, lo, hi, sd = stats(ls)
            wr = [r["wall_s"] for r in rs if not wall_reals or r["real"] in wall_reals]
            walls = statistics.median(wr) if wr else float("nan")
            dr = [r["charge_redrives"] for r in rs]
            cs = [r["cvode_steps"] for r in rs]
            print(f"| {v:g} | {rt:g} | {len(rs)} | {m:.0f} | {lo:.0f} | {hi:.0f} | {100 * (hi - lo) / m:.2f} "
                  f"| {sd:.0f} | {100 * sd / m:.2f} | {100 * (m - ref) / ref:+.2f} "
                  f"| {100 * sd / m / math.sqrt(len(rs)):.2f} | {walls:.1f} "
                  f"| {min(dr)}-{max(dr)} | {min(cs)}-{max(cs)} |")

    if len(rtols) >= 2:
        a, b = rtols[0], rtols[1]
        print(f"\n#### rtol {a:g} -> {b:g}, paired by realisation: change of the life [%]\n")
        print("| revs | " + " | ".join(reals) + " | mean | max abs | std |")
        print("|---|" + "---|" * len(reals) + "---|---|---|")
        for v in revs_list:
            ds = []
            cells = []
            for x in reals:
                la, lb = life(v, a, x), life(v, b, x)
                if la is None or lb is None:
                    cells.append("-")
                    continue
                d = 100 * (lb - la) / la
                ds.append(d)
                cells.append(f"{d:+.2f}")
            if not ds:
                continue
            sd = statistics.stdev(ds) if len(ds) > 1 else float("nan")
            print(f"| {v:g} | " + " | ".join(cells) + f" | {sum(ds) / len(ds):+.2f} | {max(abs(d) for d in ds):.2f} "
                  f"| {sd:.2f} |")

    print(f"\n#### Revolutions, paired by realisation: life against the same realisation's {ref_v:g}-revolution "
          f"run at rtol {rtols[0]:g} [%]\n")
    print("| revs | rtol | " + " | ".join(reals) + " | mean | max abs |")
    print("|---|---|" + "---|" * len(reals) + "---|---|")
    for v in revs_list:
        for rt in rtols:
            ds, cells = [], []
            for x in reals:
                l0, l1 = life(ref_v, rtols[0], x), life(v, rt, x)
                if l0 is None or l1 is None or (v == ref_v and rt == rtols[0]):
                    cells.append("-")
                    continue
                d = 100 * (l1 - l0) / l0
                ds.append(d)
                cells.append(f"{d:+.2f}")
            if ds:
                print(f"| {v:g} | {rt:g} | " + " | ".join(cells) + f" | {sum(ds) / len(ds):+.2f} "
                      f"| {max(abs(d) for d in ds):.2f} |")

    print(f"\n#### Pooled over both rtols (a change of rtol only perturbs the run: see the doc), against the pooled "
          f"{ref_v:g}-revolution mean\n")
    print("| revs | n | mean life [h] | std [%] | std err of mean [%] | mean vs pooled ref [%] "
          "| lifter end: mean [m], std [mm] | drive-to-drive net power noise [%] "
          "| impact share of the mass loss: mean, largest record per run [%] | median wall [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    pooled = {v: [(x, rt) for rt in rtols for x in reals if tag(v, rt, x) in ok] for v in revs_list}
    pref = [ok[tag(ref_v, rt, x)]["operating_hours"] for x, rt in pooled[ref_v]]
    pm = sum(pref) / len(pref) if pref else float("nan")
    for v in revs_list:
        if len(pooled[v]) < 2:
            continue
        ls = [ok[tag(v, rt, x)]["operating_hours"] for x, rt in pooled[v]]
        m, lo, hi, sd = stats(ls)
        noise = [power_noise(os.path.join(out, tag(v, rt, x).replace("|", "_"), "run", "forecast.h5"))
                 for x, rt in pooled[v]] if out else []
        noise = [n for n in noise if n == n]
        lift = [ok[tag(v, rt, x)]["lifter_height_m_final"] for x, rt in pooled[v]]
        imp = [impact_share(os.path.join(out, tag(v, rt, x).replace("|", "_"), "run", "forecast.h5"))
               for x, rt in pooled[v]] if out else []
        imp = [i for i in imp if i[0] == i[0]]
        wr = [ok[tag(v, rt, x)]["wall_s"] for x, rt in pooled[v] if not wall_reals or x in wall_reals]
        pw = statistics.median(wr) if wr else float("nan")
        imp_txt = (f"{100 * statistics.mean(i[0] for i in imp):.1f}, {100 * min(i[1] for i in imp):.0f}-"
                   f"{100 * max(i[1] for i in imp):.0f}") if imp else "-"
        print(f"| {v:g} | {len(ls)} | {m:.0f} | {100 * sd / m:.2f} | {100 * sd / m / math.sqrt(len(ls)):.2f} "
              f"| {100 * (m - pm) / pm:+.2f} | {statistics.mean(lift):.4f}, {1000 * statistics.stdev(lift):.1f} "
              f"| {statistics.mean(noise) if noise else float('nan'):.2f} | {imp_txt} | {pw:.1f} |")

    runs = sorted(ok.values(), key=lambda r: r["start"])
    if runs:
        loads = [r["load_before"] for r in runs] + [r["load_after"] for r in runs]
        print(f"\n{len(runs)} runs from {runs[0]['start']} to {runs[-1]['end']}; 1-minute load average "
              f"{min(loads):.2f}-{max(loads):.2f} (before/after each run), {statistics.median(loads):.2f} median")
    bad = [k for k, r in cache.items() if r.get("exit") != 0]
    for k in bad:
        print(f"FAILED {k}: exit {cache[k].get('exit')}: {cache[k].get('error', '')}")


def export_profile(out, t, hours, path):
    """One recorded segment profile of a run, in the frame of docs/profile-csv.md: x = R theta from the
    segment edge (the first node), y = R - r."""
    import h5py
    import numpy as np
    with h5py.File(os.path.join(out, t.replace("|", "_"), "run", "forecast.h5"), "r") as f:
        pr = f["forecast/profiles"]
        hh, off, nodes = np.asarray(pr["hours"]), np.asarray(pr["offset"]), np.asarray(pr["nodes"])
        R = float(f["surface"].attrs["shell_radius_m"])
    i = int(np.argmin(abs(hh - hours)))
    p = nodes[off[i]:off[i + 1]]
    th = np.unwrap(np.arctan2(p[:, 1], p[:, 0]))
    x, y = R * (th - th[0]), R - np.hypot(p[:, 0], p[:, 1])
    with open(path, "w") as o:
        o.write(f"# profile at {hh[i]:.0f} h of the forecast {t} ({out})\nx_m,y_m\n")
        for a, b in zip(x, y):
            o.write(f"{a:.6f},{b:.6f}\n")


def diverge(out, ta, tb):
    """Two runs' recorded histories side by side: relative difference of the net power and the
    differences of the thinnest plate and of the lifter height, at the 100 h outputs."""
    import h5py
    import numpy as np

    def load(t):
        with h5py.File(os.path.join(out, t.replace("|", "_"), "run", "forecast.h5"), "r") as f:
            hh = f["forecast/history"]
            return [np.asarray(hh[k]) for k in ("hours", "net_power_kw", "min_thickness_m", "lifter_height_m")]
    h1, p1, m1, l1 = load(ta)
    h2, p2, m2, l2 = load(tb)
    print(f"| hours | net power: rel. diff | thinnest plate: diff [m] | lifter height: diff [m] |  ({ta} vs {tb})")
    print("|---|---|---|---|")
    for i in [1, 2, 3, 5, 8, 10, 15, 20, 30, 45, 60, 80]:
        if i < min(len(h1), len(h2)):
            print(f"| {h1[i]:.0f} | {abs(p1[i] - p2[i]) / p1[i]:.1e} | {abs(m1[i] - m2[i]):.1e} | {abs(l1[i] - l2[i]):.1e} |")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--config", default=os.path.join(ROOT, "data/mills/qiu2001_sag.toml"))
    ap.add_argument("--binary", default=os.path.join(ROOT, "build/app/linerlife"))
    ap.add_argument("--out", default="/tmp/linerlife_forecast_scatter")
    ap.add_argument("--revs", default="10,20,40")
    ap.add_argument("--rtols", default="1e-4,1e-5")
    ap.add_argument("--real", default="s1,s2,s3,a2,a3")
    ap.add_argument("--report", action="store_true", help="only print the tables of what is cached")
    ap.add_argument("--diverge", default="", help="TAG_A,TAG_B (cache keys, e.g. 10|0.0001|s1,10|1e-05|s1): "
                    "print how two runs' histories part, and stop")
    ap.add_argument("--export-profile", default="", help="TAG,HOURS,CSV: write the profile of a cached run at the "
                    "output time nearest HOURS as a profile CSV (docs/profile-csv.md), and stop")
    ap.add_argument("--wall-real", default="", help="realisations whose runs count in the median wall (default all)")
    a = ap.parse_args()
    revs_list = [float(x) for x in a.revs.split(",")]
    rtols = [float(x) for x in a.rtols.split(",")]
    reals = a.real.split(",")
    for x in reals:
        if x not in REALISATIONS:
            sys.exit(f"unknown realisation {x}: one of {', '.join(REALISATIONS)}")
    if a.export_profile:
        t, hours, path = a.export_profile.split(",")
        export_profile(a.out, t, float(hours), path)
        return
    if a.diverge:
        diverge(a.out, *a.diverge.split(","))
        return
    base = open(a.config).read()
    os.makedirs(a.out, exist_ok=True)
    cache_path = os.path.join(a.out, "results.json")
    cache = json.load(open(cache_path)) if os.path.exists(cache_path) else {}
    if not a.report:
        for v, rt, x in plan(revs_list, rtols, reals):
            k = tag(v, rt, x)
            if k in cache:
                continue
            print(f"{time.strftime('%H:%M:%S')} running {k}", file=sys.stderr, flush=True)
            r = run_case(a.binary, base, v, rt, x, os.path.join(a.out, k.replace("|", "_")))
            cache[k] = r
            with open(cache_path + ".tmp", "w") as f:
                json.dump(cache, f, indent=1)
            os.replace(cache_path + ".tmp", cache_path)
            new = not os.path.exists(os.path.join(a.out, "results.csv"))
            with open(os.path.join(a.out, "results.csv"), "a", newline="") as f:
                w = csv.DictWriter(f, fieldnames=FIELDS + ["exit"], extrasaction="ignore")
                if new:
                    w.writeheader()
                w.writerow(r)
            print(f"{time.strftime('%H:%M:%S')}   -> {r.get('operating_hours', 'FAILED')} h, "
                  f"{r.get('wall_s', 0):.1f} s", file=sys.stderr, flush=True)
    report(cache, revs_list, rtols, reals, set(filter(None, a.wall_real.split(","))), a.out)


if __name__ == "__main__":
    main()
