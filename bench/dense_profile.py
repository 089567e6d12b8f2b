"""A measured-profile CSV (docs/profile-csv.md) of exactly N points: the bundled
Qiu mill's lifter (data/mills/qiu2001_sag.toml: plate 0.075 m, lifter 0.25 m,
top 0.15 m, faces 20 deg) cut into equal pieces, as a dense scan would give it,
and a copy of the mill's configuration that uses it.

    python3 bench/dense_profile.py N OUT_DIR [M]

writes OUT_DIR/pN.csv and OUT_DIR/cN.toml; M (optional) is how many points to
cut the outline into before the trim to N (by default found by trial). The faces and the top are straight
in the mill frame (as the parametric lifter), the plate straight in the CSV's
frame (an arc of the shell); only the two ends lie on the segment edges (the
points within 1.5 mm of an edge are left out). The timings of dense profiles
in docs/reliability.md ("A second review (2026-12-04)") used these files.
"""
import math
import os
import sys

R, SEGMENTS = 10.36 / 2, 64
SEG = 2 * math.pi / SEGMENTS
WIDTH = SEG * R
PLATE, HEIGHT, TOP, A_LEAD, A_TRAIL = 0.075, 0.25, 0.15, 20.0, 20.0


def meet_circle(t, d, r):
    b = t[0] * d[0] + t[1] * d[1]
    c = t[0] ** 2 + t[1] ** 2 - r * r
    s = -b + math.sqrt(max(0.0, b * b - c))
    return (t[0] + s * d[0], t[1] + s * d[1])


def face_direction(phi, alpha, side):
    er, et = (math.cos(phi), math.sin(phi)), (-math.sin(phi), math.cos(phi))
    return (math.cos(alpha) * er[0] + side * math.sin(alpha) * et[0],
            math.cos(alpha) * er[1] + side * math.sin(alpha) * et[1])


def face_foot(top, alpha, side, rp, r_mid):
    """geometry/build_liner_surface.cpp face_foot(): the face at angle alpha
    from the radial through its point at mid-height."""
    phi = math.atan2(top[1], top[0])
    for _ in range(100):
        m = meet_circle(top, face_direction(phi, alpha, side), r_mid)
        new = math.atan2(m[1], m[0])
        if abs(new - phi) < 1e-16:
            break
        phi = new
    return meet_circle(top, face_direction(phi, alpha, side), rp)


def to_csv_frame(p):
    return ((math.atan2(p[1], p[0]) + 0.5 * SEG) * R, R - math.hypot(*p))


def profile(requested):
    rp = R - PLATE
    xt, r_mid = rp - HEIGHT, rp - 0.5 * HEIGHT
    lead_top, trail_top = (xt, 0.5 * TOP), (xt, -0.5 * TOP)
    lead_foot = face_foot(lead_top, math.radians(A_LEAD), +1, rp, r_mid)
    trail_foot = face_foot(trail_top, math.radians(A_TRAIL), -1, rp, r_mid)
    mill = [None, trail_foot, trail_top, lead_top, lead_foot, None]
    corners = [(0.0, PLATE)] + [to_csv_frame(p) for p in mill[1:5]] + [(WIDTH, PLATE)]
    lengths = [math.dist(corners[i], corners[i + 1]) for i in range(5)]
    pts = []
    for i in range(5):
        n = max(1, round((requested - 1) * lengths[i] / sum(lengths)))
        for k in range(n):
            t = k / n
            if mill[i] is not None and mill[i + 1] is not None:  # straight in the mill frame
                a, b = mill[i], mill[i + 1]
                pts.append(to_csv_frame((a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t)))
            else:  # the plate: straight in the CSV frame
                a, b = corners[i], corners[i + 1]
                pts.append((a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t))
    inner = [p for p in pts[1:] if 1.5e-3 < p[0] < WIDTH - 1.5e-3]
    return [pts[0]] + inner + [corners[-1]]


def main():
    n, out_dir = int(sys.argv[1]), sys.argv[2]
    # ask for a few more points than wanted, then leave out every other point
    # at the start of the first plate stretch (straight: the shape is kept)
    requested = int(sys.argv[3]) if len(sys.argv) > 3 else n
    for _ in range(50):
        pts = profile(requested)
        if len(pts) >= n or len(sys.argv) > 3:
            break
        requested += max(1, n - len(pts))
    excess = len(pts) - n
    drop = set(range(3, 3 + 2 * excess, 2))
    pts = [p for k, p in enumerate(pts) if k not in drop]
    assert len(pts) == n
    gap = min(math.dist(pts[i], pts[i + 1]) for i in range(n - 1))
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, f"p{n}.csv"), "w") as f:
        f.write(f"# the bundled Qiu lifter cut into equal pieces, {n} points (bench/dense_profile.py)\nx_m,y_m\n")
        for p in pts:
            f.write("%.9f,%.9f\n" % p)
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "..", "data", "mills", "qiu2001_sag.toml")) as f:
        toml = f.read()
    with open(os.path.join(out_dir, f"c{n}.toml"), "w") as f:
        f.write(toml.replace("[liner]\n", f'[liner]\nprofile_csv = "p{n}.csv"\n', 1))
    print(f"{n} points, consecutive points at least {gap * 1e3:.3g} mm apart: {out_dir}/p{n}.csv, {out_dir}/c{n}.toml")


if __name__ == "__main__":
    main()
