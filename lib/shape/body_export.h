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

// A grain as LAMMPS' BODY package sees it: one entry of the Bodies section of a data file
// for `atom_style body rounded/polyhedron`, so that `pair_style body/rounded/polyhedron`
// can run the very hulls of our shape library (the peer comparison of benchmarks/peer).
//
// BODY's format (LAMMPS doc/src/Howto_body.rst, "rounded/polyhedron"): per body
//   atom-ID 3 M
//   N E F
//   ixx iyy izz ixy ixz iyz          inertia tensor about the centre of mass, box frame
//   x y z  (N times)                 vertex displacements from the centre of mass, box frame
//   i j    (E times)                 edges, vertex indices from 0
//   a b c d (F times)                faces: triangles (d = -1) or planar quads, right-hand
//                                    rule giving the outward normal
//   diameter                         rounding diameter = 2 r
// with M = 6 + 3N + 2E + 4F + 1 floating-point values. Spheres and rods (N = 1, 2) list no
// edges or faces: "N 0 0", M = 6 + 3N + 1.
#pragma once

#include "math/types.h"
#include "shape/spheropolyhedron.h"

#include <array>
#include <iosfwd>
#include <vector>

namespace nscd {

struct BodyEntry {
  std::vector<Vec3> vertices;               // box frame, relative to the centre of mass
  std::vector<std::array<int, 2>> edges;    // the shape's core edges
  std::vector<std::array<int, 4>> faces;    // triangles (-1 last) and quads; BODY allows no more
  Mat3 inertia = Mat3::Zero();              // box frame, about the centre of mass
  double diameter = 0.0;                    // 2 x rounding radius

  int value_count() const;                  // M: floating-point values of the entry
};

// The grain of `shape` turned by `orientation`, with mass `mass` (inertia scaled from the
// shape's unit-density moments). Faces of more than 4 vertices are split into a fan of
// triangles (their diagonals are not edges). Throws ShapeError for a mass that is not a
// finite positive number.
BodyEntry body_entry(const Spheropolyhedron &shape, const Quat &orientation, double mass);

// Writes the entry for atom `atom_id` with 17 significant digits, several vertices, edges
// or faces per line: read_data takes at most 32 lines of 255 characters per body, enough
// for grains of up to 60 vertices.
void write_body_entry(std::ostream &out, long long atom_id, const BodyEntry &entry);

}    // namespace nscd
