#!/usr/bin/env python3
"""Plot a sweep on log-log axes: python3 tools/plot_sweep.py SWEEPDIR... [--x Re --y Np]

Reads SWEEPDIR/sweep.csv (written by `partimix sweep`, docs/sweeps.md), keeps the rows where
both columns hold positive numbers, fits the least-squares line of log10(y) on log10(x), and
writes SWEEPDIR/<y>_<x>.png in lower case (np_re.png by default): the points and the fitted
line, its slope in the legend. Prints "slope = <value>" on stdout. A column is named as in the
header, with or without a unit after a space ("Np" matches "Np [-]"). Several sweep folders
draw into one plot, each with its own fit and legend label (--labels, default the folders'
names), one "slope = " line each, written to --out (default: in the first folder). Exit codes:
0 success, 1 plotting failed, 2 bad input (no sweep.csv, a missing column, fewer than two
usable rows, all x equal, or as many labels as folders not given).

Needs matplotlib and numpy (Debian: python3-matplotlib, python3-numpy for /usr/bin/python3).
"""

import argparse
import csv
import math
import re
import sys
from pathlib import Path

EXIT_FAILED = 1
EXIT_BAD_INPUT = 2
HEADER_CELL = re.compile(r"^\s*(.*?)(?:\s+\[[^\[\]]*\])?\s*$")


class BadInput(Exception):
    """The sweep cannot be plotted because of what is (not) in SWEEPDIR."""


def column_name(cell):
    """'Np [-]' -> 'Np'; a cell without brackets is its own name."""
    return HEADER_CELL.match(cell).group(1)


def read_table(path):
    """The header cells and the rows (lists of strings) of a CSV file."""
    if not path.is_file():
        raise BadInput(f"{path} does not exist (is this a partimix sweep folder?)")
    with path.open(newline="") as handle:
        lines = [cells for cells in csv.reader(handle) if cells]
    if not lines:
        raise BadInput(f"{path} is empty")
    return lines[0], lines[1:]


def column_index(header, name, path):
    names = [column_name(cell) for cell in header]
    if name not in names:
        raise BadInput(f"{path} has no column '{name}'; its columns: {', '.join(names)}")
    return names.index(name)


def positive_number(text):
    """The cell as a float if it is a positive finite number, else None."""
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) and value > 0 else None


def read_pairs(path, x_name, y_name):
    """The (x, y) pairs of the rows where both are positive numbers."""
    header, rows = read_table(path)
    x_at = column_index(header, x_name, path)
    y_at = column_index(header, y_name, path)
    pairs = []
    for row in rows:
        cells = row + [""] * (len(header) - len(row))
        x, y = positive_number(cells[x_at]), positive_number(cells[y_at])
        if x is not None and y is not None:
            pairs.append((x, y))
    if len(pairs) < 2:
        raise BadInput(f"{path}: fewer than two rows with positive {x_name} and {y_name}")
    if len({x for x, _ in pairs}) < 2:
        raise BadInput(f"{path}: every row has the same {x_name}; no slope to fit")
    return pairs


def fit_power_law(pairs):
    """Slope and intercept of the least-squares line log10(y) = slope log10(x) + intercept."""
    import numpy as np

    log_x = np.log10([x for x, _ in pairs])
    log_y = np.log10([y for _, y in pairs])
    slope, intercept = np.polyfit(log_x, log_y, 1)
    return float(slope), float(intercept)


def load_pyplot():
    """matplotlib.pyplot on the Agg backend (no display needed)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def draw(series, x_name, y_name, path):
    """series: (label, pairs, fit) per sweep; one colour each, points and fitted line."""
    import numpy as np

    plt = load_pyplot()
    figure, axes = plt.subplots(figsize=(6.4, 4.8))
    for label, pairs, (slope, intercept) in series:
        xs = np.array(sorted(x for x, _ in pairs))
        points = axes.loglog([x for x, _ in pairs], [y for _, y in pairs], "o", label=label)
        axes.loglog(xs, 10.0**intercept * xs**slope, "-", color=points[0].get_color(),
                    label=f"fit: slope {slope:.4f} ({y_name} = {10.0**intercept:.4g} "
                    f"{x_name}^{slope:.4f})")
    axes.set_xlabel(x_name)
    axes.set_ylabel(y_name)
    axes.grid(True, which="both", alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def main(argv):
    parser = argparse.ArgumentParser(description="Log-log plot of SWEEPDIR/sweep.csv with a "
                                     "fitted power law.")
    parser.add_argument("sweepdirs", type=Path, nargs="+", help="partimix sweep folders")
    parser.add_argument("--x", default="Re", help="column on the x axis (default: Re)")
    parser.add_argument("--y", default="Np", help="column on the y axis (default: Np)")
    parser.add_argument("--labels", nargs="+", help="one legend label per sweep folder")
    parser.add_argument("--out", type=Path, help="the PNG file (default: in the first folder)")
    args = parser.parse_args(argv)
    labels = args.labels or (["runs"] if len(args.sweepdirs) == 1
                             else [folder.name for folder in args.sweepdirs])
    try:
        if len(labels) != len(args.sweepdirs):
            raise BadInput(f"{len(labels)} labels for {len(args.sweepdirs)} sweep folders")
        all_pairs = [read_pairs(folder / "sweep.csv", args.x, args.y)
                     for folder in args.sweepdirs]
    except BadInput as error:
        print(f"plot_sweep: {error}", file=sys.stderr)
        return EXIT_BAD_INPUT
    plot = args.out or args.sweepdirs[0] / re.sub(r"[^a-z0-9_.-]", "_",
                                                  f"{args.y}_{args.x}.png".lower())
    try:
        series = [(label, pairs, fit_power_law(pairs)) for label, pairs in zip(labels, all_pairs)]
        draw(series, args.x, args.y, plot)
    except ImportError as error:
        print(f"plot_sweep: {error}; install matplotlib and numpy for {sys.executable} "
              "(Debian: python3-matplotlib python3-numpy)", file=sys.stderr)
        return EXIT_FAILED
    for _, _, (slope, _) in series:
        print(f"slope = {slope:.10g}")
    points = sum(len(pairs) for pairs in all_pairs)
    print(f"plot_sweep: {points} points, wrote {plot}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
