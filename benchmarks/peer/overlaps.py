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

"""Largest overlap between grains and with the walls, from the last snapshot of the dump
local written by in.overlap (columns: atom i, atom j or -k for the k-th wall, gap).

    overlaps.py CONTACTS_DUMP [r]      (r: rounding radius, the unit of the printout; 0.05)
"""
import argparse

import numpy as np


def last_snapshot(path):
    lines = open(path).read().split('\n')
    start = max(i for i, line in enumerate(lines) if line.startswith('ITEM: TIMESTEP'))
    n = int(lines[start + 3])
    return np.array([[float(c) for c in line.split()] for line in lines[start + 9:start + 9 + n]]).reshape(-1, 3)


def main(path, r=0.05):
    rows = last_snapshot(path)
    pairs, walls = rows[rows[:, 1] > 0], rows[rows[:, 1] < 0]
    def worst(part):
        return max(0.0, -part[:, 2].min()) / r if len(part) else 0.0
    n_over = int((pairs[:, 2] < -0.1 * r).sum()) if len(pairs) else 0
    print(f'{path}: largest overlap grain-grain {worst(pairs):.4f} r, grain-wall {worst(walls):.4f} r; '
          f'{n_over} grain-grain contact points overlap by more than 0.1 r')


if __name__ == '__main__':
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('contacts_dump', help="in.overlap's dump local (atom i, atom j or -k, gap)")
    parser.add_argument('r', nargs='?', type=float, default=0.05,
                        help='rounding radius, the unit of the printout (default 0.05)')
    args = parser.parse_args()
    main(args.contacts_dump, args.r)
