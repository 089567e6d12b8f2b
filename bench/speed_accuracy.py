#!/usr/bin/python3
"""Speed against accuracy of the charge models (issue 6 §5,
docs/validation/speed-accuracy.md).

For the Qiu SAG mill and two pilot tests, every model a user can choose
(Morrell's empirical C-model, the layer model V-1.0/1.1/1.2, the DEM
coarse-grained and at the media size) and the DEM's own convergence series
(steps per collision, coarse-graining, revolutions averaged, seed) run once
each through build/bench/bench_speed_accuracy. The error of each run is taken
against the finest DEM run of its mill (media size, 16 steps a collision, 12
revolutions averaged): toe, shoulder and centre of mass in degrees, net power
and the liner's mass-loss rate in %, and the wear distribution along the
liner segment (20 bins of equal length) as the total-variation distance
between the two normalised distributions (0: the same shape, 100 %: no
overlap).

Results are cached in OUT/results.json (a rerun only runs what is missing;
--rerun LABEL,.. forces some). The script prints the Markdown tables of the
document and draws its charts into --img.

    /usr/bin/python3 bench/speed_accuracy.py --out /tmp/speed_accuracy \\
        --img docs/validation/img [--only qiu,pilot01] [--forecast]

Needs build/bench/bench_speed_accuracy (scripts/setup.sh builds it) and matplotlib.
"""
import argparse
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from toml_edit import set_key  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

MILLS = [
    ("qiu", "Qiu SAG mill", "data/mills/qiu2001_sag.toml"),
    ("pilot01", "pilot test 1", "data/mills/pilot_test_01.toml"),
    ("pilot12", "pilot test 12", "data/mills/pilot_test_12.toml"),
]

# the largest coarse-graining each mill allows (the loader's limit, rounded down)
COARSE = {"qiu": 1.8, "pilot01": 1.3, "pilot12": 1.3}
CG_SERIES = {"qiu": (1.25, 1.5, 1.8), "pilot01": (1.15, 1.3), "pilot12": (1.15, 1.3)}

REF = ("dem ref", ["model=dem", "steps_per_collision=16", "revolutions=12"])


def runs_for(mill):
    """(label, group, args) of every run of a mill."""
    cg = COARSE[mill]
    r = [
        ("empirical", "model", ["model=empirical"]),
        ("layer 1.0", "model", ["model=layer", "variant=1.0"]),
        ("layer 1.1", "model", ["model=layer", "variant=1.1"]),
        ("layer 1.2", "model", ["model=layer", "variant=1.2"]),
        (f"dem coarse {cg:g}", "model", ["model=dem", f"coarse_grain={cg}"]),
        ("dem fine", "model", ["model=dem"]),
        (REF[0], "ref", REF[1]),
    ]
    for s in (5, 8):
        r.append((f"dem steps {s}", "steps", ["model=dem", f"steps_per_collision={s}", "revolutions=12"]))
    for cgv in CG_SERIES[mill]:
        r.append((f"dem cg {cgv:g}", "coarse", ["model=dem", f"coarse_grain={cgv}", "revolutions=12"]))
    for n in (1, 2, 6):
        r.append((f"dem revs {n}", "revs", ["model=dem", f"revolutions={n}"]))
    for seed in (2, 3):
        r.append((f"dem fine seed {seed}", "seed", ["model=dem", f"seed={seed}"]))
    return r


THREADS = 1  # every model on one thread: the wall times compare the methods, not the cores


def run(binary, cfg, args):
    p = subprocess.run([binary, os.path.join(ROOT, cfg)] + args + [f"threads={THREADS}"], capture_output=True,
                       text=True)
    if p.returncode != 0:
        return {"error": p.stderr.strip(), "exit": p.returncode}
    return json.loads(p.stdout)


def angle_err(a, b):
    d = (a - b + 180.0) % 360.0 - 180.0
    return abs(d)


def binned(run, nbins):
    """The wear of the segment per bin of equal length along it [share], from
    the element rates (each element's recession x length goes to the bin of its
    midpoint)."""
    s = run["element_s_m"]
    lens = [2 * s[0]]  # element lengths from the midpoints
    for i in range(1, len(s)):
        lens.append(2 * (s[i] - s[i - 1]) - lens[-1])
    total_len = s[-1] + 0.5 * lens[-1]
    b = [0.0] * nbins
    for si, li, r in zip(s, lens, run["recession_m_s"]):
        b[min(nbins - 1, int(si / total_len * nbins))] += r * li
    tot = sum(b)
    return [x / tot for x in b] if tot > 0 else None


NBINS = 20  # bins along a segment for the wear distribution


