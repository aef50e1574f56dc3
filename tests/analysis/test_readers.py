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

"""Dump and log readers of tools/nscd_analysis on files in LAMMPS' formats."""

import os
import tempfile
import unittest

import numpy as np

import synthetic
from nscd_analysis import dumps, layouts, logs


class DumpReading(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def path(self, name):
        return os.path.join(self.dir.name, name)

    def test_snapshots_plain_and_gzip_read_the_same(self):
        snaps = [(0, ["id", "x", "y", "z"], [[1, 0.5, -1.25, 3], [2, 1e-3, 2, 4]]),
                 (100, ["id", "x", "y", "z"], [[1, 0.75, -1.0, 2.5]])]
        for name in ("a.dump", "a.dump.gz"):
            got = dumps.read_dump(synthetic.write_dump(self.path(name), snaps))
            self.assertEqual([s.timestep for s in got], [0, 100])
            self.assertEqual(len(got[0]), 2)
            np.testing.assert_array_equal(got[0].column("y"), [-1.25, 2])
            np.testing.assert_array_equal(got[1].vectors(("x", "y", "z")), [[0.75, -1.0, 2.5]])
            np.testing.assert_array_equal(got[0].box, [[-10, 10], [-10, 10], [-1, 30]])

    def test_local_dump_with_an_empty_step(self):
        header = synthetic.indexed("p", 16)
        row = list(range(1, 17))
        path = synthetic.write_dump(self.path("pairs.dump"), [(0, header, []), (5, header, [row, row])], "ENTRIES")
        got = dumps.read_dump(path)
        self.assertEqual(len(got[0]), 0)
        self.assertEqual(got[0].vectors(("xi", "yi", "zi"), layouts.CONTACT_PAIRS).shape, (0, 3))
        np.testing.assert_array_equal(got[1].column("fn", layouts.CONTACT_PAIRS), [9, 9])

    def test_columns_by_layout_by_colname_and_subsets(self):
        # a subset of a compute's columns (c_c[9] is fn wherever it stands) and a renamed one
        header = ["c_c[1]", "c_c[2]", "c_c[9]", "fx"]
        path = synthetic.write_dump(self.path("sub.dump"), [(0, header, [[3, 4, 0.5, 0.25]])], "ENTRIES")
        s = dumps.read_dump(path)[0]
        self.assertEqual(s.column("fn", layouts.CONTACT_PAIRS)[0], 0.5)
        self.assertEqual(s.column("id_j", layouts.CONTACT_PAIRS)[0], 4)
        self.assertEqual(s.column("fx", layouts.CONTACT_PAIRS)[0], 0.25)    # by name first
        with self.assertRaisesRegex(dumps.DumpError, "no column 'nx'.*colname"):
            s.column("nx", layouts.CONTACT_PAIRS)

    def test_two_computes_in_one_dump_are_ambiguous(self):
        path = synthetic.write_dump(self.path("two.dump"), [(0, ["c_a[9]", "c_b[9]"], [[1, 2]])], "ENTRIES")
        with self.assertRaisesRegex(dumps.DumpError, "ambiguous: c_a\\[9\\], c_b\\[9\\]"):
            dumps.read_dump(path)[0].column("fn", layouts.CONTACT_PAIRS)

    def test_cut_file_is_named(self):
        text = synthetic.dump_text([(7, ["id", "x"], [[1, 2], [3, 4]])])
        with open(self.path("cut.dump"), "w") as f:
            f.write(text[:-6])
        with self.assertRaisesRegex(dumps.DumpError, "cut.dump: step 7 announces 2 rows"):
            dumps.read_dump(self.path("cut.dump"))

    def test_files_and_steps_are_selected_in_time_order(self):
        for step in (10, 2, 100):
            synthetic.write_dump(self.path(f"d.{step}.dump"), [(step, ["id"], [[1]])])
        self.assertEqual([s.timestep for s in dumps.read_dumps([self.path("d.*.dump")])], [2, 10, 100])
        self.assertEqual([s.timestep for s in dumps.read_dumps([self.path("d.*.dump")], steps=[100, 2])], [100, 2])
        self.assertEqual([s.timestep for s in dumps.read_dumps([self.path("d.*.dump")], last=True)], [100])
        with self.assertRaisesRegex(dumps.DumpError, r"timesteps \[5\] not in"):
            dumps.read_dumps([self.path("d.*.dump")], steps=[5])


class LogReading(unittest.TestCase):
    def test_thermo_blocks_with_warnings_and_repeated_steps(self):
        runs = [(["Step", "v_h", "c_ke"], [[0, 5.0, 1.0], [100, 4.5, 0.5]]),
                (["Step", "v_h", "c_ke", "f_plate[3]"], [[100, 4.5, 0.5, 0.0], [200, 4.2, 0.1, -3.0]])]
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "log.lammps")
            with open(path, "w") as f:
                f.write(synthetic.log_text(runs, warning_inside=True))
            blocks = logs.read_thermo(path)
            self.assertEqual(len(blocks), 2)
            self.assertEqual(blocks[1][0], ["Step", "v_h", "c_ke", "f_plate[3]"])
            np.testing.assert_array_equal(logs.thermo_columns(path, ["Step", "v_h"]), [[0, 5.0], [100, 4.5], [200, 4.2]])
            np.testing.assert_array_equal(logs.thermo_columns(path, ["v_h", "f_plate[3]"]), [[4.5, 0.0], [4.2, -3.0]])
            with self.assertRaisesRegex(logs.LogError, "no run prints all of v_x.*thermo columns: Step"):
                logs.thermo_columns(path, ["v_x"])

    def test_reset_timestep_keeps_the_next_run(self):
        runs = [(["Step", "v_h"], [[0, 5.0], [600, 4.0]]), (["Step", "v_h"], [[0, 4.0], [300, 3.5]])]
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "log.lammps")
            with open(path, "w") as f:
                f.write(synthetic.log_text(runs))
            np.testing.assert_array_equal(logs.thermo_columns(path, ["v_h"]).ravel(), [5.0, 4.0, 4.0, 3.5])


if __name__ == "__main__":
    unittest.main()
