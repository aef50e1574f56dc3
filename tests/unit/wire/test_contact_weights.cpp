// Weights of the points a wire element finds (lib/wire/contact_weights.h), alone and with
// the real contact geometry: the summed push of all points of a chain must not jump as a
// grain slides along the wire past a node or as an element slides onto a face.
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

TEST(NodePointWeight, SharedAmongTheElementsThatFindItAndNoneWhenAnotherCarriesIt)
{
  const Vec3 up = Vec3::UnitZ();
  EXPECT_EQ(node_point_weight(up, nullptr, 0), 1.0);    // a free end: its own
  const Vec3 along[] = {Vec3::UnitX()};
  EXPECT_EQ(node_point_weight(up, along, 1), 0.5);    // straight wire on a face
  const Vec3 rising[] = {Vec3(1, 0, 1).normalized()};
  EXPECT_EQ(node_point_weight(up, rising, 1), 0.5);    // the other element leaves the body
  const Vec3 sinking[] = {Vec3(1, 0, -1).normalized()};
  EXPECT_EQ(node_point_weight(up, sinking, 1), 0.0);    // it comes closer inside itself
  const Vec3 branch[] = {Vec3::UnitX(), Vec3::UnitY()};
  EXPECT_DOUBLE_EQ(node_point_weight(up, branch, 2), 1.0 / 3.0);
}

// The summed weighted overlap of a body with a chain of elements (nodes in order), as fix
// wire weights the points: the stretch ends, then the node's share.
double pushed(const std::vector<Vec3> &nodes, double r_w, const Spheropolyhedron &shape, const Pose &pose)
{
  ContactWorkspace ws;
  double sum = 0.0;
  const int elements = (int) nodes.size() - 1;
  for (int e = 0; e < elements; ++e) {
    const Segment segment{nodes[e], nodes[e + 1], r_w};
    const SegmentGrainContact c = contact_segment_grain(segment, shape, pose, r_w, ws);
    const double length = (nodes[e + 1] - nodes[e]).norm();
    const double ends = c.count == 2 ? stretch_end_weight((c[1].s_i - c[0].s_i) * length, r_w) : 1.0;
    for (const SegmentContact &p : c) {
      if (p.gap >= 0.0) continue;
      double weight = ends;
      const SegmentPart part = segment_part_i(p);
      if (part != SegmentPart::inside) {
        const int node = part == SegmentPart::start ? e : e + 1, other = part == SegmentPart::start ? e + 1 : e;
        std::vector<Vec3> others;
        for (int n : {node - 1, node + 1})
          if (n >= 0 && n <= elements && n != other) others.push_back((nodes[n] - nodes[node]).normalized());
        weight *= node_point_weight(p.normal, others.data(), (int) others.size());
      }
      sum += weight * -p.gap;
    }
  }
  return sum;
}

// A ball slides along a straight wire at a fixed depth d: the wire pushes it by exactly d
// everywhere, past the middle node too (counted by both elements there it pushed up to 1.5 d
// with an even split of the node, 2 d before any split).
TEST(ContactWeights, BallSlidingAlongAStraightWirePastANodeIsPushedTheSame)
{
  const double r_w = 0.02, R = 0.2, d = 1e-3;
  const Spheropolyhedron ball = make_sphere(R);
  const std::vector<Vec3> wire = {Vec3(-1, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0)};
  double worst = 0.0;
  for (double x : {-0.3, -1e-2, -1e-3, -1e-6, -1e-12, 0.0, 1e-12, 1e-6, 1e-3, 1e-2, 0.3}) {
    const double s = pushed(wire, r_w, ball, place(ball, Vec3(x, 0, R + r_w - d)));
    worst = std::max(worst, std::abs(s / d - 1.0));
  }
  EXPECT_LT(worst, 1e-9);
}

// The same over a wire bent by 40 degrees at the node (ball on the outside): the push is
// continuous, no step larger than the distance moved allows.
TEST(ContactWeights, BallSlidingOverABentWireIsPushedContinuously)
{
  const double r_w = 0.02, R = 0.2, d = 1e-3, bend = 40.0 * M_PI / 180.0;
  const Spheropolyhedron ball = make_sphere(R);
  const Vec3 down(std::cos(bend), 0, -std::sin(bend));
  const std::vector<Vec3> wire = {Vec3(-1, 0, 0), Vec3(0, 0, 0), down};
  // the ball's centre on a path at the depth d from the wire: along the first element,
  // around the node, along the second
  auto centre = [&](double u) {    // u: arc length from the node along the path
    const double h = R + r_w - d;
    if (u <= 0.0) return Vec3(u, 0, h);
    const double turned = u / h;
    if (turned <= bend) return Vec3(h * std::sin(turned), 0, h * std::cos(turned));
    const Vec3 normal(std::sin(bend), 0, std::cos(bend));
    return Vec3(h * normal + (u - bend * h) * down);
  };
  const double du = 1e-5;
  double biggest_step = 0.0, worst_depth = 0.0;
  for (double u = -0.05; u < bend * (R + r_w) + 0.05; u += du) {
    const double a = pushed(wire, r_w, ball, place(ball, centre(u)));
    const double b = pushed(wire, r_w, ball, place(ball, centre(u + du)));
    biggest_step = std::max(biggest_step, std::abs(b - a));
    worst_depth = std::max(worst_depth, std::abs(a / d - 1.0));
  }
  EXPECT_LT(biggest_step, 1e-9 * d);    // a smooth path at constant depth: no step at all
  EXPECT_LT(worst_depth, 1e-9);
}

// An element lying at depth d slides onto a face over its edge: as the stretch over the face
// grows from nothing, the push grows from that of one point, d, without a step (two points
// of full weight would jump to 2 d as soon as they stop merging, at 1e-6 of the element).
TEST(ContactWeights, ElementSlidingOntoAFaceIsPushedContinuously)
{
  const double r_w = 0.05, d = 1e-3, r = 0.1;
  const Spheropolyhedron box = make_box(1, 1, 1, r);
  const double z = 1 + r + r_w - d;
  auto push_at = [&](double e) {    // the element's near end lies e inside the face's edge
    return pushed({Vec3(1 - e, 0, z), Vec3(1 - e + 0.5, 0, z)}, r_w, box, place(box, Vec3::Zero()));
  };
  double previous = push_at(-1e-3), biggest_step = 0.0;
  for (double e = -1e-3; e <= 0.1; e += 1e-5) {
    const double now = push_at(e);
    biggest_step = std::max(biggest_step, std::abs(now - previous));
    previous = now;
  }
  for (double e : {1e-8, 5e-7, 2e-6, 1e-5}) biggest_step = std::max(biggest_step, std::abs(push_at(e) - push_at(e * 1.01)));
  EXPECT_LT(biggest_step, 1e-3 * d);    // slope d / r_w per unit of e: 1e-5 * d / 0.05 = 2e-4 d per step
  EXPECT_NEAR(push_at(0.2), 2 * d, 1e-12);    // fully on: both ends, each at depth d
}

}    // namespace
}    // namespace nscd::wire
