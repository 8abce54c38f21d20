"""Tests of tools/vtk_frame.py (run by ctest, label tools): it reads a frame the partimix
program writes (PARTIMIX_BINARY, which ctest sets) with the arrays, shapes and values the case
puts in it.
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

from vtk_frame import read_frame  # noqa: E402

FLUID = 0  # partimix's kind of a fluid particle


class FrameReaderTest(unittest.TestCase):
    def test_reads_the_frame_partimix_writes(self):
        binary = os.environ.get("PARTIMIX_BINARY")
        if not binary:
            self.skipTest("PARTIMIX_BINARY is not set (ctest sets it)")
        case = os.path.join(TOOLS, "..", "cases", "bohl_central_cmc.yaml")
        with tempfile.TemporaryDirectory() as out:
            run = subprocess.run([binary, "run", case, "--out", out, "--threads", "1",
                                  "--set", "time.end=0.002", "--set", "output.frames=true"],
                                 capture_output=True, text=True, check=False)
            self.assertEqual(run.returncode, 0, run.stderr)
            arrays = read_frame(os.path.join(out, "frames", "sph_000000.vtp"))
        count = len(arrays["Points"])
        self.assertEqual(arrays["Points"].shape, (count, 3))
        self.assertEqual(arrays["velocity"].shape, (count, 3))
        for name in ("kind", "body", "id", "density"):
            self.assertEqual(arrays[name].shape, (count, 1), name)
        self.assertEqual(len(np.unique(arrays["id"])), count)
        # The mixer's fill (radius 0.0693 m, height 0.1775 m, dp = 7 mm) is fluid at the water
        # density on a lattice inside it; the plate is body 1.
        fluid = arrays["kind"][:, 0] == FLUID
        x = arrays["Points"][fluid]
        spacing, radius, height = 0.007, 0.0693, 0.1775
        self.assertAlmostEqual(fluid.sum() * spacing**3 / (math.pi * radius**2 * height), 1.0,
                               delta=0.1)
        self.assertLess(np.hypot(x[:, 0], x[:, 1]).max(), radius)
        self.assertGreater(x[:, 2].min(), 0.0)
        self.assertAlmostEqual(x[:, 2].max(), height - spacing / 2, delta=spacing)
        self.assertAlmostEqual(np.median(arrays["density"][fluid, 0]), 1000.0, delta=50.0)
        self.assertGreater((arrays["body"][:, 0] == 1).sum(), 0)


if __name__ == "__main__":
    unittest.main()
