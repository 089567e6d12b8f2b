"""Chart of `linerlife compare`: liner life, power and direct liner impacts per case."""
import matplotlib.pyplot as plt
import numpy as np

from plot_common import save


def draw(h5, out):
    c = h5["/cases"]
    labels = c.attrs["labels"].split("\n")
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
    axes[1].legend(fontsize=8)
    axes[2].bar(x, direct, color="C3")
    axes[2].set_ylabel("direct liner impacts (mass share)")
    for a in axes:
        a.set_xticks(x)
        a.set_xticklabels(labels, rotation=30, ha="right", fontsize=8)
    fig.tight_layout()
    save(fig, out, "compare.png")
