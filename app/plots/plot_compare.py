"""Chart of `linerlife compare`: liner life, power and direct liner impacts per case."""
import matplotlib.pyplot as plt
import numpy as np

from plot_common import save

# every chart this kind of file may draw (a chart of an earlier run left in the folder under one of these
# names is removed: plot_common.commit_charts())
CHARTS = ("compare.png",)


def vary_keys(labels):
    """The keys of --vary cases read off their labels ("sec.key=v sec2.key2=w"), if every case sets the same
    ones in the same order (a compare.h5 written before the varied_keys attribute)."""
    keys = None
    for label in labels:
        parts = [p.split("=", 1) for p in label.split(" ")]
        if not all(len(p) == 2 and "." in p[0] for p in parts):
            return None
        k = [p[0] for p in parts]
        if keys is not None and k != keys:
            return None
        keys = k
    return keys


def finite_datasets(h5):
    """The datasets drawn that must hold finite numbers (linerlife_plot.py checks them before drawing)."""
    return ["/cases/operating_hours"]


def draw(h5, out):
    c = h5["/cases"]
    labels = c.attrs["labels"].split("\n")
    xlabel = ""
    if "varied_keys" in c.attrs:  # --vary: the values on the ticks, the keys under the axis
        keys = c.attrs["varied_keys"].split("\n")
        labels = [" / ".join(c[str(i)].attrs["varied_values"].split("\n")) for i in range(len(labels))]
        xlabel = " / ".join(k.split(".", 1)[1] for k in keys)
    else:
        keys = vary_keys(labels)
        if keys:
            labels = [" / ".join(p.split("=", 1)[1] for p in x.split(" ")) for x in labels]
            xlabel = " / ".join(k.split(".", 1)[1] for k in keys)
    hours = np.asarray(c["operating_hours"])
    mean_p = np.asarray(c["mean_net_power_kw"])
    end_p = np.asarray(c["final_net_power_kw"])
    direct = np.asarray(c["mean_direct_impact_fraction"])
    x = np.arange(len(labels))
    fig, axes = plt.subplots(1, 3, figsize=(12, 4))
    axes[0].bar(x, hours, color="C0")
    axes[0].set_ylabel("liner life [operating h]")
    axes[1].bar(x - 0.2, mean_p, 0.4, label="mean over the life")
    axes[1].bar(x + 0.2, end_p, 0.4, label="end of life")
    axes[1].set_ylabel("net power [kW]")
    top = np.nanmax(np.concatenate([mean_p, end_p])) if len(mean_p) else 0.0
    if np.isfinite(top) and top > 0:
        axes[1].set_ylim(0, 1.3 * top)  # room for the legend above the bars
    axes[1].legend(fontsize=8, loc="upper right")
    axes[2].bar(x, direct, color="C3")
    axes[2].set_ylabel("share of landings on the liner")
    for a in axes:
        a.set_xticks(x)
        a.set_xticklabels(labels, rotation=30, ha="right", fontsize=8)
        if xlabel:
            a.set_xlabel(xlabel, fontsize=8)
    fig.tight_layout()
    save(fig, out, "compare.png")
