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

"""Binning around the column axis: a known radial force profile is recovered from pair
rows (nscd-analysis force-profile), the axis from the grains' centre of mass, and a
per-atom column averaged in (r, z) bins (cylavg)."""

import os
import tempfile
import unittest

import numpy as np

import synthetic
from nscd_analysis import cli, cylinder, dumps, forces

PAIR_HEADER = synthetic.indexed("p", 16)


def pair_rows(rng, n, axis, fn_of_r, z_max=8.0, boundary_rows=0):
    """Pair rows (compute nscd/contacts pairs layout) whose midpoints lie at random (r, phi, z)
    around `axis`, with normal force fn_of_r(r); grains symmetric about the midpoint, so the
    grains' centre of mass is near the axis. Plus rows with a wall (id_j < 0) of huge force
    and rows without force, which the profile must leave out."""
    r = 4.0 * np.sqrt(rng.random(n))
    phi = 2 * np.pi * rng.random(n)
    mid = np.column_stack([axis[0] + r * np.cos(phi), axis[1] + r * np.sin(phi), z_max * rng.random(n)])
    half = 0.5 * rng.standard_normal((n, 3))
    rows = []
    for k in range(n):
        xi, xj = mid[k] + half[k], mid[k] - half[k]
        fn = fn_of_r(r[k])
        rows.append([2 * k + 1, 2 * k + 2, *xi, *xj, fn, 0, 0, fn, 2, 0, 0, 1])
    for k in range(boundary_rows):
        rows.append([1, -1, *mid[k], *mid[k], 1e6, 0, 0, 1e6, 4, 0, 0, 1])
        rows.append([1, 3, *mid[k], *mid[k], 0.0, 0, 0, 0, 1, 0, 0, 1])
    return rows, r


