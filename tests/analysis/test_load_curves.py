# ----------------------------------------------------------------------
# NSCD package for LAMMPS: Non-Smooth Contact Dynamics of rigid
# spheropolyhedra coupled to elastic wires.
#
# Copyright (2026) the NSCD package developers. This software is
# distributed under the GNU General Public License, version 2, the
# licence of LAMMPS. See the LICENSE file in the top-level directory
# of the package.
# ----------------------------------------------------------------------
# Contributing author: the NSCD package developers
# ----------------------------------------------------------------------

"""The plate's load-displacement files (nscd-analysis load-curves): a known linear curve gives
its sink at any load it reached, the largest force and the last row; seeds give mean and sd;
a damaged file is refused naming its line."""

import os
import tempfile
import unittest

import numpy as np

import synthetic
from nscd_analysis import cli, load_curves

TITLE = "# step load force_on_plate displacement sink_over_window\n"


def write_curve(path, stiffness, last_load, peak_at=None):
    """Load 0, 1, ... last_load; the plate sinks load / stiffness (displacement negative); the
    force on the plate is the load plus the plate's weight 10, with a bump of +50 at peak_at."""
    with open(path, "w") as f:
        f.write(TITLE)
        for k, load in enumerate(np.arange(0.0, last_load + 0.5, 1.0)):
            force = load + 10.0 + (50.0 if peak_at is not None and load == peak_at else 0.0)
            f.write(f"{1000 + 20 * k} {load} {force} {-load / stiffness} 0\n")
    return path


class LoadCurves(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def test_linear_curve_gives_its_sink_at_each_load(self):
        path = write_curve(os.path.join(self.dir.name, "a.txt"), 200.0, 60, peak_at=40)
        curve = load_curves.read_load_curve(path)
        self.assertEqual(curve.shape, (61, 5))
        np.testing.assert_allclose(load_curves.sink_at_loads(curve, [0, 12.5, 60, 61]),
                                   [0, 12.5 / 200, 60 / 200, np.nan], atol=1e-15)
        last_load, last_sink, peak, peak_sink = load_curves.summary(curve)
        self.assertEqual((last_load, peak), (60.0, 100.0))
        self.assertAlmostEqual(last_sink, 0.3)
        self.assertAlmostEqual(peak_sink, 0.2)

    def test_seeds_give_mean_and_sd_of_the_sink_and_the_figure(self):
        files = [write_curve(os.path.join(self.dir.name, f"s{k}.txt"), stiffness, last)
                 for k, (stiffness, last) in enumerate(((100.0, 80), (200.0, 80), (400.0, 30)))]
        out = os.path.join(self.dir.name, "curves")
        self.assertEqual(cli.main(["load-curves", "--run", "rings=" + ",".join(files), "--at", "20", "50",
                                   "-o", out]), 0)
        table = synthetic.read_csv(out + ".csv")
        self.assertEqual([row["last_load"] for row in table[:3]], [80, 80, 30])
        mean = [row for row in table if row["file"] == "mean"][0]
        sd = [row for row in table if row["file"] == "sd"][0]
        sinks_20 = [0.2, 0.1, 0.05]
        self.assertAlmostEqual(mean["sink_at_20"], np.mean(sinks_20), places=6)
        self.assertAlmostEqual(sd["sink_at_20"], np.std(sinks_20, ddof=1), places=6)
        self.assertAlmostEqual(mean["sink_at_50"], 0.375, places=6)    # the third curve stopped at 30
        self.assertLess(os.path.getsize(out + ".png"), 300 * 1024)

    def test_damaged_file_is_refused_naming_the_line(self):
        path = os.path.join(self.dir.name, "bad.txt")
        with open(path, "w") as f:
            f.write(TITLE + "1000 0 10 0 0\n1020 1 11 -0.01\n")
        with self.assertRaisesRegex(load_curves.LoadCurveError, "bad.txt, line 3"):
            load_curves.read_load_curve(path)
        with open(path, "w") as f:
            f.write(TITLE)
        with self.assertRaisesRegex(load_curves.LoadCurveError, "no rows"):
            load_curves.read_load_curve(path)
        self.assertEqual(cli.main(["load-curves", "--run", f"x={path}", "-o", os.path.join(self.dir.name, "o")]), 1)


if __name__ == "__main__":
    unittest.main()
