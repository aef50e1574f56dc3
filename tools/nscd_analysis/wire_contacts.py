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

"""Orientation of wire contact forces in the z-r plane (the papers' Fig. 6), from compute
wire/contacts output (layouts.WIRE_CONTACTS).

For each contact the force on the wire f = fn n + f_t is split into its radial and vertical
components at the contact point, f_r = f . e_r and f_z = f . e_z (the azimuthal part is
dropped). Its orientation is the line angle alpha = atan2(f_z, f_r) folded into [0, pi):
0 = radial, pi/2 = vertical (the papers' 90 degrees along z); alpha and alpha + pi are the
same line, so p(alpha) = p(alpha + pi) and half a turn is the whole picture."""

import numpy as np

from .cylinder import Cylindrical
from .layouts import WIRE_CONTACTS, WIRE_GRAIN


def forces_on_wire(snapshot, kind=WIRE_GRAIN):
    """Contact points and force vectors on the wire of the rows of this kind."""
    layout = WIRE_CONTACTS
    keep = snapshot.column("kind", layout) == kind
    n = snapshot.vectors(("nx", "ny", "nz"), layout)
    ft = snapshot.vectors(("ftx", "fty", "ftz"), layout)
    f = snapshot.column("fn", layout)[:, None] * n + ft
    return snapshot.vectors(("px", "py", "pz"), layout)[keep], f[keep]


def orientation_rz(points, forces, axis):
    """alpha in [0, pi) and the in-plane magnitude sqrt(f_r^2 + f_z^2) of each force."""
    cyl = Cylindrical(points, axis)
    f_r = np.einsum("ij,ij->i", forces, cyl.e_r)
    f_z = forces[:, 2]
    alpha = np.mod(np.arctan2(f_z, f_r), np.pi)
    alpha[alpha >= np.pi] = 0.0    # (round-off of mod)
    return alpha, np.hypot(f_r, f_z)


def polar_histogram(alpha, magnitude, bins):
    """Bins over [0, pi): edges, fraction of the contacts in each bin, mean in-plane force
    magnitude per bin and that mean divided by its largest bin value (the papers' normalised
    polar average; NaN for empty bins)."""
    edges = np.linspace(0.0, np.pi, bins + 1)
    k = np.minimum((alpha / np.pi * bins).astype(int), bins - 1)
    count = np.bincount(k, minlength=bins)
    fraction = count / max(1, len(alpha))
    total = np.bincount(k, weights=magnitude, minlength=bins)
    mean = np.where(count > 0, total / np.maximum(count, 1), np.nan)
    top = np.nanmax(mean) if np.any(count > 0) else np.nan
    return edges, fraction, mean, mean / top


def fraction_near_vertical(alpha, half_width_degrees=30.0):
    """Fraction of the orientations within half_width of the vertical (pi/2)."""
    if len(alpha) == 0:
        return np.nan
    return float(np.mean(np.abs(alpha - np.pi / 2) <= np.radians(half_width_degrees) + 1e-12))