class RadialForceProfile(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def test_step_profile_is_recovered_exactly_per_bin(self):
        # fn = 1 + bin index for bins of width 0.5: every bin's mean is exact, its error 0
        rng = np.random.default_rng(5)
        axis = (3.0, -2.0)
        rows, r = pair_rows(rng, 4000, axis, lambda r: 1.0 + np.floor(r / 0.5), boundary_rows=20)
        path = synthetic.write_dump(os.path.join(self.dir.name, "pairs.dump"), [(100, PAIR_HEADER, rows)], "ENTRIES")
        snap = dumps.read_dump(path)[0]
        edges = np.arange(0, 4.01, 0.5)
        count, mean, sem, found_axis = forces.radial_profile(snap, edges, axis=axis)
        np.testing.assert_array_equal(count, np.histogram(r, edges)[0])
        np.testing.assert_allclose(mean, 1.0 + np.arange(8), rtol=1e-12)
        np.testing.assert_allclose(sem, 0.0, atol=1e-12)
        # the axis from the grains' centres: their mean lies near (3, -2)
        _, _, _, com_axis = forces.radial_profile(snap, edges)
        np.testing.assert_allclose(com_axis, axis, atol=0.1)

    def test_linear_profile_from_the_command_line_with_several_loads(self):
        rng = np.random.default_rng(9)
        snaps = []
        for step, slope in ((0, 0.0), (1000, 1.0), (2000, 2.0)):
            rows, _ = pair_rows(rng, 3000, (0.0, 0.0), lambda r: 1.0 + slope * r)
            snaps.append((step, PAIR_HEADER, rows))
        path = synthetic.write_dump(os.path.join(self.dir.name, "loads.dump.gz"), snaps, "ENTRIES")
        out = os.path.join(self.dir.name, "fn")
        self.assertEqual(cli.main(["force-profile", path, "--steps", "0", "1000", "2000", "--labels", "F=0", "F=1",
                                   "F=2", "--axis", "0", "0", "--rwidth", "1", "--rmax", "4", "-o", out]), 0)
        table = synthetic.read_csv(out + ".csv")
        self.assertEqual(len(table), 12)
        for row in table:
            slope = {"F=0": 0.0, "F=1": 1.0, "F=2": 2.0}[row["label"]]
            # mean of 1 + slope r over a bin = 1 + slope x the mean r of its contacts, whose
            # density grows like r: (2/3)(r_hi^3 - r_lo^3)/(r_hi^2 - r_lo^2)
            mean_r = 2 / 3 * (row["r_hi"] ** 3 - row["r_lo"] ** 3) / (row["r_hi"] ** 2 - row["r_lo"] ** 2)
            self.assertAlmostEqual(row["mean_fn"], 1 + slope * mean_r, delta=4 * row["sem_fn"] + 1e-9)
        self.assertLess(os.path.getsize(out + ".png"), 300 * 1024)

    def test_per_point_rows(self):
        # compute nscd/contacts without 'pairs': positions are the contact points
        header = synthetic.indexed("c", 15)
        rows = [[1, 2, 1.0, 0, 0, 1, 0, 0, 2.0] + [0] * 6, [1, 2, 0, 3.0, 0, 1, 0, 0, 4.0] + [0] * 6,
                [1, -1, 0, 3.0, 0, 1, 0, 0, 9.0] + [0] * 6]
        path = synthetic.write_dump(os.path.join(self.dir.name, "points.dump"), [(0, header, rows)], "ENTRIES")
        count, mean, _, _ = forces.radial_profile(dumps.read_dump(path)[0], np.array([0, 2, 4]), axis=(0, 0),
                                                  per_point=True)
        np.testing.assert_array_equal(count, [1, 1])
        np.testing.assert_array_equal(mean, [2.0, 4.0])

    def test_seeds_with_a_uniform_force_each_give_their_mean_and_sd(self):
        # three seeds' snapshots with fn = 1, 2, 4 everywhere; the third seed's file holds two
        # snapshots (pooled into its sample); a z window keeps half of the contacts
        rng = np.random.default_rng(21)
        files = []
        for k, fn in enumerate((1.0, 2.0, 4.0)):
            snaps = [(step, PAIR_HEADER, pair_rows(rng, 1500, (0.0, 0.0), lambda r, f=fn: f, boundary_rows=5)[0])
                     for step in ((10, 20) if k == 2 else (10,))]
            files.append(synthetic.write_dump(os.path.join(self.dir.name, f"s{k}.dump"), snaps, "ENTRIES"))
        out = os.path.join(self.dir.name, "seeds")
        self.assertEqual(cli.main(["force-profile", "--run", "rest=" + ",".join(files), "--axis", "0", "0",
                                   "--rbins", "4", "--rmax", "4", "--zmax", "4", "-o", out]), 0)
        table = synthetic.read_csv(out + ".csv")
        summary = [row for row in table if row["label"] == "rest"]
        self.assertEqual(len(summary), 4)
        for row in summary:
            self.assertEqual(row["seeds"], 3)
            self.assertAlmostEqual(row["mean_fn"], 7.0 / 3, delta=1e-5)
            self.assertAlmostEqual(row["sd_over_seeds_fn"], np.std([1.0, 2.0, 4.0], ddof=1), delta=1e-5)
        third = [row for row in table if row["label"] == "rest #3"]
        self.assertEqual({row["steps"] for row in third}, {"10+20"})
        # z in [0, 8) uniformly: about half of the 4 x 1500 rows lie below z = 4
        self.assertAlmostEqual(sum(row["contacts"] for row in summary) / 6000, 0.5, delta=0.05)
        with self.assertRaises(SystemExit):    # dump files and --run together
            cli.main(["force-profile", files[0], "--run", "rest=" + ",".join(files), "-o", out])


class CylindricalAverages(unittest.TestCase):
    def test_value_equal_to_r_plus_z_is_averaged_per_bin(self):
        rng = np.random.default_rng(2)
        n = 5000
        r = 3 * rng.random(n)
        phi = 2 * np.pi * rng.random(n)
        z = 6 * rng.random(n)
        rows = [[k + 1, r[k] * np.cos(phi[k]) + 1, r[k] * np.sin(phi[k]), z[k], np.floor(r[k]) + 10 * np.floor(z[k] / 2)]
                for k in range(n)]
        with tempfile.TemporaryDirectory() as d:
            path = synthetic.write_dump(os.path.join(d, "a.dump"), [(0, ["id", "x", "y", "z", "v_q"], rows)])
            out = os.path.join(d, "q")
            self.assertEqual(cli.main(["cylavg", path, "--value", "v_q", "--axis", "1", "0", "--rwidth", "1",
                                       "--rmax", "3", "--zbins", "3", "--zmin", "0", "--zmax", "6", "-o", out]), 0)
            table = synthetic.read_csv(out + ".csv")
        self.assertEqual(len(table), 9)
        for row in table:
            # bins [0,1), [1,2), [2,3) in r and [0,2), [2,4), [4,6) in z: each holds one value
            self.assertEqual(row["z_hi"] - row["z_lo"], 2.0)
            self.assertGreater(row["count"], 300)
            self.assertAlmostEqual(row["mean"], row["r_lo"] + 10 * row["z_lo"] / 2, delta=1e-12)

    def test_edges_and_bins(self):
        e = cylinder.edges([0.0, 2.5], width=1.0)
        np.testing.assert_array_equal(e, [0, 1, 2, 3])
        np.testing.assert_array_equal(cylinder.bin_index(np.array([-0.1, 0, 0.99, 1, 2.99, 3]), e), [-1, 0, 0, 1, 2, -1])
        np.testing.assert_allclose(cylinder.axis_from_centre_of_mass([[0, 0, 0], [2, 4, 1]], [1, 3]), [1.5, 3.0])


if __name__ == "__main__":
    unittest.main()
