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

"""Grain-grain contact forces around the column axis (the papers' Fn(r), Fig. 5), from
compute nscd/contacts output: per pair (keyword pairs; position = midpoint of the two
centres, force = the pair's total normal force) or per point (position = contact point)."""

import numpy as np

from .cylinder import Cylindrical, axis_from_centre_of_mass, binned_mean
from .layouts import CONTACT_PAIRS, CONTACT_POINTS


def grain_contacts(snapshot, per_point=False):
    """Positions and normal forces of the grain-grain rows (id_j > 0) with a positive
    normal force; also the grains' centres by ID (pairs only) for the axis."""
    if per_point:
        layout = CONTACT_POINTS
        keep = (snapshot.column("id_j", layout) > 0) & (snapshot.column("fn", layout) > 0)
        points = snapshot.vectors(("px", "py", "pz"), layout)[keep]
        return points, snapshot.column("fn", layout)[keep], points
    layout = CONTACT_PAIRS
    id_j = snapshot.column("id_j", layout)
    keep = (id_j > 0) & (snapshot.column("fn", layout) > 0)
    xi = snapshot.vectors(("xi", "yi", "zi"), layout)
    xj = snapshot.vectors(("xj", "yj", "zj"), layout)
    centres = _unique_centres(snapshot.column("id_i", layout), xi, id_j[keep], xj[keep])
    return 0.5 * (xi[keep] + xj[keep]), snapshot.column("fn", layout)[keep], centres


def _unique_centres(id_i, xi, id_j, xj):
    ids = np.concatenate([id_i, id_j])
    xs = np.concatenate([xi, xj])
    _, first = np.unique(ids, return_index=True)
    return xs[first]


def radii_and_forces(snapshot, axis=None, zrange=None, per_point=False):
    """r from the axis and normal force of the snapshot's grain-grain contacts (within zrange
    in z, if given), and the axis used (default: the grains' centre of mass)."""
    positions, fn, centres = grain_contacts(snapshot, per_point)
    if axis is None:
        axis = axis_from_centre_of_mass(centres)
    if zrange is not None:
        inside = (positions[:, 2] >= zrange[0]) & (positions[:, 2] <= zrange[1])
        positions, fn = positions[inside], fn[inside]
    r = Cylindrical(positions, axis).r if len(positions) else np.zeros(0)
    return r, fn, axis


def radial_profile(snapshot, r_edges, axis=None, zrange=None, per_point=False):
    """count, mean and standard error of the normal force per r bin (one snapshot), and
    the axis used."""
    r, fn, axis = radii_and_forces(snapshot, axis, zrange, per_point)
    count, mean, sem = binned_mean(fn, r, r_edges)
    return count, mean, sem, axis
