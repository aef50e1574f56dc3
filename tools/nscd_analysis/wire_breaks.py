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

"""The breaks files of fix wire (`breaks FILE`: one line per broken element, "step node_id_1
node_id_2 tension x y z", comment lines starting with #): where the wire broke, in the
column's cylindrical coordinates."""

import numpy as np

from .cylinder import Cylindrical
from .tables import read_rows

FIELDS = ("step", "id1", "id2", "tension", "x", "y", "z")


class BreaksError(ValueError):
    pass


def read_breaks(path):
    """n x 7 array (FIELDS) of a breaks file; an empty file (no break) gives 0 rows. A line
    that is not 7 numbers is refused naming the file and line."""
    return read_rows(path, FIELDS, BreaksError)


def positions_rz(breaks, axis):
    """r and z of each break's midpoint around the vertical axis through `axis`."""
    cyl = Cylindrical(breaks[:, 4:7], axis) if len(breaks) else None
    return (cyl.r, cyl.z) if cyl is not None else (np.zeros(0), np.zeros(0))
