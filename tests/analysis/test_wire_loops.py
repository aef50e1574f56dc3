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

"""nscd-analysis wire-loops: chains found from the elements, and radius, turns, length and
slack against loops of known shape (helix, wavy ring, ring off the axis)."""

import contextlib
import csv
import io
import math
import os
import tempfile
import unittest

import numpy as np

import synthetic
from nscd_analysis import cli, wire_loops


def helix(first_id, radius, turns, pitch, nodes, z0=0.0, centre=(0.0, 0.0)):
    """Node rows id x y z of a helix from angle 0 over `turns`, and its element rows."""
    angles = np.linspace(0.0, 2.0 * math.pi * turns, nodes)
    rows = [[first_id + k, centre[0] + radius * math.cos(a), centre[1] + radius * math.sin(a),
             z0 + pitch * a / (2.0 * math.pi)] for k, a in enumerate(angles)]
    return rows, [[first_id + k, first_id + k + 1, 0, 0, 0] for k in range(nodes - 1)]


class Chains(unittest.TestCase):
    def test_open_chains_are_walked_from_an_end_and_rings_are_closed(self):
        # an open chain given out of order (5-6-7-8), a ring 20-21-22-23, a single element 30-31
        found = wire_loops.chains([7, 5, 6, 20, 21, 22, 23, 31], [8, 6, 7, 21, 22, 23, 20, 30])
        self.assertEqual(found, [([5, 6, 7, 8], False), ([20, 21, 22, 23], True), ([30, 31], False)])

    def test_a_node_with_three_elements_is_refused(self):
        with self.assertRaisesRegex(ValueError, r"wire nodes \[2\] join more than two elements"):
            wire_loops.chains([1, 2, 2], [2, 3, 4])


