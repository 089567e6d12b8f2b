"""Charts of `linerlife geometry`: one liner segment (with the thesis' lifter
grid, §5.6) and the whole ring."""
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection
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

    # One segment with the shell unrolled about the lifter (x the arc length
    # along the shell from the centreline, y the height above it, R - r: the
    # frame of docs/profile-csv.md and thesis Fig. 5-12, the one the forecast
    # and calibrate charts draw), grid cells shaded by the share of material
    # left. The shell is y = 0 in this frame. It was drawn as the Cartesian arc
    # R - R cos(t) under the unrolled surface, so it rose 12 mm at the segment
    # edges on the 5 m ball mill and its 65 mm plate looked 53 mm thick there
    # (a review; fixed 2026-12-07).
    fig, ax = plt.subplots(figsize=(7, 4))
    chain = segment_chain(nodes, begin, 0)
    x, y = lifter_frame(chain, R, 0.0)
    half = 0.5 * seg * R  # the segment's edges, where its first and last nodes lie
    shell_x, shell_y = np.array([-half, half]), np.zeros(2)
    if "/lifter_grid" in h5:
        g = h5["/lifter_grid"]
        frac = np.asarray(g["fraction"])
        x0, y0, dx, dy = (float(g.attrs[k]) for k in ("x0_m", "y0_m", "dx_m", "dy_m"))
        ny, nx = frac.shape
        # The grid is laid out in the thesis' Cartesian frame at the lifter
        # centreline (geometry/lifter_grid.h: x tangential, y radial there):
        # its corners go into the unrolled frame through the mill frame, a
        # point (u, v) there being (R - v, u) about segment 0's centreline (the
        # 0.0 of lifter_frame above). Drawn unmapped, the cells at the lifter's
        # base sat 2.5 mm above the surface they shade on the 5 m ball mill.
        cells, shades = [], []
        for j in range(ny):
            for i in range(nx):
                if frac[j, i] > 0:
                    u = x0 + dx * np.array([i, i + 1, i + 1, i])
                    v = y0 + dy * np.array([j, j, j + 1, j + 1])
                    cells.append(np.column_stack(lifter_frame(np.column_stack([R - v, u]), R, 0.0)))
                    shades.append(plt.cm.Greys(0.25 + 0.6 * frac[j, i]))
        # Edged in their own shade: mapped, the cells are no longer snapped to
        # the pixels as the rectangles were, and unedged they left light seams.
        grid = PolyCollection(cells, facecolors=shades, edgecolors=shades, linewidths=0.3)
        ax.add_collection(grid)
        # The grid's bottom row lies along the tangent to the shell at the
        # centreline, so away from it those cells reach below the shell (2.4 mm
        # at the grid's sides on the ball mill), where there is no material:
        # their shading is cut off at the shell (after add_collection, which
        # would put the axes' clip in its place).
        # (A clip reaching past the axes widens the saved chart to it:
        # bbox_inches="tight" takes it as the grid's extent.)
        grid.set_clip_path(Rectangle((-half, 0.0), 2 * half, y0 + ny * dy, transform=ax.transData))
    ax.fill(np.concatenate([x, shell_x[::-1]]), np.concatenate([y, shell_y[::-1]]), color="0.85", zorder=0,
            label="liner")
    ax.plot(x, y, "-", color="C3", lw=1.5, label="surface")
    ax.plot(x, y, ".", color="C3", ms=2)
    ax.plot(shell_x, shell_y, "k-", lw=1)
    ax.set_xlabel("along the shell from the lifter centreline [m]")
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
