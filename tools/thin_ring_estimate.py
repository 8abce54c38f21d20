#!/usr/bin/env python3
"""The thin-ring estimate of a 2D shell swollen by its inside pressure: Δp against D/D0.

    python3 tools/thin_ring_estimate.py [--shear-modulus G] [--bulk-modulus K] [--A A] [--B B]
        [--n N] [--damage-threshold P_D] [--failure-strain P_F] [--radius R0]
        [--thickness T0] [--max-strain 0.5] [--steps 20000]

docs/multi-material-sph.md, "The droplet": a ring (plane strain, ε_z = 0) of mean radius R and
thickness t holds Δp = σ_θ t / R. With ε = ln(R / R0) the hoop log strain, R = R0 e^ε, and the
ring taken to keep its area, t R = t0 R0 (the plastic flow is incompressible; the elastic
volume change, of order σ / K, is left out), t = t0 e^(-ε) and

    Δp = σ_θ(ε) (t0 / R0) e^(-2ε),   D / D0 = (R + t/2) / (R0 + t0/2),

D the diameter of the ring's outline, as the droplet analysis measures it.

σ_θ(ε) is integrated in small hoop-strain steps dε at one point of the ring, its principal axes
(r, θ, z) fixed, with σ_r = 0 (the thin ring: the pressure is small against σ_θ) and dε_z = 0;
each step's radial increment dε_r is solved for σ_r = 0. The material is the scheme's (same
document, "Johnson-Cook strength and damage" and "Radial return") without its rate and thermal
terms:
- Hooke's law in rates: dσ = K tr(dε) I + 2 G dev(dε);
- J2 plasticity by a radial return (Wilkins 1964): the trial deviator S_tr of von Mises stress
  σ_tr = (3/2 S_tr : S_tr)^½ beyond the flow stress σ_y is scaled onto it, S = S_tr σ_y / σ_tr,
  with the plastic strain increment Δε_p = (σ_tr - σ_y) / (3 G); σ_y is the step's start's
  (the scheme's consistency condition takes the step's end's: the stress here trails the
  hardening curve by one step's Δε_p, which vanishes with dε);
- flow stress (Johnson & Cook 1983): σ_y = (1 - D) (A + B ε_p^n), A at ε_p = 0;
- linear damage (Lemaitre 1996): D = clamp((ε_p - p_d) / (p_f - p_d), 0, 1), p_f = D1.

Prints the peak Δp and D/D0 there, and a table every 0.05 of ε. The defaults are the shell of
cases/gel_droplet_2d.yaml (between r = 0.46 and 0.50 mm; K = ρ0 c0² = 1000 x 300²).

Needs numpy and scipy. Exit codes: 0 success, 2 bad input (argparse's).
"""

import argparse
import math
import sys
from typing import NamedTuple

import numpy as np
from scipy.optimize import brentq

# The columns of inflate's rows.
STRAIN, SWELLING, HOOP_STRESS, PLASTIC_STRAIN, DAMAGE, PRESSURE = range(6)
TABLE_INTERVAL = 0.05  # of ε
# σ_r = 0 is solved to this share of the step's hoop increment in dε_r (near round-off).
RADIAL_TOLERANCE = 1e-13


class Material(NamedTuple):
    """Hooke's law, Johnson-Cook flow stress without rate and thermal terms, linear damage."""
    shear_modulus: float  # G [Pa]
    bulk_modulus: float  # K [Pa]
    A: float  # [Pa]
    B: float  # [Pa]
    n: float
    damage_threshold: float  # p_d
    failure_strain: float  # p_f = D1


def flow_stress(material, plastic_strain, damage):
    """σ_y = (1 - D) (A + B ε_p^n), and (1 - D) A at ε_p = 0 (Johnson & Cook 1983)."""
    hardening = material.B * plastic_strain ** material.n if plastic_strain > 0.0 else 0.0
    return (1.0 - damage) * (material.A + hardening)


def damage_of(material, plastic_strain):
    """D = clamp((ε_p - p_d) / (p_f - p_d), 0, 1), the linear damage law (Lemaitre 1996)."""
    share = (plastic_strain - material.damage_threshold) / \
        (material.failure_strain - material.damage_threshold)
    return min(max(share, 0.0), 1.0)


def stress_update(material, stress, increment, yield_stress):
    """(σ + dσ, Δε_p) for principal stresses and strain increments (r, θ, z): Hooke's law
    dσ = K tr(dε) I + 2 G dev(dε), then a radial return onto σ_y with Δε_p = (σ_tr - σ_y) / (3 G)
    (Wilkins 1964)."""
    G, K = material.shear_modulus, material.bulk_modulus
    volume = sum(increment)
    trial = [s + K * volume + 2.0 * G * (d - volume / 3.0) for s, d in zip(stress, increment)]
    mean = sum(trial) / 3.0
    deviator = [s - mean for s in trial]
    trial_von_mises = math.sqrt(1.5 * sum(s * s for s in deviator))
    if trial_von_mises <= yield_stress:
        return trial, 0.0
    scale = yield_stress / trial_von_mises
    return [mean + scale * s for s in deviator], (trial_von_mises - yield_stress) / (3.0 * G)


