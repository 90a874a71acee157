#!/usr/bin/env python3
"""Draw an x-y plot for a groundtruth report.

Usage: plot_series.py PLOT.json OUT.png

PLOT.json: {"title", "x_label", "y_label", "log_x", "log_y",
            "series": [{"label", "x": [...], "y": [...], "dashed": bool, "group": str}],
            "x_ticks": [[x, "label"], ...] (optional: labelled ticks, e.g. revisions)}
           or {"panels": [PLOT, ...]}: the plots side by side in one figure.
Series with the same non-empty group share a colour (a measurement beside its twin or its bound);
the others get one each; the legend stands beside the axes of a plot alone and under each axes of
panels side by side (beside them it squeezed each panel to a sliver), never over the data. Points carry
markers only where there are few of them (up to 40).
Non-finite or (on a log axis) non-positive points are left out. Exits 3 with a one-line reason
when matplotlib is missing, 2 on bad input; compare/report/plots.cpp shows the last line.
"""
import json
import math
import sys

from helper_lifetime import end_with_parent


def usable(x, y, log_x, log_y):
    if x is None or y is None or not math.isfinite(x) or not math.isfinite(y):
        return False
    return (not log_x or x > 0) and (not log_y or y > 0)


def draw_panel(plot, axes, plt, legend_below):
    palette = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    colours = {}
    for series in plot["series"]:
        key = series.get("group") or series["label"]
        colours.setdefault(key, palette[len(colours) % len(palette)])
        points = [(x, y) for x, y in zip(series["x"], series["y"])
                  if usable(x, y, plot["log_x"], plot["log_y"])]
        if not points:
            continue
        xs, ys = zip(*points)
        line = "--" if series.get("dashed") else "-"
        marker = "o" if len(points) <= 40 and not series.get("dashed") else ""
        # An unlabelled series (the only line of a titled plot) stays out of the legend.
        axes.plot(xs, ys, line + marker, color=colours[key], label=series["label"] or None, markersize=4)
    axes.set(xlabel=plot["x_label"], ylabel=plot["y_label"], title=plot["title"],
             xscale="log" if plot["log_x"] else "linear", yscale="log" if plot["log_y"] else "linear")
    if plot.get("x_ticks"):
        axes.set_xticks([tick[0] for tick in plot["x_ticks"]])
        labels = [tick[1] for tick in plot["x_ticks"]]
        long_labels = max(len(label) for label in labels) > 6
        axes.set_xticklabels(labels, rotation=30 if long_labels else 0, ha="right" if long_labels else "center",
                             fontsize="x-small" if long_labels else "small")
    axes.grid(True, which="both", alpha=0.3)
    # Beside or under the axes, never over the data (a history's or a ledger's lines fill the frame).
    if axes.get_legend_handles_labels()[0]:
        if legend_below:
            entries = len(axes.get_legend_handles_labels()[0])
            axes.legend(fontsize="small", loc="upper center", bbox_to_anchor=(0.5, -0.2), borderaxespad=0.0,
                        ncol=2 if entries > 6 else 1)
        else:
            axes.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)


def main(argv):
    if len(argv) != 3:
        print("usage: plot_series.py PLOT.json OUT.png")
        return 2
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as error:
        print(f"matplotlib is not available: {error}")
        return 3
    try:
        with open(argv[1], encoding="utf-8") as f:
            plot = json.load(f)
        panels = plot["panels"] if "panels" in plot else [plot]
        figure, all_axes = plt.subplots(1, len(panels), figsize=(8 if len(panels) == 1 else 5 * len(panels), 4),
                                        dpi=100, squeeze=False)
        for panel, axes in zip(panels, all_axes[0]):
            draw_panel(panel, axes, plt, legend_below=len(panels) > 1)
        if len(panels) > 1:
            # tight_layout would count the legends under the axes and squash the axes to make room;
            # savefig's tight box takes them in instead.
            figure.subplots_adjust(left=0.06, right=0.98, wspace=0.3)
        else:
            figure.tight_layout()
        figure.savefig(argv[2], bbox_inches="tight")  # with the legends beside the axes
    except (OSError, KeyError, TypeError, ValueError) as error:
        print(f"cannot draw the plot: {error}")
        return 2
    return 0


if __name__ == "__main__":
    end_with_parent()
    sys.exit(main(sys.argv))
