#!/usr/bin/python3
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

"""Coefficients of the arctangent polynomial in lib/wire/elastic_forces.cpp (node angles).

atan(y) = y + y z P(z), z = y^2, on 0 <= y <= tan(pi/8). P interpolates
g(z) = (atan(sqrt z) - sqrt z) / z^(3/2) at the 11 Chebyshev nodes of [0, tan^2(pi/8)]
(near-minimax), in 50-digit arithmetic. Prints the coefficients (P's constant term
first) and the largest error of y + y z P(z) evaluated in double precision, in units of
2^-53 of atan(y), over 20000 points.
"""
import mpmath as mp

mp.mp.dps = 50
DEGREE = 10
Z = (mp.sqrt(2) - 1) ** 2


def g(z):
    if z == 0:
        return mp.mpf(-1) / 3
    r = mp.sqrt(z)
    return (mp.atan(r) - r) / (z * r)


nodes = [Z / 2 * (1 + mp.cos(mp.pi * (k + mp.mpf(1) / 2) / (DEGREE + 1))) for k in range(DEGREE + 1)]
A = mp.matrix([[x ** j for j in range(DEGREE + 1)] for x in nodes])
coefficients = [float(c) for c in mp.lu_solve(A, mp.matrix([g(x) for x in nodes]))]
for c in coefficients:
    print(repr(c))
worst = 0
for i in range(1, 20001):
    y = float(mp.sqrt(Z)) * i / 20000
    z = y * y
    p = coefficients[-1]
    for c in reversed(coefficients[:-1]):
        p = p * z + c
    exact = mp.atan(mp.mpf(y))
    worst = max(worst, abs((mp.mpf(y + y * z * p) - exact) / exact) * 2 ** 53)
print("largest error:", float(worst), "x 2^-53 relative")
