#!/usr/bin/python3
"""Charts of docs/validation/wear.md from the wear benchmarks' output.

Usage (from the repository root, after building in build/):
  build/bench/bench_wear_submodels > /tmp/submodels.csv
  build/bench/bench_wear_smoothing csv > /tmp/smoothing.txt
  build/bench/bench_wear_remesh_interval > /tmp/interval.txt
  /usr/bin/python3 bench/plot_wear_validation.py /tmp/submodels.csv /tmp/smoothing.txt /tmp/interval.txt docs/validation/img
"""
import io
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def sections(path):
    """CSV sections separated by blank lines, each headed by '# name: col,col,...'."""
    out, head, rows = {}, None, []
    for line in open(path).read().splitlines() + [""]:
        if line.startswith("#"):
            head = line[1:].strip()
            rows = []
        elif line.strip() == "":
            if head is not None and rows:
                out[head.split(":")[0].strip()] = (head, np.loadtxt(io.StringIO("\n".join(rows)), delimiter=","))
            head = None
        else:
            rows.append(line)
    return out


def save(fig, out, name):
    fig.savefig(os.path.join(out, name), dpi=120, bbox_inches="tight")
    plt.close(fig)


def interval_tables(path):
    """The tables of bench_wear_remesh_interval: title -> rows of numbers."""
    tables, title = {}, None
    for line in open(path):
        if line.startswith("## "):
            title = line[3:].strip()
            tables[title] = []
        elif title and line.strip() and not line.strip().startswith("k"):
            tables[title].append([float(x) for x in line.split()])
    return tables


def main(sub_csv, smooth_txt, interval_txt, out):
    os.makedirs(out, exist_ok=True)
    s = sections(sub_csv)

    _, d = s["restitution"]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(d[:, 0], d[:, 1], label="liner 350 BHN (default Cr-Mo)")
    ax.plot(d[:, 0], d[:, 2], label="liner 250 BHN")
    ax.plot(d[:, 0], d[:, 3], "k:", label="Johnson (1985) asymptote 1.185 (V_y/v)^(1/4)")
    ax.set_xscale("log")
    ax.set_ylim(0, 1.05)
    ax.set_xlabel("normal impact speed [m/s]")
    ax.set_ylabel("coefficient of restitution e")
    ax.set_title("Restitution of a steel ball on the liner (cf. thesis Fig. 5-5)", fontsize=9)
    ax.legend(fontsize=8)
    save(fig, out, "wear_restitution.png")

    _, d = s["friction"]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(d[:, 0], d[:, 1], label="ball 0.05 m")
    ax.plot(d[:, 0], d[:, 2], "--", label="ball 0.1333 m (Qiu mill)")
    ax.axhspan(0.15, 0.3, color="0.9", label="range of thesis Fig. 5-6 (Yabuki 1999 data)")
    ax.set_xscale("log")
    ax.set_xlabel("normal impact speed [m/s]")
    ax.set_ylabel("impact friction coefficient f (eq. 5.20)")
    ax.set_title("Impact friction of a steel ball on the liner (cf. thesis Fig. 5-6)", fontsize=9)
    ax.legend(fontsize=8)
    save(fig, out, "wear_friction.png")

    _, d = s["erosion at 8 m/s per kg of 0.1333 m balls [m3/kg]"]
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    names = ["Finnie", "Bitter, deformation", "Bitter, cutting", "Bitter", "Rabinowicz", "Sheldon-Kanhere"]
    styles = ["-", ":", ":", "-", "-", "-"]
    for i, (n, st) in enumerate(zip(names, styles)):
        ax.plot(d[:, 0], d[:, i + 1] * 1e9, st, label=n)
    ax.set_xlabel("impact angle from the surface [deg]")
    ax.set_ylabel("volume removed per kg of impacting balls [mm3]")
    ax.set_title("Impact wear against impact angle at 8 m/s (cf. thesis Fig. 5-7)", fontsize=9)
    ax.legend(fontsize=8)
    save(fig, out, "wear_erosion_angle.png")

    # thesis Fig. 5-18: residuals element by element on one simulated profile
    text = open(smooth_txt).read()
    csv = text[text.index("node,truth"):]
    cols = csv.splitlines()[0].split(",")
    d = np.loadtxt(io.StringIO(csv), delimiter=",", skiprows=1)
    col = {c: i for i, c in enumerate(cols)}
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    mean = d[:, col["truth"]].mean()
    a1.plot(d[:, 0], d[:, col["raw"]] * 1e3, "k+", label="raw wear data (simulated events)")
    a1.plot(d[:, 0], d[:, col["truth"]] * 1e3, "k-", lw=0.8, label="truth")
    show = ["moving average 10 (thesis)", "csaps p = 0.999900", "Tukey 3RRSHRRSRR (thesis)",
            "Tukey 3RRSHRRSRR + csaps 0.9999 (thesis' choice)"]
    for name in show:
        a1.plot(d[:, 0], d[:, col[name]] * 1e3, label=name)
        a2.plot(d[:, 0], (d[:, col[name]] - d[:, col["raw"]]) / mean * 100, ".-", label=name)
    a1.set_ylabel("recession depth [mm]")
    a1.legend(fontsize=7)
    a1.set_title("Smoothers on a simulated worn-liner depth field (cf. thesis Fig. 5-18)", fontsize=9)
    a2.axhline(0, color="k", lw=0.5)
    a2.set_xlabel("node number on the liner profile")
    a2.set_ylabel("residual, smoothed - raw [% of mean depth]")
    save(fig, out, "wear_smoothing_residuals.png")

    # remesh interval: error against the every-step reference and wall time
    tables = interval_tables(interval_txt)
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4))
    for title, rows in tables.items():
        if "tukey" in title:
            continue
        r = np.array(rows)
        a1.plot(r[1:, 0], r[1:, 6], "o-", label=title)
        a2.plot(r[1:, -1], r[1:, 6], "o-", label=title)
        for k, x, y in zip(r[1:, 0], r[1:, -1], r[1:, 6]):
            a2.annotate(f"{int(k)}", (x, y), fontsize=6)
    for a in (a1, a2):
        a.set_yscale("log")
        a.set_ylabel("final profile of liner 0 vs every-step remesh [mm]")
        a.grid(True, which="both", lw=0.3)
    a1.set_xscale("log")
    a1.set_xlabel("remesh every k time steps")
    a2.set_xscale("log")
    a2.set_xlabel("wall time of the run [s] (median of 5, synthetic loads)")
    a1.legend(fontsize=7)
    a1.set_title("Remesh interval: convergence", fontsize=9)
    a2.set_title("Remesh interval: speed against accuracy (labels: k)", fontsize=9)
    save(fig, out, "wear_remesh_interval.png")


if __name__ == "__main__":
    if len(sys.argv) != 5:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    main(*sys.argv[1:])
