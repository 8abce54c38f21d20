#!/usr/bin/env python3
"""Tables and plots of the drum aspect-ratio study (docs/dem.md, "The seed's study drum").

    python3 tools/drum_aspect_ratio_study.py OUT_DIR RUN_DIR... [--from 2.0] [--figures DIR]

Each RUN_DIR is the output folder of one `partimix run` of cases/drum_seed_ellipsoids.yaml (its
run.json names the aspect ratio sigma = c / a of species 0). Prints one Markdown table row per
run, sorted by sigma: the Lacey index at the end, the fitted mixing rates (exp and erf, from
run.json's figures), and the mean translational and rotational kinetic energies per grain over
t >= --from (series.csv); and, where the run has them, the mean orientation order over the same
samples (NaN where it has not, as spheres): `flow_alignment`, S_dir against each grain's
direction of motion, and `nematic_order`, S, of an `orientation_order` analysis named `flow`,
and `axial_alignment`, S_dir against the drum's axis, of one named `axial` (docs/mixing.md,
"Orientation order"). Writes OUT_DIR/aspect_ratio_study.csv with the same columns and, in
--figures (default OUT_DIR), drum_aspect_ratio_lacey.png (M against time, one line per sigma),
drum_aspect_ratio_rates.png (the rate and the two energies against sigma) and
drum_aspect_ratio_orientation.png (the three orientation figures against sigma).

Needs matplotlib and numpy (Debian: python3-matplotlib, python3-numpy for /usr/bin/python3).
Exit codes: 0 success, 2 bad input (a folder without run.json or series.csv, or no rows).
"""

import argparse
import csv
import json
import math
import sys
from pathlib import Path

EXIT_BAD_INPUT = 2


def mean_of_finite(rows, key):
    """The mean of the finite values of column `key` in rows; NaN when there are none."""
    values = [float(r[key]) for r in rows if key in r and math.isfinite(float(r[key]))]
    return sum(values) / len(values) if values else math.nan


def read_run(folder, start):
    """One row of the table from a run folder."""
    run = json.loads((folder / "run.json").read_text())
    species = run["case"]["dem"]["species"][0]
    sigma = species.get("shape", {}).get("aspect_ratio", 1.0)
    count = run["case"]["dem"]["fill"]["count"]
    with open(folder / "series.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    times = [float(r["time [s]"]) for r in rows]
    lacey = [float(r["lacey [-]"]) for r in rows]
    late = [r for r, t in zip(rows, times) if t >= start]
    if not late:
        raise ValueError(f"{folder}: no sample at t >= {start} s")
    mean = lambda key: sum(float(r[key]) for r in late) / len(late) / count
    figures = run["figures"]
    orientation = {
        "flow_alignment [-]": "flow.alignment [-]",
        "nematic_order [-]": "flow.nematic_order [-]",
        "axial_alignment [-]": "axial.alignment [-]",
    }
    return {
        "sigma": sigma,
        "grains": count,
        "lacey_final": lacey[-1],
        "rate_exp [1/s]": figures["lacey_rate_exp"],
        "rate_erf [1/s]": figures["lacey_rate_erf"],
        "translational_energy_per_grain [J]": mean("kinetic_energy [J]"),
        "rotational_energy_per_grain [J]": mean("rotational_energy [J]"),
        "rotational_share [-]": mean("rotational_energy [J]")
        / (mean("kinetic_energy [J]") + mean("rotational_energy [J]")),
        **{name: mean_of_finite(late, key) for name, key in orientation.items()},
        "_times": times,
        "_lacey": lacey,
    }


def write_table(rows, path):
    """The rows' columns (those not starting with _) as CSV at path and as Markdown on stdout."""
    path.parent.mkdir(parents=True, exist_ok=True)
    columns = [k for k in rows[0] if not k.startswith("_")]
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore", lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    print("| " + " | ".join(columns) + " |")
    print("|" + "---|" * len(columns))
    for r in rows:
        print("| " + " | ".join(f"{r[c]:.4g}" for c in columns) + " |")


def plot(rows, figures, start):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 4))
    for r in rows:
        ax.plot(r["_times"], r["_lacey"], label=f"sigma = {r['sigma']:g}")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("Lacey index M")
    ax.set_ylim(-0.05, 1.05)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(figures / "drum_aspect_ratio_lacey.png", dpi=120)

    sigmas = [r["sigma"] for r in rows]
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    axes[0].plot(sigmas, [r["rate_exp [1/s]"] for r in rows], "o-", label="exp fit")
    axes[0].plot(sigmas, [r["rate_erf [1/s]"] for r in rows], "s--", label="erf fit")
    axes[0].set_xlabel("aspect ratio sigma = c / a")
    axes[0].set_ylabel("mixing rate [1/s]")
    axes[0].set_xscale("log")
    axes[0].legend(fontsize=8)
    axes[1].plot(sigmas, [r["translational_energy_per_grain [J]"] for r in rows], "o-",
                 label="translational")
    axes[1].plot(sigmas, [r["rotational_energy_per_grain [J]"] for r in rows], "s--",
                 label="rotational")
    axes[1].set_xlabel("aspect ratio sigma = c / a")
    axes[1].set_ylabel(f"mean energy per grain, t >= {start:g} s [J]")
    axes[1].set_xscale("log")
    axes[1].set_yscale("log")
    axes[1].legend(fontsize=8)
    for a in axes:
        a.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(figures / "drum_aspect_ratio_rates.png", dpi=120)

    fig, ax = plt.subplots(figsize=(6, 4))
    for key, style, label in (
        ("flow_alignment [-]", "o-", "S_dir against the motion"),
        ("nematic_order [-]", "s--", "nematic order S"),
        ("axial_alignment [-]", "^:", "S_dir against the drum axis"),
    ):
        ax.plot(sigmas, [r[key] for r in rows], style, label=label)
    ax.axhline(0.0, color="grey", linewidth=0.8)
    ax.set_xlabel("aspect ratio sigma = c / a (long axis; symmetry axis when oblate)")
    ax.set_ylabel(f"mean over t >= {start:g} s [-]")
    ax.set_xscale("log")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(figures / "drum_aspect_ratio_orientation.png", dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--from", dest="start", type=float, default=2.0)
    parser.add_argument("--figures")
    args = parser.parse_args()
    try:
        rows = sorted((read_run(Path(r), args.start) for r in args.runs), key=lambda r: r["sigma"])
    except (OSError, KeyError, ValueError) as error:
        print(f"drum_aspect_ratio_study: {error}", file=sys.stderr)
        return EXIT_BAD_INPUT
    out = Path(args.out)
    write_table(rows, out / "aspect_ratio_study.csv")
    plot(rows, Path(args.figures) if args.figures else out, args.start)
    return 0


if __name__ == "__main__":
    sys.exit(main())
