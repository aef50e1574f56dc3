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

"""Writes the LAMMPS data file of the wire benchmark column (benchmarks/wire/in.settle).

Layers of grains on two staggered square lattices, as in the papers' column (shape 0
here; the deck gives them random shapes), with a double wire loop (a flat two-turn spiral
with loose ends) laid on each layer, under the next one. Atoms: grains first (type 2),
then the wire nodes (type 1), layer by layer. The floor is at z = 0.

    make_column.py [--layers 4] [--side 7] [--spacing 1.0] [--radius 2.3]
                   [--element 0.05] [--turn-gap 0.045] > column.data
"""
import argparse
import math


def spiral(radius, turn_gap, element):
    """Nodes of a two-turn flat spiral r = radius + turn_gap * theta / (2 pi), about
    `element` apart along the curve."""
    nodes, theta = [], 0.0
    while theta <= 4.0 * math.pi:
        r = radius + turn_gap * theta / (2.0 * math.pi)
        nodes.append((r * math.cos(theta), r * math.sin(theta)))
        theta += element / r
    return nodes


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--layers", type=int, default=4)
    p.add_argument("--side", type=int, default=7, help="grains per row of the first lattice")
    p.add_argument("--spacing", type=float, default=1.0, help="lattice spacing of the grains")
    p.add_argument("--size", type=float, default=1.0, help="largest grain diameter")
    p.add_argument("--radius", type=float, default=2.3, help="inner radius of the spiral")
    p.add_argument("--element", type=float, default=0.05, help="laid element length")
    p.add_argument("--turn-gap", type=float, default=0.045, help="radial distance of the turns")
    a = p.parse_args()

    # lattice B sits over the holes of lattice A, high enough that bounding spheres of
    # diameter `size` do not overlap; the wire lies on B, the next layer's A over it
    half = 0.5 * (a.side - 1) * a.spacing
    rise = math.sqrt(max(a.size ** 2 - 0.5 * a.spacing ** 2, 0.0)) + 0.02
    pitch = rise + a.size + 0.12
    grains, wires = [], []
    loop = spiral(a.radius, a.turn_gap, a.element)
    for k in range(a.layers):
        z_a = 0.5 * a.size + 0.01 + k * pitch
        for i in range(a.side):
            for j in range(a.side):
                grains.append((i * a.spacing - half, j * a.spacing - half, z_a))
        for i in range(a.side - 1):
            for j in range(a.side - 1):
                grains.append(((i + 0.5) * a.spacing - half, (j + 0.5) * a.spacing - half, z_a + rise))
        wires.append([(x, y, z_a + rise + 0.5 * a.size + 0.05) for x, y in loop])

    atoms, bonds, angles = [], [], []
    for g in grains:
        atoms.append((2, g))
    for wire in wires:
        first = len(atoms) + 1
        for node in wire:
            atoms.append((1, node))
        ids = list(range(first, first + len(wire)))
        bonds += [(ids[n], ids[n + 1]) for n in range(len(ids) - 1)]
        angles += [(ids[n], ids[n + 1], ids[n + 2]) for n in range(len(ids) - 2)]

    reach = half + a.spacing
    out = ["wire benchmark column: %d grains, %d wire nodes in %d double loops"
           % (len(grains), len(atoms) - len(grains), a.layers), "",
           "%d atoms" % len(atoms), "2 atom types", "%d bonds" % len(bonds), "1 bond types",
           "%d angles" % len(angles), "1 angle types", "",
           "%g %g xlo xhi" % (-reach, reach), "%g %g ylo yhi" % (-reach, reach),
           "%g %g zlo zhi" % (-0.5, (a.layers + 1) * pitch), "", "Atoms # hybrid", ""]
    for n, (t, (x, y, z)) in enumerate(atoms, start=1):
        out.append("%d %d %.10g %.10g %.10g 0 1 1 0 0 0 0" % (n, t, x, y, z))
    out += ["", "Bonds", ""]
    out += ["%d 1 %d %d" % (n, i, j) for n, (i, j) in enumerate(bonds, start=1)]
    out += ["", "Angles", ""]
    out += ["%d 1 %d %d %d" % (n, i, j, k) for n, (i, j, k) in enumerate(angles, start=1)]
    print("\n".join(out))


if __name__ == "__main__":
    main()
