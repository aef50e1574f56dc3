// Weights of the points a wire element finds (lib/wire/contact_weights.h), alone and with
// the real contact geometry: the summed push of all points of a chain must not jump as a
// grain slides along the wire past a node or as elements slide onto a face.
#include "wire/contact_weights.h"

#include "../geometry/shapes_for_tests.h"
#include "geometry/contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace nscd::wire {
namespace {

using test::make_box;
using test::make_sphere;
using test::place;

TEST(StretchEndWeight, RampsFromHalfToOneOverTheRampLength)
{
  EXPECT_EQ(stretch_end_weight(0.0, 0.05), 0.5);
  EXPECT_DOUBLE_EQ(stretch_end_weight(0.025, 0.05), 0.75);
  EXPECT_EQ(stretch_end_weight(0.05, 0.05), 1.0);
  EXPECT_EQ(stretch_end_weight(3.0, 0.05), 1.0);
  EXPECT_EQ(stretch_end_weight(1.0, 0.0), 1.0);    // no ramp: every point whole
}

// The summed weighted overlap of a body with a chain of elements (nodes in order), as fix
// wire weights the points: each element its own contact, the ends of a stretch ramped.
double pushed(const std::vector<Vec3> &nodes, double r_w, const Spheropolyhedron &shape, const Pose &pose)
{
  ContactWorkspace ws;
  double sum = 0.0;
  for (size_t e = 0; e + 1 < nodes.size(); ++e) {
    const SegmentGrainContact c = contact_segment_grain({nodes[e], nodes[e + 1], r_w}, shape, pose, r_w, ws);
    const double length = (nodes[e + 1] - nodes[e]).norm();
    const double weight = c.count == 2 ? stretch_end_weight((c[1].s_i - c[0].s_i) * length, r_w) : 1.0;
    for (const SegmentContact &p : c)
      if (p.gap < 0.0) sum += weight * -p.gap;
  }
  return sum;
}

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
  const std::vector<Vec3> wire = {Vec3(-1, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0)};
  auto push = [&](double x) { return pushed(wire, r_w, ball, place(ball, Vec3(x, 0, R + r_w - d))); };
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
    auto push = [&](double x) {
      return pushed(wire, r_w, ball, place(ball, Vec3(x, 0, side * (R + r_w - d))));
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
  const double z = 1 + r + r_w - d;
  for (int elements : {1, 3}) {
    auto push = [&](double e) {    // the chain's near end lies e inside the face's edge
      std::vector<Vec3> nodes;
      for (int k = 0; k <= elements; ++k) nodes.emplace_back(1 - e + 0.5 * k, 0, z);
      return pushed(nodes, r_w, box, place(box, Vec3::Zero()));
    };
    Sweep s = sweep(push, -1e-3, 0.1, 1e-5);
    for (double e : {1e-8, 5e-7, 2e-6, 1e-5})
      s.biggest_step = std::max(s.biggest_step, std::abs(push(e) - push(e * 1.01)));
    EXPECT_LT(s.biggest_step, 1e-2 * d) << elements << " elements";    // slope d / r_w: 2e-4 d per step
  }
  // one element fully on: both ends, each at depth d
  EXPECT_NEAR(pushed({Vec3(0, 0, z), Vec3(0.5, 0, z)}, r_w, box, place(box, Vec3::Zero())), 2 * d, 1e-12);
}

}    // namespace
}    // namespace nscd::wire
