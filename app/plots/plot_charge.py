"""Charts of `linerlife charge`: a snapshot of the charge with toe, shoulder
and centre of mass marked (in the style of thesis Appendix A), the forces on
one lifter over a revolution (thesis Figs. 4-21/4-22) and the layer speeds."""
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Circle, Wedge
from matplotlib.collections import PatchCollection

from plot_common import save, surface, surface_datasets

# every chart this kind of file may draw (a chart of an earlier run left in the folder under one of these
# names is removed: plot_common.commit_charts())
CHARTS = ("charge_snapshot.png", "lifter_forces.png", "layer_speeds.png")


def _attr(g, name, default=np.nan):
    return float(g.attrs[name]) if name in g.attrs else default


def _mark_angle(ax, R, deg, label, color):
    t = np.radians(deg)
    ax.plot([0, R * np.cos(t)], [0, R * np.sin(t)], "--", color=color, lw=1.2)
    ax.annotate(f"{label} {deg:.1f}°", (1.04 * R * np.cos(t), 1.04 * R * np.sin(t)), color=color, fontsize=9,
                ha="center", va="center", fontweight="bold")


def finite_datasets(h5):
    """The datasets drawn that must hold finite numbers (linerlife_plot.py checks them before drawing); the
    snapshot positions are NaN where a frame has fewer elements."""
    return surface_datasets("/surface") + ["/snapshots/liner_angle_rad"]


def draw(h5, out):
    nodes, begin, R, segments = surface(h5)
    g = h5["/charge"]
    model = g.attrs["model"]
    model = model.decode() if isinstance(model, bytes) else str(model)
    # the layer model's version (files of other models written before
    # 2026-12-07 carry the configuration's, which means nothing for them)
    variant = g.attrs.get("variant", "") if model == "layer" else ""
    variant = variant.decode() if isinstance(variant, bytes) else str(variant)
    toe, shoulder = _attr(g, "toe_deg"), _attr(g, "shoulder_deg")
    com_a, com_r = _attr(g, "com_angle_deg"), _attr(g, "com_radius_m")

    # 1. The charge.
    fig, ax = plt.subplots(figsize=(7, 7))
    t = np.linspace(0, 2 * np.pi, 721)
    if "/snapshots" in h5 and "liner_angle_rad" in h5["/snapshots"]:
        a = float(h5["/snapshots/liner_angle_rad"][-1])  # the liner has turned with the mill
        rot = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
        nodes = nodes @ rot.T
    closed = np.vstack([nodes, nodes[:1]])
    ax.fill(R * np.cos(t), R * np.sin(t), color="0.75", zorder=0)
    ax.fill(closed[:, 0], closed[:, 1], color="white", zorder=1)
    ax.plot(closed[:, 0], closed[:, 1], "-", color="0.3", lw=0.6, zorder=2)
    if "/snapshots" in h5:
        s = h5["/snapshots"]
        pos = np.asarray(s["position_m"])[-1]
        st = np.asarray(s["state"])[-1]
        rad = np.asarray(s["radius_m"])
        colors = {0: "#3b6fb6", 1: "#d1495b", 2: "#2e8b57"}
        names = {0: "en masse", 1: "in flight", 2: "sliding off a lifter"}
        for code in (0, 1, 2):
            sel = st == code
            if not np.any(sel):
                continue
            pc = PatchCollection([Circle(p, r) for p, r in zip(pos[sel], rad[sel])], facecolor=colors[code],
                                 edgecolor="none", alpha=0.9, zorder=3)
            ax.add_collection(pc)
            ax.plot([], [], "o", color=colors[code], label=names[code])
        version = f", version {variant}" if variant else ""
        title = f"{model} model{version}: charge after {float(s['time_s'][-1]):.1f} s"
    else:
        # the C-model's en-masse charge: the sector r_i < r < R, toe to shoulder
        ri = _attr(g, "inner_radius_m", 0.0)
        rot = g.attrs["rotation"]
        rot = rot.decode() if isinstance(rot, bytes) else str(rot)
        a0, a1 = (toe, shoulder + 360.0) if rot == "ccw" else (shoulder, toe)
        ax.add_patch(Wedge((0, 0), R, a0, a1, width=R - ri, facecolor="#3b6fb6", alpha=0.6, zorder=3,
                           label="en-masse charge (Morrell)"))
        title = f"{model} model (Morrell C-model)"
    _mark_angle(ax, R, toe, "toe", "#c0392b")
    _mark_angle(ax, R, shoulder, "shoulder", "#27ae60")
    ax.plot([com_r * np.cos(np.radians(com_a))], [com_r * np.sin(np.radians(com_a))], "*", color="gold", ms=18,
            mec="k", zorder=5, label=f"centre of mass {com_a:.1f}°, {com_r:.2f} m")
    ax.set_aspect("equal")
    ax.set_xlim(-1.15 * R, 1.15 * R)
    ax.set_ylim(-1.15 * R, 1.15 * R)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(f"{title}\nphi = {_attr(g, 'fraction_critical'):.3f} of critical, filling {_attr(g, 'filling'):.2f}, "
                 f"net power {_attr(g, 'net_power_kw'):.1f} kW", fontsize=10)
    ax.legend(loc="lower right", fontsize=8)
    save(fig, out, "charge_snapshot.png")

    # 2. Forces on lifter 0 over a revolution.
    if "/charge/lifter" in h5 and len(h5["/charge/lifter/angle_deg"]) > 0:
        lg = h5["/charge/lifter"]
        a = np.asarray(lg["angle_deg"])
        fig, ax = plt.subplots(figsize=(8, 4))
        ax.plot(a, np.asarray(lg["normal_force_n_per_m"]) / 1000.0, ".-", ms=3, label="normal (radial, outward)")
        ax.plot(a, np.asarray(lg["tangential_force_n_per_m"]) / 1000.0, ".-", ms=3,
                label="tangential (against the rotation)")
        ax.axvline(toe, color="#c0392b", ls="--", lw=1, label="toe")
        ax.axvline(shoulder, color="#27ae60", ls="--", lw=1, label="shoulder")
        ax.set_xlim(0, 360)
        ax.set_xlabel("angular position of the lifter [deg, anticlockwise from 3 o'clock]")
        ax.set_ylabel("force on the lifter [kN per m of length]")
        ax.set_title("Forces of the charge on one lifter (segment 0) over a revolution")
        ax.legend(fontsize=8)
        save(fig, out, "lifter_forces.png")

    # 3. Layer speeds.
    sp = np.asarray(h5["/charge/layer_speed_rpm"])
    if sp.size:
        fig, ax = plt.subplots(figsize=(6, 3.5))
        ax.plot(np.arange(1, sp.size + 1), sp, "o-")
        ax.set_xlabel("layer (1 = next to the liner)")
        ax.set_ylabel("layer speed [rpm]")
        ax.set_title("Layer speeds")
        save(fig, out, "layer_speeds.png")
