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

// Where a wire is laid: its centre line (a loop or helix around an axis, a straight line, a
// polyline) cut into nodes a given straight distance apart. Used by the `create_wire`
// command; pure geometry, no LAMMPS. See doc/create_wire.rst.
//
// Nodes follow the path at equal chords: node k+1 is the first point after node k along
// the path at straight distance `chord` from it. The first node is the path's start; an
// open path ends at the last node that fits, less than one chord before the path's end (a
// loop's gap is widened by less than one element), so every element has exactly the rest
// length. A closed path (a flat loop of one turn without a gap) gets n equal arcs, n the
// whole number nearest to length / chord: its chords differ from the requested one by
// the rounding (WireLayout::chord says by how much).
#pragma once

#include "math/types.h"
#include "wire/elastic_forces.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace nscd::wire {

// Bad path or spacing (the message names the value and the way out).
class WirePathError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Circle of radius `radius` around `axis` through `centre`, swept from angle `start` (rad,
// measured from the first axis-perpendicular direction, see loop_frame) through `turns`
// turns less `gap` (rad), rising `pitch` along the axis per turn. One flat turn without a
// gap is closed.
struct LoopPath {
  Vec3 centre = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double radius = 1.0;
  double turns = 1.0;
  double pitch = 0.0;
  double gap = 0.0;
  double start = 0.0;
};

// A piecewise straight path through the points (two points: a line).
struct PolylinePath {
  std::vector<Vec3> points;
};

// The points of a polyline file (`create_wire polyline FILE`): one point "x y z" per line,
// three decimal numbers (as in a deck: 1, -0.5, 2.5e-3); blank lines and comments (from '#')
// are skipped. Throws WirePathError naming the source, the line number and the line for any
// other line, e.g. a header line, nan, inf, or a number beyond the range of doubles (1e400).
PolylinePath read_polyline(const std::string &text, const std::string &source_name);

// Unit vectors e1, e2 with (e1, e2, axis) right-handed: angle 0 of a loop points along e1.
// For the z axis e1 = x and e2 = y; otherwise e1 is the world axis least aligned with
// `axis`, made perpendicular to it.
void loop_frame(const Vec3 &axis, Vec3 &e1, Vec3 &e2);

struct WireLayout {
  std::vector<Vec3> nodes;
  bool closed = false;     // an element joins the last node to the first
  double chord = 0.0;      // the straight length of every element
  WireTopology topology;   // elements (rest length `chord`) and joints
};

// Nodes `chord` apart along the path (see the file comment). Throws WirePathError for a
// chord that is not positive, that does not fit into the path (a loop's chord must be
// below its diameter; no point of the path as far as a chord from its start), or a path
// with coinciding points.
WireLayout lay_loop(const LoopPath &path, double chord);
WireLayout lay_polyline(const PolylinePath &path, double chord);

// The same paths cut into exactly `nodes` nodes (>= 2) at equal chords that span the whole
// path (closed loop: `nodes` equal arcs); the chord follows.
WireLayout lay_loop_nodes(const LoopPath &path, int nodes);
WireLayout lay_polyline_nodes(const PolylinePath &path, int nodes);

// The same paths continuing a wire from its free end `from` (create_wire ... from ID): the
// path walked at equal chords is the straight segment from `from` to the path's start (none
// if they coincide within 1e-9 of a chord), then the path; node 0 is `from` itself, so the
// first element is the join, at the rest length like every other. A closed loop cannot
// continue a wire (it has no free end to continue with): WirePathError.
WireLayout lay_loop_from(const Vec3 &from, const LoopPath &path, double chord);
WireLayout lay_polyline_from(const Vec3 &from, const PolylinePath &path, double chord);

// The point of the loop at sweep fraction t in [0, 1].
Vec3 loop_point(const LoopPath &path, double t);

// Topology of a closed ring of n nodes: elements (k, k+1 mod n), joints at every node.
WireTopology closed_ring_topology(int num_nodes, double rest_length);

}    // namespace nscd::wire