def wear_shape_err(run, ref):
    """Total-variation distance [%] between the binned wear distributions of
    the segment (NBINS bins: element-level noise of a few revolutions is not
    what a forecast sees, it smooths the rates along the surface)."""
    if run.get("recession_m_s") is None or ref.get("recession_m_s") is None:
        return None
    a, b = binned(run, NBINS), binned(ref, NBINS)
    if a is None or b is None:
        return None
    return 50.0 * sum(abs(x - y) for x, y in zip(a, b))


def errors(run, ref):
    if "error" in run:
        return None
    e = {
        "toe": angle_err(run["toe_deg"], ref["toe_deg"]),
        "shoulder": angle_err(run["shoulder_deg"], ref["shoulder_deg"]),
        "com": angle_err(run["com_angle_deg"], ref["com_angle_deg"]),
        "power": 100.0 * abs(run["net_power_kw"] / ref["net_power_kw"] - 1.0),
        "wear_shape": wear_shape_err(run, ref),
        "wear_rate": (100.0 * abs(run["mass_rate_kg_s_per_m"] / ref["mass_rate_kg_s_per_m"] - 1.0)
                      if run.get("recession_m_s") is not None else None),
    }
    return e


# Whole-life forecasts of the Qiu mill (--forecast): the relining time each
# charge model gives, with the DEM's drive cut to what a forecast can afford
# (and its wear calibration scaled to the layer model's initial wear rate, see
# run_forecasts).
FORECASTS = [
    ("layer 1.0", {"model": {"charge": '"layer"', "variant": '"1.0"'}}),
    ("layer 1.1", {"model": {"charge": '"layer"', "variant": '"1.1"'}}),
    ("layer 1.2", {"model": {"charge": '"layer"', "variant": '"1.2"'}}),
    ("layer 1.2, 2 revolutions, 8 mm", {"model": {"charge": '"layer"', "variant": '"1.2"'},
                                         "forecast": {"revolutions_per_drive": "2", "refresh_tol_m": "0.008"}}),
    ("dem, 2 revolutions, 8 mm", {"model": {"charge": '"dem"'},
                                  "forecast": {"revolutions_per_drive": "2", "refresh_tol_m": "0.008"}}),
]


def forecast_rows(cache, labels, ncols, dem_label="dem, 2 revolutions, 8 mm"):
    """(label, result, life against the DEM forecast) of each cached forecast
    of `labels`; a failed one is printed as a table row of ncols columns."""
    dem = cache.get(f"forecast/{dem_label}", {})
    for label in labels:
        r = cache.get(f"forecast/{label}")
        if not r:
            continue
        if "error" in r:
            print(f"| {label} | failed (exit {r['exit']}) after {r['wall_s']:.0f} s: {r['error'][:100]} |"
                  + " |" * (ncols - 2))
            continue
        rel = (f"{100 * (r['operating_hours'] / dem['operating_hours'] - 1):+.1f} %"
               if dem and "error" not in dem else "-")
        yield label, r, rel


def run_forecasts(cache, out_dir, linerlife):
    import time
    base = open(os.path.join(ROOT, "data/mills/qiu2001_sag.toml")).read()
    for label, keys in FORECASTS:
        ck = f"forecast/{label}"
        if ck in cache:
            continue
        text = base
        scale = None
        if label.startswith("dem"):
            # The wear laws' calibration is per charge model (the DEM's loads
            # are not the layer model's): scale the DEM's three calibration
            # factors so that its new-liner mass-loss rate (the reference run)
            # equals the layer V-1.2's, as a plant calibration to the same
            # measured wear would; the relining times then differ by where
            # the wear goes and how it feeds back, not by its amount.
            scale = cache["qiu/layer 1.2"]["mass_rate_kg_s_per_m"] / cache["qiu/dem ref"]["mass_rate_kg_s_per_m"]
            for k in ("calibration_centrifugal", "calibration_gravitational", "calibration_impact"):
                text = set_key(text, "wear", k, f"{scale:.6g}")
        for sec, kv in keys.items():
            for k, v in kv.items():
                text = set_key(text, sec, k, v)
        cfg = os.path.join(out_dir, "forecast_" + label.replace(" ", "_").replace(",", "") + ".toml")
        open(cfg, "w").write(text)
        print(f"running {ck} ...", file=sys.stderr, flush=True)
        t0 = time.time()
        out = cfg[:-5] + "_out"
        p = subprocess.run([linerlife, "forecast", cfg, "--json", "--quiet", "--out", out], capture_output=True,
                           text=True)
        wall = time.time() - t0
        if p.returncode != 0:
            cache[ck] = {"error": p.stderr.strip(), "exit": p.returncode, "wall_s": wall}
        else:
            j = json.loads(p.stdout)
            cache[ck] = {k: j[k] for k in ("operating_hours", "criterion", "charge_redrives", "remeshes",
                                          "charge_simulated_s", "wall_s", "history")}
            cache[ck]["results"] = os.path.join(out, "forecast.h5")
            cache[ck]["wall_s"] = wall
            cache[ck]["calibration_scale"] = scale
        tmp = os.path.join(out_dir, "results.json.tmp")
        json.dump(cache, open(tmp, "w"), indent=1)
        os.replace(tmp, os.path.join(out_dir, "results.json"))
    print("\n### Relining time (Qiu mill, whole-life forecast)\n")
    print("| charge model | relining [h] | criterion | charge drives | wall [s] | vs the DEM forecast |")
    print("|---|---|---|---|---|---|")
    for label, r, rel in forecast_rows(cache, [label for label, _ in FORECASTS], 6):
        print(f"| {label} | {r['operating_hours']:.0f} | {r['criterion']} | {r['charge_redrives']} | "
              f"{r['wall_s']:.0f} | {rel} |")