class Measures(unittest.TestCase):
    def test_helix_length_turns_and_slack_in_closed_form(self):
        radius, turns, pitch, nodes = 2.5, 1.75, 0.3, 2001
        rows, _ = helix(1, radius, turns, pitch, nodes, z0=4.0)
        m = wire_loops.loop_measures(np.array(rows)[:, 1:], closed=False)
        step = 2.0 * math.pi * turns / (nodes - 1)    # angle per element
        chord = math.hypot(2.0 * radius * math.sin(0.5 * step), pitch * step / (2.0 * math.pi))
        self.assertEqual(m["nodes"], nodes)
        self.assertAlmostEqual(m["r_median"], radius, places=12)
        self.assertAlmostEqual(m["turns"], turns, places=12)
        self.assertAlmostEqual(m["z_mean"], 4.0 + 0.5 * turns * pitch, places=12)
        self.assertAlmostEqual(m["z_span"], turns * pitch, places=12)    # the helix's rise
        self.assertAlmostEqual(m["length"], (nodes - 1) * chord, places=10)
        self.assertAlmostEqual(m["horizontal_length"], (nodes - 1) * 2.0 * radius * math.sin(0.5 * step), places=10)
        self.assertAlmostEqual(m["slack"], (nodes - 1) * chord / (2.0 * math.pi * radius * turns) - 1.0, places=12)
        # and the continuous helix's slack within the chords' shortfall, step^2 / 24
        exact_slack = math.sqrt(1.0 + (pitch / (2.0 * math.pi * radius)) ** 2) - 1.0
        self.assertAlmostEqual(m["slack"], exact_slack, delta=step ** 2 / 12)

    def test_wavy_ring_off_the_axis(self):
        # a closed ring of radius 2 about (1, -3), its height waving 8 times round with
        # amplitude a: length = integral of sqrt(R^2 + (8 a cos 8t)^2) dt over one turn
        radius, waves, amplitude, nodes, centre = 2.0, 8, 0.15, 4000, (1.0, -3.0)
        t = np.arange(nodes) * 2.0 * math.pi / nodes
        points = np.column_stack([centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t),
                                  amplitude * np.sin(waves * t)])
        m = wire_loops.loop_measures(points, closed=True, axis=centre)
        fine = np.linspace(0.0, 2.0 * math.pi, 400001)
        exact = np.trapz(np.sqrt(radius ** 2 + (waves * amplitude * np.cos(waves * fine)) ** 2), fine)
        self.assertAlmostEqual(m["turns"], 1.0, places=12)
        self.assertAlmostEqual(m["z_span"], 2.0 * amplitude, places=12)    # a crest on node 4000 / 32
        self.assertAlmostEqual(m["length"] / exact, 1.0, delta=1e-5)
        self.assertAlmostEqual(m["slack"], exact / (2.0 * math.pi * radius) - 1.0, delta=1e-5)
        self.assertGreater(m["slack"], 0.02)
        self.assertAlmostEqual(m["offset"], 0.0, places=12)     # about its own centre
        # about the origin instead, the same ring spans no turn: its slack is undefined, and
        # its centre is (1, -3) off the axis
        about_origin = wire_loops.loop_measures(points, closed=True)
        self.assertTrue(math.isnan(about_origin["slack"]))
        self.assertAlmostEqual(about_origin["x_offset"], 1.0, places=12)
        self.assertAlmostEqual(about_origin["y_offset"], -3.0, places=12)
        self.assertAlmostEqual(about_origin["offset"], math.sqrt(10.0), places=12)
        # about its own centre it is the same ring wherever the axis is
        self.assertAlmostEqual(about_origin["own_r_median"], radius, places=9)
        self.assertAlmostEqual(about_origin["own_slack"], m["slack"], places=9)

    def test_a_ring_moved_off_the_axis_is_taut_about_its_own_centre(self):
        # a flat regular 60-gon of circumradius 3 about (1.2, 0.5): it still encloses the
        # axis, but its nodes' median distance from it exceeds 3 by far more than the ring's
        # slack, so the slack about the axis goes negative; about its own centre the slack is
        # the polygon's, 60 sin(pi / 60) / pi - 1
        radius, nodes, centre = 3.0, 60, (1.2, 0.5)
        t = np.arange(nodes) * 2.0 * math.pi / nodes
        points = np.column_stack([centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t), 0.0 * t])
        m = wire_loops.loop_measures(points, closed=True)
        polygon = nodes * math.sin(math.pi / nodes) / math.pi - 1.0
        self.assertEqual(m["turns"], 1.0)
        self.assertLess(m["slack"], 10.0 * polygon)     # about the axis: -0.083, the polygon's -0.0005
        self.assertAlmostEqual(m["own_r_median"], radius, places=12)
        self.assertAlmostEqual(m["own_slack"], polygon, places=12)

    def test_a_ring_beside_the_axis_spans_no_turn(self):
        # a rough ring that has left the axis, crossing the azimuth's branch cut back and forth:
        # its unwrapped azimuth returns to the start only to round-off (-8.9e-16 for this one),
        # which made its slack 5e15 before a closed chain's turns were whole
        rng = np.random.default_rng(3)
        t = np.arange(94) * 2.0 * math.pi / 94
        points = np.column_stack([-4.0 + 2.9 * np.cos(t), 2.9 * np.sin(t) + rng.normal(0.0, 0.1, 94), 0.0 * t])
        m = wire_loops.loop_measures(points, closed=True)
        self.assertEqual(m["turns"], 0.0)
        self.assertTrue(math.isnan(m["slack"]))
        self.assertAlmostEqual(m["offset"], 4.0, delta=0.05)
        self.assertTrue(math.isfinite(m["own_slack"]))    # about its own centre it is a ring
        self.assertAlmostEqual(m["own_r_median"], 2.9, delta=0.1)


