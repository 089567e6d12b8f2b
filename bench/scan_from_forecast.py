"""A measured-profile history (docs/measured-profiles.md: hours,x_m,y_m) made
from a forecast's own profile: segment 0 of the profile nearest HOURS in
forecast.h5 (`linerlife forecast --out DIR`), in the unrolled frame of
docs/profile-csv.md, every STEP-th node (both ends kept), labelled LABEL hours.
A scan whose hours are mislabelled (LABEL far from HOURS) is the review's
calibration case in docs/reliability.md ("A second review (2026-12-04)").

    /usr/bin/python3 bench/scan_from_forecast.py DIR/forecast.h5 HOURS LABEL STEP > scan.csv

The calibrations in docs/reliability.md used the bundled mill's forecast
(`linerlife forecast --out DIR`), HOURS 2000, LABEL 60000 or 49999, STEP 2
(s*.csv) or 1 (a*.csv, all 84 nodes).
"""
import math
import sys

import h5py
import numpy as np


def segment0_unrolled(path, hours):
    """Segment 0 of the profile nearest `hours` in forecast.h5 `path`, in the
    unrolled frame: (x, y, the profile's hours)."""
    with h5py.File(path, "r") as f:
        hrs = f["forecast/profiles/hours"][:]
        off = f["forecast/profiles/offset"][:]
        nodes = f["forecast/profiles/nodes"][:]
        R = float(f["surface"].attrs["shell_radius_m"])
        segments = int(f["surface"].attrs["segments"])
    i = int(np.argmin(abs(hrs - hours)))
    pts = nodes[off[i]:off[i + 1]]
    th = np.arctan2(pts[:, 1], pts[:, 0])
    th = np.where(th > math.pi, th - 2 * math.pi, th)
    x = R * th + math.pi * R / segments  # segment 0 spans -seg/2 .. seg/2
    y = R - np.hypot(pts[:, 0], pts[:, 1])
    return x, y, hrs[i]


def main():
    path, hours, label, step = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4])
    x, y, at = segment0_unrolled(path, hours)
    keep = list(range(0, len(x), step))
    if keep[-1] != len(x) - 1:
        keep.append(len(x) - 1)
    print("# segment 0 of %s at %g h, labelled %g h, every %d-th node" % (path, at, label, step))
    print("hours,x_m,y_m")
    for k in keep:
        print("%g,%.6f,%.6f" % (label, x[k], y[k]))


if __name__ == "__main__":
    main()
