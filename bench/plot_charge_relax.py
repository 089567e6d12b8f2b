#!/usr/bin/python3
"""Chart of the layer model's relaxation-interval study (docs/models/layer.md §9,
"The relaxation interval").

Usage: bench/plot_charge_relax.py RELAX.csv OUT.png

RELAX.csv is written by `build/bench/bench_charge_relax REVS RELAX.csv` (one row per
run: mill, interval, realisation). Left: the net power, mean over the realisations,
relative to the finest interval's, against the interval in outer cells (log scale),
the default (half a cell) marked. Right: speed against accuracy: the CPU time of one
run (median over the realisations) against the magnitude of that power deviation.
"""
import csv
import sys
from collections import defaultdict
from statistics import mean, median

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

DEFAULT_CELLS = 0.5  # charge/charge_spec.h ModelSpec::relaxation_interval_cells


def main(path, out):
    runs = defaultdict(lambda: defaultdict(list))
    with open(path) as f:
        for r in csv.DictReader(f):
            runs[r["mill"]][float(r["interval_cells"])].append(r)
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.6))
    for mill, by_cell in runs.items():
        cells = sorted(by_cell)
        power = [mean(float(r["net_power_kw"]) for r in by_cell[c]) for c in cells]
        cpu = [median(float(r["cpu_s"]) for r in by_cell[c]) for c in cells]
        ref = power[0]
        dev = [100.0 * (p / ref - 1.0) for p in power]
        name = mill.replace(".toml", "")
        line = ax.plot(cells, dev, "o-", ms=4, label=name)[0]
        bx.plot([max(abs(d), 0.01) for d in dev], cpu, "o-", ms=4, color=line.get_color(), label=name)
        for c, d, t in zip(cells, dev, cpu):
            if c == DEFAULT_CELLS:
                bx.plot([max(abs(d), 0.01)], [t], "s", ms=9, mfc="none", color=line.get_color())
    ax.axvline(DEFAULT_CELLS, color="grey", lw=0.8, ls=":")
    ax.set_xscale("log", base=2)
    ax.set_xlabel("relaxation interval [outer cells of shell travel]")
    ax.set_ylabel("net power / finest interval's - 1 [%]")
    ax.set_title("power against the relaxation interval\n(dotted: the default, half a cell)")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    bx.set_xscale("log")
    bx.set_yscale("log")
    bx.set_xlabel("|net power / finest interval's - 1| [%] (0.01 % where below)")
    bx.set_ylabel("CPU per run [s]")
    bx.set_title("speed against accuracy (squares: the default)")
    bx.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
