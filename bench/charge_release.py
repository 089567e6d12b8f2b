#!/usr/bin/python3
"""The release study of docs/models/layer.md §3: layer runs against the DEM.

Usage: bench/charge_release.py DEM.csv LABEL=RUN.csv [LABEL=RUN.csv ...]

DEM.csv is a bench_charge_validation output with DEM rows (`bench_charge_validation
DEM.csv "qiu,pilot"`); each RUN.csv one of the same bench with the layer model's study
options (`--unheld-mu MU`, `--pocket-balls P`). Prints, per run and layer version, the
mean absolute difference from the DEM over the mills the DEM was run on: toe, shoulder
and centre-of-mass angle [deg], the net power by the torque arm (thesis eq. 4.3) and by
the energy reading (lift + kinetic energy given to departing elements) [%].
"""
import csv
import statistics as st
import sys

VERSIONS = ["1.0", "1.1", "1.2"]


def load(path):
    runs = {}
    for r in csv.DictReader(open(path)):
        key = "dem" if r["model"] == "dem" else ("M" if r["model"] == "empirical" else r["variant"])
        runs.setdefault(r["case"], {})[key] = r
    return runs


def wrap180(a):
    return (a + 180.0) % 360.0 - 180.0


def main(dem_path, runs):
    dem = {c: d["dem"] for c, d in load(dem_path).items() if "dem" in d}
    if not dem:
        sys.exit(f"{dem_path}: no DEM rows (run bench_charge_validation with DEM_CASES)")
    print(f"Mean absolute difference from the DEM over {len(dem)} mills ({', '.join(dem)}):\n")
    print("| run | version | toe [deg] | shoulder [deg] | CoM [deg] | power, torque [%] | power, energy [%] |")
    print("|---|---|---|---|---|---|---|")
    for arg in runs:
        label, path = arg.split("=", 1)
        x = load(path)
        for v in VERSIONS:
            cases = [c for c in dem if c in x and v in x[c]]
            if len(cases) != len(dem):
                sys.exit(f"{path}: version {v} lacks mills the DEM was run on")

            def ang(key):
                return st.mean(abs(wrap180(float(x[c][v][key]) - float(dem[c][key]))) for c in cases)

            def power(key):
                return st.mean(abs(100.0 * (float(x[c][v][key]) / float(dem[c]["net_power_kw"]) - 1.0)) for c in cases)

            print(f"| {label} | V-{v} | {ang('toe_deg'):.1f} | {ang('shoulder_deg'):.1f} | {ang('com_deg'):.1f} | "
                  f"{power('net_power_kw'):.0f} | {power('alt_net_power_kw'):.0f} |")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
