#!/usr/bin/python3
"""Chart of the layer model's time-step study (docs/models/layer.md §9).

Usage: bench/plot_charge_timestep.py TIMESTEP.csv OUT.png

TIMESTEP.csv is written by `build/bench/bench_charge_timestep REVS TIMESTEP.csv`.
One column per mill; rows: net power relative to the 1 ms run, toe, shoulder,
all against the requested step (log scale), as given (no sub-stepping) and as a
user gets it (sub-stepped beyond Courant 0.45). The step at which the shell moves
0.45 media diameters is marked.
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

KMAX = 0.45  # charge/layer_model.h kLayerMaxCourant


def main(path, out):
    rows = defaultdict(lambda: defaultdict(list))
    with open(path) as f:
        for r in csv.DictReader(f):
            rows[r["mill"]][r["mode"]].append(r)
    mills = list(rows)
    fig, axes = plt.subplots(3, len(mills), figsize=(4.2 * len(mills), 8.5), sharex=True, squeeze=False)
    for c, mill in enumerate(mills):
        given = rows[mill]["as_given"]
        sub = rows[mill]["substepped"]
        ref = float(given[0]["net_power_kw"])
        step = [float(r["step_ms"]) for r in given]
        courant_per_ms = float(given[0]["courant"]) / float(given[0]["step_ms"])
        limit_ms = KMAX / courant_per_ms
        for k, (key, label) in enumerate(
            [("net_power_kw", "net power / 1 ms run - 1 [%]"), ("toe_deg", "toe [deg]"), ("shoulder_deg", "shoulder [deg]")]
        ):
            ax = axes[k][c]
            for data, style, name in ((given, "o-", "as given (no sub-steps)"), (sub, "x--", "sub-stepped (default)")):
                y = [float(r[key]) for r in data]
                if key == "net_power_kw":
                    y = [100.0 * (v / ref - 1.0) for v in y]
                ax.plot(step, y, style, label=name, ms=4)
            ax.axvline(limit_ms, color="grey", lw=0.8, ls=":")
            ax.set_xscale("log")
            ax.grid(True, which="both", lw=0.3)
            if c == 0:
                ax.set_ylabel(label)
            if k == 0:
                ax.set_title(f"{mill.replace('.toml', '')}\n(Courant {KMAX} at {limit_ms:.1f} ms)", fontsize=9)
            if k == 2:
                ax.set_xlabel("requested time step [ms]")
    axes[0][0].legend(fontsize=7)
    fig.suptitle("Layer model V-1.2: time-step study (thesis §3.2.1, Fig. 3-1)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
