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

"""Orientation of wire contact forces in the z-r plane (nscd-analysis wire-contacts, the
papers' Fig. 6) from rows in the proposed compute wire/contacts layout: contacts placed on
known rays give the known histogram."""

import os
import tempfile
import unittest

import numpy as np

import synthetic
from nscd_analysis import cli, dumps, layouts, wire_contacts

HEADER = synthetic.indexed("wc", 16)


def contact_rows(rng, alphas, magnitudes, axis=(0.0, 0.0), kind=1, flip_every=2):
    """One wire-grain row per (alpha, magnitude): at a random azimuth and height around the
    axis, the force on the wire in the z-r plane at angle alpha from e_r (sign flipped on
    every flip_every-th row: the same line), plus a tangential part along e_phi that the
    analysis must drop. The force is split into fn along a unit normal and ft across it."""
    rows = []
    for k, (alpha, magnitude) in enumerate(zip(alphas, magnitudes)):
        phi = 2 * np.pi * rng.random()
        e_r, e_phi, e_z = synthetic.cylindrical_frame(phi)
        sign = -1.0 if k % flip_every == 0 else 1.0
        f = sign * magnitude * (np.cos(alpha) * e_r + np.sin(alpha) * e_z) + 0.7 * magnitude * e_phi
        # normal: f's in-plane part turned by 0.3 rad in the r-z plane (friction carries the rest)
        turn = alpha + 0.3
        n = sign * (np.cos(turn) * e_r + np.sin(turn) * e_z)
        fn = f @ n
        ft = f - fn * n
        point = np.array([axis[0], axis[1], 0.0]) + 2.0 * e_r + np.array([0, 0, 5 * rng.random()])
        rows.append([10 + k, 11 + k, 3, kind, *point, *n, fn, *ft, 1e-3, k % 2])
    return rows


class WireContactOrientations(unittest.TestCase):
    def test_known_rays_give_the_known_histogram(self):
        rng = np.random.default_rng(4)
        # 12 bins of 15 degrees: rays at bin centres, with chosen counts and magnitudes
        centres = np.radians(7.5 + 15 * np.arange(12))
        counts = np.array([1, 0, 2, 3, 5, 9, 12, 7, 4, 2, 1, 0])
        alphas = np.repeat(centres, counts)
        magnitudes = np.repeat(np.linspace(1.0, 2.1, 12), counts)
        rows = contact_rows(rng, alphas, magnitudes)
        rows += contact_rows(rng, np.radians([45.0, 90.0]), [100.0, 100.0], kind=2)    # wire-wire: ignored
        with tempfile.TemporaryDirectory() as d:
            path = synthetic.write_dump(os.path.join(d, "wc.dump"), [(0, HEADER, rows)], "ENTRIES")
            snap = dumps.read_dump(path)[0]
            points, f = wire_contacts.forces_on_wire(snap)
            self.assertEqual(len(points), counts.sum())
            alpha, magnitude = wire_contacts.orientation_rz(points, f, (0.0, 0.0))
            np.testing.assert_allclose(np.sort(alpha), np.sort(alphas), atol=1e-12)
            edges, fraction, mean, normalised = wire_contacts.polar_histogram(alpha, magnitude, 12)
            np.testing.assert_allclose(fraction, counts / counts.sum(), atol=1e-15)
            expected_mean = np.where(counts > 0, np.linspace(1.0, 2.1, 12), np.nan)
            np.testing.assert_allclose(mean, expected_mean, rtol=1e-12)
            np.testing.assert_allclose(normalised, expected_mean / 2.0, rtol=1e-12)    # largest filled bin: 2.0
            # within 30 degrees of the vertical: bins centred at 67.5 ... 112.5 degrees
            self.assertAlmostEqual(wire_contacts.fraction_near_vertical(alpha), counts[4:8].sum() / counts.sum())

            out = os.path.join(d, "fig6")
            self.assertEqual(cli.main(["wire-contacts", path, "--axis", "0", "0", "--labels", "no load", "-o", out]), 0)
            table = synthetic.read_csv(out + ".csv")
            within = [row for row in table if row["alpha_lo_deg"] == "within"]
            self.assertAlmostEqual(within[0]["fraction"], counts[4:8].sum() / counts.sum(), places=5)
            np.testing.assert_allclose([row["fraction"] for row in table if row not in within],
                                       counts / counts.sum(), atol=1e-6)
            self.assertLess(os.path.getsize(out + ".png"), 300 * 1024)

    def test_axis_elsewhere_and_two_snapshots(self):
        rng = np.random.default_rng(8)
        axis = (4.0, -3.0)
        vertical = contact_rows(rng, np.full(50, np.pi / 2), np.ones(50), axis=axis)
        radial = contact_rows(rng, np.zeros(50), np.ones(50), axis=axis)
        with tempfile.TemporaryDirectory() as d:
            path = synthetic.write_dump(os.path.join(d, "wc.dump"), [(0, HEADER, vertical), (500, HEADER, radial)],
                                        "ENTRIES")
            snaps = dumps.read_dump(path)
            for snap, expected in zip(snaps, (1.0, 0.0)):
                alpha, _ = wire_contacts.orientation_rz(*wire_contacts.forces_on_wire(snap), axis)
                self.assertEqual(wire_contacts.fraction_near_vertical(alpha), expected)
            out = os.path.join(d, "two")
            self.assertEqual(cli.main(["wire-contacts", path, "--axis", "4", "-3", "--steps", "0", "500", "-o", out]), 0)
            within = [row for row in synthetic.read_csv(out + ".csv") if row["alpha_lo_deg"] == "within"]
            self.assertEqual([row["fraction"] for row in within], [1.0, 0.0])

    def test_seeds_give_the_mean_fraction_and_its_sd(self):
        # seeds all vertical, all radial, all vertical: 2/3 within 30 degrees, sd sqrt(1/3)
        rng = np.random.default_rng(13)
        with tempfile.TemporaryDirectory() as d:
            files = []
            for k, alpha in enumerate((np.pi / 2, 0.0, np.pi / 2)):
                rows = contact_rows(rng, np.full(40, alpha), np.full(40, 1.0 + k))
                files.append(synthetic.write_dump(os.path.join(d, f"s{k}.dump"), [(0, HEADER, rows)], "ENTRIES"))
            out = os.path.join(d, "seeds")
            self.assertEqual(cli.main(["wire-contacts", "--run", "rest=" + ",".join(files), "--axis", "0", "0",
                                       "--bins", "5", "-o", out]), 0)
            table = synthetic.read_csv(out + ".csv")
            within = [row for row in table if row["label"] == "rest" and row["alpha_lo_deg"] == "within"][0]
            self.assertAlmostEqual(within["fraction"], 2 / 3, places=5)
            self.assertAlmostEqual(within["sd_fraction"], np.sqrt(1 / 3), places=5)
            bins = [row for row in table if row["label"] == "rest" and row["alpha_lo_deg"] != "within"]
            np.testing.assert_allclose([row["fraction"] for row in bins], [1 / 3, 0, 2 / 3, 0, 0], atol=1e-6)
            self.assertLess(os.path.getsize(out + ".png"), 300 * 1024)

    def test_layout_is_the_proposed_one(self):
        self.assertEqual(list(layouts.WIRE_CONTACTS), ["id1", "id2", "other", "kind", "px", "py", "pz", "nx", "ny",
                                                        "nz", "fn", "ftx", "fty", "ftz", "overlap", "status"])


if __name__ == "__main__":
    unittest.main()
