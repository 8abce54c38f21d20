#!/usr/bin/env python3
"""Overlay one column of several runs: python3 tools/plot_compare.py OUTDIR... --y xi --out F.png

Reads OUTDIR/series.csv of every run (the format of tools/plot_series.py), and draws the column
named by --y against time, one line per run, labelled with --labels (default: the folders'
names), into the PNG file --out. Exit codes: 0 success, 1 plotting failed, 2 bad input (a run
without series.csv, a run without the column, or as many labels as runs not given).

Needs matplotlib and numpy (Debian: python3-matplotlib, python3-numpy for /usr/bin/python3).
"""

import argparse
import sys
from pathlib import Path

from plot_series import BadInput, load_pyplot, read_series, save, time_index

EXIT_FAILED = 1
EXIT_BAD_INPUT = 2


def read_column(outdir, name):
    """(time, values, time column, column) of the column `name` in outdir/series.csv."""
    path = outdir / "series.csv"
    columns, data = read_series(path)
    names = [column_name for column_name, _ in columns]
    if name not in names:
        raise BadInput(f"{path} has no column '{name}'; its columns: {', '.join(names)}")
    t_index = time_index(columns)
    at = names.index(name)
    return data[t_index], data[at], columns[t_index], columns[at]


def draw(runs, labels, path, title):
    plt = load_pyplot()
    figure, axes = plt.subplots(figsize=(6.4, 4.2))
    for (time, values, _, _), label in zip(runs, labels):
        axes.plot(time, values, label=label)
    axes.set_xlabel("{} [{}]".format(*runs[0][2]))
    axes.set_ylabel("{} [{}]".format(*runs[0][3]))
    if title:
        axes.set_title(title)
    axes.grid(True, alpha=0.3)
    axes.legend()
    save(plt, figure, path, dpi=110)


def main(argv):
    parser = argparse.ArgumentParser(description="Overlay one series.csv column of several runs.")
    parser.add_argument("outdirs", type=Path, nargs="+", help="partimix output folders")
    parser.add_argument("--y", required=True, help="the column to draw against time")
    parser.add_argument("--out", type=Path, required=True, help="the PNG file to write")
    parser.add_argument("--labels", nargs="+", help="one legend label per run")
    parser.add_argument("--title", default="", help="the plot's title")
    args = parser.parse_args(argv)
    labels = args.labels or [outdir.name for outdir in args.outdirs]
    try:
        if len(labels) != len(args.outdirs):
            raise BadInput(f"{len(labels)} labels for {len(args.outdirs)} runs")
        runs = [read_column(outdir, args.y) for outdir in args.outdirs]
    except BadInput as error:
        print(f"plot_compare: {error}", file=sys.stderr)
        return EXIT_BAD_INPUT
    try:
        draw(runs, labels, args.out, args.title)
    except ImportError as error:
        print(f"plot_compare: {error}; install matplotlib and numpy for {sys.executable} "
              "(Debian: python3-matplotlib python3-numpy)", file=sys.stderr)
        return EXIT_FAILED
    print(f"plot_compare: {len(runs)} runs, wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
