#!/usr/bin/env python3
"""Orientation order of the grains that flow relative to a rotating drum, from a run's frames.

    python3 tools/drum_flowing_layer_order.py FRAME.vtp... [--rpm 30] [--axis 0 0 1]
        [--axis-point 0 0 0] [--min-speed 0.05]

The `orientation_order` analysis (docs/mixing.md) takes each grain's own velocity as its flow
direction, so in a drum it averages over the bed that turns with the drum as well as over the
flowing layer, where seed 002 says the long axes line up. This reads DEM frames (VTK PolyData
with raw appended data, as partimix writes them) and takes each grain's velocity relative to
the drum turning rigidly, v_rel = v - omega x (x - p) with omega = 2 pi rpm / 60 along the
axis: the grains with |v_rel| > --min-speed are the flowing layer. For them it prints, per
frame and over all frames together, their number and
    S_dir = <P2(u . v_rel / |v_rel|)>  and  S = largest eigenvalue of <(3 u u^T - I) / 2>,
u the grain's axis (the longest half-axis, or the shortest for oblate grains): S_dir as the
analysis defines it with its `rotating_frame`, S over the flowing grains alone (the analysis
counts every grain in S; docs/mixing.md, "Orientation order").

Needs numpy. Exit codes: 0 success, 2 bad input (a file that is not such a frame, or no grain
with an axis above the speed).
"""

import argparse
import math
import sys

import numpy as np

from vtk_frame import read_frame

EXIT_BAD_INPUT = 2


def grain_axes(orientation, half_axes):
    """Unit axis of each grain (NaN rows for grains without one), world frame."""
    longest = half_axes.max(axis=1, keepdims=True)
    shortest = half_axes.min(axis=1, keepdims=True)
    one_longest = (half_axes == longest).sum(axis=1) == 1
    one_shortest = (half_axes == shortest).sum(axis=1) == 1
    index = np.where(one_longest, half_axes.argmax(axis=1), half_axes.argmin(axis=1))
    w, x, y, z = orientation.T
    columns = np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)], axis=1),
        np.stack([2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)], axis=1),
        np.stack([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)], axis=1),
    ], axis=1)
    axes = columns[np.arange(len(index)), index]
    axes[~(one_longest | one_shortest)] = np.nan
    return axes


def flowing(arrays, omega, axis_point, min_speed):
    """The axes u and unit relative velocities e of the flowing grains of one frame."""
    u = grain_axes(arrays["orientation"], arrays["half_axes"])
    v_rel = arrays["velocity"] - np.cross(omega, arrays["Points"] - axis_point)
    speed = np.linalg.norm(v_rel, axis=1)
    keep = (speed > min_speed) & np.isfinite(u).all(axis=1)
    return u[keep], v_rel[keep] / speed[keep, None]


def order(u, e):
    """S_dir and S of axes u against directions e."""
    cosine = np.einsum("ij,ij->i", u, e)
    s_dir = float(np.mean(1.5 * cosine ** 2 - 0.5))
    q = 1.5 * np.einsum("ij,ik->jk", u, u) / len(u) - 0.5 * np.eye(3)
    return s_dir, float(np.linalg.eigvalsh(q)[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("frames", nargs="+")
    parser.add_argument("--rpm", type=float, default=30.0)
    parser.add_argument("--axis", type=float, nargs=3, default=[0.0, 0.0, 1.0])
    parser.add_argument("--axis-point", type=float, nargs=3, default=[0.0, 0.0, 0.0])
    parser.add_argument("--min-speed", type=float, default=0.05)
    args = parser.parse_args()
    axis = np.array(args.axis) / np.linalg.norm(args.axis)
    omega = 2.0 * math.pi * args.rpm / 60.0 * axis
    all_u, all_e = [], []
    try:
        for path in args.frames:
            u, e = flowing(read_frame(path), omega, np.array(args.axis_point), args.min_speed)
            if len(u):
                print(f"{path}: {len(u)} grains flowing, S_dir %.3f, S %.3f" % order(u, e))
            all_u.append(u)
            all_e.append(e)
    except (OSError, ValueError, KeyError) as error:
        print(f"error: {error}", file=sys.stderr)
        return EXIT_BAD_INPUT
    u, e = np.concatenate(all_u), np.concatenate(all_e)
    if not len(u):
        print("error: no grain with an axis flows faster than --min-speed", file=sys.stderr)
        return EXIT_BAD_INPUT
    print(f"all frames: {len(u)} grains flowing, S_dir %.3f, S %.3f" % order(u, e))
    return 0


if __name__ == "__main__":
    sys.exit(main())
