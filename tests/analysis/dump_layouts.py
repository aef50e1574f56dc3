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

"""The column layouts nscd_analysis reads (tools/nscd_analysis/layouts.py) against the
columns the C++ computes write, so that the two cannot drift apart: lmp runs
tests/analysis/in.dump_layouts, which dumps each compute whole (c_ID[*], as LAMMPS expands
it from the compute's own column count), and nscd_analysis.dumps reads each dump's header.

1. The header's c_ID[k] are exactly k = 1 .. len(layout): a column added to or removed from a
   compute, or a name added to or removed from its layout, fails here.
2. Every named column holds what its name says, checked against quantities of the scene
   that do not depend on the column order: atom positions and masses (dumped by name),
   the wire's bond coefficients, unit normals, force = fn n + tangential, equilibrium of
   the top ball, fabric = the mean n (x) n of the pair rows. Two columns swapped fail here.

    dump_layouts.py LMP SOURCE_DIR WORK_DIR
"""
import pathlib
import subprocess
import sys

import numpy as np

from nscd_analysis import layouts, stress
from nscd_analysis.dumps import indexed_entry, read_dump

# the deck's numbers (tests/analysis/in.dump_layouts)
GRAVITY = 1.0
K_ELO, REST_LENGTH = 100.0, 0.196                   # bond_coeff after create_wire
WIRE_RADIUS, MU_S, MU_D = 0.02, 0.5, 0.4            # fix wire
S0 = 2.0                                            # compute nscd/crush/atom
FLOOR = -1                                          # the first (only) boundary fix

failures = []


def check(condition, what):
    if not np.all(condition):
        failures.append(what)


def close(a, b, what, rtol=1e-9, atol=1e-9):
    check(np.allclose(a, b, rtol=rtol, atol=atol), f"{what}: {np.asarray(a).ravel()[:6]} != {np.asarray(b).ravel()[:6]}")


def header_matches(snapshot, compute_id, layout, name):
    """The c_ID[k] of the dump header are 1..len(layout), in order."""
    ks = [indexed_entry(c)[1] for c in snapshot.columns if indexed_entry(c) and indexed_entry(c)[0] == compute_id]
    check(ks == list(range(1, len(layout) + 1)),
          f"{name}: the compute writes {len(ks)} columns (c_{compute_id}[{ks[0] if ks else '?'}..{ks[-1] if ks else '?'}]), "
          f"layouts.py names {len(layout)}: {' '.join(layout)}")


def vectors(s, layout, names):
    return s.vectors(names, layout)


def check_points(s, atoms):
    L = layouts.CONTACT_POINTS
    col = lambda n: s.column(n, L)
    id_i, id_j = col("id_i").astype(int), col("id_j").astype(int)
    p, n = vectors(s, L, ("px", "py", "pz")), vectors(s, L, ("nx", "ny", "nz"))
    f = vectors(s, L, ("fx", "fy", "fz"))
    check(len(s) == 4, f"contact points: {len(s)} rows, expected 4 (2 ball-ball, 2 ball-floor)")
    close(np.linalg.norm(n, axis=1), 1.0, "contact points: |n| (nx ny nz)")
    for k in range(len(s)):
        xi = atoms[id_i[k]]["x"]
        if id_j[k] == FLOOR:
            close(n[k], [0, 0, 1], f"contact points row {k}: floor normal")
            close(p[k], [xi[0], xi[1], 0.0], f"contact points row {k}: floor point below the centre")
        else:
            xj = atoms[id_j[k]]["x"]
            close(n[k], (xi - xj) / np.linalg.norm(xi - xj), f"contact points row {k}: normal from j to i")
            close(p[k], 0.5 * (xi + xj), f"contact points row {k}: point midway between equal balls")
    fn, ft = col("fn"), col("ft")
    close(np.sum(f * n, axis=1), fn, "contact points: f . n = fn")
    close(np.linalg.norm(f - fn[:, None] * n, axis=1), ft, "contact points: |f - fn n| = ft")
    check(fn > 0, "contact points: fn > 0 on every contact of a resting stack")
    close(col("gap"), 0.0, "contact points: gap of touching balls")
    check(np.isin(col("status"), (1, 2)), f"contact points: status {col('status')} not 1 (stick) or 2 (slip)")
    top = max(a for a in atoms if atoms[a]["type"] == 2)       # the top ball: its weight on its two contacts
    on_top = -np.sum(f[id_j == top], axis=0) + np.sum(f[id_i == top], axis=0)
    close(on_top, [0, 0, atoms[top]["mass"] * GRAVITY], "contact points: forces on the top ball = its weight")


