"""Tests of tools/truck_drum_grains.py (run by ctest, label tools).

The concrete case's drum (1:10 of the 8 m^3 drum) with its mortar level: every grain lies in
the drum's core (the shell's radius less the clearance, less its own radius) and below the level
by at least its radius, no two overlap, the species follow the split (or are mixed), the seed
makes the file reproducible, and a mortar too small for the grains is exit 2.
"""

import csv
import math
import os
import subprocess
import sys
import tempfile
import unittest

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
sys.path.insert(0, TOOLS)

from truck_drum_grains import shell_radius  # noqa: E402

PROFILE = [0.09, 0.18, 0.115, 0.16, 0.20, 0.035]
LEVEL = [0.27, 0.0, 0.0, 0.25882, 0.0, 0.96593]
RADIUS = 0.0005
CLEARANCE = 0.03


def run(out, count, extra):
    args = [sys.executable, os.path.join(TOOLS, "truck_drum_grains.py"), out, "--count",
            str(count), "--radius", str(RADIUS), "--seed", "3", "--profile"]
    args += [str(v) for v in PROFILE] + ["--clearance", str(CLEARANCE), "--level"]
    args += [str(v) for v in LEVEL] + extra
    return subprocess.run(args, capture_output=True, text=True, check=False)


def read(out):
    with open(out, encoding="utf-8") as f:
        rows = [line for line in f if not line.startswith("#")]
    return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(rows)]


class TruckDrumGrainsTest(unittest.TestCase):
    def test_grains_lie_in_the_mortar_core_apart_and_split(self):
        with tempfile.TemporaryDirectory() as folder:
            out = os.path.join(folder, "grains.csv")
            self.assertEqual(run(out, 400, ["--split", "0.18"]).returncode, 0)
            grains = read(out)
            self.assertEqual(len(grains), 400)
            norm = math.hypot(LEVEL[3], LEVEL[5])
            for g in grains:
                x, y, z = g["x"], g["y"], g["z"]
                self.assertLessEqual(math.hypot(y, z) + RADIUS,
                                     shell_radius(x, PROFILE) - CLEARANCE + 1e-12)
                height = ((x - LEVEL[0]) * LEVEL[3] + z * LEVEL[5]) / norm
                self.assertLess(height, -RADIUS)
                self.assertEqual(g["species"], 1.0 if x > 0.18 else 0.0)
                self.assertEqual(g["radius"], RADIUS)
            points = [(g["x"], g["y"], g["z"]) for g in grains]
            closest = min(math.dist(p, q) for i, p in enumerate(points) for q in points[:i])
            self.assertGreaterEqual(closest, 2.0 * RADIUS)

    def test_the_seed_reproduces_the_file_and_mixed_gives_both_species(self):
        with tempfile.TemporaryDirectory() as folder:
            first = os.path.join(folder, "a.csv")
            second = os.path.join(folder, "b.csv")
            run(first, 200, ["--mixed"])
            run(second, 200, ["--mixed"])
            with open(first, encoding="utf-8") as a, open(second, encoding="utf-8") as b:
                self.assertEqual(a.read().split("\n", 1)[1], b.read().split("\n", 1)[1])
            species = [g["species"] for g in read(first)]
            self.assertGreater(species.count(0.0), 50)
            self.assertGreater(species.count(1.0), 50)

    def test_no_room_is_exit_2(self):
        with tempfile.TemporaryDirectory() as folder:
            out = os.path.join(folder, "grains.csv")
            result = run(out, 10, ["--split", "0.18", "--clearance", "0.2"])
            self.assertEqual(result.returncode, 2)
            self.assertIn("no room", result.stderr)
            self.assertFalse(os.path.exists(out))


if __name__ == "__main__":
    unittest.main()
