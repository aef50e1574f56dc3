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

"""VTK PolyData of the force network and the wire (nscd-analysis vtk-network, vtk-wire),
read back as XML; time series from a log (timeseries); errors that name the problem."""

import os
import tempfile
import unittest
import xml.etree.ElementTree as ET

import numpy as np

import synthetic
from nscd_analysis import cli

PAIR_HEADER = synthetic.indexed("p", 16)


def read_vtp(path):
    """Points, line connectivity and the data arrays (by name) of a .vtp written in ascii."""
    piece = ET.parse(path).getroot().find("PolyData/Piece")
    def array(node):
        values = np.array(node.text.split(), dtype=float)
        k = int(node.get("NumberOfComponents", "1"))
        return values.reshape(-1, k) if k > 1 else values
    points = array(piece.find("Points/DataArray"))
    lines = {a.get("Name"): array(a) for a in piece.findall("Lines/DataArray")}
    cells = {a.get("Name"): array(a) for a in piece.findall("CellData/DataArray")}
    point_data = {a.get("Name"): array(a) for a in piece.findall("PointData/DataArray")}
    return points, lines["connectivity"].astype(int).reshape(-1, 2), lines["offsets"], point_data, cells, piece


class Network(unittest.TestCase):
    def test_pairs_become_segments_between_centres(self):
        rows = [[1, 2, 0, 0, 0, 0, 0, 1, 3.0, 0, 0, 3.0, 4, 0, 0, -1],
                [2, 3, 0, 0, 1, 1, 0, 1, 1.5, -1.5, 0, 0, 2, -1, 0, 0],
                [3, 4, 1, 0, 1, 2, 0, 1, 0.0, 0, 0, 0, 1, 1, 0, 0],        # no force: left out
                [1, -1, 0, 0, 0, 0, 0, -0.5, 6.0, 0, 0, 6.0, 4, 0, 0, 1]]   # floor: only on request
        with tempfile.TemporaryDirectory() as d:
            path = synthetic.write_dump(os.path.join(d, "pairs.dump"), [(0, PAIR_HEADER, []), (40, PAIR_HEADER, rows)],
                                        "ENTRIES")
            out = os.path.join(d, "vtk", "network")
            self.assertEqual(cli.main(["vtk-network", path, "-o", out]), 0)
            self.assertTrue(os.path.exists(out + ".0.vtp"))    # an empty network is a valid file
            points, lines, offsets, point_data, cells, piece = read_vtp(out + ".40.vtp")
            self.assertEqual(piece.get("NumberOfLines"), "2")
            np.testing.assert_array_equal(points, [[0, 0, 0], [0, 0, 1], [0, 0, 1], [1, 0, 1]])
            np.testing.assert_array_equal(lines, [[0, 1], [2, 3]])
            np.testing.assert_array_equal(offsets, [2, 4])
            np.testing.assert_array_equal(cells["fn"], [3.0, 1.5])
            np.testing.assert_array_equal(cells["fn_norm"], [1.0, 0.5])
            np.testing.assert_array_equal(point_data["fn_norm"], [1.0, 1.0, 0.5, 0.5])
            np.testing.assert_array_equal(cells["force"], [[0, 0, 3.0], [-1.5, 0, 0]])
            self.assertEqual(cli.main(["vtk-network", path, "--steps", "40", "--with-boundaries",
                                       "--reference-force", "12", "-o", out]), 0)
            _, lines, _, _, cells, _ = read_vtp(out + ".40.vtp")
            self.assertEqual(len(lines), 3)
            np.testing.assert_array_equal(cells["fn_norm"], [0.25, 0.125, 0.5])


class Wire(unittest.TestCase):
    def test_elements_become_segments_between_nodes_with_their_energy(self):
        # a square loop of four nodes (IDs 11-14) among grains (IDs 1-2) in the node dump
        nodes = [[1, 5, 5, 5], [11, 0, 0, 0], [12, 1, 0, 0], [2, 6, 6, 6], [13, 1, 1, 0], [14, 0, 1, 0]]
        elements = [[11, 12, 0.01, 0.2, 0.001], [12, 13, 0.02, 0.4, 0.004], [13, 14, 0.0, 0.0, 0.0],
                    [14, 11, 0.01, 0.2, 0.001]]
        with tempfile.TemporaryDirectory() as d:
            node_path = synthetic.write_dump(os.path.join(d, "nodes.dump"),
                                             [(0, ["id", "x", "y", "z"], nodes), (9, ["id", "x", "y", "z"], nodes)])
            element_path = synthetic.write_dump(os.path.join(d, "wire.dump"), [(9, synthetic.indexed("el", 5), elements)],
                                                "ENTRIES")
            out = os.path.join(d, "wire")
            self.assertEqual(cli.main(["vtk-wire", "--elements", element_path, "--nodes", node_path, "-o", out]), 0)
            points, lines, _, point_data, cells, _ = read_vtp(out + ".9.vtp")
            np.testing.assert_array_equal(point_data["id"], [11, 12, 13, 14])
            np.testing.assert_array_equal(points, [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]])
            np.testing.assert_array_equal(lines, [[0, 1], [1, 2], [2, 3], [3, 0]])
            np.testing.assert_array_equal(cells["energy"], [0.001, 0.004, 0.0, 0.001])
            np.testing.assert_array_equal(cells["energy_norm"], [0.25, 1.0, 0.0, 0.25])
            np.testing.assert_array_equal(cells["tension"], [0.2, 0.4, 0.0, 0.2])
            np.testing.assert_allclose(point_data["node_energy"], [0.001, 0.0025, 0.002, 0.0005])

    def test_a_node_without_position_is_named(self):
        with tempfile.TemporaryDirectory() as d:
            node_path = synthetic.write_dump(os.path.join(d, "n.dump"), [(0, ["id", "x", "y", "z"], [[11, 0, 0, 0]])])
            element_path = synthetic.write_dump(os.path.join(d, "w.dump"), [(0, synthetic.indexed("el", 5),
                                                                              [[11, 12, 0, 0, 0]])], "ENTRIES")
            with _stderr() as err:
                self.assertEqual(cli.main(["vtk-wire", "--elements", element_path, "--nodes", node_path,
                                           "-o", os.path.join(d, "w")]), 1)
            self.assertIn("no position for wire node IDs [12]", err.getvalue())


