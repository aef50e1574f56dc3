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

"""Writers of LAMMPS-format text dumps and logs with chosen contents, for the tests of
tools/nscd_analysis (the format LAMMPS writes: dump custom / dump local, thermo blocks)."""

import gzip
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TOOLS = os.path.join(HERE, "..", "..", "tools")
if TOOLS not in sys.path:
    sys.path.insert(0, TOOLS)


def dump_text(snapshots, kind="ATOMS"):
    """snapshots: list of (timestep, columns, rows); kind ATOMS (dump custom) or ENTRIES
    (dump local)."""
    out = []
    for step, columns, rows in snapshots:
        rows = np.atleast_2d(np.asarray(rows, dtype=float)) if len(rows) else np.zeros((0, len(columns)))
        out += ["ITEM: TIMESTEP", str(step),
                f"ITEM: NUMBER OF {'ATOMS' if kind == 'ATOMS' else 'ENTRIES'}", str(len(rows)),
                "ITEM: BOX BOUNDS ff ff ff", "-10 10", "-10 10", "-1 30",
                f"ITEM: {kind} " + " ".join(columns)]
        for row in rows:
            out.append(" ".join(_number(v) for v in row))
    return "\n".join(out) + "\n"


def _number(v):
    return str(int(v)) if float(v).is_integer() and abs(v) < 1e15 else repr(float(v))


def write_dump(path, snapshots, kind="ATOMS"):
    text = dump_text(snapshots, kind)
    if path.endswith(".gz"):
        with gzip.open(path, "wt") as f:
            f.write(text)
    else:
        with open(path, "w") as f:
            f.write(text)
    return path


def indexed(compute_id, count):
    """Header names c_ID[1] ... c_ID[count]."""
    return [f"c_{compute_id}[{k}]" for k in range(1, count + 1)]


def fabric_rows(positions, tensors_xyz, counts=None):
    """Rows id x y z fxx fyy fzz fxy fxz fyz nc for grains at `positions` with 3 x 3 fabric
    tensors."""
    rows = []
    for k, (p, t) in enumerate(zip(positions, tensors_xyz)):
        n = 1 if counts is None else counts[k]
        rows.append([k + 1, *p, t[0, 0], t[1, 1], t[2, 2], t[0, 1], t[0, 2], t[1, 2], n])
    return rows


FABRIC_HEADER = ["id", "x", "y", "z"] + indexed("fab", 7)


def cylindrical_frame(phi):
    e_r = np.array([np.cos(phi), np.sin(phi), 0.0])
    e_phi = np.array([-np.sin(phi), np.cos(phi), 0.0])
    return e_r, e_phi, np.array([0.0, 0.0, 1.0])


def grains_with_direction(rng, n, axis, angle_of_r, r_max=5.0, z_max=10.0, spread=0.0):
    """Grains at random (r, phi, z) around `axis`, each with the fabric of one direction
    in its r-z plane at the signed angle angle_of_r(r) (+ optional random spread) plus a
    weaker isotropic part: F = 0.6 d d + 0.4 I / 3 (trace 1)."""
    r = r_max * np.sqrt(rng.random(n))
    phi = 2 * np.pi * rng.random(n)
    z = z_max * rng.random(n)
    positions, tensors = [], []
    for k in range(n):
        e_r, _, e_z = cylindrical_frame(phi[k])
        a = angle_of_r(r[k]) + spread * rng.standard_normal()
        d = np.sin(a) * e_r + np.cos(a) * e_z
        tensors.append(0.6 * np.outer(d, d) + 0.4 * np.eye(3) / 3)
        positions.append([axis[0] + r[k] * np.cos(phi[k]), axis[1] + r[k] * np.sin(phi[k]), z[k]])
    return np.array(positions), tensors, r


def log_text(runs, warning_inside=False):
    """A LAMMPS-like log with one thermo block per run: runs = list of (columns, rows)."""
    out = ["LAMMPS (4 Feb 2025)", "units lj"]
    for columns, rows in runs:
        out += ["run 100", "Per MPI rank memory allocation (min/avg/max) = 1 | 1 | 1 Mbytes",
                "   " + "   ".join(columns)]
        for k, row in enumerate(rows):
            out.append("   " + "   ".join(_number(v) for v in row))
            if warning_inside and k == 0:
                out.append("WARNING: fix nscd: step 1 ended unconverged (src/fix_nscd.cpp:700)")
        out.append("Loop time of 0.1 on 1 procs for 100 steps with 7 atoms")
    return "\n".join(out) + "\n"


def read_csv(path):
    """The CSV of an nscd-analysis figure (comment lines start with '#'): a list of dicts,
    numbers as floats."""
    import csv
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    for row in rows:
        for key, value in row.items():
            try:
                row[key] = float(value)
            except ValueError:
                pass
    return rows


def csv_column(rows, name):
    return np.array([row[name] for row in rows])
