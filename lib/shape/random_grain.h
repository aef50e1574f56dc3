/* -*- c++ -*- ----------------------------------------------------------
   NSCD package for LAMMPS: Non-Smooth Contact Dynamics of rigid
   spheropolyhedra coupled to elastic wires.

   Copyright (2026) the NSCD package developers. This software is
   distributed under the GNU General Public License, version 2, the
   licence of LAMMPS. See the LICENSE file in the top-level directory
   of the package.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing author: the NSCD package developers
------------------------------------------------------------------------- */

// Seeded random ballast-like grains: the convex hull of random points on an ellipsoid,
// scaled to a drawn volume-equivalent diameter, optionally rounded.
//
// Reproducible: the same seed and parameters give the same grains on every platform and
// standard library (only the raw std::mt19937_64 output is used, with our own conversion
// to reals; points come from rejection sampling and square roots, no trigonometry).
#pragma once

#include "shape/shape_library.h"
#include "shape/spheropolyhedron.h"

#include <cstdint>

namespace nscd {

struct RandomGrainParams {
  int min_vertices = 12;        // points per grain, drawn uniformly in [min, max]; >= 4
  int max_vertices = 24;
  double min_diameter = 1.0;    // diameter of the sphere of equal (dilated) volume,
  double max_diameter = 1.0;    // drawn uniformly in [min, max]; > 0
  double ratio_b = 0.8;         // ellipsoid semi-axes 1 : b/a : c/a, each in (0, 1]
  double ratio_c = 0.6;
  double ratio_spread = 0.0;    // each grain's ratios drawn in ratio * [1 - s, 1 + s], capped at 1; s in [0, 1)
  double radius = 0.0;          // rounding radius r >= 0, below min_diameter / 2
};

// Throws ShapeError naming the first bad parameter and the allowed range.
void validate(const RandomGrainParams &params);

// Grain number `index` (0-based) of the stream of `seed`: independent of how many grains
// are drawn, so the first k grains of a run are the same for any count >= k.
Spheropolyhedron random_grain(const RandomGrainParams &params, std::uint64_t seed, int index);

// Appends `count` grains named grain_<seed>_<k> (k = 1..count); returns the first new id.
int add_random_grains(ShapeLibrary &library, const RandomGrainParams &params, int count, std::uint64_t seed);

}    // namespace nscd