class TimeSeries(unittest.TestCase):
    def test_panels_and_csv_from_thermo_columns(self):
        runs = [(["Step", "v_height", "f_w[1]"], [[0, 10.0, 0.0], [100, 9.5, 0.1]]),
                (["Step", "v_height", "f_w[1]", "v_disp", "f_plate[3]"],
                 [[100, 9.5, 0.1, 0.0, 0.0], [200, 9.4, 0.2, 0.01, -5.0], [300, 9.3, 0.3, 0.02, -10.0]])]
        with tempfile.TemporaryDirectory() as d:
            log = os.path.join(d, "log.lammps")
            with open(log, "w") as f:
                f.write(synthetic.log_text(runs))
            out = os.path.join(d, "series")
            self.assertEqual(cli.main(["timeseries", log, "--plot", "Step:v_height", "--plot", "Step:f_w[1]",
                                       "-o", out]), 0)
            table = synthetic.read_csv(out + ".csv")
            np.testing.assert_array_equal(synthetic.csv_column(table, "v_height"), [10.0, 9.5, 9.4, 9.3])
            self.assertLess(os.path.getsize(out + ".png"), 300 * 1024)
            self.assertEqual(cli.main(["timeseries", log, "--plot", "v_disp:f_plate[3]", "--plot", "Step:v_height",
                                       "-o", out]), 0)
            table = synthetic.read_csv(out + ".csv")    # the plate's columns only in the second run
            np.testing.assert_array_equal(synthetic.csv_column(table, "f_plate[3]"), [np.nan, np.nan, -5.0, -10.0])
            np.testing.assert_array_equal(synthetic.csv_column(table, "v_height"), [10.0, 9.5, 9.4, 9.3])
            with _stderr() as err:
                self.assertEqual(cli.main(["timeseries", log, "--plot", "Step:v_nothing", "-o", out]), 1)
            self.assertIn("panel Step:v_nothing skipped: the log has no v_nothing", err.getvalue())
            self.assertIn("no panel can be drawn", err.getvalue())
            # a panel the log lacks is skipped with a warning, the others drawn
            with _stderr() as err:
                self.assertEqual(cli.main(["timeseries", log, "--plot", "Step:v_nothing", "--plot",
                                           "Step:v_height,v_gone", "-o", out]), 0)
            self.assertIn("panel Step:v_nothing skipped: the log has no v_nothing", err.getvalue())
            self.assertIn("panel Step:v_height,v_gone drawn without v_gone", err.getvalue())
            np.testing.assert_array_equal(synthetic.csv_column(synthetic.read_csv(out + ".csv"), "v_height"),
                                          [10.0, 9.5, 9.4, 9.3])

    def test_a_run_split_in_two_logs_is_joined(self):
        first = [(["Step", "v_height"], [[0, 10.0], [100, 9.5]])]
        second = [(["Step", "v_height"], [[100, 9.5], [200, 9.4]])]    # the restart repeats step 100
        with tempfile.TemporaryDirectory() as d:
            logs = []
            for k, runs in enumerate((first, second)):
                logs.append(os.path.join(d, f"log.{k}"))
                with open(logs[-1], "w") as f:
                    f.write(synthetic.log_text(runs))
            out = os.path.join(d, "series")
            self.assertEqual(cli.main(["timeseries"] + logs + ["--plot", "Step:v_height", "-o", out]), 0)
            table = synthetic.read_csv(out + ".csv")
            np.testing.assert_array_equal(synthetic.csv_column(table, "Step"), [0, 100, 200])

    def test_column_preset_reads_the_column_decks_thermo(self):
        names = ["Step", "v_phase", "v_height", "v_retained", "v_e_stretch", "v_e_bend", "v_e_contact",
                 "v_plate_force", "v_plate_disp"]
        rows = [[0, 1, 5.0, 1.0, 0, 0, 0, 0, 0], [200, 3, 4.8, 0.95, 0.1, 0.01, 0.02, 0, 0],
                [400, 5, 4.7, 0.95, 0.2, 0.02, 0.03, 50.0, -0.01]]
        with tempfile.TemporaryDirectory() as d:
            log = os.path.join(d, "log.column")
            with open(log, "w") as f:
                f.write(synthetic.log_text([(names, rows)]))
            out = os.path.join(d, "column")
            self.assertEqual(cli.main(["timeseries", log, "--preset", "column", "-o", out]), 0)
            table = synthetic.read_csv(out + ".csv")
            np.testing.assert_array_equal(synthetic.csv_column(table, "v_retained"), [1.0, 0.95, 0.95])
            np.testing.assert_array_equal(synthetic.csv_column(table, "v_plate_force"), [0, 0, 50.0])


class _stderr:
    """Captures sys.stderr."""
    def __enter__(self):
        import io
        import sys
        self.saved, sys.stderr = sys.stderr, io.StringIO()
        return sys.stderr

    def __exit__(self, *exc):
        import sys
        sys.stderr = self.saved
        return False


if __name__ == "__main__":
    unittest.main()