def check_pairs(s, atoms, points):
    L = layouts.CONTACT_PAIRS
    col = lambda n: s.column(n, L)
    id_i, id_j = col("id_i").astype(int), col("id_j").astype(int)
    xi, xj = vectors(s, L, ("xi", "yi", "zi")), vectors(s, L, ("xj", "yj", "zj"))
    n, f = vectors(s, L, ("nx", "ny", "nz")), vectors(s, L, ("fx", "fy", "fz"))
    P = layouts.CONTACT_POINTS
    check(len(s) == 4, f"contact pairs: {len(s)} rows, expected 4")
    close(col("points"), 1, "contact pairs: points per pair of balls")
    for k in range(len(s)):
        close(xi[k], atoms[id_i[k]]["x"], f"contact pairs row {k}: centre of i")
        if id_j[k] != FLOOR:
            close(xj[k], atoms[id_j[k]]["x"], f"contact pairs row {k}: centre of j")
        row = np.flatnonzero((points.column("id_i", P) == id_i[k]) & (points.column("id_j", P) == id_j[k]))
        check(len(row) == 1, f"contact pairs row {k}: no single point row of pair {id_i[k]} {id_j[k]}")
        if len(row) == 1:
            r = row[0]
            close(col("fn")[k], points.column("fn", P)[r], f"contact pairs row {k}: fn = its point's")
            close(f[k], points.vectors(("fx", "fy", "fz"), P)[r], f"contact pairs row {k}: force = its point's")
            close(n[k], points.vectors(("nx", "ny", "nz"), P)[r], f"contact pairs row {k}: normal = its point's")


def check_fabric(s, pairs):
    L, P = layouts.FABRIC, layouts.CONTACT_PAIRS
    ids = s.column("id").astype(int)
    grains = pairs.column("id_j", P) != FLOOR        # fabric/atom counts grain pairs (boundaries no)
    pid_i, pid_j = pairs.column("id_i", P)[grains].astype(int), pairs.column("id_j", P)[grains].astype(int)
    normals = pairs.vectors(("nx", "ny", "nz"), P)[grains]
    for k, atom in enumerate(ids):
        mine = normals[(pid_i == atom) | (pid_j == atom)]
        count = len(mine)
        close(s.column("nc", L)[k], count, f"fabric atom {atom}: nc = its grain pairs")
        expected = np.einsum("ni,nj->ij", mine, mine) / count if count else np.zeros((3, 3))
        for name, (a, b) in zip(("fxx", "fyy", "fzz", "fxy", "fxz", "fyz"),
                                ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))):
            close(s.column(name, L)[k], expected[a, b], f"fabric atom {atom}: {name} = mean n n of its pairs")


def check_stress_and_crush(s, atoms, points, pairs):
    """compute nscd/stress/atom: sigma_i V_i = sum over i's points of sym(f (x) (x_c - x_i)),
    V_i = mass (density 1); compute nscd/crush/atom: F = the largest total normal force of i's
    pairs (floor included), d = (6 V / pi)^(1/3), sigma = F / d^2, index = sigma / S0."""
    P, Q = layouts.CONTACT_POINTS, layouts.CONTACT_PAIRS
    pid_i, pid_j = points.column("id_i", P).astype(int), points.column("id_j", P).astype(int)
    p, f = points.vectors(("px", "py", "pz"), P), points.vectors(("fx", "fy", "fz"), P)
    qid_i, qid_j, qfn = pairs.column("id_i", Q).astype(int), pairs.column("id_j", Q).astype(int), pairs.column("fn", Q)
    for k, atom in enumerate(s.column("id").astype(int)):
        x, volume = atoms[atom]["x"], atoms[atom]["mass"]
        moment = np.zeros((3, 3))
        for c in np.flatnonzero((pid_i == atom) | (pid_j == atom)):
            on_me = f[c] if pid_i[c] == atom else -f[c]
            moment += np.outer(on_me, p[c] - x)
        sigma = 0.5 * (moment + moment.T) / volume
        for name, (a, b) in zip(stress.STRESS_COMPONENTS, ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))):
            close(stress.compute_column(s, name, layouts.STRESS, "sig")[k], sigma[a, b],
                  f"stress atom {atom}: {name} = Love-Weber sum of its points / V")
        force = qfn[(qid_i == atom) | (qid_j == atom)].max()
        d = (6 * volume / np.pi) ** (1 / 3)
        got = {name: stress.compute_column(s, name, layouts.CRUSH, "crush")[k] for name in layouts.CRUSH}
        close([got["fmax"], got["d"], got["sigma"], got["index"]], [force, d, force / d ** 2, force / d ** 2 / S0],
              f"crush atom {atom}: fmax d sigma index")


