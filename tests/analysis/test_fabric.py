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

"""Fabric tensors in the column's cylindrical frame: known principal directions give their
signed angle, isotropic fabrics give a zero mean angle (tools/nscd_analysis/fabric.py)."""

import os
import tempfile
import unittest

import numpy as np

import synthetic
from nscd_analysis import cli, cylinder, dumps, fabric, fields


class SignConvention(unittest.TestCase):
    def test_signed_angle_of_lines_in_the_rz_plane(self):
        # (v_r, v_z): leaning outward going up is positive, the line's sign does not matter
        cases = {(1, 1): np.pi / 4, (-1, -1): np.pi / 4, (-1, 1): -np.pi / 4, (1, -1): -np.pi / 4,
                 (0, 1): 0.0, (0, -1): 0.0, (1, 0): np.pi / 2, (-1, 0): np.pi / 2}
        for v, expected in cases.items():
            self.assertAlmostEqual(float(fabric.signed_angle(np.array(v, dtype=float))), expected, places=14, msg=v)

    def test_known_direction_at_any_azimuth_gives_its_angle(self):
        rng = np.random.default_rng(1)
        axis = np.array([2.0, -1.0])
        angles = rng.uniform(-1.5, 1.5, 200)
        phi = rng.uniform(0, 2 * np.pi, 200)
        r = rng.uniform(0.1, 4, 200)
        pos = np.column_stack([axis[0] + r * np.cos(phi), axis[1] + r * np.sin(phi), rng.uniform(0, 5, 200)])
        world = []
        for a, p in zip(angles, phi):
            e_r, _, e_z = synthetic.cylindrical_frame(p)
            d = np.sin(a) * e_r + np.cos(a) * e_z
            world.append(0.7 * np.outer(d, d) + 0.1 * np.eye(3))
        cyl = cylinder.Cylindrical(pos, axis)
        blocks = fabric.rz_blocks(np.array(world), cyl)
        lam_max, v_max, lam_min, v_min = fabric.principal_rz(blocks)
        np.testing.assert_allclose(fabric.signed_angle(v_max), angles, atol=1e-12)
        np.testing.assert_allclose(lam_max, 0.8, atol=1e-12)
        np.testing.assert_allclose(lam_min, 0.1, atol=1e-12)
        np.testing.assert_allclose(np.einsum("ij,ij->i", v_max, v_min), 0.0, atol=1e-12)

    def test_tensor_components_round_trip(self):
        c = np.array([[0.2, 0.3, 0.5, 0.01, -0.02, 0.03]])
        t = fabric.tensors(c)[0]
        np.testing.assert_array_equal(t, t.T)
        self.assertEqual(t[0, 2], -0.02)
        self.assertEqual(t[1, 2], 0.03)


