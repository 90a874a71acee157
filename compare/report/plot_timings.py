#!/usr/bin/env python3
"""Plot groundtruth benchmark rows: median ms per run and Mcell-iterations/s over grid size.

Usage: plot_timings.py ROWS.json OUT.png

ROWS.json is the "benchmarks" array of report.json (or a whole report.json). One line per
(algorithm, backend), one per peer library for peers' rows, log-log axes, the devices named in
the title. Rows whose numbers are null (non-finite in the run) are left out. Exits 3 with a
one-line reason when matplotlib is missing, 2 on bad input; compare/report/plots.cpp shows the
last line of output as the reason.
"""
import json
import sys

from helper_lifetime import end_with_parent
from collections import defaultdict


def load_rows(path):
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    rows = data["benchmarks"] if isinstance(data, dict) else data
    # The bandwidth probe (memory.copy) is one size, a reference for the table's floor column,
    # not a line over sizes.
    return [r for r in rows if r.get("median_ms") and r.get("size") and not r.get("note")
            and r.get("algorithm") != "memory.copy"]


def line_name(row):
    """The backend, or "peer: NAME" for a peer library's row."""
    return f"peer: {row['peer']}" if row.get("peer") else row["backend"]


def series_by_line(rows):
    """{(algorithm, backend or peer): [(size, median_ms, mcell_per_s), ...] sorted by size}."""
    lines = defaultdict(list)
    for r in rows:
        lines[(r["algorithm"], line_name(r))].append(
            (r["size"], r["median_ms"], r.get("mcell_iterations_per_s")))
    return {key: sorted(points) for key, points in sorted(lines.items())}


def devices_title(rows):
    by_backend = defaultdict(set)
    for r in rows:
        by_backend[r["backend"]].add(r.get("device") or "unknown device")
    return "\n".join(f"{backend}: {', '.join(sorted(devices))}" for backend, devices in sorted(by_backend.items()))


def plot(rows, out_path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    lines = series_by_line(rows)
    algorithms = sorted({algorithm for algorithm, _ in lines})
    colours = {algorithm: plt.get_cmap("tab20")(i % 20) for i, algorithm in enumerate(algorithms)}
    styles = {"gpu": "-o", "cpu": "--s"}  # anything else (published figures, peers): dotted, own marker
    # Three legend columns, two when a label is long (peers name their library and function).
    longest_label = max(len(f"{algorithm} ({backend})") for algorithm, backend in lines)
    legend_columns = 3 if longest_label <= 55 else 2
    legend_rows = (len(lines) + legend_columns - 1) // legend_columns
    legend_height = 0.3 + 0.2 * legend_rows  # inches
    height = 5.0 + legend_height
    fig, (time_axis, rate_axis) = plt.subplots(1, 2, figsize=(12, height))
    other_markers = [":^", ":v", ":D", ":x", ":P"]  # one per published or peer line of an algorithm
    others_drawn = defaultdict(int)
    for (algorithm, backend), points in lines.items():
        style = styles.get(backend)
        if style is None:
            style = other_markers[others_drawn[algorithm] % len(other_markers)]
            others_drawn[algorithm] += 1
        colour = colours[algorithm]
        label = f"{algorithm} ({backend})"
        sizes = [p[0] for p in points]
        time_axis.plot(sizes, [p[1] for p in points], style, color=colour, label=label)
        rated = [p for p in points if p[2] is not None and p[2] > 0]
        rate_axis.plot([p[0] for p in rated], [p[2] for p in rated], style, color=colour)

    time_axis.set(xscale="log", yscale="log", xlabel="side n (n × n cells; n³ voxels for 3-D rows)", ylabel="median ms per run",
                  title="Time per run (lower is better)")
    rate_axis.set(xscale="log", yscale="log", xlabel="side n (n × n cells; n³ voxels for 3-D rows)", ylabel="Mcell-iterations / s (M voxels / s)",
                  title="Throughput (higher is better)")
    # The measured sides as the x ticks, in plain numbers, and decades only on the y axes: matplotlib's
    # labelled minor ticks of a log axis spanning under a decade overlapped into an unreadable row.
    from matplotlib.ticker import FixedLocator, LogLocator, NullFormatter
    sides = sorted({point[0] for points in lines.values() for point in points})
    if len(sides) > 10:
        sides = sides[::(len(sides) + 9) // 10]
    for axis in (time_axis, rate_axis):
        axis.grid(True, which="both", alpha=0.3)
        axis.xaxis.set_major_locator(FixedLocator(sides))
        axis.set_xticklabels([str(side) for side in sides])
        axis.xaxis.set_minor_formatter(NullFormatter())
        axis.yaxis.set_major_locator(LogLocator(base=10, numticks=12))
        axis.yaxis.set_minor_formatter(NullFormatter())
    # One legend for both plots, below them, so that it covers no line.
    fig.legend(loc="lower center", ncol=legend_columns, fontsize="small")
    fig.subplots_adjust(left=0.07, right=0.98, wspace=0.25, top=1.0 - 0.9 / height,
                        bottom=(legend_height + 0.6) / height)
    fig.suptitle(devices_title(rows), fontsize="medium")
    fig.savefig(out_path, dpi=100)


def main(argv):
    if len(argv) != 3:
        print("usage: plot_timings.py ROWS.json OUT.png", file=sys.stderr)
        return 2
    try:
        import matplotlib  # noqa: F401
    except ImportError as e:
        print(f"matplotlib is not available to {sys.executable}: {e}", file=sys.stderr)
        return 3
    try:
        rows = load_rows(argv[1])
    except (OSError, ValueError, KeyError, TypeError) as e:
        print(f"cannot read benchmark rows from {argv[1]}: {e}", file=sys.stderr)
        return 2
    if not rows:
        print("no benchmark rows with finite times", file=sys.stderr)
        return 2
    plot(rows, argv[2])
    return 0


if __name__ == "__main__":
    end_with_parent()
    sys.exit(main(sys.argv))
