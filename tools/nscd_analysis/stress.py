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

"""Per-grain stresses (compute nscd/stress/atom) and crushing indices (compute nscd/crush/atom)
around the column's axis: principal stress directions in the r-z plane, the signed angle of
the major principal stress, sigma_zz vs r, and the fraction of grains past a crushing
threshold vs r and z. Numbers only; plots.py draws them.

Sign. compute nscd/stress/atom reports tension positive (LAMMPS' convention): a loaded
column's grains have sigma_zz < 0. The principal directions here are those of the
compressive stress -sigma (soil mechanics' sign), so the "major" principal stress is the most
compressive one, the largest eigenvalue of -sigma, and the fabric's machinery (fabric.py:
r-z blocks, principal_rz, signed_angle and its sign convention) applies unchanged."""

import numpy as np

from . import fabric
from .cylinder import Cylindrical, binned_mean
from .dumps import DumpError
from .layouts import CRUSH, STRESS

STRESS_COMPONENTS = ("sxx", "syy", "szz", "sxy", "sxz", "syz")


def compute_column(snapshot, name, layout, compute_id=None):
    """Column `name` of a compute's array: the header named `name`, else c_ID[k] with k its
    entry in `layout` (compute_id given: only that compute's columns, so that c_sig[*] and
    c_crush[*] in one dump are told apart)."""
    if compute_id is None or snapshot.has(name):
        return snapshot.column(name, layout)
    header = f"c_{compute_id}[{layout[name]}]"
    if not snapshot.has(header):
        raise DumpError(f"{snapshot.source}: no column '{name}' nor '{header}' in ITEM line "
                        f"({' '.join(snapshot.columns)}); give the compute's ID (--stress-id, --crush-id)")
    return snapshot.column(header)


def positions(snapshot):
    return np.column_stack([snapshot.first_column(n) for n in (("xu", "x"), ("yu", "y"), ("zu", "z"))])


def _within(pos, zrange):
    if zrange is None:
        return np.ones(len(pos), dtype=bool)
    return (pos[:, 2] >= zrange[0]) & (pos[:, 2] <= zrange[1])


def stress_components(snapshot, compute_id=None):
    """n x 6 (xx yy zz xy xz yz), tension positive, as the compute writes them."""
    return np.column_stack([compute_column(snapshot, c, STRESS, compute_id) for c in STRESS_COMPONENTS])


def per_grain(snapshot, axis, zrange=None, compute_id=None, min_anisotropy=1e-12):
    """Per loaded grain (a stress tensor not all zero: grains without contacts are left out):
    r, z, the r-z block of the compressive stress -sigma in its cylindrical frame, and the
    signed angle of the major (most compressive) principal direction with the vertical (NaN
    where the block's eigenvalues are equal within min_anisotropy x its largest magnitude)."""
    pos = positions(snapshot)
    comps = stress_components(snapshot, compute_id)
    chosen = np.any(comps != 0.0, axis=1) & _within(pos, zrange)
    pos, comps = pos[chosen], comps[chosen]
    cyl = Cylindrical(pos, axis)
    blocks = fabric.rz_blocks(fabric.tensors(-comps), cyl)
    lam_max, v_max, lam_min, _ = fabric.principal_rz(blocks)
    angle = fabric.signed_angle(v_max)
    scale = np.maximum(np.abs(lam_max), np.abs(lam_min))
    angle[lam_max - lam_min <= min_anisotropy * scale] = np.nan
    return cyl.r, cyl.z, blocks, angle


def szz_profile(snapshot, axis, r_edges, zrange=None, compute_id=None):
    """Per r bin: grains, mean and standard error of sigma_zz (tension positive) over the grains
    with contacts."""
    pos = positions(snapshot)
    comps = stress_components(snapshot, compute_id)
    chosen = np.any(comps != 0.0, axis=1) & _within(pos, zrange)
    r = Cylindrical(pos[chosen], axis).r
    return binned_mean(comps[chosen, 2], r, r_edges)


def crushed(snapshot, threshold, value="index", zrange=None, compute_id=None):
    """Positions of the grains and whether each is past the threshold: `value` (index,
    sigma = F/d^2 or fmax) >= threshold. Grains with no contact (fmax 0) count as intact."""
    pos = positions(snapshot)
    v = compute_column(snapshot, value, CRUSH, compute_id)
    inside = _within(pos, zrange)
    return pos[inside], v[inside] >= threshold


def fraction_profile(flags, coordinate, bin_edges):
    """Per bin of `coordinate`: grains, fraction past the threshold, its binomial standard
    error sqrt(f (1 - f) / n) (NaN for empty bins)."""
    count, fraction, _ = binned_mean(np.asarray(flags, dtype=float), coordinate, bin_edges)
    with np.errstate(invalid="ignore", divide="ignore"):
        error = np.sqrt(fraction * (1.0 - fraction) / count)
    return count, fraction, error
