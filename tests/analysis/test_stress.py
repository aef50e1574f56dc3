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

"""Stress and crushing fields around the column axis (tools/nscd_analysis/stress.py and the
stress-field, stress-angle, stress-profile and crush-profile subcommands) on synthetic dumps
with known answers: uniaxial compressions along known r-z directions, a sigma_zz that grows
with r, and crushing indices past the threshold in known bins."""

import os
import tempfile
import unittest

import numpy as np

import synthetic
from nscd_analysis import cli, cylinder, dumps, fabric, stress, wire_breaks

HEADER = ["id", "x", "y", "z"] + synthetic.indexed("sig", 6) + synthetic.indexed("crush", 4)


def rows(positions, sigmas, crush=None):
    """Rows id x y z sxx syy szz sxy sxz syz fmax d sigma index."""
    crush = np.zeros((len(positions), 4)) if crush is None else crush
    return [[k + 1, *p, s[0, 0], s[1, 1], s[2, 2], s[0, 1], s[0, 2], s[1, 2], *c]
            for k, (p, s, c) in enumerate(zip(positions, sigmas, crush))]


def around(rng, n, axis=(0.0, 0.0), r_max=5.0, z_max=10.0):
    r = r_max * np.sqrt(rng.random(n))
    phi = 2 * np.pi * rng.random(n)
    z = z_max * rng.random(n)
    return np.column_stack([axis[0] + r * np.cos(phi), axis[1] + r * np.sin(phi), z]), r, phi


def uniaxial(angle, phi, p=2.0, lateral=0.5):
    """sigma (tension positive) of a compression p along the r-z direction at `angle` from
    the vertical plus an isotropic compression `lateral`: the major principal stress is p +
    lateral along that direction."""
    e_r, _, e_z = synthetic.cylindrical_frame(phi)
    d = np.sin(angle) * e_r + np.cos(angle) * e_z
    return -p * np.outer(d, d) - lateral * np.eye(3)


