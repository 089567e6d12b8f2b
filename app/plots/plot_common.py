"""Helpers shared by the chart modules."""
import os

import numpy as np


class NotFinite(Exception):
    """A dataset the charts draw holds a NaN or an infinite value: the file is damaged."""

    def __init__(self, path, detail):
        super().__init__(f"{path}: {detail}")
        self.path, self.detail = path, detail


# No quantity a results file draws comes near this (lengths of metres, hours
# up to 1e5, tonnes up to 1e9); a node at 1e155 m made matplotlib fail with a
# singular matrix and a traceback (a review, 2026-12-04).
LARGEST_PLAUSIBLE = 1e12


def check_finite(h5, paths):
    """Raises NotFinite for the first of the datasets `paths` that holds a value that is not a finite number,
    or one beyond +-LARGEST_PLAUSIBLE. Datasets the file lacks are left to draw(), whose KeyError names them."""
    for path in paths:
        if path not in h5:
            continue
        v = np.asarray(h5[path][()])
        if v.dtype.kind not in "fc":  # integers and strings are always finite
            continue
        with np.errstate(invalid="ignore"):
            huge = np.abs(v) > LARGEST_PLAUSIBLE
        for bad, what in ((~np.isfinite(v), "are not finite numbers"),
                          (huge, f"are beyond +-{LARGEST_PLAUSIBLE:g}, which no results file holds")):
            if bad.any():
                first = tuple(int(i) for i in np.argwhere(bad)[0])
                where = ", ".join(str(i) for i in first)
                raise NotFinite(path, f"{int(bad.sum())} of {v.size} values {what} (the first, {v[first]:g}, at "
                                      f"[{where}])")


def surface_datasets(group):
    """The datasets of a liner surface group the charts draw (the nodes)."""
    return [f"{group}/nodes"]


# The charts drawn so far, as (temporary, final) paths: save() writes each
# under a temporary name and commit_charts() renames them all once every chart
# of the file is drawn, so that a file that fails part-way (a dataset missing
# from its third chart) leaves none of them (a review, 2026-12-06: two of three
# charts were left, with exit 2 saying the file was damaged).
_pending = []


def save(fig, out_dir, name):
    """Draws fig into a temporary file for out_dir/name; commit_charts() gives it its name."""
    final = os.path.join(out_dir, name)
    tmp = os.path.join(out_dir, f".{name}.tmp.{os.getpid()}.png")
    _pending.append((tmp, final))
    try:
        fig.savefig(tmp, dpi=130, bbox_inches="tight")
    except OSError as e:  # name the chart, not its temporary
        raise OSError(e.errno, e.strerror, final) from e
    finally:
        import matplotlib.pyplot as plt

        plt.close(fig)


def discard_charts():
    """Removes the temporaries of the charts drawn so far (a kill -9 still can leave them: the next run's
    OutputDir::prepare() removes those of dead processes)."""
    for tmp, _ in _pending:
        try:
            os.remove(tmp)
        except OSError:
            pass
    _pending.clear()


def commit_charts(out_dir, charts=()):
    """Gives every chart drawn its name. A chart whose name a folder holds is refused before any is renamed
    (OSError naming it), so the charts are written all or none. Of `charts`, the names a kind of file may draw,
    those not drawn this time are removed from out_dir: a chart an earlier run left there (the layer model's
    lifter_forces.png beside an empirical charge.h5) would be read as this file's (a review, 2026-12-06)."""
    try:
        for _, final in _pending:
            if os.path.isdir(final):
                raise IsADirectoryError(21, "Is a directory", final)
        drawn = {os.path.basename(final) for _, final in _pending}
        for tmp, final in _pending:
            os.replace(tmp, final)
        for name in charts:
            old = os.path.join(out_dir, name)
            if name not in drawn and os.path.isfile(old):
                os.remove(old)
    finally:
        discard_charts()


def surface(h5, group="/surface"):
    """Nodes (n x 2), segment_begin, shell radius and segment count of a surface group."""
    g = h5[group]
    return (np.asarray(g["nodes"]), np.asarray(g["segment_begin"]), float(g.attrs["shell_radius_m"]),
            int(g.attrs["segments"]))


def segment_chain(nodes, begin, k):
    """Nodes of segment k including the first node of the next segment."""
    n = len(nodes)
    idx = list(range(begin[k], begin[k + 1])) + [begin[k + 1] % n]
    return nodes[idx]


def unrolled(chain, R, centre, seg_angle):
    """Mill-frame points -> (x along the shell from the segment start, thickness), as in thesis Fig. 5-12."""
    th = np.arctan2(chain[:, 1], chain[:, 0]) - centre + 0.5 * seg_angle
    th = (th + np.pi) % (2 * np.pi) - np.pi
    return th * R, R - np.hypot(chain[:, 0], chain[:, 1])


def lifter_frame(chain, R, centre):
    """Mill-frame points -> the shell unrolled about the lifter: x the arc
    length along the shell (R times the angle, anticlockwise) from the lifter
    centreline, y the height above the shell, R - |p| (the thickness the
    criteria read). A Cartesian frame at the centreline put the plate at the
    segment's edges about 6 mm too high on a 10 m mill (R - r cos(angle))."""
    c, s = np.cos(centre), np.sin(centre)
    xr = c * chain[:, 0] + s * chain[:, 1]
    yr = -s * chain[:, 0] + c * chain[:, 1]
    return R * np.arctan2(yr, xr), R - np.hypot(xr, yr)
