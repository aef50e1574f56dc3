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

// A bar lying edge-down across the top of a narrow block, its lowest edge slightly tilted:
// the edge crosses the block's top face from one border edge to the other, touching (or
// nearly) at the lower crossing. The pair meets edge-first; its other crossing is the
// point a bar turning about the first one brings down (tests of speculative points).
#pragma once

#include "shapes_for_tests.h"

#include <cmath>

namespace nscd::test {

struct BarAcrossBlock {
  double radius = 0.05;
  double tilt = 0.0;           // of the bar's lowest edge, rising towards +x (rad)
  double gap = 0.0;            // at the lower crossing, x = -half_width
  double half_width = 0.3;     // of the block's top face along x (along y it is 1)
  Spheropolyhedron block = make_box(half_width, 1.0, 0.5, radius);
  Spheropolyhedron bar = make_box(1.0, 0.2, 0.2, radius);
  // The block's top face is z = 0.5; the bar turned 45 degrees about x puts its lowest
  // edge at depth h below its centre, then turned by -tilt about y.
  double h = 0.2 * std::sqrt(2.0);

  Quat bar_rotation() const
  {
    return rotation_about(Vec3::UnitY(), -tilt) * rotation_about(Vec3::UnitX(), std::acos(-1.0) / 4);
  }
  // Unit normal of the crossings (the edges' common normal), from the block to the bar.
  Vec3 normal() const { return Vec3(-std::sin(tilt), 0.0, std::cos(tilt)); }
  // Centre height that puts the lower crossing at `gap`: along normal(), the edge line
  // through (h sin(tilt), 0, z - h cos(tilt)) lies gap + 2r above the border edge
  // (-half_width, y, 0.5).
  Vec3 bar_centre() const
  {
    const double s = std::sin(tilt), c = std::cos(tilt);
    return Vec3(0.0, 0.0, 0.5 + (gap + 2 * radius + h + half_width * s) / c);
  }
  // Gap at the upper crossing, x = +half_width: 2 half_width sin(tilt) more.
  double upper_gap() const { return gap + 2 * half_width * std::sin(tilt); }
  Pose bar_pose() const { return place(bar, bar_centre(), bar_rotation()); }
  Pose block_pose() const { return place(block, Vec3::Zero()); }
};

}    // namespace nscd::test
