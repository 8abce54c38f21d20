#!/usr/bin/env python3
"""Plot a design search: python3 tools/plot_optimise.py SEARCHDIR FIGURE

Reads SEARCHDIR/optimise.csv (written by `partimix optimise`, docs/design-loop.md) and writes
SEARCHDIR/search.png: on the left FIGURE at each evaluation with the best so far as a line; on
the right the evaluated designs, FIGURE against the key for one varied key, or the first two
keys with FIGURE as the colour for more, the best design ringed. Exit codes: 0 success, 1
plotting failed, 2 bad input (no optimise.csv, no FIGURE column, no row with FIGURE).

Needs matplotlib (Debian: python3-matplotlib for /usr/bin/python3).
"""

import csv
import re
import sys
from pathlib import Path

EXIT_FAILED = 1
EXIT_BAD_INPUT = 2
HEADER_CELL = re.compile(r"^\s*(.*?)(?:\s+\[[^\[\]]*\])?\s*$")


def column_name(cell):
    """'segregation_degree [%]' -> 'segregation_degree'."""
    return HEADER_CELL.match(cell).group(1)


def read_search(folder, figure):
    """The varied keys, and per row with the figure: (index, key values, figure value)."""
    path = Path(folder) / "optimise.csv"
    if not path.is_file():
        raise ValueError(f"no {path}")
    with open(path, newline="") as handle:
        rows = list(csv.reader(handle))
    names = [column_name(cell) for cell in rows[0]]
    if figure not in names:
        raise ValueError(f"{path} has no column {figure}")
    keys = names[1:names.index("status")]
    column = names.index(figure)
    points = []
    for index, row in enumerate(rows[1:]):
        if row[column]:
            values = [float(v) for v in row[1:1 + len(keys)]]
            points.append((index, values, float(row[column])))
    if not points:
        raise ValueError(f"no evaluation in {path} has {figure}")
    return keys, points


def plot(folder, figure, keys, points):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (history, space) = plt.subplots(1, 2, figsize=(11, 4.5))
    index = [p[0] for p in points]
    value = [p[2] for p in points]
    best = [min(value[:k + 1]) for k in range(len(value))]
    history.plot(index, value, "o", label=figure)
    history.step(index, best, where="post", label="best so far")
    history.set_xlabel("evaluation")
    history.set_ylabel(figure)
    history.legend()
    top = min(points, key=lambda p: p[2])
    if len(keys) == 1:
        space.plot([p[1][0] for p in points], value, "o")
        space.plot([top[1][0]], [top[2]], "o", mfc="none", ms=14, color="k")
        space.set_xlabel(keys[0])
        space.set_ylabel(figure)
    else:
        drawn = space.scatter([p[1][0] for p in points], [p[1][1] for p in points], c=value)
        space.plot([top[1][0]], [top[1][1]], "o", mfc="none", ms=14, color="k")
        fig.colorbar(drawn, ax=space, label=figure)
        space.set_xlabel(keys[0])
        space.set_ylabel(keys[1])
    space.set_title("best: " + ", ".join(f"{k} = {v:.4g}" for k, v in zip(keys, top[1])))
    fig.tight_layout()
    fig.savefig(Path(folder) / "search.png", dpi=110)


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return EXIT_BAD_INPUT
    try:
        keys, points = read_search(argv[1], argv[2])
    except (ValueError, IndexError) as error:
        print(f"error: {error}", file=sys.stderr)
        return EXIT_BAD_INPUT
    try:
        plot(argv[1], argv[2], keys, points)
    except Exception as error:  # noqa: BLE001 - any plotting failure is reported the same way
        print(f"plot failed: {error}", file=sys.stderr)
        return EXIT_FAILED
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
