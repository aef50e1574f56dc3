/* ----------------------------------------------------------------------
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

// lib/wire/wire_overlap: overlaps between wire elements, against closed forms.
#include "wire/wire_overlap.h"
#include "wire/wire_path.h"
#include "../geometry/shapes_for_tests.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace nscd;
using namespace nscd::wire;

namespace {
constexpr double kPi = 3.141592653589793;

WirePieces pieces_of(const WireLayout &layout)
{
  return {layout.nodes, layout.topology.elements};
}
}    // namespace

// A straight wire and a flat ring never overlap themselves: neighbouring elements and those
// joined by one element are exempt (they meet at the nodes).
TEST(WireOverlap, StraightWireAndRingAreFree)
{
  PolylinePath line;
  line.points = {Vec3(0, 0, 0), Vec3(10, 0, 0)};
  EXPECT_EQ(deepest_overlap_within(pieces_of(lay_polyline(line, 0.1)), 0.05, {}).depth, 0.0);
  LoopPath ring;
  ring.radius = 1.0;
  EXPECT_EQ(deepest_overlap_within(pieces_of(lay_loop(ring, 0.1)), 0.05, {}).depth, 0.0);
}

// Two turns of a helix of pitch p overlap by 2 r - p cos(a) (the distance of the turns along
// the normal to the helix, at angle a to the plane), up to the sagitta s of a chord (the
// elements cut inside the curve, by at most s).
TEST(WireOverlap, HelixTurnsCloserThanTheDiameterOverlapByTheDifference)
{
  const double r = 0.05, R = 1.0, chord = 0.1;
  for (double pitch : {0.02, 0.05, 0.09}) {
    LoopPath helix;
    helix.radius = R;
    helix.turns = 2.0;
    helix.pitch = pitch;
    const ElementOverlap o = deepest_overlap_within(pieces_of(lay_loop(helix, chord)), r, {});
    const double a = std::atan(pitch / (2 * kPi * R));
    const double sagitta = R * (1.0 - std::cos(std::asin(chord / (2 * R))));
    EXPECT_NEAR(o.depth, 2 * r - pitch * std::cos(a), sagitta) << pitch;
    EXPECT_GT(std::abs(o.a - o.b), 2);    // one turn apart, not neighbours
  }
  LoopPath wide;
  wide.radius = R;
  wide.turns = 2.0;
  wide.pitch = 2.2 * r;
  EXPECT_EQ(deepest_overlap_within(pieces_of(lay_loop(wide, chord)), r, {}).depth, 0.0);
}

// A ring of radius 2 in a periodic box 3 wide along x reaches its own image; in a box 5
// wide it does not (4 + 2 r < 5).
TEST(WireOverlap, RingWiderThanThePeriodicBoxOverlapsItsImage)
{
  LoopPath ring;
  ring.radius = 2.0;
  const WirePieces wire = pieces_of(lay_loop(ring, 0.1));
  const ElementOverlap o = deepest_overlap_within(wire, 0.05, {Vec3(3, 0, 0), Vec3(-3, 0, 0)});
  EXPECT_GT(o.depth, 0.05);
  EXPECT_EQ(std::abs(o.shift.x()), 3.0);
  EXPECT_EQ(deepest_overlap_within(wire, 0.05, {Vec3(5, 0, 0), Vec3(-5, 0, 0)}).depth, 0.0);
}

// Two straight wires crossing at right angles, their axes d apart, overlap by 2 r - d; a
// periodic shift moves the second onto the first.
TEST(WireOverlap, CrossingWiresOverlapByTheDiameterLessTheirDistance)
{
  PolylinePath a, b;
  a.points = {Vec3(-1, 0, 0), Vec3(1, 0, 0)};
  b.points = {Vec3(0, -1, 0.06), Vec3(0, 1, 0.06)};
  const WirePieces first = pieces_of(lay_polyline(a, 0.1)), second = pieces_of(lay_polyline(b, 0.1));
  EXPECT_NEAR(deepest_overlap_between(first, second, 0.05, {}).depth, 0.04, 1e-12);
  b.points = {Vec3(0, -1, 5.06), Vec3(0, 1, 5.06)};
  const WirePieces far = pieces_of(lay_polyline(b, 0.1));
  EXPECT_EQ(deepest_overlap_between(first, far, 0.05, {}).depth, 0.0);
  const ElementOverlap o = deepest_overlap_between(first, far, 0.05, {Vec3(0, 0, -5), Vec3(0, 0, 5)});
  EXPECT_NEAR(o.depth, 0.04, 1e-12);
  EXPECT_EQ(o.shift.z(), -5.0);
}

// first_touch_drop: a sphere of radius 0.5 whose centre is 2 above a plane touches it after
// a drop of 1.5; found within the tolerance, from the clear side.
TEST(WireDrop, SphereAbovePlaneTouchesAfterItsGap)
{
  const double r = 0.5, h = 2.0, tolerance = 1e-9;
  int calls = 0;
  const Drop drop = first_touch_drop([&](double d) { calls++; return r - (h - d); }, 10.0, 0.025, tolerance);
  EXPECT_TRUE(drop.touched);
  EXPECT_LE(drop.distance, h - r);
  EXPECT_GT(drop.distance, h - r - tolerance);
  EXPECT_LT(calls, 1.5 / 0.025 + 40);    // the scan, then bisection
}

// Nothing below: the whole drop, not touched; overlapping already: no drop, touched.
TEST(WireDrop, NothingBelowOrAlreadyOverlapping)
{
  const Drop free_fall = first_touch_drop([](double) { return -1.0; }, 3.0, 0.1, 1e-6);
  EXPECT_FALSE(free_fall.touched);
  EXPECT_EQ(free_fall.distance, 3.0);
  const Drop stuck = first_touch_drop([](double) { return 0.01; }, 3.0, 0.1, 1e-6);
  EXPECT_TRUE(stuck.touched);
  EXPECT_EQ(stuck.distance, 0.0);
}

// A ring of wire (radius 0.05) dropped onto a cube of half-edge 0.5 rounded by 0.05: a ring
// of radius 0.4 lands on the top face (its centre line 0.05 above the top at 0.55); a ring
// of radius 1.0 is wider than the cube's diagonal (0.55 sqrt 2 = 0.78) and falls past it.
TEST(WireDrop, RingLandsOnACubeOrFallsPastIt)
{
  const double wire_radius = 0.05, top = 0.55, start = 3.0;
  const Spheropolyhedron cube = test::make_box(0.5, 0.5, 0.5, 0.05);
  const std::vector<PlacedGrain> grains = {{&cube, test::place(cube, Vec3::Zero())}};
  for (double ring_radius : {0.4, 1.0}) {
    LoopPath ring;
    ring.radius = ring_radius;
    ring.centre = Vec3(0, 0, start);
    const WirePieces wire = pieces_of(lay_loop(ring, 0.1));
    auto depth = [&](double d) {
      WirePieces lowered = wire;
      for (Vec3 &x : lowered.nodes) x.z() -= d;
      const ElementOverlap o = deepest_overlap_with_grains(lowered, wire_radius, grains, {});
      return o.a >= 0 ? o.depth : -1.0;
    };
    const Drop drop = first_touch_drop(depth, 5.0, wire_radius, 1e-9);
    if (ring_radius < 0.5) {
      EXPECT_TRUE(drop.touched);
      EXPECT_NEAR(drop.distance, start - top - wire_radius, 1e-8);
    } else {
      EXPECT_FALSE(drop.touched);
    }
  }
}
