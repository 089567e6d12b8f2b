"""Charts of `linerlife geometry`: one liner segment (with the thesis' lifter
grid, §5.6) and the whole ring."""
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Rectangle

from plot_common import lifter_frame, save, segment_chain, surface, surface_datasets

# every chart this kind of file may draw (a chart of an earlier run left in the folder under one of these
# names is removed: plot_common.commit_charts())
CHARTS = ("liner_segment.png", "liner_ring.png")


def finite_datasets(h5):
    """The datasets drawn that must hold finite numbers (linerlife_plot.py checks them before drawing)."""
    return surface_datasets("/surface") + ["/lifter_grid/fraction"]


def draw(h5, out):
    nodes, begin, R, segments = surface(h5)
    seg = 2 * np.pi / segments

    # One segment in the lifter's Cartesian frame (as thesis Fig. 5-12), grid
    # cells shaded by the share of material left.
    fig, ax = plt.subplots(figsize=(7, 4))
    chain = segment_chain(nodes, begin, 0)
    x, y = lifter_frame(chain, R, 0.0)
    t = np.linspace(-0.5 * seg, 0.5 * seg, 101)
    shell_x, shell_y = R * np.sin(t), R - R * np.cos(t)
    if "/lifter_grid" in h5:
        g = h5["/lifter_grid"]
        frac = np.asarray(g["fraction"])
        x0, y0, dx, dy = (float(g.attrs[k]) for k in ("x0_m", "y0_m", "dx_m", "dy_m"))
        ny, nx = frac.shape
        for j in range(ny):
            for i in range(nx):
                if frac[j, i] > 0:
                    ax.add_patch(Rectangle((x0 + i * dx, y0 + j * dy), dx, dy, linewidth=0,
                                           facecolor=plt.cm.Greys(0.25 + 0.6 * frac[j, i])))
    ax.fill(np.concatenate([x, shell_x[::-1]]), np.concatenate([y, shell_y[::-1]]), color="0.85", zorder=0,
            label="liner")
    ax.plot(x, y, "-", color="C3", lw=1.5, label="surface")
    ax.plot(x, y, ".", color="C3", ms=2)
    ax.plot(shell_x, shell_y, "k-", lw=1)
    ax.set_xlabel("x from the lifter centreline [m]")
    ax.set_ylabel("thickness above the shell [m]")
    ax.set_aspect("equal")
    ax.set_title(f"Liner segment 0 of {segments} (lifter grid shaded by material left)")
    ax.legend(loc="upper right", fontsize=8)
    save(fig, out, "liner_segment.png")

    # The whole ring in the mill frame.
    fig, ax = plt.subplots(figsize=(6, 6))
    closed = np.vstack([nodes, nodes[:1]])
    t = np.linspace(0, 2 * np.pi, 721)
    ax.fill(R * np.cos(t), R * np.sin(t), color="0.85", zorder=0)
    ax.fill(closed[:, 0], closed[:, 1], color="white", zorder=1)
    ax.plot(closed[:, 0], closed[:, 1], "-", color="C3", lw=0.8, zorder=2)
    ax.plot(R * np.cos(t), R * np.sin(t), "k-", lw=1)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(f"Liner ring: {segments} rows, shell diameter {2 * R:.3f} m")
    save(fig, out, "liner_ring.png")