def f(v, nd=1):
    return "-" if v is None else f"{v:.{nd}f}"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=os.path.join(ROOT, "build/bench/bench_speed_accuracy"))
    ap.add_argument("--out", default="/tmp/speed_accuracy")
    ap.add_argument("--img", default=None)
    ap.add_argument("--only", default=None, help="mills to run (qiu,pilot01,pilot12)")
    ap.add_argument("--rerun", default="", help="labels to run again")
    ap.add_argument("--forecast", action="store_true", help="also the whole-life forecasts of the Qiu mill")
    ap.add_argument("--linerlife", default=os.path.join(ROOT, "build/app/linerlife"))
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    cache_path = os.path.join(a.out, "results.json")
    cache = json.load(open(cache_path)) if os.path.exists(cache_path) else {}
    rerun = set(x for x in a.rerun.split(",") if x)
    mills = [m for m in MILLS if not a.only or m[0] in a.only.split(",")]
    for key, name, cfg in mills:
        for label, group, args in runs_for(key):
            ck = f"{key}/{label}"
            if ck in cache and label not in rerun:
                continue
            print(f"running {ck} ...", file=sys.stderr, flush=True)
            res = run(a.binary, cfg, args)
            res["group"] = group
            res["args"] = args
            cache[ck] = res
            tmp = cache_path + ".tmp"
            json.dump(cache, open(tmp, "w"), indent=1)
            os.replace(tmp, cache_path)

    # tables
    for key, name, cfg in mills:
        ref = cache[f"{key}/{REF[0]}"]
        if "error" in ref:
            print(f"{name}: the reference run failed: {ref['error']}")
            continue
        print(f"\n### {name}\n")
        print(f"Reference: DEM at the media size, 16 steps a collision, 12 revolutions averaged: "
              f"{ref['particles']} discs, toe {ref['toe_deg']:.1f} deg, shoulder {ref['shoulder_deg']:.1f} deg, "
              f"CoM {ref['com_angle_deg']:.1f} deg, net power {ref['net_power_kw']:.4g} kW, "
              f"{ref['simulated_s']:.1f} s simulated in {ref['wall_s']:.1f} s wall.\n")
        print("| run | discs | wall [s] | toe [deg] | shoulder [deg] | CoM [deg] | power [%] | wear shape [%] "
              "| wear rate [%] |")
        print("|---|---|---|---|---|---|---|---|---|")
        for label, group, args in runs_for(key):
            if group == "ref":
                continue
            r = cache[f"{key}/{label}"]
            if "error" in r:
                print(f"| {label} | | | failed (exit {r['exit']}): {r['error'][:80]} | | | | | |")
                continue
            e = errors(r, ref)
            print(f"| {label} | {r['particles'] if r['model'] != 'empirical' else '-'} | {r['wall_s']:.3g} | "
                  f"{f(e['toe'])} | {f(e['shoulder'])} | {f(e['com'])} | {f(e['power'])} | {f(e['wear_shape'])} | "
                  f"{f(e['wear_rate'])} |")

    if a.forecast:
        run_forecasts(cache, a.out, a.linerlife)
    if a.img:
        draw(cache, mills, a.img)


def label_axes(ax, xlabel, ylabel):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)


