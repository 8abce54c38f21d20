#!/usr/bin/env python3
"""Tables and plots of the speed and fill sweeps of the seed's study drum (docs/dem.md).

    python3 tools/drum_speed_fill_study.py OUT_DIR RUN_DIR... [--from 3.0] [--rpm 30]
        [--figures DIR]

Each RUN_DIR is the output folder of one run of tools/drum_speed_fill_study.sh (its run.json
gives the shape, the drum's radius and speed, the grain count and the periodic length). Prints
one Markdown table row per run, sorted by aspect ratio, speed and fill: sigma, rpm, the drum's
diameter [mm], the fill (the grains' volume over the drum's) [%], the Lacey index at the end, the
fitted mixing rates (exp and erf) and the mean translational and rotational kinetic energies per
grain over t >= --from. Writes OUT_DIR/speed_fill_study.csv with the same columns and, in
--figures (default OUT_DIR), drum_speed_fill_rates.png: the rate against the speed in the
smallest drum and against the fill at --rpm, one line per aspect ratio.

Needs matplotlib and numpy (Debian: python3-matplotlib, python3-numpy for /usr/bin/python3).
Exit codes: 0 success, 2 bad input (a folder without run.json or series.csv, or no rows).
"""

import argparse
import json
import math
import sys
from pathlib import Path

from drum_aspect_ratio_study import read_run, write_table

EXIT_BAD_INPUT = 2


def drum_row(folder, start):
    """The aspect-ratio study's row of a run, with its drum, speed and fill."""
    row = read_run(folder, start)
    case = json.loads((folder / "run.json").read_text())["case"]
    drum = case["walls"][0]
    species = case["dem"]["species"][0]
    radius = species.get("shape", {}).get("equivalent_radius") or case["dem"]["fill"]["radius"]
    length = case["domain"]["max"][2] - case["domain"]["min"][2]
    grains = row["grains"] * 4.0 / 3.0 * math.pi * radius**3
    return {
        "sigma": row["sigma"],
        "rpm": drum["motion"]["rpm"],
        "diameter [mm]": 2000.0 * drum["radius"],
        "fill [%]": 100.0 * grains / (math.pi * drum["radius"] ** 2 * length),
        **{k: v for k, v in row.items() if k not in ("sigma", "grains")},
    }


def plot(rows, figures, rpm):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    smallest = min(r["diameter [mm]"] for r in rows)
    for sigma in sorted({r["sigma"] for r in rows}):
        label = "spheres" if sigma == 1.0 else f"sigma = {sigma:g}"
        by_speed = sorted(
            (r for r in rows if r["sigma"] == sigma and r["diameter [mm]"] == smallest),
            key=lambda r: r["rpm"],
        )
        axes[0].plot([r["rpm"] for r in by_speed], [r["rate_exp [1/s]"] for r in by_speed], "o-",
                     label=label)
        by_fill = sorted((r for r in rows if r["sigma"] == sigma and r["rpm"] == rpm),
                         key=lambda r: r["fill [%]"])
        axes[1].plot([r["fill [%]"] for r in by_fill], [r["rate_exp [1/s]"] for r in by_fill],
                     "o-", label=label)
    axes[0].set_xlabel(f"drum speed [rpm] (drum {smallest:g} mm)")
    axes[1].set_xlabel(f"fill [%] ({rpm:g} rpm)")
    for a in axes:
        a.set_ylabel("mixing rate, exp fit [1/s]")
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(figures / "drum_speed_fill_rates.png", dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--from", dest="start", type=float, default=3.0)
    parser.add_argument("--rpm", type=float, default=30.0)
    parser.add_argument("--figures")
    args = parser.parse_args()
    try:
        rows = sorted(
            (drum_row(Path(r), args.start) for r in args.runs),
            key=lambda r: (r["sigma"], r["rpm"], -r["fill [%]"]),
        )
    except (OSError, KeyError, ValueError, TypeError) as error:
        print(f"drum_speed_fill_study: {error}", file=sys.stderr)
        return EXIT_BAD_INPUT
    out = Path(args.out)
    write_table(rows, out / "speed_fill_study.csv")
    plot(rows, Path(args.figures) if args.figures else out, args.rpm)
    return 0


if __name__ == "__main__":
    sys.exit(main())
