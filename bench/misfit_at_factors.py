"""The misfit of measured profiles against the bundled mill's forecast at given
wear calibration factors, without a fit: for each ABRASION,IMPACT pair (the
centrifugal and gravitational factors both ABRASION), `linerlife forecast`
of the bundled configuration with those factors, then the rms distance of
every scan point (docs/measured-profiles.md: hours,x_m,y_m) to segment 0 of
the forecast profile nearest its hours, in the unrolled frame. The distance is
unsigned and taken in the unrolled frame, so it is close to, not the same as,
calibrate's misfit. It maps the misfit `calibrate` sees (docs/measured-profiles.md,
"Two scales of slope").

    /usr/bin/python3 bench/misfit_at_factors.py BUILD SCANS.csv A,I [A,I ...]

Two forecasts run at once (about 6 s each on the 2-core machine).
"""
import math
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scan_from_forecast import segment0_unrolled  # noqa: E402
from toml_edit import set_key  # noqa: E402


def distance_to_polyline(p, poly):
    a, b = poly[:-1], poly[1:]
    ab = b - a
    t = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-30), 0, 1)
    return float(np.min(np.linalg.norm(p - (a + t[:, None] * ab), axis=1)))


def misfit(linerlife, base, scans, abrasion, impact, work):
    text = base
    for key, v in (("calibration_centrifugal", abrasion), ("calibration_gravitational", abrasion),
                   ("calibration_impact", impact)):
        text = set_key(text, "wear", key, repr(v))
    d = os.path.join(work, "a%g_i%g" % (abrasion, impact))
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "m.toml"), "w") as f:
        f.write(text)
    subprocess.run([linerlife, "forecast", os.path.join(d, "m.toml"), "--out", os.path.join(d, "fc"), "--quiet"],
                   check=True, capture_output=True)
    dist = []
    for h in sorted(set(scans[:, 0])):
        x, y, _ = segment0_unrolled(os.path.join(d, "fc", "forecast.h5"), h)
        poly = np.stack([x, y], 1)
        dist += [distance_to_polyline(q, poly) for q in scans[scans[:, 0] == h][:, 1:]]
    return 1000 * math.sqrt(np.mean(np.square(dist)))


def main():
    build, scans_path = sys.argv[1], sys.argv[2]
    pairs = [tuple(float(v) for v in a.split(",")) for a in sys.argv[3:]]
    linerlife = os.path.join(build, "app", "linerlife")
    base = subprocess.run([linerlife, "defaults"], check=True, capture_output=True, text=True).stdout
    scans = np.array([[float(v) for v in ln.split(",")] for ln in open(scans_path)
                      if ln.strip() and not ln.startswith("#") and not ln.startswith("hours")])
    with tempfile.TemporaryDirectory() as work, ThreadPoolExecutor(2) as ex:
        rms = ex.map(lambda p: misfit(linerlife, base, scans, p[0], p[1], work), pairs)
        print("abrasion impact rms_mm")
        for (a, i), r in zip(pairs, rms):
            print("%g %g %.3f" % (a, i, r))


if __name__ == "__main__":
    main()
