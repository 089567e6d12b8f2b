#!/usr/bin/python3
"""Tables and chart of docs/validation/charge.md from bench_charge_validation's CSV.

Usage: bench/charge_validation.py VALIDATION.csv [OUT.png]

Prints Markdown: the indicators of every mill for the empirical model (Morrell's
C-model, the reference here), the layer model V-1.0/1.1/1.2 and the DEM where it
was run; then the error statistics in the format of thesis Tables 4.3/4.4 (mean
and standard deviation of the relative and of the absolute error, in %), and the
angle errors in degrees. With OUT.png, draws layer (and DEM) against Morrell.
"""
import csv
import statistics as st
import sys
from collections import OrderedDict

VERSIONS = ["1.0", "1.1", "1.2"]
IND = [("toe_deg", "toe [deg]", "TA"), ("shoulder_deg", "shoulder [deg]", "SA"), ("com_deg", "CoM [deg]", "CoM"),
       ("net_power_kw", "net power [kW]", "P")]


def load(path):
    runs = OrderedDict()
    for r in csv.DictReader(open(path)):
        key = "dem" if r["model"] == "dem" else ("M" if r["model"] == "empirical" else r["variant"])
        runs.setdefault(r["case"], {"phi": float(r["fraction_critical"]), "J": float(r["filling"]),
                                    "rot": r["rotation"]})[key] = r
    return runs


def fmt(v, key):
    return f"{v:.3g}" if key == "net_power_kw" else f"{v:.1f}"


def errors(runs, key, ver, cases=None):
    rel, dif = [], []
    for case, d in runs.items():
        if cases and case not in cases:
            continue
        if ver not in d:
            continue
        ref, x = float(d["M"][key]), float(d[ver][key])
        rel.append(100.0 * (x - ref) / ref)
        dif.append(x - ref)
    return rel, dif


def sense(d):
    return 1.0 if d["rot"] == "ccw" else -1.0


def wrap180(a):
    return (a + 180.0) % 360.0 - 180.0


def sd(v):
    return st.stdev(v) if len(v) > 1 else float("nan")


