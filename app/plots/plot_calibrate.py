"""Chart of `linerlife calibrate`: measured and fitted lifter profiles at the measured hours."""
import matplotlib.pyplot as plt
import numpy as np

from plot_common import lifter_frame, save

# every chart this kind of file may draw (a chart of an earlier run left in the folder under one of these
# names is removed: plot_common.commit_charts())
CHARTS = ("calibrate_profiles.png",)


def finite_datasets(h5):
    """The datasets drawn that must hold finite numbers (linerlife_plot.py checks them before drawing)."""
    g = h5["/calibrate"] if "/calibrate" in h5 else {}
    return [f"/calibrate/{k}/{d}" for k in g if k.startswith("profile_") for d in ("measured", "fitted")]


def draw(h5, out):
    R = float(h5["/surface"].attrs["shell_radius_m"])
    g = h5["/calibrate"]
    names = sorted((k for k in g if k.startswith("profile_")), key=lambda k: int(k.split("_")[1]))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for i, k in enumerate(names):
        p = g[k]
        mx, my = lifter_frame(np.asarray(p["measured"]), R, 0.0)
        fx, fy = lifter_frame(np.asarray(p["fitted"]), R, 0.0)
        ax.plot(mx, my, "o", ms=3, color=f"C{i}", label=f"measured {p.attrs['hours']:.0f} h")
        ax.plot(fx, fy, "-", color=f"C{i}", lw=1, label=f"fitted {p.attrs['hours']:.0f} h")
    ax.axhline(0.0, color="0.3", lw=0.8)  # the shell
    ax.set_aspect("equal")
    ax.set_xlabel("along the shell from the lifter centreline [m]")
    ax.set_ylabel("height above the shell, R - r [m]")
    ax.set_title(f"Calibration: RMS misfit {1000 * g.attrs['rms_m']:.2f} mm")
    ax.legend(fontsize=7)
    save(fig, out, "calibrate_profiles.png")
