#!/usr/bin/env python3
"""How well a thin solid body of an SPH run keeps apart the fluid on its two faces, from frames.

    python3 tools/plate_crosstalk.py FRAME.vtp... --spacing DP [--body 1] [--smoothing-ratio 1.5]

partimix warns when a body is thinner than the kernel support 2h (docs/geometry-meshes.md). This
measures what that does in a run. The body's particles (field `body`) give the body's thin
direction (the smallest principal axis of their positions) and its mid-plane. Away from the
body's edges (more than 2h inside its extent along both of its long axes) it prints per frame:
- for the fluid within 2h of the mid-plane, the share of each particle's Wendland C2 kernel
  weight (h = ratio x spacing) over fluid neighbours that comes from the far side of the
  mid-plane (mean and largest), and the fluid's nearest distance to the mid-plane;
- for the body's particles with fluid around, the share of their fluid kernel weight from the
  side opposite their own: the ghost pressure and velocity they extrapolate from the fluid
  (docs/sph.md, "Walls") mix the two faces' states by that share.

Needs numpy and scipy. Exit codes: 0 success, 2 bad input (a file that is not a frame, or no
particle of the body).
"""

import argparse
import sys

import numpy as np
from scipy.spatial import cKDTree

from vtk_frame import read_frame

EXIT_BAD_INPUT = 2
FLUID_KIND = 0


def wendland_c2(r, h):
    """Wendland C2 up to its constant factor, which the shares do not need."""
    q = r / h
    return np.where(q < 2.0, (1.0 - q / 2.0) ** 4 * (2.0 * q + 1.0), 0.0)


def far_side_shares(points, own_sides, tree, fluid, fluid_sides, h):
    """For each point, the share of its fluid kernel weight from the other side (NaN if none)."""
    shares = np.full(len(points), np.nan)
    for k, neighbours in enumerate(tree.query_ball_point(points, 2.0 * h)):
        if not neighbours:
            continue
        weights = wendland_c2(np.linalg.norm(fluid[neighbours] - points[k], axis=1), h)
        if weights.sum() > 0.0:
            far = fluid_sides[neighbours] != own_sides[k]
            shares[k] = weights[far].sum() / weights.sum()
    return shares


def measure(arrays, body, h):
    """The fluid's and the body's far-side shares of one frame, and the fluid's closest approach."""
    x = arrays["Points"]
    on_body = arrays["body"][:, 0] == body
    if not on_body.any():
        raise ValueError(f"no particle of body {body}")
    centre = x[on_body].mean(axis=0)
    axes = np.linalg.svd(x[on_body] - centre, full_matrices=False)[2]
    local = (x - centre) @ axes.T  # long, second, thin
    half_extent = np.abs(local[on_body, :2]).max(axis=0)
    inside = (np.abs(local[:, :2]) < half_extent - 2.0 * h).all(axis=1)
    is_fluid = arrays["kind"][:, 0] == FLUID_KIND
    fluid = x[is_fluid]
    fluid_sides = np.sign(local[is_fluid, 2])
    tree = cKDTree(fluid)
    beside = is_fluid & inside & (np.abs(local[:, 2]) < 2.0 * h)
    if not beside.any():
        raise ValueError("no fluid within 2h of the body's mid-plane away from its edges")
    fluid_share = far_side_shares(x[beside], np.sign(local[beside, 2]), tree, fluid,
                                  fluid_sides, h)
    plate = on_body & inside
    body_share = far_side_shares(x[plate], np.sign(local[plate, 2]), tree, fluid,
                                 fluid_sides, h)
    return fluid_share, body_share, np.abs(local[beside, 2]).min()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("frames", nargs="+")
    parser.add_argument("--spacing", type=float, required=True, help="sph.spacing [m]")
    parser.add_argument("--body", type=int, default=1, help="the body's index (walls[k])")
    parser.add_argument("--smoothing-ratio", type=float, default=1.5, help="h / spacing")
    args = parser.parse_args()
    h = args.smoothing_ratio * args.spacing
    for path in args.frames:
        try:
            fluid_share, body_share, closest = measure(read_frame(path), args.body, h)
        except (OSError, ValueError, KeyError) as error:
            print(f"{path}: {error}", file=sys.stderr)
            return EXIT_BAD_INPUT
        print(f"{path}: fluid beside the body ({np.isfinite(fluid_share).sum()}): far-side share "
              f"mean {np.nanmean(fluid_share):.2e}, largest {np.nanmax(fluid_share):.2e}, "
              f"closest to the mid-plane {closest * 1e3:.2f} mm; the body's particles "
              f"({np.isfinite(body_share).sum()}): far-side share mean "
              f"{np.nanmean(body_share):.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
