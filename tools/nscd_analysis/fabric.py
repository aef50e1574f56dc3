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

"""Fabric tensors (compute fabric/atom) in the cylindrical frame of the column, their
principal directions in the r-z plane and the signed angle of the largest with the vertical.

Signed angle. A principal direction is a line: of its two unit vectors take the one with
v_z > 0 (v_r > 0 if v_z = 0). In the (r, z) half-plane through the grain, its angle with the
vertical is phi = atan2(v_r, v_z), in (-pi/2, pi/2]: positive when the line leans outward
going up (first quadrant of the (r, z) plane), i.e. a force line followed downward moves
toward the axis - the papers' "inward" for the wire column; negative when it moves
outward going down (second quadrant), as arches carry loads to a silo's wall. The angle is
discontinuous at +-pi/2 (a horizontal line): grains whose largest direction is nearly
horizontal push a mean of per-grain angles toward zero."""

import numpy as np

from .cylinder import Cylindrical

COMPONENTS = ("fxx", "fyy", "fzz", "fxy", "fxz", "fyz")


def tensors(components):
    """n x 6 (xx yy zz xy xz yz) -> n x 3 x 3 symmetric."""
    c = np.asarray(components, dtype=float)
    t = np.empty((len(c), 3, 3))
    t[:, 0, 0], t[:, 1, 1], t[:, 2, 2] = c[:, 0], c[:, 1], c[:, 2]
    t[:, 0, 1] = t[:, 1, 0] = c[:, 3]
    t[:, 0, 2] = t[:, 2, 0] = c[:, 4]
    t[:, 1, 2] = t[:, 2, 1] = c[:, 5]
    return t


def rz_blocks(world_tensors, cylindrical: Cylindrical):
    """The r-z blocks [[F_rr, F_rz], [F_rz, F_zz]] of the tensors in each point's
    cylindrical frame (n x 2 x 2)."""
    b = cylindrical.basis()
    local = np.einsum("nik,nkl,njl->nij", b, world_tensors, b)
    return local[:, [0, 2]][:, :, [0, 2]]


def principal_rz(blocks):
    """Largest and smallest eigenvalues of 2 x 2 symmetric blocks and their unit eigenvectors
    as (v_r, v_z), each turned to v_z > 0 (v_r > 0 if v_z = 0)."""
    values, vectors = np.linalg.eigh(np.asarray(blocks, dtype=float))
    lam_min, lam_max = values[..., 0], values[..., 1]
    v_min, v_max = _upward(vectors[..., :, 0]), _upward(vectors[..., :, 1])
    return lam_max, v_max, lam_min, v_min


def _upward(v):
    flip = (v[..., 1] < 0) | ((v[..., 1] == 0) & (v[..., 0] < 0))
    return np.where(flip[..., None], -v, v)


def signed_angle(v):
    """Angle (radians) of upward-turned (v_r, v_z) directions with the vertical, in
    (-pi/2, pi/2]; positive: leaning outward going up (see the module's doc)."""
    v = _upward(np.asarray(v, dtype=float))
    return np.arctan2(v[..., 0], v[..., 1])


def per_grain(snapshot, axis, zrange=None, min_anisotropy=1e-9):
    """Per grain with contacts of a dump custom snapshot (columns x y z or xu yu zu, and the
    fabric/atom columns): r, z, r-z block, largest direction's angle. Grains whose r-z block
    has no principal direction (equal eigenvalues within min_anisotropy, e.g. one contact
    along e_phi) get a NaN angle."""
    from .layouts import FABRIC
    count = snapshot.column("nc", FABRIC)
    chosen = count > 0
    pos = np.column_stack([snapshot.first_column(names) for names in (("xu", "x"), ("yu", "y"), ("zu", "z"))])
    comps = snapshot.vectors(COMPONENTS, FABRIC)
    pos, comps = pos[chosen], comps[chosen]
    if zrange is not None:
        inside = (pos[:, 2] >= zrange[0]) & (pos[:, 2] <= zrange[1])
        pos, comps = pos[inside], comps[inside]
    cyl = Cylindrical(pos, axis)
    blocks = rz_blocks(tensors(comps), cyl)
    lam_max, v_max, lam_min, _ = principal_rz(blocks)
    angle = signed_angle(v_max)
    angle[lam_max - lam_min <= min_anisotropy] = np.nan
    return cyl.r, cyl.z, blocks, angle
