"""Charts of `linerlife wear` (thesis Figs. 5-13, 5-16, 5-17 and B-5).

Profiles are drawn as the thesis draws them: one lifter turned to the bottom of
the mill, x along the shell and y the mill-frame height [m], so an
anticlockwise mill moves the lifter to the right (its leading face is the
right-hand one).
"""
import json

import matplotlib.pyplot as plt
import numpy as np

from plot_common import save, segment_chain, surface, surface_datasets

# every chart this kind of file may draw (a chart of an earlier run left in the folder under one of these
# names is removed: plot_common.commit_charts())
CHARTS = ("wear_profiles.png", "wear_impact_contribution.png", "wear_impact_only.png", "wear_history.png",
          "wear_rates.png")


def bottom_frame(chain, centre):
    """Mill-frame points of a segment centred on `centre` -> turned so that the
    segment sits at the bottom of the mill (-90 deg)."""
    a = -0.5 * np.pi - centre
    c, s = np.cos(a), np.sin(a)
    return c * chain[:, 0] - s * chain[:, 1], s * chain[:, 0] + c * chain[:, 1]


def profile(h5, group, k=0):
    nodes, begin, R, segments = surface(h5, group)
    chain = segment_chain(nodes, begin, k)
    return bottom_frame(chain, k * 2 * np.pi / segments), R, segments


def shell(ax, R, segments):
    t = np.linspace(-0.5, 0.5, 50) * 2 * np.pi / segments - 0.5 * np.pi
    ax.plot(R * np.cos(t), R * np.sin(t), "k-", lw=1)


def summary(h5):
    v = h5["/wear/summary_json"][()]
    return json.loads(v.decode() if isinstance(v, bytes) else v)


def required_rows(h5):
    """The datasets the charts need rows of (a history of no rows drew empty axes and exit 0, a review found)."""
    return ["/snapshots/time_s", "/history/time_s", "/history/per_segment_kg_per_m", "/history/centrifugal_kg_per_m",
            "/history/gravitational_kg_per_m", "/history/impact_kg_per_m", "/history/total_kg_per_m"]


def finite_datasets(h5):
    """The datasets drawn that must hold finite numbers (linerlife_plot.py checks them before drawing)."""
    groups = ["/surface_initial", "/surface_final", "/companions/abrasion_only", "/companions/impact_only",
              "/rates/surface"]
    if "/snapshots/time_s" in h5:
        groups += [f"/snapshots/{i}" for i in range(len(h5["/snapshots/time_s"]))]
    paths = [p for g in groups for p in surface_datasets(g)]
    paths += ["/snapshots/time_s", "/history/time_s", "/history/per_segment_kg_per_m", "/history/centrifugal_kg_per_m",
              "/history/gravitational_kg_per_m", "/history/impact_kg_per_m", "/rates/centrifugal_m_s",
              "/rates/gravitational_m_s", "/rates/impact_m_s"]
    return paths


