"""Tests of tools/plate_crosstalk.py (run by ctest, label tools).

The plate tool's shares are checked against their definition evaluated by a direct double loop
on a synthetic frame, for a plate placed along the axes and the same plate turned and moved.
"""

import math
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
sys.path.insert(0, TOOLS)

from plate_crosstalk import measure  # noqa: E402
from vtk_frame import read_frame  # noqa: E402
from frame_writer import write_frame  # noqa: E402

SPACING = 0.01
# h/dp = 1.3, not partimix's 1.5: the tool keeps the particles more than 2h inside the plate's
# extent, and with 2h = 3 dp that edge would pass through lattice points (ties of round-off).
H = 1.3 * SPACING
FLUID, BODY = 0, 2  # partimix's kinds of particle; the tool only needs fluid = 0


def plate_and_fluid(gap):
    """A 2-layer plate in the plane z = 0 (layers at +-dp/2), 16 x 12 spacings, with three fluid
    layers on each face, the first at |z| = gap, over a slightly larger extent."""
    kind, body, points = [], [], []
    for i in range(16):
        for j in range(12):
            for z in (-0.5, 0.5):
                points.append(((i - 7.5) * SPACING, (j - 5.5) * SPACING, z * SPACING))
                kind.append(BODY)
                body.append(1)
    for i in range(20):
        for j in range(16):
            for layer in range(3):
                for side in (-1.0, 1.0):
                    z = side * (gap + layer * SPACING)
                    points.append(((i - 9.5) * SPACING, (j - 7.5) * SPACING, z))
                    kind.append(FLUID)
                    body.append(-1)
    return np.array(points), np.array(kind), np.array(body)


def far_share_by_definition(points, kind, k, side_of):
    """The share of particle k's fluid Wendland C2 weight (h = H) from the other side."""
    near = far = 0.0
    for m in np.flatnonzero(kind == FLUID):
        q = np.linalg.norm(points[m] - points[k]) / H
        if q < 2.0:
            weight = (1.0 - q / 2.0) ** 4 * (2.0 * q + 1.0)
            if side_of(points[m]) == side_of(points[k]):
                near += weight
            else:
                far += weight
    return far / (near + far)


def rotation(angle_x, angle_z):
    cx, sx, cz, sz = math.cos(angle_x), math.sin(angle_x), math.cos(angle_z), math.sin(angle_z)
    return np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]]) @ \
        np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])


class PlateCrosstalkTest(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.directory.cleanup()

    def measure_frame(self, points, kind, body):
        path = os.path.join(self.directory.name, "frame.vtp")
        write_frame(path, points, kind, body)
        return measure(read_frame(path), 1, H)

    def test_faces_further_apart_than_the_support_share_nothing(self):
        # Fluid at |z| >= 1.05 h: the two faces' fluid are more than 2h apart.
        fluid_share, _, closest = self.measure_frame(*plate_and_fluid(1.05 * H))
        self.assertGreater(np.isfinite(fluid_share).sum(), 0)
        self.assertEqual(np.nanmax(fluid_share), 0.0)
        self.assertAlmostEqual(closest, 1.05 * H, delta=1e-12)

    def test_shares_match_their_definition_and_do_not_depend_on_the_plate_pose(self):
        # Fluid at |z| = 0.8 dp: fluid within 2h of each other across the plate.
        points, kind, body = plate_and_fluid(0.8 * SPACING)
        fluid_share, body_share, closest = self.measure_frame(points, kind, body)
        self.assertAlmostEqual(closest, 0.8 * SPACING, delta=1e-12)
        # Near the middle of the plate: plate particle (7, 5) at z = +dp/2 (index 2 * (7 * 12 +
        # 5) + 1) and the fluid point (9, 7) above it in the first layer.
        plate_index = 2 * (7 * 12 + 5) + 1
        fluid_index = 16 * 12 * 2 + 2 * 3 * (9 * 16 + 7) + 1
        side = lambda x: np.sign(x[2])  # noqa: E731
        expected_body = far_share_by_definition(points, kind, plate_index, side)
        expected_fluid = far_share_by_definition(points, kind, fluid_index, side)
        self.assertGreater(expected_fluid, 1e-3)
        self.assertTrue(np.any(np.abs(body_share - expected_body) < 1e-12))
        self.assertTrue(np.any(np.abs(fluid_share - expected_fluid) < 1e-12))
        # The same plate and fluid turned about two axes and moved.
        turn = rotation(0.7, -1.1)
        moved = points @ turn.T + np.array([0.3, -0.2, 1.5])
        fluid_turned, body_turned, closest_turned = self.measure_frame(moved, kind, body)
        self.assertAlmostEqual(closest_turned, closest, delta=1e-12)
        np.testing.assert_allclose(np.sort(fluid_turned), np.sort(fluid_share), atol=1e-12)
        np.testing.assert_allclose(np.sort(body_turned), np.sort(body_share), atol=1e-12)

    def test_bad_input_exits_2_with_a_reason(self):
        tool = os.path.join(TOOLS, "plate_crosstalk.py")
        not_a_frame = os.path.join(self.directory.name, "not_a_frame.vtp")
        with open(not_a_frame, "w") as out:
            out.write("hello")
        points, kind, body = plate_and_fluid(1.05 * H)
        no_body = os.path.join(self.directory.name, "no_body.vtp")
        write_frame(no_body, points, kind, np.where(body == 1, 4, body))
        for path, reason in ((not_a_frame, "not a frame"), (no_body, "no particle of body 1")):
            run = subprocess.run([sys.executable, tool, path, "--spacing", str(SPACING)],
                                 capture_output=True, text=True, check=False)
            self.assertEqual(run.returncode, 2, run.stderr)
            self.assertIn(reason, run.stderr)


if __name__ == "__main__":
    unittest.main()
