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

// Overlaps of wire elements (spherocylinders of the wire's radius) with each other, as the
// contact model would see them, and with grains: for create_wire, which refuses to lay a
// wire into itself (turns of a helix closer than the wire's diameter, a loop reaching its
// own periodic image), into a wire already there or into grains, and for fix wire, which
// warns about elements inside grains at the start of a run. Between elements of one wire,
// those joined by a node or by one element are exempt, as in the contact model (that is
// the wire's own bending). Pure geometry, no LAMMPS.
#pragma once

#include "math/types.h"
#include "shape/spheropolyhedron.h"
#include "wire/elastic_forces.h"

#include <functional>
#include <vector>

namespace nscd::wire {

// Elements by their nodes' positions (unwrapped) and the topology's node indices.
struct WirePieces {
  std::vector<Vec3> nodes;
  std::vector<WireElement> elements;
};

// The deepest overlap found (depth > 0), or depth 0 if none: elements a of the first set and
// b of the second (indices into `elements`), the second set shifted by `shift` (one of the
// periodic translations given, or zero).
struct ElementOverlap {
  double depth = 0.0;
  int a = -1, b = -1;
  Vec3 shift = Vec3::Zero();
};

// Within one wire: every pair of its elements not joined (see the file comment), and every
// pair of an element and a copy shifted by one of `shifts` (periodic images; zero vectors
// are ignored there).
ElementOverlap deepest_overlap_within(const WirePieces &wire, double radius, const std::vector<Vec3> &shifts);

// Between two wires (no pair exempt), the second also shifted by each of `shifts`.
ElementOverlap deepest_overlap_between(const WirePieces &first, const WirePieces &second, double radius,
                                       const std::vector<Vec3> &shifts);

// A grain where it stands.
struct PlacedGrain {
  const Spheropolyhedron *shape;
  Pose pose;
};

// The deepest overlap of the wire's elements with the grains, each grain also shifted by
// each of `shifts` (zero vectors are ignored there): element a, grain b (indices).
ElementOverlap deepest_overlap_with_grains(const WirePieces &wire, double radius, const std::vector<PlacedGrain> &grains,
                                           const std::vector<Vec3> &shifts);

// How far a wire can be lowered (create_wire's `drop`) before it touches something.
// `depth(d)` is the deepest overlap of the wire lowered by d with what lies below (<= 0:
// clear). Scans down from d = 0 in steps of `step`, then halves the last step until it is
// shorter than `tolerance`: `distance` is the largest drop found clear, within `tolerance`
// of the first touch. An obstacle thinner than `step` can be stepped over: the caller takes
// a step below the thinnest thing a wire can meet (the wire's own radius: the wire is 2
// radii thick). Already overlapping at d = 0: distance 0, touched. Nothing met down to
// `max_drop`: distance max_drop, not touched.
struct Drop {
  double distance = 0.0;
  bool touched = false;
};
Drop first_touch_drop(const std::function<double(double)> &depth, double max_drop, double step, double tolerance);

}    // namespace nscd::wire