def draw(h5, out):
    info = summary(h5)
    rot = info.get("rotation", "ccw")
    revs = f"{info.get('revolutions', 0)} rev"
    if info.get("worn_through", False):  # it stopped before the revolutions asked for
        revs = f"{info.get('revolutions_simulated', 0):.2f} of {info.get('revolutions', 0)} rev, worn through"
    title_tail = f"{info.get('charge_model', '')} model, {revs}, A = {info.get('amplification_abrasion', 1):g}"

    # Fig. 5-13: the profile as it wears, snapshots superimposed.
    fig, ax = plt.subplots(figsize=(7, 5))
    times = np.asarray(h5["/snapshots/time_s"])
    colors = plt.cm.viridis(np.linspace(0, 0.9, len(times)))
    R = segments = None
    for i, t in enumerate(times):
        (x, y), R, segments = profile(h5, f"/snapshots/{i}")
        label = "initial" if i == 0 else ("final" if i == len(times) - 1 else "intermediate")
        ax.plot(x, y, "-", color=colors[i], lw=1.6 if i in (0, len(times) - 1) else 0.9,
                label=f"{label}, t = {t:.2f} s")
    shell(ax, R, segments)
    ax.set_aspect("equal")
    ax.set_xlabel("x - coordinate of mill [m]")
    ax.set_ylabel("y - coordinate of mill [m]")
    ax.set_title(f"Lifter 0 as it wears ({rot} mill; leading face {'right' if rot == 'ccw' else 'left'})\n{title_tail}",
                 fontsize=9)
    ax.legend(fontsize=7, loc="upper right")
    save(fig, out, "wear_profiles.png")

    # Fig. 5-16: with and without impact wear; Fig. 5-17: impact wear alone.
    if "/companions" in h5:
        (x0, y0), R, segments = profile(h5, "/surface_initial")
        (x1, y1), _, _ = profile(h5, "/surface_final")
        if "/companions/abrasion_only" in h5:
            fig, ax = plt.subplots(figsize=(7, 5))
            (xa, ya), _, _ = profile(h5, "/companions/abrasion_only")
            ax.plot(x0, y0, "k-", lw=1.2, label="initial")
            ax.plot(x1, y1, "C3-", lw=1.4, label="impact + abrasion")
            ax.plot(xa, ya, "C0--", lw=1.4, label="abrasion only (no impact)")
            shell(ax, R, segments)
            ax.set_aspect("equal")
            ax.set_xlabel("x - coordinate of mill [m]")
            ax.set_ylabel("y - coordinate of mill [m]")
            ax.set_title(f"Contribution of impact wear (thesis Fig. 5-16)\n{title_tail}", fontsize=9)
            ax.legend(fontsize=8)
            save(fig, out, "wear_impact_contribution.png")
        if "/companions/impact_only" in h5:
            fig, ax = plt.subplots(figsize=(7, 5))
            (xi, yi), _, _ = profile(h5, "/companions/impact_only")
            ax.plot(x0, y0, "k-", lw=1.2, label="initial")
            ax.plot(xi, yi, "C1-", lw=1.4, label="impact wear only")
            shell(ax, R, segments)
            ax.set_aspect("equal")
            ax.set_xlabel("x - coordinate of mill [m]")
            ax.set_ylabel("y - coordinate of mill [m]")
            ax.set_title(f"Impact wear with no abrasion (thesis Fig. 5-17)\n{title_tail}", fontsize=9)
            ax.legend(fontsize=8)
            save(fig, out, "wear_impact_only.png")

    # Fig. B-5: wear accumulated per liner, and the three contributions.
    hs = h5["/history"]
    t = np.asarray(hs["time_s"])
    per = np.asarray(hs["per_segment_kg_per_m"])
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2))
    for k in range(per.shape[1]):
        a1.plot(t, per[:, k], lw=0.7)
    a1.set_xlabel("simulated time [s]")
    a1.set_ylabel("accumulated wear per liner [kg per m of length]")
    a1.set_title("Accumulated wear on every liner (thesis Fig. B-5)", fontsize=9)
    a2.stackplot(t, np.asarray(hs["centrifugal_kg_per_m"]), np.asarray(hs["gravitational_kg_per_m"]),
                 np.asarray(hs["impact_kg_per_m"]), labels=["abrasion, centrifugal", "abrasion, gravitational", "impact"])
    a2.set_xlabel("simulated time [s]")
    a2.set_ylabel("wear asked for by the laws [kg per m of length]")
    a2.set_title(f"Contributions (amplified); impact share {info.get('impact_fraction', 0):.1%}", fontsize=9)
    a2.legend(fontsize=8, loc="upper left")
    save(fig, out, "wear_history.png")

    # Recession rates along lifter 0 (calibrated, not amplified).
    rg = h5["/rates"]
    nodes, begin, R, segments = surface(h5, "/rates/surface")
    b, e = int(begin[0]), int(begin[1])
    fig, ax = plt.subplots(figsize=(8, 4))
    el = np.arange(b, e) - b
    for name, lab in (("centrifugal_m_s", "abrasion, centrifugal"), ("gravitational_m_s", "abrasion, gravitational"),
                      ("impact_m_s", "impact")):
        ax.plot(el, np.asarray(rg[name])[b:e] * 1e3 * 86400, label=lab)
    ax.set_xlabel("element number on liner 0 (anticlockwise)")
    ax.set_ylabel("recession rate [mm/day], not amplified")
    ax.set_title("Where the wear goes on liner 0 (last rates of the run)", fontsize=9)
    ax.legend(fontsize=8)
    save(fig, out, "wear_rates.png")
