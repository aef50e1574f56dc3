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

"""check_png.py MIN_FRACTION FILE...: each PNG must be under 300 KB and have more than
MIN_FRACTION of its pixels away from the white background, some of them in colour (a
colour-mapped wire or network, not only grey grains). Exit 1 naming the first that fails."""

import os
import sys

import matplotlib.image


def drawn_fractions(path):
    image = matplotlib.image.imread(path)[..., :3]
    drawn = (1.0 - image).max(axis=-1) > 0.1
    coloured = (image.max(axis=-1) - image.min(axis=-1)) > 0.3
    return drawn.mean(), coloured.mean()


def main(argv):
    minimum = float(argv[0])
    for path in argv[1:]:
        size = os.path.getsize(path)
        drawn, coloured = drawn_fractions(path)
        print(f"{path}: {size} bytes, {100 * drawn:.2f} % drawn, {100 * coloured:.2f} % in colour")
        if size >= 300 * 1024:
            sys.exit(f"check_png: {path} is {size} bytes (>= 300 KB)")
        if drawn <= minimum or coloured <= minimum / 10:
            sys.exit(f"check_png: {path} is nearly empty ({100 * drawn:.3f} % drawn, {100 * coloured:.3f} % in "
                     f"colour; expected > {100 * minimum:g} % and > {10 * minimum:g} %)")


if __name__ == "__main__":
    main(sys.argv[1:])
