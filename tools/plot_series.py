#!/usr/bin/env python3
"""Plot a run's time series: python3 tools/plot_series.py OUTDIR

Reads OUTDIR/series.csv (header "name [unit]", one row per sample time) and writes one PNG
per column against time, OUTDIR/plots/<name>.png, plus OUTDIR/plots/overview.png with every
column as a subplot. With OUTDIR/run.json the plots are titled with the case's name and
description, and a column whose mean is a summary figure shows its averaging window (shaded)
and the mean (dashed), marked "unreliable" when run.json gives the figure a caveat; one line
per such plot is printed. Exit codes: 0 success, 1 plotting failed, 2 bad input (no
series.csv, an empty one, no rows, or only a time column).

Needs matplotlib and numpy (Debian: python3-matplotlib, python3-numpy for /usr/bin/python3).
"""

import argparse
import csv
import json
import math
import re
import sys
from pathlib import Path

EXIT_FAILED = 1
EXIT_BAD_INPUT = 2
HEADER_CELL = re.compile(r"^\s*(.*?)\s*\[(.*)\]\s*$")


class BadInput(Exception):
    """The series cannot be plotted because of what is (not) in OUTDIR."""


def parse_header_cell(cell):
    """'kinetic_energy [J]' -> ('kinetic_energy', 'J'); a cell without brackets has unit '-'."""
    match = HEADER_CELL.match(cell)
    if match:
        return match.group(1), match.group(2) or "-"
    return cell.strip(), "-"


def parse_row(cells, width, line_number, path):
    """The row as floats, or None (with a warning) if it is not a complete numeric row."""
    try:
        if len(cells) == width:
            return [float(cell) for cell in cells]
    except ValueError:
        pass
    print(f"warning: {path}:{line_number}: skipped malformed row", file=sys.stderr)
    return None


def read_series(path):
    """Columns [(name, unit)] and the values as a list of columns (lists of floats)."""
    if not path.is_file():
        raise BadInput(f"{path} does not exist (is this a partimix output folder?)")
    with path.open(newline="") as handle:
        lines = list(csv.reader(handle))
    if not lines or not any(cell.strip() for cell in lines[0]):
        raise BadInput(f"{path} is empty")
    columns = [parse_header_cell(cell) for cell in lines[0]]
    if len(columns) < 2:
        raise BadInput(f"{path} has no column to plot against time")
    rows = [parse_row(cells, len(columns), number, path)
            for number, cells in enumerate(lines[1:], start=2) if cells]
    rows = [row for row in rows if row is not None]
    if not rows:
        raise BadInput(f"{path} has a header but no rows")
    return columns, [list(values) for values in zip(*rows)]


def time_index(columns):
    """The column named 'time', else the first column."""
    names = [name for name, _ in columns]
    return names.index("time") if "time" in names else 0


def file_stem(name):
    """A column name made safe as a file name."""
    return re.sub(r"[^A-Za-z0-9_.-]", "_", name) or "column"


def read_summary(path):
    """The title and averaging windows of run.json: (title, {figure: (from, to, mean, caveat)}).
    A time average is the figure named like its column; its window is that of the longest
    prefix P of its name with figures P + "average_from" and P + "average_to". No title and no
    windows when there is no readable run.json."""
    try:
        run = json.loads(path.read_text())
    except (OSError, ValueError):
        return "", {}
    case = run.get("case") if isinstance(run.get("case"), dict) else {}
    title = " - ".join(str(part) for part in (case.get("name"), case.get("description")) if part)
    figures = run.get("figures") if isinstance(run.get("figures"), dict) else {}
    caveats = run.get("caveats") if isinstance(run.get("caveats"), dict) else {}
    prefixes = [key[: -len("average_from")] for key in figures if key.endswith("average_from")
                and key[: -len("average_from")] + "average_to" in figures]
    windows = {}
    for name, mean in figures.items():
        owners = [prefix for prefix in prefixes if name.startswith(prefix)]
        if not owners or "average_" in name or not isinstance(mean, (int, float)):
            continue
        prefix = max(owners, key=len)
        windows[name] = (figures[prefix + "average_from"], figures[prefix + "average_to"], mean,
                         caveats.get(name, ""))
    return title, windows