class IsotropicAndDirectedFabrics(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def test_isotropic_contacts_give_a_zero_mean_angle(self):
        # 8000 grains with 6 isotropically random contact normals each: the largest direction
        # of each grain is random, its angle symmetric about 0 -> mean 0 in every r bin
        rng = np.random.default_rng(7)
        n = 8000
        r = 5 * np.sqrt(rng.random(n))
        phi = 2 * np.pi * rng.random(n)
        pos = np.column_stack([r * np.cos(phi), r * np.sin(phi), 10 * rng.random(n)])
        tensors = []
        for _ in range(n):
            normals = rng.standard_normal((6, 3))
            normals /= np.linalg.norm(normals, axis=1)[:, None]
            tensors.append(np.einsum("ki,kj->ij", normals, normals) / 6)
        path = synthetic.write_dump(os.path.join(self.dir.name, "iso.dump"),
                                    [(0, synthetic.FABRIC_HEADER, synthetic.fabric_rows(pos, tensors, [6] * n))])
        snap = dumps.read_dump(path)[0]
        r_got, _, blocks, angle = fabric.per_grain(snap, axis=(0.0, 0.0))
        edges = np.linspace(0, 5, 6)
        count, mean, sem, tensor_angle = fields.angle_profile(r_got, blocks, angle, edges)
        self.assertEqual(count.sum(), n)
        for b in range(5):
            self.assertLess(abs(mean[b]), 3.5 * sem[b], f"bin {b}: {mean[b]} +- {sem[b]}")
        self.assertLess(abs(np.nanmean(angle)), 3.5 * np.nanstd(angle) / np.sqrt(n))
        # the mean tensor is nearly isotropic: its r-z block's eigenvalues differ little
        _, mean_block, _ = cylinder.binned_mean(blocks.reshape(n, 4), r_got, edges)
        lam_max, _, lam_min, _ = fabric.principal_rz(mean_block.reshape(-1, 2, 2))
        self.assertTrue(np.all(lam_max - lam_min < 0.03))

    def test_directed_fabric_field_recovers_its_angle_per_bin(self):
        # inward (positive) angle growing with r, axis found from the centre of mass
        rng = np.random.default_rng(3)
        axis = (1.5, -0.5)
        pos, tensors, r = synthetic.grains_with_direction(rng, 3000, axis, lambda r: 0.1 * r)
        path = synthetic.write_dump(os.path.join(self.dir.name, "col.dump"),
                                    [(0, synthetic.FABRIC_HEADER, synthetic.fabric_rows(pos, tensors))])
        out = os.path.join(self.dir.name, "field")
        self.assertEqual(cli.main(["fabric-field", path, "--axis", "1.5", "-0.5", "--rbins", "5", "--rmax", "5",
                                   "--zbins", "4", "-o", out]), 0)
        table = synthetic.read_csv(out + ".csv")
        self.assertEqual(len(table), 20)
        self.assertEqual(synthetic.csv_column(table, "grains").sum(), 3000)
        # the mean of blocks with angles 0.1 r over a bin: the angle at the grains' mean r there
        kr = cylinder.bin_index(r, np.linspace(0, 5, 6))
        kz = cylinder.bin_index(pos[:, 2], cylinder.edges(pos[:, 2], count=4, low=pos[:, 2].min()))
        for row, (i, j) in zip(table, [(i, j) for i in range(5) for j in range(4)]):    # r outer, z inner
            inside = (kr == i) & (kz == j)
            self.assertEqual(row["grains"], inside.sum())
            self.assertAlmostEqual(row["angle_rad"], 0.1 * r[inside].mean(), delta=2e-3)
        self.assertLess(os.path.getsize(out + ".png"), 300 * 1024)

    def test_column_and_silo_angles_have_opposite_signs(self):
        rng = np.random.default_rng(11)
        files = {}
        for label, sign in (("column", 1.0), ("silo", -1.0)):
            pos, tensors, _ = synthetic.grains_with_direction(rng, 2000, (0.0, 0.0), lambda r: sign * 0.25, spread=0.1)
            files[label] = synthetic.write_dump(os.path.join(self.dir.name, f"{label}.dump"),
                                                [(0, synthetic.FABRIC_HEADER, synthetic.fabric_rows(pos, tensors))])
        out = os.path.join(self.dir.name, "angle")
        self.assertEqual(cli.main(["fabric-angle", "--run", f"column={files['column']}", "--run",
                                   f"silo={files['silo']}", "--rbins", "4", "-o", out]), 0)
        table = synthetic.read_csv(out + ".csv")
        self.assertEqual(len(table), 8)
        for row in table:
            expected = 0.25 if row["run"] == "column" else -0.25
            self.assertAlmostEqual(row["mean_angle_rad"], expected, delta=4 * row["sem_rad"] + 1e-3)
            self.assertAlmostEqual(row["tensor_angle_rad"], expected, delta=0.02)
        self.assertLess(os.path.getsize(out + ".png"), 300 * 1024)

    def test_seeds_spread_is_the_sd_of_the_seeds_means(self):
        # three seeds with a uniform angle each: every bin's mean over the seeds is their mean,
        # its bar their sample standard deviation
        rng = np.random.default_rng(12)
        files = []
        for k, angle in enumerate((0.1, 0.2, 0.4)):
            pos, tensors, _ = synthetic.grains_with_direction(rng, 400, (0.0, 0.0), lambda r, a=angle: a)
            files.append(synthetic.write_dump(os.path.join(self.dir.name, f"seed{k}.dump"),
                                              [(100 * k, synthetic.FABRIC_HEADER, synthetic.fabric_rows(pos, tensors))]))
        out = os.path.join(self.dir.name, "seeds")
        self.assertEqual(cli.main(["fabric-angle", "--run", "column=" + ",".join(files), "--spread", "seeds",
                                   "--axis", "0", "0", "--rbins", "3", "--rmax", "5", "-o", out]), 0)
        table = synthetic.read_csv(out + ".csv")
        self.assertEqual(len(table), 4 * 3)
        for k, angle in enumerate((0.1, 0.2, 0.4)):
            seed_rows = [row for row in table if row["run"] == f"column #{k + 1}"]
            np.testing.assert_allclose([row["mean_angle_rad"] for row in seed_rows], angle, atol=1e-6)
        summary = [row for row in table if row["run"] == "column"]
        self.assertEqual(sum(row["grains"] for row in summary), 1200)
        for row in summary:
            self.assertEqual(row["seeds"], 3)
            self.assertAlmostEqual(row["mean_angle_rad"], 0.7 / 3, delta=1e-5)
            self.assertAlmostEqual(row["sd_over_seeds_rad"], np.std([0.1, 0.2, 0.4], ddof=1), delta=1e-5)
            self.assertAlmostEqual(row["tensor_angle_rad"], 0.7 / 3, delta=1e-5)
        self.assertLess(os.path.getsize(out + ".png"), 300 * 1024)
        # one file is no spread over seeds; --steps cannot pick a snapshot per seed
        with self.assertRaises(SystemExit):
            cli.main(["fabric-angle", "--run", f"one={files[0]}", "--spread", "seeds", "-o", out])
        with self.assertRaises(SystemExit):
            cli.main(["fabric-angle", "--run", "column=" + ",".join(files), "--spread", "seeds", "--steps", "0",
                      "-o", out])

    def test_over_samples_skips_empty_bins_of_a_sample(self):
        n, mean, sd = cylinder.over_samples([[1.0, np.nan, 3.0], [3.0, np.nan, np.nan], [5.0, 2.0, 5.0]])
        np.testing.assert_array_equal(n, [3, 1, 2])
        np.testing.assert_allclose(mean, [3.0, 2.0, 4.0])
        np.testing.assert_allclose(sd, [2.0, np.nan, np.sqrt(2.0)])


if __name__ == "__main__":
    unittest.main()
