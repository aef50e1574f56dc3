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

"""Cylindrical coordinates around a vertical column axis and averages in bins of r (and z).

The axis is parallel to z through (ax, ay): given, or the centre of mass of the grains in
x and y. A point at r = 0 gets e_r = e_x (its azimuth is undefined)."""

import numpy as np


def axis_from_centre_of_mass(positions, masses=None):
    """(x, y) of the column axis: the (mass-weighted) mean of the grains' x and y."""
    positions = np.asarray(positions, dtype=float)
    if len(positions) == 0:
        raise ValueError("no grains to place the axis at their centre of mass; give --axis X Y")
    w = np.ones(len(positions)) if masses is None else np.asarray(masses, dtype=float)
    return np.average(positions[:, :2], axis=0, weights=w)


class Cylindrical:
    """r, z and the local unit vectors e_r, e_phi, e_z of points around an axis through
    `axis` (x, y), parallel to z."""

    def __init__(self, points, axis):
        points = np.atleast_2d(np.asarray(points, dtype=float))
        radial = points[:, :2] - np.asarray(axis, dtype=float)[None, :]
        self.r = np.hypot(radial[:, 0], radial[:, 1])
        self.z = points[:, 2].copy()
        on_axis = self.r == 0.0
        cos_phi = np.where(on_axis, 1.0, radial[:, 0] / np.where(on_axis, 1.0, self.r))
        sin_phi = np.where(on_axis, 0.0, radial[:, 1] / np.where(on_axis, 1.0, self.r))
        n = len(points)
        self.e_r = np.column_stack([cos_phi, sin_phi, np.zeros(n)])
        self.e_phi = np.column_stack([-sin_phi, cos_phi, np.zeros(n)])
        self.e_z = np.tile([0.0, 0.0, 1.0], (n, 1))

    def basis(self):
        """n x 3 x 3: rows e_r, e_phi, e_z of each point (world -> cylindrical components)."""
        return np.stack([self.e_r, self.e_phi, self.e_z], axis=1)


def edges(values, count=None, width=None, low=0.0, high=None):
    """Bin edges from `low` to `high` (default: the largest value) by `count` bins or bins of
    `width`."""
    values = np.asarray(values, dtype=float)
    if high is None:
        high = float(values.max()) if len(values) else 1.0
        high = np.nextafter(high, np.inf)    # the largest value falls in the last bin
    if high <= low:
        high = low + 1.0
    if width is not None:
        n = max(1, int(np.ceil((high - low) / width - 1e-12)))
        return low + width * np.arange(n + 1)
    return np.linspace(low, high, (count or 10) + 1)


def bin_index(values, bin_edges):
    """Bin of each value (-1 outside [first edge, last edge))."""
    k = np.searchsorted(bin_edges, values, side="right") - 1
    k[(values < bin_edges[0]) | (values >= bin_edges[-1])] = -1
    return k


def binned_mean(values, coordinate, bin_edges):
    """Per bin of `coordinate`: count, mean and standard error of `values` (rows of values
    may be vectors or tensors: their mean is taken componentwise). Empty bins give NaN."""
    values = np.asarray(values, dtype=float)
    k = bin_index(np.asarray(coordinate, dtype=float), bin_edges)
    nbins = len(bin_edges) - 1
    count = np.bincount(k[k >= 0], minlength=nbins)
    shape = (nbins,) + values.shape[1:]
    mean = np.full(shape, np.nan)
    sem = np.full(shape, np.nan)
    for b in range(nbins):
        chosen = values[k == b]
        if len(chosen):
            mean[b] = chosen.mean(axis=0)
            sem[b] = chosen.std(axis=0, ddof=1) / np.sqrt(len(chosen)) if len(chosen) > 1 else np.nan
    return count, mean, sem


def binned_mean_2d(values, r, z, r_edges, z_edges):
    """Per (r, z) bin: count and mean of `values` (componentwise for vector/tensor rows)."""
    values = np.asarray(values, dtype=float)
    kr, kz = bin_index(np.asarray(r), r_edges), bin_index(np.asarray(z), z_edges)
    nr, nz = len(r_edges) - 1, len(z_edges) - 1
    count = np.zeros((nr, nz), dtype=int)
    mean = np.full((nr, nz) + values.shape[1:], np.nan)
    inside = (kr >= 0) & (kz >= 0)
    for i in range(nr):
        for j in range(nz):
            chosen = values[inside & (kr == i) & (kz == j)]
            count[i, j] = len(chosen)
            if len(chosen):
                mean[i, j] = chosen.mean(axis=0)
    return count, mean


def over_samples(per_sample):
    """Per bin, over samples that each give a value per bin (one row per sample, e.g. one per
    seed; NaN where a sample's bin is empty): how many samples have a value, their mean and
    their sample standard deviation (NaN below two samples). Rows may hold vectors per bin."""
    values = np.asarray(per_sample, dtype=float)
    has = ~np.isnan(values)
    n = has.sum(axis=0)
    mean = np.where(n > 0, np.where(has, values, 0.0).sum(axis=0) / np.maximum(n, 1), np.nan)
    squares = np.where(has, values - mean, 0.0) ** 2
    sd = np.where(n > 1, np.sqrt(squares.sum(axis=0) / np.maximum(n - 1, 1)), np.nan)
    return n, mean, sd


def centres(bin_edges):
    return 0.5 * (bin_edges[1:] + bin_edges[:-1])