def draw(axes, time, values, time_label, column, window=None):
    name, unit = column
    axes.plot(time, values, marker="." if len(time) < 50 else None)
    axes.set_xlabel(time_label)
    axes.set_ylabel(f"{name} [{unit}]")
    axes.grid(True, alpha=0.3)
    if window:
        start, end, mean, caveat = window
        label = f"mean {mean:.4g} over t = {start:.4g} to {end:.4g} s"
        if caveat:
            label += " (unreliable)"
        axes.axvspan(start, end, color="tab:orange", alpha=0.15)
        axes.hlines(mean, start, end, colors="tab:orange", linestyles="dashed", label=label)
        axes.legend(fontsize="small")


def load_pyplot():
    """matplotlib.pyplot on the Agg backend (no display needed)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def plot_all(columns, data, plots, summary=("", {})):
    """Writes one PNG per non-time column and the overview; returns the files written."""
    import numpy as np

    plt = load_pyplot()
    title, windows = summary
    t_index = time_index(columns)
    time = np.asarray(data[t_index])
    time_label = "{} [{}]".format(*columns[t_index])
    series = [(columns[k], np.asarray(data[k])) for k in range(len(columns)) if k != t_index]
    plots.mkdir(parents=True, exist_ok=True)
    written = []
    for column, values in series:
        figure, axes = plt.subplots(figsize=(6.4, 4.0))
        window = windows.get(column[0])
        draw(axes, time, values, time_label, column, window)
        if title:
            axes.set_title(title, fontsize="medium")
        written.append(plots / f"{file_stem(column[0])}.png")
        save(plt, figure, written[-1], dpi=120)
        if window:
            print(f"plot_series: {written[-1].name}: averaging window t = {window[0]:.4g} to "
                  f"{window[1]:.4g} s, mean {window[2]:.4g}"
                  + (" (unreliable)" if window[3] else ""))
    written.append(plots / "overview.png")
    save(plt, overview(plt, series, time, time_label, summary), written[-1], dpi=100)
    return written


def overview(plt, series, time, time_label, summary):
    """One figure with every series as a subplot, in two columns when there are many."""
    title, windows = summary
    ncols = 1 if len(series) <= 3 else 2
    nrows = math.ceil(len(series) / ncols)
    figure, grid = plt.subplots(nrows, ncols, figsize=(6.4 * ncols, 2.8 * nrows),
                                squeeze=False, sharex=True)
    cells = grid.ravel()
    for axes, (column, values) in zip(cells, series):
        draw(axes, time, values, time_label, column, windows.get(column[0]))
    for axes in cells[len(series):]:
        axes.set_visible(False)
    if title:
        figure.suptitle(title)
    return figure


def save(plt, figure, path, dpi):
    figure.tight_layout()
    figure.savefig(path, dpi=dpi)
    plt.close(figure)


def record_outputs(outdir, paths):
    """Lists the plots in the folder's manifest (src/app/output_folder.hpp), so that the next
    run into the folder removes them and nothing else of the user's."""
    with open(outdir / ".partimix-files", "a", encoding="utf-8") as manifest:
        manifest.write("plots\n")
        for path in paths:
            manifest.write(f"{path.relative_to(outdir)}\n")


def main(argv):
    parser = argparse.ArgumentParser(description="Plot OUTDIR/series.csv into OUTDIR/plots.")
    parser.add_argument("outdir", type=Path, help="a partimix output folder")
    args = parser.parse_args(argv)
    try:
        columns, data = read_series(args.outdir / "series.csv")
    except BadInput as error:
        print(f"plot_series: {error}", file=sys.stderr)
        return EXIT_BAD_INPUT
    try:
        summary = read_summary(args.outdir / "run.json")
        if summary[0]:
            print(f"plot_series: title '{summary[0]}'")
        written = plot_all(columns, data, args.outdir / "plots", summary)
    except ImportError as error:
        print(f"plot_series: {error}; install matplotlib and numpy for {sys.executable} "
              "(Debian: python3-matplotlib python3-numpy)", file=sys.stderr)
        return EXIT_FAILED
    record_outputs(args.outdir, written)
    print(f"plot_series: wrote {len(written)} plots to {args.outdir / 'plots'}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
