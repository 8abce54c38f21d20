#!/usr/bin/env python3
"""docs/figures/collapse_runout.png: the planar column collapse's runout against the aspect ratio.

The points are the runouts (L_f - L_i) / L_i recorded in docs/validation.md ("MPM column
collapse"), measured with cases/column_collapse_2d.yaml and the column's height changed; the
lines are the published fits: Lube et al. 2005 (1.2 a, 1.9 a^(2/3)) and the exponent of
Balmforth & Kerswell 2005 for wide channels (a^0.9, drawn through the 5 mm grid's a = 2 point
to show the slope only: their constant depends on the material).
Run: /usr/bin/python3 tools/figures/collapse_runout.py (needs matplotlib, numpy).
"""
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

GRID_10MM = {0.5: 0.42, 1: 1.23, 2: 2.98, 3: 4.52, 4: 5.86, 6: 8.31}
GRID_5MM = {0.5: 0.55, 1: 1.39, 2: 3.11, 3: 4.37, 4: 5.86}


def main():
    a = np.linspace(0.3, 7, 200)
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.plot(a[a <= 2.8], 1.2 * a[a <= 2.8], "k--", label="Lube et al. 2005: 1.2 a")
    ax.plot(a[a >= 1.8], 1.9 * a[a >= 1.8] ** (2 / 3), "k:", label="Lube et al. 2005: 1.9 a$^{2/3}$")
    anchor = GRID_5MM.get(2, GRID_10MM[2])
    ax.plot(a[a >= 1.5], anchor * (a[a >= 1.5] / 2) ** 0.9, "0.5", lw=1,
            label="Balmforth & Kerswell 2005, wide channels: slope a$^{0.9}$")
    ax.plot(list(GRID_10MM), list(GRID_10MM.values()), "o-", label="MPM, 1 cm grid (10 cells across)")
    if GRID_5MM:
        ax.plot(list(GRID_5MM), list(GRID_5MM.values()), "s-", label="MPM, 5 mm grid (20 cells across)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("aspect ratio a = H$_i$ / L$_i$ [-]")
    ax.set_ylabel("(L$_f$ - L$_i$) / L$_i$ [-]")
    ax.set_title("Planar granular column collapse, mu(I) MPM (L$_i$ = 10 cm)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(Path(__file__).resolve().parents[2] / "docs/figures/collapse_runout.png", dpi=110)


if __name__ == "__main__":
    main()
