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

"""Cost of a step of fix nscd split into a per-step part and a per-sweep part, from the
per-step thermo lines of in.bed_run (step, sweeps, residual, overlap, contacts, floor force,
weight, cpu): a least-squares fit t_step = a + b * sweeps over all steps of both runs (the
cpu column restarts at 0 with each run). b / contacts is the cost of one sweep per contact,
which is constant if the solver's cost is linear in the size of the pile.

    fit.py LOG [LOG ...]
"""
import argparse

import numpy as np


def thermo_blocks(path):
    lines, blocks = open(path).read().split('\n'), []
    for i, line in enumerate(lines):
        if line.split()[:1] == ['Step']:
            rows = []
            for row in lines[i + 1:]:
                words = row.split()
                if not words or not words[0].isdigit():
                    break
                rows.append([float(w) for w in words])
            blocks.append(np.array(rows))
    return blocks


def main(paths):
    for path in paths:
        blocks = thermo_blocks(path)
        steps = np.vstack([np.c_[b[1:, 1], np.diff(b[:, 7])] for b in blocks])    # sweeps, seconds
        a, b = np.linalg.lstsq(np.c_[np.ones(len(steps)), steps[:, 0]], steps[:, 1], rcond=None)[0]
        contacts = int(blocks[-1][-1, 4])
        cold_sweeps, cold_seconds = steps[0]
        print(f'{path}: cold first step {cold_sweeps:.0f} sweeps in {1000 * cold_seconds:.0f} ms; '
              f'fit {1000 * a:.1f} ms per step + {1000 * b:.3f} ms per sweep; {contacts} contact points, '
              f'{1e6 * b / contacts:.3f} ms per sweep per 1000 contact points')


if __name__ == '__main__':
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('logs', nargs='+', metavar='LOG', help='log of in.bed_run (per-step thermo)')
    main(parser.parse_args().logs)
