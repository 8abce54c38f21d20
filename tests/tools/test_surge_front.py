"""Tests of tools/surge_front.py (run by ctest, label tools).

A synthetic run: a wedge of fluid on a lattice, H (1 - x / L) high, whose front readings have
closed forms, and a drop ahead of it whose position follows Martin & Moyce's points with a known
delay of the start.
"""

import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
sys.path.insert(0, TOOLS)

from frame_writer import write_series  # noqa: E402
from surge_front import GRAVITY, MARTIN_MOYCE, best_delay, series  # noqa: E402

COLUMN = 0.146
SPACING = 0.005
WEDGE_LENGTH = 0.303  # L
WEDGE_HEIGHT = 0.0437  # H
DELAY = 0.2  # in T


def wedge():
    """Lattice points ((i + 1/2) dp, (j + 1/2) dp) under y = H (1 - x / L)."""
    points = []
    for i in range(int(WEDGE_LENGTH / SPACING) + 1):
        x = (i + 0.5) * SPACING
        for j in range(int(WEDGE_HEIGHT / SPACING) + 1):
            y = (j + 0.5) * SPACING
            if y < WEDGE_HEIGHT * (1.0 - x / WEDGE_LENGTH):
                points.append((x, y, 0.0))
    return np.array(points)


def martin_moyce(T):
    """Their front, linear between and beyond their points."""
    T_mm, Z_mm = MARTIN_MOYCE[:, 0], MARTIN_MOYCE[:, 1]
    if T <= T_mm[0]:
        return Z_mm[0] + (T - T_mm[0]) * (Z_mm[1] - Z_mm[0]) / (T_mm[1] - T_mm[0])
    if T >= T_mm[-1]:
        return Z_mm[-1] + (T - T_mm[-1]) * (Z_mm[-1] - Z_mm[-2]) / (T_mm[-1] - T_mm[-2])
    return np.interp(T, T_mm, Z_mm)


def lattice_front(depth):
    """The largest lattice x with a particle at y = (depth - 1/2) dp under the wedge's top."""
    i = np.floor(WEDGE_LENGTH * (1.0 - (depth - 0.5) * SPACING / WEDGE_HEIGHT) / SPACING - 0.5)
    return (i + 0.5) * SPACING


class SurgeFrontTest(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.TemporaryDirectory()
        self.run = self.directory.name
        fluid = wedge()
        scale = np.sqrt(2.0 * GRAVITY / COLUMN)
        frames = []
        for T in np.arange(0.0, 2.8, 0.01):
            # The drop is on the floor, well ahead of the wedge (Z >= 2.4 + the delay's share).
            drop = np.array([[COLUMN * (martin_moyce(T + DELAY) + 1.0), 0.5 * SPACING, 0.0]])
            points = np.vstack([fluid, drop])
            frames.append((T / scale, points, np.zeros(len(points)), np.full(len(points), -1)))
        write_series(self.run, frames)

    def tearDown(self):
        self.directory.cleanup()

    def test_each_reading_has_its_closed_form(self):
        rows = series(self.run, SPACING, COLUMN, [2.0, 4.0])
        k = 100  # any frame: the wedge does not move
        self.assertAlmostEqual(rows[k, 1], martin_moyce(rows[k, 0] + DELAY) + 1.0, delta=1e-9)
        self.assertAlmostEqual(rows[k, 2] * COLUMN, lattice_front(1.0), delta=1e-12)
        self.assertAlmostEqual(rows[k, 3] * COLUMN, lattice_front(2.0), delta=1e-12)
        self.assertAlmostEqual(rows[k, 4] * COLUMN, lattice_front(4.0), delta=1e-12)
        self.assertLess(rows[k, 4], rows[k, 3])

    def test_the_delay_of_the_start_is_found(self):
        # A tip that runs Martin & Moyce's course shifted by one column ahead and started DELAY
        # early: take the column off and the best delay is DELAY, leaving nothing.
        rows = series(self.run, SPACING, COLUMN, [])
        rows[:, 1] -= 1.0
        shift, left = best_delay(rows)
        self.assertAlmostEqual(shift, DELAY, delta=1.5e-3)
        self.assertLess(np.abs(left).max(), 2e-3)

    def test_bad_input_exits_2_with_a_reason(self):
        tool = os.path.join(TOOLS, "surge_front.py")
        short = os.path.join(self.run, "short")
        write_series(short, [(0.0, wedge(), np.zeros(len(wedge())), np.full(len(wedge()), -1))])
        for folder, reason in ((os.path.join(self.run, "none"), "No such file"),
                               (short, "before Martin & Moyce's last point")):
            run = subprocess.run([sys.executable, tool, folder, "--spacing", str(SPACING)],
                                 capture_output=True, text=True, check=False)
            self.assertEqual(run.returncode, 2, run.stderr)
            self.assertIn(reason, run.stderr)


if __name__ == "__main__":
    unittest.main()
