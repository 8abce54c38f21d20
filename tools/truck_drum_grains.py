#!/usr/bin/env python3
"""Grains spread evenly through the mortar of a truck drum, as a grains_file CSV.

python3 tools/truck_drum_grains.py OUT.csv --count N --radius R --seed S
    --profile HEAD_RADIUS FRONT_LENGTH RADIUS CYLINDER_LENGTH REAR_LENGTH OPENING_RADIUS
    --clearance C --level X Y Z NX NY NZ [--split X | --mixed]

The drum's axis is the x axis from its head's centre at the origin (the cases' placement); the
mortar lies behind the plane through (X, Y, Z) with the upward normal (NX, NY, NZ), as the
case's `fluid.regions` plane. Each grain's centre is drawn uniformly in the mortar within the
drum's core: at most (shell radius at x) - C from the axis, C the blades' height plus a margin,
so that no grain starts in a blade; a draw that would overlap an earlier grain is drawn again.
Species: 1 for the grains beyond x = X of --split (the rear part marked, so that the segregation
degree starts high), or with --mixed each grain 0 or 1 at random (an even mixture). The seed
(`random.Random(S)`) makes the file reproducible. Columns: x, y, z, radius, species.
Exit codes: 0 success, 2 bad input (no room for the grains, bad numbers).
"""

import argparse
import math
import random
import sys

EXIT_BAD_INPUT = 2
MOST_DRAWS_PER_GRAIN = 1000


def shell_radius(x, profile):
    """The shell's radius at x along the axis: front cone, cylinder, rear cone; 0 outside."""
    head, front, radius, cylinder, rear, opening = profile
    if x < 0.0 or x > front + cylinder + rear:
        return 0.0
    if x <= front:
        return head + (radius - head) * x / front
    if x <= front + cylinder:
        return radius
    return radius + (opening - radius) * (x - front - cylinder) / rear


def in_mortar(point, level_point, normal, radius):
    """Whether the ball of `radius` at `point` lies below the level plane."""
    return sum((p - q) * n for p, q, n in zip(point, level_point, normal)) < -radius


def draw_grains(args):
    """The grains as (x, y, z, radius, species); raises ValueError when they do not fit."""
    rng = random.Random(args.seed)
    norm = math.sqrt(sum(n * n for n in args.level[3:]))
    if norm == 0.0:
        raise ValueError("the level's normal must not be zero")
    normal = [n / norm for n in args.level[3:]]
    length = sum(args.profile[1:4])
    widest = max(args.profile[0], args.profile[2])
    grains = []
    cell = 2.0 * args.radius
    occupied = {}
    for _ in range(args.count):
        for _ in range(MOST_DRAWS_PER_GRAIN):
            x = rng.uniform(0.0, length)
            y = rng.uniform(-widest, widest)
            z = rng.uniform(-widest, widest)
            core = shell_radius(x, args.profile) - args.clearance - args.radius
            if math.hypot(y, z) > core or not in_mortar((x, y, z), args.level[:3], normal,
                                                        args.radius):
                continue
            key = (int(x // cell), int(y // cell), int(z // cell))
            near = [occupied.get((key[0] + i, key[1] + j, key[2] + k), [])
                    for i in (-1, 0, 1) for j in (-1, 0, 1) for k in (-1, 0, 1)]
            if any(math.dist((x, y, z), other) < 2.0 * args.radius for group in near
                   for other in group):
                continue
            occupied.setdefault(key, []).append((x, y, z))
            species = rng.randint(0, 1) if args.mixed else int(x > args.split)
            grains.append((x, y, z, args.radius, species))
            break
        else:
            raise ValueError(f"no room for grain {len(grains) + 1} of {args.count} in the mortar "
                             f"after {MOST_DRAWS_PER_GRAIN} draws")
    return grains


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--count", type=int, required=True)
    parser.add_argument("--radius", type=float, required=True)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--profile", type=float, nargs=6, required=True)
    parser.add_argument("--clearance", type=float, required=True)
    parser.add_argument("--level", type=float, nargs=6, required=True)
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--split", type=float)
    group.add_argument("--mixed", action="store_true")
    args = parser.parse_args(argv)
    if args.count < 1 or not args.radius > 0.0 or min(args.profile) <= 0.0:
        parser.error("count, radius and the profile's lengths must be above zero")
    return args


def main(argv):
    try:
        args = parse(argv)
        grains = draw_grains(args)
    except ValueError as error:
        print(f"truck_drum_grains: {error}", file=sys.stderr)
        return EXIT_BAD_INPUT
    with open(args.out, "w", encoding="utf-8") as out:
        out.write("# written by tools/truck_drum_grains.py " + " ".join(argv) + "\n")
        out.write("x,y,z,radius,species\n")
        for grain in grains:
            out.write(",".join(f"{v:.9g}" for v in grain[:4]) + f",{grain[4]}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