def save(plt, fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def draw(cache, mills, img):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(img, exist_ok=True)
    metrics = [("toe", "toe error [deg]"), ("shoulder", "shoulder error [deg]"), ("power", "net power error [%]"),
               ("wear_shape", "wear distribution error [%]")]
    colours = {"empirical": "k", "layer 1.0": "tab:blue", "layer 1.1": "tab:orange", "layer 1.2": "tab:green"}
    markers = {"qiu": "o", "pilot01": "s", "pilot12": "^"}
    fig, axes = plt.subplots(2, 2, figsize=(10, 8))
    for ax, (m, title) in zip(axes.flat, metrics):
        for key, name, cfg in mills:
            ref = cache.get(f"{key}/{REF[0]}")
            if not ref or "error" in ref:
                continue
            for label, group, args in runs_for(key):
                if group not in ("model",):
                    continue
                r = cache[f"{key}/{label}"]
                e = errors(r, ref)
                if not e or e[m] is None:
                    continue
                c = colours.get(label, "tab:red" if "coarse" in label else "tab:purple")
                ax.scatter(max(r["wall_s"], 1e-4), e[m], c=c, marker=markers[key], s=40)
        ax.set_xscale("log")
        ax.set_xlabel("wall time of one run [s]")
        ax.set_ylabel(title)
        ax.grid(True, which="both", alpha=0.3)
    from matplotlib.lines import Line2D
    handles = [Line2D([], [], ls="", marker="o", c=c, label=l) for l, c in colours.items()]
    handles += [Line2D([], [], ls="", marker="o", c="tab:red", label="dem coarse"),
                Line2D([], [], ls="", marker="o", c="tab:purple", label="dem fine (default)")]
    handles += [Line2D([], [], ls="", marker=mk, c="grey", label=n) for (k, n, _), mk in
                zip(mills, [markers[k] for k, _, _ in mills])]
    fig.legend(handles=handles, loc="lower center", ncol=5, fontsize=8)
    fig.suptitle("Speed against accuracy: error relative to the finest DEM run of each mill")
    fig.tight_layout(rect=(0, 0.07, 1, 0.96))
    fig.savefig(os.path.join(img, "speed_accuracy.png"), dpi=110)
    plt.close(fig)

    # the wear distribution along the segment, per mill
    fig, axes = plt.subplots(1, len(mills), figsize=(5 * len(mills), 4), squeeze=False)
    for ax, (key, name, cfg) in zip(axes.flat, mills):
        for n, label in enumerate(("layer 1.0", "layer 1.1", "layer 1.2", f"dem coarse {COARSE[key]:g}", "dem fine",
                                   REF[0])):
            r = cache.get(f"{key}/{label}")
            if not r or "error" in r or r.get("recession_m_s") is None:
                continue
            b = binned(r, NBINS)
            if b is None:
                continue
            ax.stairs(b, [i / NBINS for i in range(NBINS + 1)], label=label, lw=2.5 if label == REF[0] else 1.2,
                      color="k" if label == REF[0] else f"C{n}")
        ax.set_title(name)
        label_axes(ax, "position along the segment [fraction of its length]",
                   f"share of the segment's wear per 1/{NBINS}")
    save(plt, fig, os.path.join(img, "speed_accuracy_wear.png"))

    # the whole-life forecasts: lifter, thinnest point and power along the life
    fc = [(label, cache[f"forecast/{label}"]) for label, _ in FORECASTS
          if f"forecast/{label}" in cache and "history" in cache[f"forecast/{label}"]]
    if fc:
        fig, axes = plt.subplots(1, 3, figsize=(15, 4))
        for label, r in fc:
            h = r["history"]
            for ax, key in zip(axes, ("lifter_height_m", "min_thickness_m", "net_power_kw")):
                ax.plot(h["hours"], h[key], label=label, lw=2.2 if label.startswith("dem") else 1.2,
                        c="k" if label.startswith("dem") else None)
        for ax, yl in zip(axes, ("lifter height [m]", "thinnest point of the liner [m]", "net power [kW]")):
            label_axes(ax, "operating hours", yl)
        fig.suptitle("Qiu mill, whole-life forecast per charge model")
        save(plt, fig, os.path.join(img, "speed_accuracy_forecast.png"))

    # DEM convergence: error against the reference for each series
    fig, axes = plt.subplots(1, 3, figsize=(14, 4))
    series = [("steps", "steps a collision", lambda r: float(r["args"][1].split("=")[1])),
              ("coarse", "coarse-graining s", lambda r: float(r["args"][1].split("=")[1])),
              ("revs", "revolutions averaged", lambda r: float(r["args"][1].split("=")[1]))]
    for ax, (g, xl, xv) in zip(axes, series):
        for key, name, cfg in mills:
            ref = cache.get(f"{key}/{REF[0]}")
            if not ref or "error" in ref:
                continue
            pts = []
            for label, group, args in runs_for(key):
                if group != g and not (g == "revs" and label == "dem fine"):  # the default: 3 revolutions
                    continue
                r = cache[f"{key}/{label}"]
                e = errors(r, ref)
                if e:
                    pts.append((3.0 if label == "dem fine" else xv(r), e["power"], e["wear_rate"]))
            pts.sort()
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=markers[key], label=f"{name}: power")
            ax.plot([p[0] for p in pts], [p[2] for p in pts], marker=markers[key], ls="--",
                    label=f"{name}: wear rate")
        label_axes(ax, xl, "error against the reference [%]")
    save(plt, fig, os.path.join(img, "speed_accuracy_dem_convergence.png"))


if __name__ == "__main__":
    main()
