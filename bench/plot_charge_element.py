#!/usr/bin/python3
"""Chart of the agglomerated-element study (docs/models/layer.md §1, "Agglomerated elements").

Usage: bench/plot_charge_element.py ELEMENT.csv OUT.png

ELEMENT.csv is written by `build/bench/bench_charge_element REVS ELEMENT.csv` (one row per run:
case, element edge, realisation). Speed against accuracy: for every case and element edge, the
real-time ratio by CPU time (median over the realisations) against the change of the mean net
power from the one-diameter element; industrial cases (the Qiu mill and its variations) as
circles, pilot tests as triangles, one colour per edge; the 1000 x target marked.
"""
import csv
import sys
from collections import defaultdict
from statistics import mean, median

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(path, out):
    runs = defaultdict(list)
    industrial = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            runs[(r["case"], float(r["element_diameters"]))].append(r)
            industrial[r["case"]] = r["industrial"] == "1"
    edges = sorted({k for _, k in runs})
    fig, ax = plt.subplots(figsize=(7.5, 5))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, k in enumerate(edges):
        for ind, marker, label in ((True, "o", "industrial"), (False, "^", "pilot")):
            xs, ys = [], []
            for (case, kk), rows in runs.items():
                if kk != k or industrial[case] != ind or (case, edges[0]) not in runs:
                    continue
                p = mean(float(r["net_power_kw"]) for r in rows)
                p0 = mean(float(r["net_power_kw"]) for r in runs[(case, edges[0])])
                ratio = median(float(r["simulated_s"]) / max(float(r["cpu_s"]), 1e-6) for r in rows)
                xs.append(ratio)
                ys.append(100.0 * (p / p0 - 1.0))
            ax.scatter(xs, ys, marker=marker, color=colours[i % len(colours)], s=28, alpha=0.8,
                       label=f"edge {k:g} d, {label}")
    ax.axvline(1000, color="grey", ls=":", lw=1)
    ax.axhline(0, color="grey", lw=0.5)
    ax.set_xscale("log")
    ax.set_xlabel("real-time ratio, CPU (simulated s / CPU s)")
    ax.set_ylabel("net power / one-diameter element's - 1 [%]")
    ax.set_title("agglomerated elements: speed against accuracy\n(dotted: the 1000 x target)")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