def main(path, png=None):
    runs = load(path)
    have_dem = [c for c, d in runs.items() if "dem" in d]
    cols = ["M"] + VERSIONS + (["dem"] if have_dem else [])
    names = {"M": "Morrell", "1.0": "V-1.0", "1.1": "V-1.1", "1.2": "V-1.2", "dem": "DEM"}
    for group in (IND[:2], IND[2:]):
        head = "| case | rot | phi | J |" + "".join(f" {lab} {names[c]} |" for _, lab, _ in group for c in cols)
        print(head)
        print("|" + "---|" * (4 + len(group) * len(cols)))
        for case, d in runs.items():
            line = f"| {case} | {d['rot']} | {d['phi']:.3f} | {d['J']:.2f} |"
            for key, _, _ in group:
                for c in cols:
                    line += f" {fmt(float(d[c][key]), key)} |" if c in d else " - |"
            print(line)
        print()
    # Table 4.3/4.4 format
    for title, cases in (("all 17 mills (Qiu + 16 pilot tests)", None),
                         ("16 pilot tests", [c for c in runs if c.startswith("pilot")])):
        print(f"Error against Morrell's C-model, {title}, in % (thesis Tables 4.3/4.4 format):\n")
        print("| | mean rel. V-1.0 | V-1.1 | V-1.2 | mean abs. V-1.0 | V-1.1 | V-1.2 | "
              "std rel. V-1.0 | V-1.1 | V-1.2 | std abs. V-1.0 | V-1.1 | V-1.2 |")
        print("|---" * 13 + "|")
        for key, _, short in IND:
            stats = {v: errors(runs, key, v, cases)[0] for v in VERSIONS}
            mr = [st.mean(stats[v]) for v in VERSIONS]
            ma = [st.mean([abs(x) for x in stats[v]]) for v in VERSIONS]
            sr = [sd(stats[v]) for v in VERSIONS]
            sa = [sd([abs(x) for x in stats[v]]) for v in VERSIONS]
            print(f"| {short} | " + " | ".join(f"{x:.0f}" for x in mr + ma + sr + sa) + " |")
        print()
    print("Angle differences in degrees, model - Morrell, measured along the direction of rotation (a clockwise "
          "mill's difference is negated), mean +- standard deviation over the mills run:\n")
    print("| | V-1.0 | V-1.1 | V-1.2 |" + (" DEM |" if have_dem else ""))
    print("|---|---|---|---|" + ("---|" if have_dem else ""))
    for key, lab, _ in IND[:3]:
        line = f"| {lab} |"
        for v in VERSIONS + (["dem"] if have_dem else []):
            dif = [sense(runs[c]) * wrap180(float(d[v][key]) - float(d["M"][key])) for c, d in runs.items() if v in d]
            line += f" {st.mean(dif):+.1f} +- {sd(dif):.1f} (n={len(dif)}) |"
        print(line)
    print()
    if have_dem:
        print(f"Against the DEM on the {len(have_dem)} mills it was run on ({', '.join(have_dem)}): mean absolute "
              "error in % (angles in degrees along the rotation, mean absolute):\n")
        print("| | Morrell | V-1.0 | V-1.1 | V-1.2 |")
        print("|---|---|---|---|---|")
        for key, lab, _ in IND:
            line = f"| {lab} |"
            for v in ["M"] + VERSIONS:
                if key == "net_power_kw":
                    e = [abs(100.0 * (float(runs[c][v][key]) / float(runs[c]["dem"][key]) - 1.0)) for c in have_dem]
                    line += f" {st.mean(e):.0f} % |"
                else:
                    e = [abs(wrap180(float(runs[c][v][key]) - float(runs[c]["dem"][key]))) for c in have_dem]
                    line += f" {st.mean(e):.1f} |"
            print(line)
        print()
        print("DEM - layer V-1.2 per mill (angles along the rotation):\n")
        print("| case | toe [deg] | shoulder [deg] | CoM [deg] | power [%] |")
        print("|---|---|---|---|---|")
        for c in have_dem:
            d = runs[c]
            a, b = d["dem"], d["1.2"]
            dd = [sense(d) * wrap180(float(a[k]) - float(b[k])) for k in ("toe_deg", "shoulder_deg", "com_deg")]
            print(f"| {c} | {dd[0]:+.1f} | {dd[1]:+.1f} | {dd[2]:+.1f} | "
                  f"{100 * (float(a['net_power_kw']) / float(b['net_power_kw']) - 1):+.0f} |")
        print()
    if png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, 4, figsize=(16, 4.2))
        marks = {"1.0": ("o", "V-1.0"), "1.1": ("s", "V-1.1"), "1.2": ("^", "V-1.2"), "dem": ("*", "DEM")}
        for ax, (key, lab, _) in zip(axes, IND):
            lo, hi = float("inf"), -float("inf")
            for v, (m, name) in marks.items():
                if key == "net_power_kw":  # the mills span 1 kW to 6 MW: the ratio against phi
                    xs = [d["phi"] for d in runs.values() if v in d]
                    ys = [float(d[v][key]) / float(d["M"][key]) for d in runs.values() if v in d]
                else:
                    xs = [float(d["M"][key]) for d in runs.values() if v in d]
                    ys = [float(d[v][key]) for d in runs.values() if v in d]
                if not xs:
                    continue
                ax.scatter(xs, ys, marker=m, label=name, s=22 if v != "dem" else 70, alpha=0.8)
                lo, hi = min(lo, *xs, *ys), max(hi, *xs, *ys)
            if key == "net_power_kw":
                ax.axhline(1.0, color="k", lw=0.6)
                ax.set_xlabel("fraction of critical speed phi")
                ax.set_ylabel("net power / Morrell's P_t + P_c")
            else:
                ax.plot([lo, hi], [lo, hi], "k-", lw=0.6)
                ax.set_xlabel(f"Morrell C-model: {lab}")
                ax.set_ylabel(f"model: {lab}")
            ax.grid(True, lw=0.3)
        axes[0].legend(fontsize=8)
        fig.suptitle("Layer model (V-1.0/1.1/1.2) and DEM against Morrell's C-model: Qiu mill and 16 pilot tests",
                     fontsize=10)
        fig.tight_layout()
        fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else None)
