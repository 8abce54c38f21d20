#!/usr/bin/env python3
"""The surge front of a 2D dam-break run against Martin & Moyce (1952), read three ways.

    python3 tools/surge_front.py RUN_DIR --spacing DP [--column 0.146] [--depth 2 4]

The front position Z = x / a at T = t sqrt(2 g / a) (a the column's width, its left side at
x = 0), from the frames of RUN_DIR/sph.pvd:
- tip: the farthest fluid particle (what analysis `front_position` reports);
- continuous: the farthest particle of the fluid joined to the column, in bins one spacing wide
  along x (a bin with no particle ends it: drops thrown ahead do not count);
- depth >= k dp: the farthest particle in a bin of that joined fluid whose depth (its highest
  particle's y plus dp / 2) is at least k spacings, for each k of --depth.
Each at Martin & Moyce's four times (n^2 = 2), linearly between frames, with its deviation, and
the delay of the simulated start (a shift of T) that brings the tip closest to the four points,
with the deviations left.

Needs numpy. Exit codes: 0 success, 2 bad input (no run folder, frames or fluid, or a run that
ends before the last point).
"""

import argparse
import os
import re
import sys

import numpy as np

from vtk_frame import read_frame

EXIT_BAD_INPUT = 2
FLUID_KIND = 0
GRAVITY = 9.81
MARTIN_MOYCE = np.array([(0.832, 1.217), (1.219, 1.474), (1.997, 2.292), (2.547, 2.995)])


def frames_of(run):
    """(time, path) of every frame of the run's sph.pvd."""
    with open(os.path.join(run, "sph.pvd"), encoding="utf-8") as pvd:
        entries = re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', pvd.read())
    if not entries:
        raise ValueError(f"{run}/sph.pvd lists no frame")
    return [(float(t), os.path.join(run, path)) for t, path in entries]


def fronts(points, spacing, depths):
    """x of the tip, of the joined fluid, and of the joined fluid at least k dp deep, per k."""
    bins = np.floor(points[:, 0] / spacing).astype(int)
    if bins.min() < 0:
        raise ValueError("fluid left of x = 0: the column's left side must be at x = 0")
    occupied = np.zeros(bins.max() + 2, bool)
    occupied[bins] = True
    end = int(np.argmin(occupied))  # the first empty bin
    joined = bins < end
    height = np.full(end, -np.inf)
    np.maximum.at(height, bins[joined], points[joined, 1] + spacing / 2)
    result = [points[:, 0].max(), points[joined, 0].max()]
    for k in depths:
        deep = np.flatnonzero(height >= k * spacing)
        result.append(points[bins == deep.max(), 0].max() if len(deep) else np.nan)
    return result


def series(run, spacing, column, depths):
    """Rows (T, Z of each reading) over the run's frames."""
    scale = np.sqrt(2.0 * GRAVITY / column)
    rows = []
    for time, path in frames_of(run):
        arrays = read_frame(path)
        fluid = arrays["Points"][arrays["kind"][:, 0] == FLUID_KIND]
        if len(fluid) == 0:
            raise ValueError(f"{path}: no fluid")
        rows.append([time * scale] + [x / column for x in fronts(fluid, spacing, depths)])
    rows = np.array(rows)
    if rows[-1, 0] < MARTIN_MOYCE[-1, 0]:
        raise ValueError(f"the run ends at T = {rows[-1, 0]:.3f}, before Martin & Moyce's last "
                         f"point, T = {MARTIN_MOYCE[-1, 0]}")
    return rows


def best_delay(rows):
    """The shift of T (a delayed start, 0-0.5) that minimises the tip's largest deviation."""
    shifts = np.arange(0.0, 0.5, 0.001)
    worst = [np.abs(np.interp(MARTIN_MOYCE[:, 0] - s, rows[:, 0], rows[:, 1]) /
                    MARTIN_MOYCE[:, 1] - 1.0).max() for s in shifts]
    shift = shifts[int(np.argmin(worst))]
    return shift, np.interp(MARTIN_MOYCE[:, 0] - shift, rows[:, 0], rows[:, 1]) / \
        MARTIN_MOYCE[:, 1] - 1.0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run")
    parser.add_argument("--spacing", type=float, required=True, help="sph.spacing [m]")
    parser.add_argument("--column", type=float, default=0.146, help="the column's width a [m]")
    parser.add_argument("--depth", type=float, nargs="*", default=[2.0, 4.0],
                        help="depths in spacings")
    args = parser.parse_args()
    try:
        rows = series(args.run, args.spacing, args.column, args.depth)
    except (OSError, ValueError, KeyError) as error:
        print(f"{args.run}: {error}", file=sys.stderr)
        return EXIT_BAD_INPUT
    names = ["tip", "continuous"] + [f"depth >= {k:g} dp" for k in args.depth]
    print("T      Martin-Moyce  " + "  ".join(f"{name:>20}" for name in names))
    for T, Z in MARTIN_MOYCE:
        readings = [np.interp(T, rows[:, 0], rows[:, k]) for k in range(1, len(names) + 1)]
        print(f"{T:.3f}  {Z:12.3f}  " +
              "  ".join(f"{z:10.3f} ({100 * (z / Z - 1):+6.1f}%)" for z in readings))
    shift, left = best_delay(rows)
    print(f"a start delayed by T = {shift:.3f} (t = {shift / np.sqrt(2 * GRAVITY / args.column) * 1e3:.1f}"
          f" ms) leaves the tip at " + ", ".join(f"{100 * d:+.1f}%" for d in left))
    return 0


if __name__ == "__main__":
    sys.exit(main())