class Fields(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def write(self, name, positions, sigmas, crush=None, step=0):
        return synthetic.write_dump(os.path.join(self.dir.name, name),
                                    [(step, HEADER, rows(positions, sigmas, crush))])

    def test_major_principal_stress_has_the_compression_direction_and_value(self):
        rng = np.random.default_rng(5)
        axis = (1.0, 2.0)
        pos, r, phi = around(rng, 300, axis)
        angles = rng.uniform(-1.4, 1.4, len(pos))
        path = self.write("u.dump", pos, [uniaxial(a, f) for a, f in zip(angles, phi)])
        got_r, _, blocks, angle = stress.per_grain(dumps.read_dump(path)[0], axis, compute_id="sig")
        np.testing.assert_allclose(got_r, r, atol=1e-9)
        np.testing.assert_allclose(angle, angles, atol=1e-9)
        lam_max, _, lam_min, _ = fabric.principal_rz(blocks)
        np.testing.assert_allclose(lam_max, 2.5, atol=1e-9)    # compression positive: p + lateral
        np.testing.assert_allclose(lam_min, 0.5, atol=1e-9)

    def test_tension_is_not_the_major_stress(self):
        # sigma_zz = +1 (tension), sigma_rr = -1 (compression): the major stress is horizontal
        pos = np.array([[2.0, 0.0, 1.0]])
        path = self.write("t.dump", pos, [np.diag([-1.0, 0.0, 1.0])])
        _, _, _, angle = stress.per_grain(dumps.read_dump(path)[0], (0.0, 0.0), compute_id="sig")
        self.assertAlmostEqual(float(angle[0]), np.pi / 2, places=12)

    def test_grains_without_contacts_are_left_out(self):
        pos = np.array([[1.0, 0.0, 1.0], [2.0, 0.0, 1.0]])
        path = self.write("z.dump", pos, [np.zeros((3, 3)), uniaxial(0.0, 0.0)])
        r, _, _, _ = stress.per_grain(dumps.read_dump(path)[0], (0.0, 0.0), compute_id="sig")
        np.testing.assert_allclose(r, [2.0])

    def test_stress_field_and_angle_for_column_and_silo(self):
        rng = np.random.default_rng(9)
        files = {}
        for label, sign in (("column", 1.0), ("silo", -1.0)):
            pos, r, phi = around(rng, 2000)
            files[label] = self.write(f"{label}.dump", pos, [uniaxial(sign * 0.05 * ri, f) for ri, f in zip(r, phi)])
        out = os.path.join(self.dir.name, "angle")
        self.assertEqual(cli.main(["stress-angle", "--run", f"column={files['column']}", "--run",
                                   f"silo={files['silo']}", "--rbins", "5", "--rmax", "5", "--axis", "0", "0",
                                   "-o", out]), 0)
        table = synthetic.read_csv(out + ".csv")
        self.assertEqual(len(table), 10)
        for row in table:
            sign = 1.0 if row["run"] == "column" else -1.0
            # the mean of 0.05 r over a bin lies within the bin's angles
            self.assertGreaterEqual(sign * row["mean_angle_rad"], 0.05 * row["r_lo"] - 1e-12)
            self.assertLessEqual(sign * row["mean_angle_rad"], 0.05 * row["r_hi"] + 1e-12)
        field = os.path.join(self.dir.name, "field")
        self.assertEqual(cli.main(["stress-field", files["column"], "--axis", "0", "0", "--rbins", "5", "--rmax", "5",
                                   "--zbins", "2", "-o", field]), 0)
        table = synthetic.read_csv(field + ".csv")
        self.assertEqual(len(table), 10)
        self.assertEqual(synthetic.csv_column(table, "grains").sum(), 2000)
        for row in table:
            self.assertAlmostEqual(row["lambda_max"], 2.5, delta=1e-3)
            self.assertGreater(row["angle_rad"], 0.05 * (row["r"] - 0.5) - 1e-3)
            self.assertLess(row["angle_rad"], 0.05 * (row["r"] + 0.5) + 1e-3)
        self.assertLess(os.path.getsize(field + ".png"), 300 * 1024)

    def test_stress_field_with_fabric_panel(self):
        rng = np.random.default_rng(2)
        pos, r, phi = around(rng, 400)
        path = self.write("s.dump", pos, [uniaxial(0.3, f) for f in phi])
        fpos, ftensors, _ = synthetic.grains_with_direction(rng, 400, (0.0, 0.0), lambda r: -0.3)
        fpath = synthetic.write_dump(os.path.join(self.dir.name, "f.dump"),
                                     [(0, synthetic.FABRIC_HEADER, synthetic.fabric_rows(fpos, ftensors))])
        out = os.path.join(self.dir.name, "both")
        self.assertEqual(cli.main(["stress-field", path, "--fabric", fpath, "--axis", "0", "0", "--rbins", "2",
                                   "--rmax", "5", "--zbins", "2", "-o", out]), 0)
        table = synthetic.read_csv(out + ".csv")
        for row in table:
            self.assertAlmostEqual(row["angle_rad"], 0.3 if row["field"] == "stress" else -0.3, delta=1e-6)
        self.assertEqual({row["field"] for row in table}, {"stress", "fabric"})

    def test_szz_profile_is_the_mean_per_bin(self):
        rng = np.random.default_rng(4)
        pos, r, phi = around(rng, 1500)
        szz = -(1.0 + r ** 2)
        sig = [np.diag([-0.2, -0.2, s]) for s in szz]
        path = self.write("p.dump", pos, sig)
        out = os.path.join(self.dir.name, "szz")
        self.assertEqual(cli.main(["stress-profile", path, "--axis", "0", "0", "--rbins", "5", "--rmax", "5",
                                   "-o", out]), 0)
        table = synthetic.read_csv(out + ".csv")
        edges = np.linspace(0, 5, 6)
        for b, row in enumerate(table):
            inside = (r >= edges[b]) & (r < edges[b + 1])
            self.assertEqual(row["grains"], inside.sum())
            self.assertAlmostEqual(row["mean_szz"], szz[inside].mean(), delta=1e-5 * abs(szz[inside].mean()))

    def test_crush_fraction_per_r_and_z_bin(self):
        # grains crushed (index 1.5) in the inner half radius and the lower half height, in
        # known numbers per bin; index 0.99 elsewhere (just under the threshold)
        rng = np.random.default_rng(6)
        pos, r, _ = around(rng, 4000)
        past = (r < 2.5) & (pos[:, 2] < 5.0)
        crush = np.zeros((len(pos), 4))
        crush[:, 3] = np.where(past, 1.5, 0.99)
        path = self.write("c.dump", pos, [uniaxial(0.0, 0.0)] * len(pos), crush)
        out = os.path.join(self.dir.name, "crush")
        self.assertEqual(cli.main(["crush-profile", path, "--axis", "0", "0", "--rbins", "2", "--rmax", "5",
                                   "--zmin", "0", "--zmax", "10", "--zbins", "2", "-o", out]), 0)
        table = synthetic.read_csv(out + ".csv")
        by_r = [row for row in table if row["along"] == "r"]
        by_z = [row for row in table if row["along"] == "z"]
        self.assertEqual(len(by_r), 2)
        self.assertEqual(len(by_z), 2)
        low = pos[:, 2] < 5.0
        inner = r < 2.5
        self.assertAlmostEqual(by_r[0]["fraction"], low[inner].mean(), delta=1e-5)
        self.assertEqual(by_r[1]["fraction"], 0.0)
        self.assertAlmostEqual(by_z[0]["fraction"], inner[low].mean(), delta=1e-5)
        self.assertEqual(by_z[1]["fraction"], 0.0)
        self.assertEqual(by_r[0]["grains"] + by_r[1]["grains"], 4000)

    def test_labels_follow_the_files_of_several_runs(self):
        # a later step first: labels go with the files as given, not with the steps' order
        pos = np.array([[1.0, 0.0, 1.0], [2.0, 0.0, 1.0]])
        crush = np.array([[0, 0, 0, 2.0], [0, 0, 0, 2.0]])
        late = self.write("late.dump", pos, [uniaxial(0.0, 0.0)] * 2, crush, step=900)
        early = self.write("early.dump", pos, [uniaxial(0.0, 0.0)] * 2, np.zeros((2, 4)), step=100)
        out = os.path.join(self.dir.name, "order")
        self.assertEqual(cli.main(["crush-profile", late, early, "--labels", "late", "early", "--axis", "0", "0",
                                   "--rbins", "1", "--rmax", "3", "--zbins", "1", "-o", out]), 0)
        by_label = {row["label"]: row for row in synthetic.read_csv(out + ".csv") if row["along"] == "r"}
        self.assertEqual(by_label["late"]["fraction"], 1.0)
        self.assertEqual(by_label["early"]["fraction"], 0.0)

    def test_fraction_profile_counts_and_binomial_error(self):
        count, fraction, error = stress.fraction_profile([1, 0, 0, 1, 1, 1], [0.5, 0.5, 0.5, 0.5, 1.5, 1.5],
                                                         np.array([0.0, 1.0, 2.0, 3.0]))
        np.testing.assert_array_equal(count, [4, 2, 0])
        np.testing.assert_allclose(fraction[:2], [0.5, 1.0])
        np.testing.assert_allclose(error[:2], [0.25, 0.0])
        self.assertTrue(np.isnan(fraction[2]))

    def test_two_computes_in_one_dump_are_told_apart(self):
        pos = np.array([[1.0, 0.0, 1.0]])
        crush = np.array([[3.0, 0.5, 12.0, 0.7]])
        path = self.write("two.dump", pos, [np.diag([-1.0, -2.0, -3.0])], crush)
        snap = dumps.read_dump(path)[0]
        np.testing.assert_allclose(stress.stress_components(snap, "sig")[0], [-1, -2, -3, 0, 0, 0])
        _, flags = stress.crushed(snap, 10.0, "sigma", compute_id="crush")
        self.assertTrue(flags[0])
        _, flags = stress.crushed(snap, 1.0, "index", compute_id="crush")
        self.assertFalse(flags[0])
        with self.assertRaises(dumps.DumpError):
            stress.stress_components(snap, "other")


class WireBreaks(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def write(self, name, text):
        path = os.path.join(self.dir.name, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_breaks_in_cylindrical_coordinates(self):
        # midpoints at known (r, z) around the axis (1, -1)
        path = self.write("b.txt", "# step node_id_1 node_id_2 tension x y z   (fix wire w: broken elements)\n"
                                   "1200 17 18 0.61 4 -1 2.5\n1210 40 41 0.58 1 1.5 0.75\n")
        b = wire_breaks.read_breaks(path)
        r, z = wire_breaks.positions_rz(b, (1.0, -1.0))
        np.testing.assert_allclose(r, [3.0, 2.5])
        np.testing.assert_allclose(z, [2.5, 0.75])
        empty = self.write("none.txt", "# step node_id_1 node_id_2 tension x y z\n")
        out = os.path.join(self.dir.name, "breaks")
        self.assertEqual(cli.main(["wire-breaks", "--run", f"a={path}", "--run", f"b={empty}", "--axis", "1", "-1",
                                   "--R", "3", "-o", out]), 0)
        table = synthetic.read_csv(out + ".csv")
        self.assertEqual(len(table), 2)
        self.assertAlmostEqual(table[0]["r"], 3.0, places=9)
        self.assertEqual(table[1]["id1"], 40)

    def test_a_damaged_line_is_refused(self):
        path = self.write("bad.txt", "1200 17 18 0.61 4 -1\n")
        with self.assertRaises(wire_breaks.BreaksError):
            wire_breaks.read_breaks(path)
        self.assertEqual(cli.main(["wire-breaks", "--run", f"a={path}", "-o", os.path.join(self.dir.name, "x")]), 1)


if __name__ == "__main__":
    unittest.main()
