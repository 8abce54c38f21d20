"""Tests of tools/thin_ring_estimate.py (run by ctest, label tools).

The ring's integration against closed forms: the elastic plane-strain modulus, rigid-plastic
linear hardening and its Considère peak, the linear damage law's failure; and the command line
on the gel droplet case's shell against the figures of docs/multi-material-sph.md.
"""

import math
import os
import re
import subprocess
import sys
import unittest

import numpy as np

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
sys.path.insert(0, TOOLS)

from thin_ring_estimate import (DAMAGE, HOOP_STRESS, PLASTIC_STRAIN, PRESSURE,  # noqa: E402
                                STRAIN, SWELLING, Material, flow_stress, inflate)

RADIUS, THICKNESS = 0.48e-3, 40e-6  # the case's shell, R0 and t0
NEVER = 1e30  # a yield stress or damage threshold never reached
SHELL = dict(G=2.0e7, K=9.0e7, A=5.0e5, B=8.0e6, n=1.0, p_d=0.32, p_f=0.36)


class ThinRingEstimateTest(unittest.TestCase):
    def test_elastic_ring_has_the_plane_strain_modulus(self):
        # Plane strain with σ_r = 0: σ_r = λ (ε_r + ε) + 2 G ε_r = 0 gives ε_r = -λ ε / (λ + 2 G),
        # and σ_θ = λ (ε_r + ε) + 2 G ε = 4 G (λ + G) / (λ + 2 G) ε; with λ = K - 2 G / 3,
        # E' = 4 G (3 K + G) / (3 K + 4 G). Hooke's law is linear and the log-strain increments
        # add up to ε exactly, so the integration has no O(ε) or step error in σ_θ: only
        # round-off and the σ_r solve (dε_r to 1e-13 of dε) are left, hence 1e-12 relative.
        G, K, strain = SHELL["G"], SHELL["K"], 1e-3
        rows = inflate(Material(G, K, NEVER, 0.0, 1.0, NEVER, 2.0 * NEVER), RADIUS, THICKNESS,
                       strain, 10)
        modulus = 4.0 * G * (3.0 * K + G) / (3.0 * K + 4.0 * G)
        last = rows[-1]
        self.assertAlmostEqual(last[STRAIN], strain, delta=1e-15)
        outline = (RADIUS * math.exp(strain) + THICKNESS / 2.0 * math.exp(-strain)) / \
            (RADIUS + THICKNESS / 2.0)
        self.assertAlmostEqual(last[SWELLING], outline, delta=1e-15)
        self.assertAlmostEqual(last[HOOP_STRESS] / (modulus * strain), 1.0, delta=1e-12)
        self.assertAlmostEqual(last[PRESSURE] / (modulus * strain * THICKNESS / RADIUS *
                                                 math.exp(-2.0 * strain)), 1.0, delta=1e-12)
        self.assertEqual(last[PLASTIC_STRAIN], 0.0)

    def test_rigid_plastic_linear_hardening_peaks_at_considere(self):
        # G, K = 1e12: rigid-plastic. In plane strain with σ_r = 0 the flow is incompressible,
        # ε_r = -ε, so ε_eq = (2 / √3) ε; σ_z = σ_θ / 2, so σ_eq = (√3 / 2) σ_θ; thus
        # σ_θ = (2 / √3) (A + B (2 / √3) ε). Δp = σ_θ (t0 / R0) e^(-2ε) peaks where
        # dσ_θ/dε = 2 σ_θ: ε* = 1/2 - √3 A / (2 B), Δp* = (2 B / 3) (t0 / R0) e^(-2ε*).
        A, B, steps, max_strain = 1.0e6, 8.0e6, 2000, 0.5
        step = max_strain / steps
        rows = inflate(Material(1e12, 1e12, A, B, 1.0, NEVER, 2.0 * NEVER), RADIUS, THICKNESS,
                       max_strain, steps)
        strain = rows[:, STRAIN]
        # The radial return takes the step's start's flow stress, so σ_θ trails the curve by one
        # step's hardening, (4/3) B dε; the elastic strains (σ / G ~ 5e-6) add 2% of that.
        hoop = 2.0 / math.sqrt(3.0) * (A + B * 2.0 / math.sqrt(3.0) * strain)
        self.assertLess(np.abs(rows[:, HOOP_STRESS] - hoop).max(), 1.05 * 4.0 / 3.0 * B * step)
        # ε_p = ε_eq up to the elastic strains, σ / G <= 5e-6.
        self.assertLess(np.abs(rows[:, PLASTIC_STRAIN] - 2.0 / math.sqrt(3.0) * strain).max(),
                        1e-5)
        peak_strain = 0.5 - math.sqrt(3.0) * A / (2.0 * B)
        peak_pressure = 2.0 * B / 3.0 * THICKNESS / RADIUS * math.exp(-2.0 * peak_strain)
        peak = rows[int(np.argmax(rows[:, PRESSURE]))]
        # The trailing stress moves the peak one step later; the grid adds half a step.
        self.assertAlmostEqual(peak[STRAIN], peak_strain, delta=2.0 * step)
        # The trailing (4/3) B dε is 2 dε of σ_θ* = 2 B / 3; the flat peak's grid error is
        # O(dε²).
        self.assertAlmostEqual(peak[PRESSURE] / peak_pressure, 1.0, delta=3.0 * step)

    def test_damage_takes_the_stress_to_zero_past_the_failure_strain(self):
        p_d, p_f = 0.05, 0.1
        material = Material(SHELL["G"], SHELL["K"], SHELL["A"], SHELL["B"], SHELL["n"], p_d, p_f)
        self.assertEqual(flow_stress(material, p_f, 1.0), 0.0)
        rows = inflate(material, RADIUS, THICKNESS, 0.3, 1200)
        plastic, damage = rows[:, PLASTIC_STRAIN], rows[:, DAMAGE]
        self.assertEqual(damage[plastic <= p_d].max(), 0.0)
        failed = np.flatnonzero(plastic >= p_f)
        self.assertGreater(len(failed), 100)
        self.assertTrue((damage[failed] == 1.0).all())
        # The step that reaches p_f still returned onto the previous step's (1 - D) σ_y; from
        # the next on σ_y = 0, S = 0 and σ_r = 0 leaves the mean stress, hence σ_θ, at zero up to
        # the σ_r solve (K x 1e-13 dε ~ 1e-9 Pa): 1e-3 Pa, 1e-9 of A.
        after = failed[1:]
        self.assertLess(np.abs(rows[after, HOOP_STRESS]).max(), 1e-3)
        self.assertLess(np.abs(rows[after, PRESSURE]).max(), 1e-3 * THICKNESS / RADIUS)
        # Softening: Δp falls while the damage grows (at D = 0 the flow stress's slope in ε_p
        # is B - (A + B p_d) / (p_f - p_d) < 0).
        damaging = np.flatnonzero((plastic > p_d) & (plastic < p_f))
        self.assertTrue((np.diff(rows[damaging, PRESSURE]) < 0.0).all())

    def test_command_line_gives_the_documented_peak_for_the_case_shell(self):
        # docs/multi-material-sph.md, "The droplet": the shell as shipped rises to 152 kPa at
        # D/D0 = 1.365 (of the outline; the mean radius has swollen by 1.39 then). A smoke test that the command line runs and prints them: 5,000 steps
        # (dε = 1e-4) move the peak by 0.02% against the default 20,000.
        args = [sys.executable, os.path.join(TOOLS, "thin_ring_estimate.py"), "--steps", "5000",
                "--shear-modulus", str(SHELL["G"]), "--bulk-modulus", str(SHELL["K"]),
                "--A", str(SHELL["A"]), "--B", str(SHELL["B"]), "--n", str(SHELL["n"]),
                "--damage-threshold", str(SHELL["p_d"]), "--failure-strain", str(SHELL["p_f"]),
                "--radius", str(RADIUS), "--thickness", str(THICKNESS)]
        run = subprocess.run(args, capture_output=True, text=True, check=False)
        self.assertEqual(run.returncode, 0, run.stderr)
        found = re.search(r"peak (\S+) Pa at D/D0 (\S+)", run.stdout)
        self.assertIsNotNone(found, run.stdout)
        self.assertTrue(140e3 <= float(found.group(1)) <= 165e3, run.stdout)
        self.assertTrue(1.35 <= float(found.group(2)) <= 1.43, run.stdout)

    def test_bad_input_exits_2_with_a_reason(self):
        tool = os.path.join(TOOLS, "thin_ring_estimate.py")
        run = subprocess.run([sys.executable, tool, "--damage-threshold", "0.4",
                              "--failure-strain", "0.3"],
                             capture_output=True, text=True, check=False)
        self.assertEqual(run.returncode, 2, run.stderr)
        self.assertIn("must exceed the damage threshold", run.stderr)


if __name__ == "__main__":
    unittest.main()
