#!/usr/bin/env python3
"""docs/figures/silo_beverloo.png: the slot silo's discharge rate against the outlet width.

The points are the rates measured by tests/validation/mpm_silo_test.cpp (1 cm grid) and by
cases/silo_2d.yaml (2 cm grid), as recorded in docs/validation.md ("Silo and Beverloo"); the
lines are Beverloo's law W = C rho_b sqrt(g) (D - k d)^(3/2) with the fitted and the typical
constants. Run: /usr/bin/python3 tools/figures/silo_beverloo.py (needs matplotlib, numpy).
"""
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

OUTLETS = np.array([0.06, 0.08, 0.10])  # D [m]
RATES = np.array([78.0, 140.0, 208.2])  # W [kg/(s m)], whole silo
CASE_OUTLET, CASE_RATE = 0.14, 406.3
FITTED_C, FITTED_K = 1.26, 3.3
GRAIN, DENSITY, GRAVITY = 0.005, 2200.0, 9.81


def beverloo(width, c, k):
    return c * DENSITY * np.sqrt(GRAVITY) * np.clip(width - k * GRAIN, 0.0, None) ** 1.5


def main():
    width = np.linspace(0.04, 0.16, 200)
    fig, ax = plt.subplots(figsize=(6.2, 4))
    ax.plot(OUTLETS, RATES, "o", label="MPM, 1 cm grid (tests/validation/mpm_silo_test.cpp)")
    ax.plot([CASE_OUTLET], [CASE_RATE], "s", label="MPM, cases/silo_2d.yaml (2 cm grid)")
    ax.plot(width, beverloo(width, FITTED_C, FITTED_K), "-",
            label=f"Beverloo fitted: C = {FITTED_C:.2f}, k = {FITTED_K:.1f}")
    ax.plot(width, beverloo(width, 1.03, 1.5), "--", label="Beverloo, C = 1.03, k = 1.5 (typical)")
    ax.set_xlabel("outlet width D [m]")
    ax.set_ylabel("discharge rate W [kg/(s m)]")
    ax.set_title("Slot silo discharge vs Beverloo (plane strain, per metre of depth)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(Path(__file__).resolve().parents[2] / "docs/figures/silo_beverloo.png", dpi=110)


if __name__ == "__main__":
    main()