def hoop_step(material, stress, hoop_increment, yield_stress):
    """stress_update for the increment (dε_r, dε, 0) whose dε_r gives σ_r = 0, by Brent's
    bracketing root search (σ_r rises with dε_r); the bracket starts at ±2 dε and doubles."""
    def radial_stress(radial_increment):
        return stress_update(material, stress, (radial_increment, hoop_increment, 0.0),
                             yield_stress)[0][0]

    reach = 2.0 * hoop_increment
    while radial_stress(-reach) > 0.0 or radial_stress(reach) < 0.0:
        reach *= 2.0
    radial_increment = brentq(radial_stress, -reach, reach,
                              xtol=RADIAL_TOLERANCE * hoop_increment)
    return stress_update(material, stress, (radial_increment, hoop_increment, 0.0), yield_stress)


def outline_ratio(radius, thickness, strain):
    """D/D0 of the outline, (R + t/2) / (R0 + t0/2), with R = R0 e^ε and t = t0 e^(-ε)."""
    return (radius * math.exp(strain) + 0.5 * thickness * math.exp(-strain)) / \
        (radius + 0.5 * thickness)


def inflate(material, radius, thickness, max_strain, steps):
    """Rows (ε, D/D0 = (R + t/2) / (R0 + t0/2), σ_θ, ε_p, D, Δp = σ_θ (t0 / R0) e^(-2ε)) after
    each of `steps` equal hoop-strain steps to max_strain, from the unstressed ring."""
    stress = [0.0, 0.0, 0.0]
    plastic_strain = damage = 0.0
    hoop_increment = max_strain / steps
    rows = []
    for k in range(1, steps + 1):
        yield_stress = flow_stress(material, plastic_strain, damage)
        stress, plastic_increment = hoop_step(material, stress, hoop_increment, yield_stress)
        plastic_strain += plastic_increment
        damage = damage_of(material, plastic_strain)
        strain = k * hoop_increment
        pressure = stress[1] * thickness / radius * math.exp(-2.0 * strain)
        rows.append((strain, outline_ratio(radius, thickness, strain), stress[1], plastic_strain,
                     damage, pressure))
    return np.array(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--shear-modulus", type=float, default=2.0e7, help="G [Pa]")
    parser.add_argument("--bulk-modulus", type=float, default=9.0e7, help="K [Pa]")
    parser.add_argument("--A", type=float, default=5.0e5, help="Johnson-Cook A [Pa]")
    parser.add_argument("--B", type=float, default=8.0e6, help="Johnson-Cook B [Pa]")
    parser.add_argument("--n", type=float, default=1.0, help="Johnson-Cook n")
    parser.add_argument("--damage-threshold", type=float, default=0.32, help="p_d")
    parser.add_argument("--failure-strain", type=float, default=0.36, help="p_f (D1)")
    parser.add_argument("--radius", type=float, default=0.48e-3, help="mean radius R0 [m]")
    parser.add_argument("--thickness", type=float, default=40e-6, help="thickness t0 [m]")
    parser.add_argument("--max-strain", type=float, default=0.5, help="the last hoop log strain")
    parser.add_argument("--steps", type=int, default=20000, help="hoop-strain steps")
    args = parser.parse_args()
    if min(args.shear_modulus, args.bulk_modulus, args.radius, args.thickness,
           args.max_strain, args.steps) <= 0.0 or args.A < 0.0 or args.B < 0.0:
        parser.error("moduli, radius, thickness, max strain and steps must be positive, "
                     "A and B not negative")
    if args.failure_strain <= args.damage_threshold:
        parser.error("the failure strain must exceed the damage threshold")
    material = Material(args.shear_modulus, args.bulk_modulus, args.A, args.B, args.n,
                        args.damage_threshold, args.failure_strain)
    rows = inflate(material, args.radius, args.thickness, args.max_strain, args.steps)
    peak = rows[int(np.argmax(rows[:, PRESSURE]))]
    print(f"peak {peak[PRESSURE]:.0f} Pa at D/D0 {peak[SWELLING]:.3f} (ε {peak[STRAIN]:.4f}, "
          f"σ_θ {peak[HOOP_STRESS] / 1e6:.3f} MPa, ε_p {peak[PLASTIC_STRAIN]:.4f}, "
          f"D {peak[DAMAGE]:.3f})")
    print("ε      D/D0    σ_θ [MPa]  ε_p     D      Δp [Pa]")
    for strain in np.arange(TABLE_INTERVAL, args.max_strain + 1e-12, TABLE_INTERVAL):
        row = [np.interp(strain, rows[:, STRAIN], rows[:, k]) for k in range(PRESSURE + 1)]
        print(f"{strain:.2f}  {row[SWELLING]:6.3f}  {row[HOOP_STRESS] / 1e6:9.3f}  "
              f"{row[PLASTIC_STRAIN]:6.4f}  {row[DAMAGE]:5.3f}  {row[PRESSURE]:8.0f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
