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

// Weights of the points a wire element finds (lib/wire/contact_weights.h), alone and in the
// contact model (lib/wire/contact_model.h) with the real geometry: the force of all points
// of a chain on a grain must not jump as the grain slides along the wire past a node or
// as elements slide onto a face.
#include "wire/contact_model.h"
#include "wire/contact_weights.h"

#include "../geometry/shapes_for_tests.h"
#include "contact_model_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace nscd::wire {
namespace {

using nscd::test::make_box;
using nscd::test::make_sphere;
using nscd::test::place;

TEST(StretchEndWeight, RampsFromHalfToOneOverTheRampLength)
{
  EXPECT_EQ(stretch_end_weight(0.0, 0.05), 0.5);
  EXPECT_DOUBLE_EQ(stretch_end_weight(0.025, 0.05), 0.75);
  EXPECT_EQ(stretch_end_weight(0.05, 0.05), 1.0);
  EXPECT_EQ(stretch_end_weight(3.0, 0.05), 1.0);
  EXPECT_EQ(stretch_end_weight(1.0, 0.0), 1.0);    // no ramp: every point whole
}

// The push of a chain (nodes in order, at rest) on a grain, divided by k_n: the weighted
// sum of the overlaps of all points, from the normal forces of the contact model of a
// frictionless, undamped wire with k_n = 1. One model follows the grain through a sweep (lists, skipping and tracking
// in use), as in a run.
class Pusher {
 public:
  Pusher(const std::vector<Vec3> &nodes, double r_w, const Spheropolyhedron &shape)
      : nodes_(nodes), shape_(shape), model_(test::frictionless(1.0), r_w, 0.1)
  {
    model_.set_elements(test::chain_elements(static_cast<int>(nodes.size())));
  }
  double push(const Pose &pose)
  {
    model_.begin_step(test::chain_scene(nodes_, {{1000, &shape_, pose}}), 1e-3, false);
    GrainForceAccumulator reactions;
    reactions.reset(1);
    std::vector<Vec3> f(nodes_.size(), Vec3::Zero());
    return model_.add_forces(nodes_, std::vector<Vec3>(nodes_.size(), Vec3::Zero()), 0.0, 1e-5, f, reactions)
        .normal_force;
  }

 private:
  std::vector<Vec3> nodes_;
  const Spheropolyhedron &shape_;
  ContactModel model_;
};

// Largest change of push(u) between neighbouring u in [from, to] (step du), and its range.
struct Sweep {
  double biggest_step = 0.0, lowest = INFINITY, highest = -INFINITY;
};
template <class Push>
Sweep sweep(Push push, double from, double to, double du)
{
  Sweep out;
  double previous = push(from);
  for (double u = from; u <= to; u += du) {
    const double now = push(u);
    out.biggest_step = std::max(out.biggest_step, std::abs(now - previous));
    out.lowest = std::min(out.lowest, now);
    out.highest = std::max(out.highest, now);
    previous = now;
  }
  return out;
}

// A ball slides along a straight wire at a fixed depth d, past the middle node: pushed by d
// along an element, and by both elements near the node (up to 2 d right at it, where both
// touch with the node's sphere), with no step.
TEST(ContactWeights, BallSlidingAlongAStraightWirePastANodeIsPushedContinuously)
{
  const double r_w = 0.02, R = 0.2, d = 1e-3;
  const Spheropolyhedron ball = make_sphere(R);
  Pusher pusher({Vec3(-1, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0)}, r_w, ball);
  auto push = [&](double x) { return pusher.push(place(ball, Vec3(x, 0, R + r_w - d))); };
  const Sweep s = sweep(push, -0.3, 0.3, 1e-5);
  EXPECT_LT(s.biggest_step, 1e-2 * d);    // smooth: slope ~95 d, 1e-3 d per step; a jump is ~d
  EXPECT_NEAR(s.lowest, d, 1e-12);
  EXPECT_NEAR(push(0.0), 2 * d, 1e-12);
  EXPECT_LE(s.highest, 2 * d + 1e-12);
}

// The same over a wire bent by 40 degrees at the node, on the outer and on the inner side of
// the bend: no step.
TEST(ContactWeights, BallSlidingOverABentWireIsPushedContinuously)
{
  const double r_w = 0.02, R = 0.2, d = 1e-3, bend = 40.0 * M_PI / 180.0;
  const Spheropolyhedron ball = make_sphere(R);
  const std::vector<Vec3> wire = {Vec3(-1, 0, 0), Vec3(0, 0, 0), Vec3(std::cos(bend), 0, -std::sin(bend))};
  for (double side : {1.0, -1.0}) {    // outer (above), inner (below)
    Pusher pusher(wire, r_w, ball);
    auto push = [&](double x) {
      return pusher.push(place(ball, Vec3(x, 0, side * (R + r_w - d))));
    };
    const Sweep s = sweep(push, -0.4, 0.4, 1e-5);
    EXPECT_LT(s.biggest_step, 5e-2 * d) << "side " << side;    // slope up to ~650 d (inner side); a jump is ~d
    EXPECT_GT(s.highest, 0.0) << "side " << side;
  }
}

// Elements lying at depth d slide onto a face over its edge: as the stretch over the face
// grows from nothing, the push grows from that of one point without a step (two points of
// full weight would jump to twice as soon as they stop merging, at 1e-6 of the element).
// One free element, then a chain of three.
TEST(ContactWeights, ElementsSlidingOntoAFaceArePushedContinuously)
{
  const double r_w = 0.05, d = 1e-3, r = 0.1;
  const Spheropolyhedron box = make_box(1, 1, 1, r);
  const Pose at_origin = place(box, Vec3::Zero());
  const double z = 1 + r + r_w - d;
  for (int elements : {1, 3}) {
    auto push = [&](double e) {    // the chain's near end lies e inside the face's edge
      std::vector<Vec3> nodes;
      for (int k = 0; k <= elements; ++k) nodes.emplace_back(1 - e + 0.5 * k, 0, z);
      return Pusher(nodes, r_w, box).push(at_origin);
    };
    Sweep s = sweep(push, -1e-3, 0.1, 1e-5);
    for (double e : {1e-8, 5e-7, 2e-6, 1e-5})
      s.biggest_step = std::max(s.biggest_step, std::abs(push(e) - push(e * 1.01)));
    EXPECT_LT(s.biggest_step, 1e-2 * d) << elements << " elements";    // slope d / r_w: 2e-4 d per step
  }
  // one element fully on: both ends, each at depth d
  EXPECT_NEAR(Pusher({Vec3(0, 0, z), Vec3(0.5, 0, z)}, r_w, box).push(at_origin), 2 * d, 1e-12);
}

}    // namespace
}    // namespace nscd::wire
