#!/usr/bin/env bash
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

# The small column of tools/run_example.sh (examples/column/README.md gives its measured
# numbers), in one place for every script that runs it: sourced, it sets the array
# small_column to the -vars of examples/column/in.column.
small_column=(-var layers 5 -var R 2.5 -var window cylinder -var cells 2 -var element 0.3
              -var layer_steps 500 -var wire_steps 150 -var relax_chunk 250 -var wall_speed 0.2
              -var wall_travel 0.8 -var load_rate 20 -var load_max 20)
