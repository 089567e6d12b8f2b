"""Charts of `linerlife forecast`: the profile evolution of one lifter (like
thesis Fig. 5-13), the lifter metrics along the life, and the charge
indicators along the life."""
import matplotlib.pyplot as plt
import numpy as np

from plot_common import lifter_frame, save

# every chart this kind of file may draw (a chart of an earlier run left in the folder under one of these
# names is removed: plot_common.commit_charts()); app/plots.h's kForecastCharts repeats them for a failed
# run, which removes them without Python (a test checks the two agree)
CHARTS = ("forecast_profiles.png", "forecast_lifter.png", "forecast_charge.png")


def finite_datasets(h5):
    """The datasets drawn that must hold finite numbers (linerlife_plot.py checks them before drawing). The other
    history columns may be NaN (a face angle where the liner has no lifter, a power the model does not give)."""
    return ["/forecast/profiles/nodes", "/forecast/profiles/hours", "/forecast/history/hours",
            "/forecast/history/min_thickness_m", "/forecast/history/liner_mass_kg_per_m"]


def config_table(h5):
    """The run's configuration (its /config) as a dict, {} where it cannot be read."""
    try:
        import tomllib
        text = h5["/config"][()]
        return tomllib.loads(text.decode() if isinstance(text, bytes) else text)
    except Exception:  # an older Python without tomllib, or a /config it cannot read
        return {}


def charge_model_name(h5):
    """"the layer model V-1.2", "the empirical model", "the dem model" from the run's [model], "the charge model"
    where it cannot be read."""
    m = config_table(h5).get("model", {})
    name = m.get("charge", "charge")
    return f"the layer model V-{m['variant']}" if name == "layer" and "variant" in m else f"the {name} model"


def criteria(h5):
    """The [forecast] relining criteria of the run (its /config), {} where it cannot be read."""
    f = config_table(h5).get("forecast", {})
    try:
        return {k: float(f[k]) for k in ("min_lifter_height_m", "min_plate_thickness_m", "max_face_angle_leading_deg")
                if k in f}
    except (TypeError, ValueError):  # a value that is not a number: no lines
        return {}


def draw(h5, out):
    f = h5["/forecast"]
    R = float(h5["/surface"].attrs["shell_radius_m"])
    hist = f["history"]

    def H(key):  # a history column as a numpy array (h5py datasets do not take 2D indexing)
        return np.asarray(hist[key])

    hours = np.asarray(hist["hours"])
    date = f.attrs["relining_date"]  # "" when no criterion was reached
    crit = f.attrs["criterion"]
    end = f.attrs["end_date"] if "end_date" in f.attrs else date
    method = f.attrs["method"]

    # Profile evolution: every snapshot in the lifter's frame, coloured by time.
    p = f["profiles"]
    nodes, offset, ph = np.asarray(p["nodes"]), np.asarray(p["offset"]), np.asarray(p["hours"])
    fig, ax = plt.subplots(figsize=(7, 4.5))
    cmap = plt.cm.viridis
    step = max(1, len(ph) // 12)
    picks = list(range(0, len(ph), step))
    if picks[-1] != len(ph) - 1:
        picks.append(len(ph) - 1)
    for i in picks:
        x, y = lifter_frame(nodes[offset[i]:offset[i + 1]], R, 0.0)
        ax.plot(x, y, "-", color=cmap(ph[i] / max(ph[-1], 1e-9)), lw=1.2 if i in (0, len(ph) - 1) else 0.7,
                label=f"{ph[i]:.0f} h" if i in (picks[0], picks[len(picks) // 2], picks[-1]) else None)
    ax.plot([x.min(), x.max()], [0.0, 0.0], "k-", lw=1)  # the shell (y = 0 in the unrolled frame)
    ax.set_aspect("equal")
    ax.set_xlabel("along the shell from the lifter centreline [m]")
    ax.set_ylabel("height above the shell, R - r [m]")
    ax.set_title(f"Lifter profile over the life ({method}): ends {end}, {crit}")
    ax.legend(fontsize=8)
    save(fig, out, "forecast_profiles.png")

    # Lifter metrics against operating hours.
    fig, axes = plt.subplots(2, 2, figsize=(9, 6), sharex=True)
    axes[0, 0].plot(hours, 1000 * np.asarray(hist["lifter_height_m"]))
    axes[0, 0].set_ylabel("lifter height [mm]")
    axes[0, 1].plot(hours, H("face_angle_leading_deg"), label="leading")
    axes[0, 1].plot(hours, H("face_angle_trailing_deg"), label="trailing")
    axes[0, 1].set_ylabel("face angle from radial [deg]")
    axes[0, 1].legend(fontsize=8)
    axes[1, 0].plot(hours, 1000 * np.asarray(hist["min_thickness_m"]))
    axes[1, 0].set_ylabel("thinnest point [mm]")
    axes[1, 1].plot(hours, np.asarray(hist["liner_mass_kg_per_m"]) / 1000)
    axes[1, 1].set_ylabel("liner mass [t per m]")
    # the relining criteria of the run's configuration, dashed
    limits = criteria(h5)
    for ax, key, scale in ((axes[0, 0], "min_lifter_height_m", 1000), (axes[0, 1], "max_face_angle_leading_deg", 1),
                           (axes[1, 0], "min_plate_thickness_m", 1000)):
        if key in limits:
            ax.axhline(scale * limits[key], color="C3", ls="--", lw=0.8, label="relining criterion")
    axes[1, 0].legend(fontsize=8)
    for a in axes[1]:
        a.set_xlabel("operating hours")
    fig.suptitle(f"Liner along the life: relining {date} ({crit})" if date
                 else f"Liner along the life: no criterion reached by {end} ({crit})")
    fig.tight_layout()
    save(fig, out, "forecast_lifter.png")

    # Charge indicators against operating hours.
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.5))
    axes[0].plot(hours, H("net_power_kw"))
    axes[0].set_ylabel("net power [kW]")
    axes[1].plot(hours, H("toe_deg"), label="toe")
    axes[1].plot(hours, H("shoulder_deg"), label="shoulder")
    axes[1].set_ylabel("angle [deg, mill frame]")
    axes[1].legend(fontsize=8)
    axes[2].plot(hours, H("direct_impact_fraction"), label="direct liner impacts")
    axes[2].plot(hours, H("impact_fraction"), label="impact share of wear")
    axes[2].set_ylabel("fraction")
    axes[2].legend(fontsize=8)
    for a in axes:
        a.set_xlabel("operating hours")
    # the power is the charge model's on the worn profile, not a motor load
    # (the same note as the run's caveat, app/common.cpp worn_power_caveat())
    model = charge_model_name(h5)
    fig.suptitle(f"Charge along the life by {model} (the power is the model's net power, not the mill motor's "
                 "load)", fontsize=10)
    fig.tight_layout()
    save(fig, out, "forecast_charge.png")
