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

"""The load-displacement files of examples/column (NAME.load_curve.txt, written by fix print
from fix nscd/plate: "step load force_on_plate displacement sink_over_window" per row,
comment lines starting with #): the curve, how far the plate sank at given loads, and the
largest force it felt."""

import numpy as np

from .tables import read_rows

FIELDS = ("step", "load", "force", "displacement", "sink_over_window")


class LoadCurveError(ValueError):
    pass


def read_load_curve(path):
    """n x 5 array (FIELDS) of a load-curve file, in its order. A line that is not 5 finite
    numbers is refused naming the file and line; so is a file without rows."""
    curve = read_rows(path, FIELDS, LoadCurveError)
    if not len(curve):
        raise LoadCurveError(f"{path}: no rows (the plate's phase did not start?)")
    return curve


def sink(curve):
    """How far the plate has sunk below where the loading started (the displacement is
    negative downward)."""
    return -curve[:, 3]


def sink_at_loads(curve, loads):
    """The plate's sink when the load first reached each of `loads` (linear between rows; NaN
    for a load the curve never reached)."""
    load, down = curve[:, 1], sink(curve)
    out = []
    for target in loads:
        reached = np.nonzero(load >= target)[0]
        if len(reached) == 0:
            out.append(np.nan)
            continue
        k = reached[0]
        if k == 0 or load[k] == load[k - 1]:
            out.append(float(down[k]))
        else:
            w = (target - load[k - 1]) / (load[k] - load[k - 1])
            out.append(float(down[k - 1] + w * (down[k] - down[k - 1])))
    return np.array(out)


def summary(curve):
    """(last load, last sink, largest force on the plate, the sink where it was felt)."""
    k = int(np.argmax(curve[:, 2]))
    return curve[-1, 1], sink(curve)[-1], curve[k, 2], sink(curve)[k]