class Command(unittest.TestCase):
    def test_one_row_per_loop_and_step(self):
        first, first_elements = helix(10, 2.5, 1.8, 0.12, 91)
        second, second_elements = helix(200, 2.0, 1.8, 0.12, 91, z0=1.0)
        grains = [[1, 0.3, 0.2, 0.5], [2, -0.4, 0.1, 1.4]]
        header = ["id", "xu", "yu", "zu"]
        with tempfile.TemporaryDirectory() as d:
            nodes = synthetic.write_dump(os.path.join(d, "nodes.dump"),
                                         [(100, header, grains + first + second)])
            elements = synthetic.write_dump(os.path.join(d, "wire.dump"),
                                            [(100, synthetic.indexed("el", 5), second_elements + first_elements)],
                                            "ENTRIES")
            out = os.path.join(d, "loops")
            printed = io.StringIO()
            with contextlib.redirect_stdout(printed):
                self.assertEqual(cli.main(["wire-loops", "--elements", elements, "--nodes", nodes, "-o", out]), 0)
            with open(out + ".csv") as f:
                rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
            self.assertTrue(os.path.getsize(out + ".png") > 0)
        self.assertEqual([(r["step"], r["first_id"], r["kind"], r["nodes"]) for r in rows],
                         [("100", "10", "open", "91"), ("100", "200", "open", "91")])
        self.assertAlmostEqual(float(rows[0]["r_median"]), 2.5, places=5)
        self.assertAlmostEqual(float(rows[1]["r_median"]), 2.0, places=5)
        self.assertAlmostEqual(float(rows[1]["turns"]), 1.8, places=5)
        self.assertAlmostEqual(float(rows[1]["z_span"]), 1.8 * 0.12, places=5)
        # the printed summary: the median of the loops' radii (2.25), not of another column
        self.assertIn("median radius 2.250", printed.getvalue())
        # the offset: the mean node position's distance from the axis (1.8 turns: not zero)
        centre = np.array(first)[:, 1:3].mean(axis=0)
        self.assertAlmostEqual(float(rows[0]["x_offset"]), centre[0], places=5)
        self.assertAlmostEqual(float(rows[0]["y_offset"]), centre[1], places=5)
        self.assertAlmostEqual(float(rows[0]["offset"]), float(np.hypot(*centre)), places=5)
        self.assertGreater(float(rows[0]["offset"]), 0.1)

    def test_contacts_say_how_the_grains_press_each_loop(self):
        # two loops (nodes 10-100 and 200-290); contact rows of compute wire/contacts: id1 id2
        # other kind px py pz nx ny nz fn ftx fty ftz overlap status
        first, first_elements = helix(10, 2.5, 1.8, 0.12, 91)
        second, second_elements = helix(200, 2.0, 1.8, 0.12, 91, z0=1.0)
        points = [[10, 11, 5, 1, 2.0, 0.0, 0.1, 0.0, 0.0, -1.0, 3.0, 0, 0, 0, 1e-3, 0],    # pressed down by 3
                  [11, 12, 6, 1, 0.0, 2.0, 0.2, 0.0, 0.6, 0.8, 5.0, 0, 0, 0, 1e-3, 0],    # up 4, out 3
                  [200, 201, 7, 1, -2.0, 0.0, 1.0, 1.0, 0.0, 0.0, 2.0, 0, 0, 0, 1e-3, 0],  # in 2 (axis at -x)
                  [11, 12, 200, 2, 1.0, 1.0, 0.5, 0.0, 0.0, 1.0, 1.5, 0, 0, 0, 1e-3, 0],  # wire-wire: both loops
                  [12, 0, -1, 3, 2.5, 0.0, 0.0, 0.0, 0.0, 1.0, 9.0, 0, 0, 0, 1e-3, 0]]    # a wall: not counted
        with tempfile.TemporaryDirectory() as d:
            nodes = synthetic.write_dump(os.path.join(d, "nodes.dump"), [(100, ["id", "xu", "yu", "zu"], first + second)])
            elements = synthetic.write_dump(os.path.join(d, "wire.dump"),
                                            [(100, synthetic.indexed("el", 5), first_elements + second_elements)],
                                            "ENTRIES")
            contacts = synthetic.write_dump(os.path.join(d, "wc.dump"), [(100, synthetic.indexed("wc", 16), points)],
                                            "ENTRIES")
            out = os.path.join(d, "loops")
            with contextlib.redirect_stdout(io.StringIO()):
                self.assertEqual(cli.main(["wire-loops", "--elements", elements, "--nodes", nodes, "--contacts",
                                           contacts, "-o", out]), 0)
            with open(out + ".csv") as f:
                rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
        pressed = {r["first_id"]: {k: float(r[k]) for k in wire_loops.PRESS_FIELDS} for r in rows}
        self.assertEqual(pressed["10"], {"grain_points": 2, "press_down": 3.0, "press_up": 4.0, "press_out": 3.0,
                                         "press_in": 0.0, "wire_wire_fn": 1.5})
        self.assertEqual(pressed["200"], {"grain_points": 1, "press_down": 0.0, "press_up": 0.0, "press_out": 0.0,
                                          "press_in": 2.0, "wire_wire_fn": 1.5})


if __name__ == "__main__":
    unittest.main()
