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

"""Per-grain r-z tensor blocks (fabric.per_grain, stress.per_grain) pooled over snapshots and
reduced to what the figures show: the mean block and its principal directions per (r, z)
bin, and the mean signed angle per r bin."""

import numpy as np

from . import cylinder, fabric


def pooled(per_grain, snapshots):
    """per_grain(snapshot) -> (r, z, blocks, angle) of the snapshot's grains; the arrays of
    all snapshots joined in their order, and the number of snapshots."""
    parts = [per_grain(s) for s in snapshots]
    r, z, blocks, angle = (np.concatenate([p[k] for p in parts]) for k in range(4))
    return r, z, blocks, angle, len(snapshots)


def principal_field(r, z, blocks, r_edges, z_edges):
    """Per non-empty (r, z) bin: the mean r-z block, its principal values and directions and
    the signed angle of the largest (rows for the CSV, segments for plots.draw_field)."""
    count, mean = cylinder.binned_mean_2d(blocks.reshape(len(blocks), 4), r, z, r_edges, z_edges)
    rc, zc = cylinder.centres(r_edges), cylinder.centres(z_edges)
    rows, segments = [], []
    for i in range(len(rc)):
        for j in range(len(zc)):
            if count[i, j] == 0:
                continue
            block = mean[i, j].reshape(2, 2)
            lam_max, v_max, lam_min, v_min = fabric.principal_rz(block[None])
            angle = float(fabric.signed_angle(v_max)[0])
            rows.append((rc[i], zc[j], count[i, j], block[0, 0], block[0, 1], block[1, 1], lam_max[0],
                         v_max[0, 0], v_max[0, 1], lam_min[0], v_min[0, 0], v_min[0, 1], angle))
            segments.append((rc[i], zc[j], lam_max[0], v_max[0], lam_min[0], v_min[0], angle))
    return rows, segments


def angle_profile(r, blocks, angle, r_edges):
    """Per r bin: grains, mean of the per-grain angles, its standard error, and the angle of
    the bin's mean r-z block."""
    ok = ~np.isnan(angle)
    count, mean, sem = cylinder.binned_mean(angle[ok], r[ok], r_edges)
    _, mean_block, _ = cylinder.binned_mean(blocks.reshape(len(blocks), 4), r, r_edges)
    tensor_angle = np.full(len(count), np.nan)
    for b in range(len(count)):
        if not np.isnan(mean_block[b]).any():
            tensor_angle[b] = fabric.signed_angle(fabric.principal_rz(mean_block[b].reshape(1, 2, 2))[1])[0]
    return count, mean, sem, tensor_angle
