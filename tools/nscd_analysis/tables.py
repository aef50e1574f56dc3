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

"""Text files of numbers, one row per line and comment lines starting with # (fix wire's
breaks files, fix print's load curves)."""

import numpy as np


def read_rows(path, fields, error):
    """n x len(fields) array of the file's rows, in order. A line that is not len(fields)
    finite numbers raises `error` naming the file and line."""
    rows = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            text = line.strip()
            if not text or text.startswith("#"):
                continue
            try:
                values = [float(w) for w in text.split()]
            except ValueError:
                values = []
            if len(values) != len(fields) or not np.all(np.isfinite(values)):
                raise error(f"{path}, line {number}: expected {len(fields)} numbers ({' '.join(fields)}), "
                            f"got '{text}'")
            rows.append(values)
    return np.array(rows, dtype=float).reshape(-1, len(fields))