def check_wire_elements(s, atoms):
    L = layouts.WIRE_ELEMENTS
    col = lambda n: s.column(n, L)
    id1, id2 = col("id1").astype(int), col("id2").astype(int)
    check(len(s) == 15 and np.all(id2 == id1 + 1), f"wire elements: ids {id1} {id2}, expected 15 chained")
    length = np.array([np.linalg.norm(atoms[b]["x"] - atoms[a]["x"]) for a, b in zip(id1, id2)])
    strain = length / REST_LENGTH - 1.0
    close(col("strain"), strain, "wire elements: strain = L / r0 - 1 of the node positions")
    close(col("tension"), K_ELO * col("strain"), "wire elements: tension = k_elo strain")
    close(col("energy"), 0.5 * K_ELO * REST_LENGTH * col("strain") ** 2, "wire elements: energy = k_elo r0 strain^2 / 2")
    check(np.all(col("strain") > 0.004), "wire elements: the wire laid 1 % long is stretched")


def check_wire_contacts(s, atoms):
    L = layouts.WIRE_CONTACTS
    col = lambda n: s.column(n, L)
    node = col("id1").astype(int)
    p, n = vectors(s, L, ("px", "py", "pz")), vectors(s, L, ("nx", "ny", "nz"))
    ft = vectors(s, L, ("ftx", "fty", "ftz"))
    check(len(s) == 16, f"wire contacts: {len(s)} rows, expected 16 (one per node on the floor)")
    check(col("id2") == 0, "wire contacts: id2 = 0 at a wall")
    check(col("other") == FLOOR, f"wire contacts: other = {FLOOR} (the floor)")
    check(col("kind") == layouts.WIRE_BOUNDARY, "wire contacts: kind = wire-boundary")
    z = np.array([atoms[a]["x"][2] for a in node])
    close(col("overlap"), WIRE_RADIUS - z, "wire contacts: overlap = r_w - z of the node")
    close(p[:, 2], -0.5 * col("overlap"), "wire contacts: point midway between the floor and the wire's surface")
    close(p[:, :2], np.array([atoms[a]["x"][:2] for a in node]), "wire contacts: point below the node")
    close(n, np.tile([0.0, 0.0, 1.0], (len(s), 1)), "wire contacts: normal from the floor to the wire")
    fn, ft_size = col("fn"), np.linalg.norm(ft, axis=1)
    check(fn > 0, "wire contacts: fn > 0")
    close(ft[:, 2], 0.0, "wire contacts: tangential force has no normal part")
    check(ft_size <= MU_S * fn * (1 + 1e-9), "wire contacts: |ft| <= mu_s fn")
    status = col("status")
    check(np.isin(status, (0, 1)), f"wire contacts: status {status} not 0 or 1")
    check(ft_size[status == 1] >= MU_D * fn[status == 1] * (1 - 1e-9), "wire contacts: sliding rows at the limit")


def atom_table(s):
    ids = s.column("id").astype(int)
    pos = s.vectors(("x", "y", "z"))
    return {int(a): {"x": pos[k], "mass": s.column("mass")[k], "type": int(s.column("type")[k])}
            for k, a in enumerate(ids)}


def main():
    lmp, src, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    work.mkdir(parents=True, exist_ok=True)
    deck = src / "tests" / "analysis" / "in.dump_layouts"
    subprocess.run([lmp, "-in", str(deck), "-var", "dir", str(deck.parent), "-log", "log.lammps", "-screen", "none"],
                   cwd=work, check=True)
    snap = {name: read_dump(work / f"{name}.5.dump")[0]
            for name in ("atoms", "stress", "points", "pairs", "wire", "wcontacts")}
    for name, compute_id, layout in (("atoms", "fab", layouts.FABRIC), ("stress", "sig", layouts.STRESS),
                                     ("stress", "crush", layouts.CRUSH), ("points", "pts", layouts.CONTACT_POINTS),
                                     ("pairs", "pairs", layouts.CONTACT_PAIRS), ("wire", "el", layouts.WIRE_ELEMENTS),
                                     ("wcontacts", "wc", layouts.WIRE_CONTACTS)):
        header_matches(snap[name], compute_id, layout, name)
    atoms = atom_table(snap["atoms"])
    balls = snap["atoms"]
    balls.data = balls.data[balls.column("type") == 2]
    check_points(snap["points"], atoms)
    check_pairs(snap["pairs"], atoms, snap["points"])
    check_fabric(balls, snap["pairs"])
    check_stress_and_crush(snap["stress"], atoms, snap["points"], snap["pairs"])
    check_wire_elements(snap["wire"], atoms)
    check_wire_contacts(snap["wcontacts"], atoms)
    for line in failures:
        print("FAIL", line)
    print(f"{len(failures)} failed checks; layouts of fabric/atom, nscd/stress/atom, nscd/crush/atom, "
          f"nscd/contacts (points, pairs), wire/local, wire/contacts against {work}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
