// The wire's contact model (lib/wire/contact_model.h): friction memory across changes of
// a contact's points, element-element and node-boundary contacts in closed form, and the
// fast paths (candidate lists kept over substeps, contact-free pairs skipped, features
// tracked) against a model rebuilt from scratch at every substep.
#include "wire/contact_model.h"
#include "wire/contact_weights.h"

#include "../geometry/shapes_for_tests.h"
#include "contact_model_util.h"

#include <gtest/gtest.h>

#include <random>

namespace nscd::wire {
namespace {

using nscd::test::make_box;
using nscd::test::make_random_grain;
using nscd::test::place;

SoftContactLaw sticky_law()
{
  SoftContactLaw law;
  law.k_n = 1e4;
  law.k_t = 1e4;
  law.mu_s = law.mu_d = 0.5;
  return law;
}

// One element over the unit box's top face (half size 0.5, rounding 0.02), driven node by
// node; each substep returns the total contact force on the element.
struct ElementOnBox {
  const double r = 0.02, r_w = 0.02, depth = 1e-3, dt = 1e-5;
  const double z = 0.5 + r + r_w - depth;    // height of an element pressed by `depth`
  Spheropolyhedron box = make_box(0.5, 0.5, 0.5, r);
  ContactModel model{sticky_law(), r_w, 0.05};
  std::vector<Vec3> x, v{Vec3::Zero(), Vec3::Zero()};
  int points = 0;    // of the last substep, touching

  ElementOnBox(const Vec3 &a, const Vec3 &b) : x{a, b}
  {
    model.set_elements(test::chain_elements(2));
    model.begin_step(test::chain_scene(x, {{7, &box, place(box, Vec3::Zero())}}), 1e-3, false);
  }
  Vec3 substep()
  {
    for (int k = 0; k < 2; ++k) x[k] += v[k] * dt;
    std::vector<Vec3> f(2, Vec3::Zero());
    GrainForceAccumulator reactions;
    reactions.reset(1);
    const ContactTotals t = model.add_forces(x, v, 0.0, dt, f, reactions);
    points = t.wire_grain;
    return f[0] + f[1];
  }
};

// An element lies on a face with its first end and reaches past the face's edge; dragged
// sideways it sticks, each end of the touching stretch with its own spring. Its first end
// is then lifted: the stretch loses that end (the element now touches the face's edge at
// one point) and the spring of both goes to the remaining point, so the friction force
// stays. (With history slots by the points' order along the element the remaining point
// took the empty slot of a second inside point: its spring restarted from zero.)
TEST(ContactMemory, SpringSurvivesTheStretchLosingAnEnd)
{
  ElementOnBox s(Vec3(-0.2, 0, 0), Vec3(0.7, 0, 0));
  s.x[0].z() = s.x[1].z() = s.z;
  const double u = 0.1;
  s.v = {Vec3(0, u, 0), Vec3(0, u, 0)};
  Vec3 f;
  for (int k = 0; k < 100; ++k) f = s.substep();
  EXPECT_EQ(s.points, 1);    // one contact (with two points)
  // two ends, each k_t u t = 1 (the stretch is 0.7 long: weight 1 each)
  EXPECT_NEAR(f.y(), -2.0, 1e-9);
  s.x[0].z() += 1e-3;    // tilt: the face patch turns into one point at the edge
  const Vec3 after = s.substep();
  EXPECT_NEAR(after.y(), -2.0, 0.03) << "friction before " << f.y();
  EXPECT_LT(std::abs(after.y()), 0.5 * std::abs(after.z())) << "within the Coulomb limit";
}

// An element lying flat beyond a face's edge touches it with its first end's sphere;
// dragged sideways it sticks (one point, weight 1). Then it slides onto the face: the
// stretch over the face opens from that point, its two ends weigh 1/2 each at first and
// both start from the point's spring, so the friction force goes on without a step.
// (Before, the new end started from zero: the friction force halved.)
TEST(ContactMemory, StretchOpeningFromOnePointKeepsItsFrictionForce)
{
  ElementOnBox s(Vec3(0.5 + 2e-4, 0, 0), Vec3(1.0 + 2e-4, 0, 0));
  s.x[0].z() = s.x[1].z() = s.z;
  const double u = 0.1;
  s.v = {Vec3(0, u, 0), Vec3(0, u, 0)};
  Vec3 f;
  for (int k = 0; k < 100; ++k) f = s.substep();
  EXPECT_NEAR(f.y(), -1.0, 2e-3);    // one point: k_t u t
  s.v = {Vec3(-u, 0, 0), Vec3(-u, 0, 0)};
  double biggest_step = 0.0;
  for (int k = 0; k < 400; ++k) {    // the first end moves 2e-4 onto the face
    const Vec3 now = s.substep();
    biggest_step = std::max(biggest_step, (now - f).norm());
    f = now;
  }
  EXPECT_LT(s.x[0].x(), 0.5 - 1e-4);
  // each substep adds k_t u dt = 0.01 along x; a halving of the sideways spring is 0.5
  EXPECT_LT(biggest_step, 0.05);
  // both ends carry the spring, each weighed by the ramp over the stretch's length
  EXPECT_NEAR(f.y(), -2.0 * stretch_end_weight(0.5 - s.x[0].x(), s.r_w), 2e-3);
  EXPECT_NEAR(f.x(), 4.0, 0.05);
}

// Two crossing elements, the upper pressed into the lower: the force is k_n times the
// overlap along the line of centres, split over each element's nodes by the lever rule.
TEST(WireWireContact, CrossingElementsPushApartByTheOverlapSplitByTheLeverRule)
{
  const double r_w = 0.05, overlap = 2e-3, k_n = 1e3;
  ContactModel model(test::frictionless(k_n), r_w, 0.1);
  // element 1-2 along x, element 3-4 along y above it, crossing at s = 0.25 and t = 0.6
  const std::vector<Vec3> x = {Vec3(-0.25, 0, 0), Vec3(0.75, 0, 0), Vec3(0, -0.6, 2 * r_w - overlap),
                               Vec3(0, 0.4, 2 * r_w - overlap)};
  ContactScene scene = test::chain_scene(x, {});
  scene.elements = {{0, 1, 1, 2, true}, {2, 3, 3, 4, true}};
  model.set_elements({{1, 2}, {3, 4}});
  model.begin_step(scene, 1e-3, false);
  std::vector<Vec3> f(4, Vec3::Zero());
  GrainForceAccumulator none;
  none.reset(0);
  const ContactTotals t = model.add_forces(x, std::vector<Vec3>(4, Vec3::Zero()), 0.0, 1e-5, f, none);
  EXPECT_EQ(t.wire_wire, 1);    // once, though both elements are computed here
  const double fn = k_n * overlap;
  EXPECT_NEAR(f[0].z(), -0.75 * fn, 1e-12);
  EXPECT_NEAR(f[1].z(), -0.25 * fn, 1e-12);
  EXPECT_NEAR(f[2].z(), 0.4 * fn, 1e-12);
  EXPECT_NEAR(f[3].z(), 0.6 * fn, 1e-12);
  EXPECT_NEAR(t.energy, 0.5 * k_n * overlap * overlap, 1e-15);
}

// Elements sharing a node or joined by one element never touch (the wire's own bending),
// however close: a hairpin of four elements folded flat.
TEST(WireWireContact, ElementsJoinedByANodeOrAnElementDoNotTouch)
{
  const double r_w = 0.05;
  ContactModel model(test::frictionless(1e3), r_w, 0.1);
  // nodes 1..5: 1-2-3 along x, back 3-4-5 just above: 1-2 and 4-5 are joined by nothing,
  // 2-3 and 3-4 share node 3, 1-2 and 3-4 are joined by element 2-3
  const std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0.2, 0, 0.05), Vec3(0.1, 0, 0.09),
                               Vec3(0.0, 0, 0.09)};
  model.set_elements(test::chain_elements(5));
  model.begin_step(test::chain_scene(x, {}), 1e-3, false);
  std::vector<Vec3> f(5, Vec3::Zero());
  GrainForceAccumulator none;
  none.reset(0);
  const ContactTotals t = model.add_forces(x, std::vector<Vec3>(5, Vec3::Zero()), 0.0, 1e-5, f, none);
  EXPECT_EQ(t.wire_wire, 1);    // only 1-2 against 4-5
  EXPECT_TRUE(model.joined(2, 3));
  EXPECT_FALSE(model.joined(1, 3));
}

// A node pressed into a plane boundary: k_n times the overlap, the reaction in the
// boundary's slot after the grains.
struct Floor final : NodeBoundary {
  ContactPoint touch_sphere(const Vec3 &centre, double radius, double) const override
  {
    return contact_sphere_plane(centre, radius, PlaneWall{Vec3::Zero(), Vec3::UnitZ()});
  }
  Vec3 surface_velocity() const override { return Vec3::Zero(); }
};

TEST(WireBoundaryContact, NodeOnAFloorIsPushedByTheOverlap)
{
  const double r_w = 0.05, k_n = 1e3;
  ContactModel model(test::frictionless(k_n), r_w, 0.1);
  const std::vector<Vec3> x = {Vec3(0, 0, r_w - 1e-3), Vec3(0.1, 0, r_w + 0.5)};
  model.set_elements(test::chain_elements(2));
  ContactScene scene = test::chain_scene(x, {});
  Floor floor;
  scene.boundaries.push_back({&floor, test::frictionless(k_n), -5, 0.0});
  scene.node_boundaries = {1u, 1u};
  model.begin_step(scene, 1e-3, false);
  std::vector<Vec3> f(2, Vec3::Zero());
  GrainForceAccumulator reactions;
  reactions.reset(1);
  const ContactTotals t = model.add_forces(x, std::vector<Vec3>(2, Vec3::Zero()), 0.0, 1e-5, f, reactions);
  reactions.count_substep();
  EXPECT_EQ(t.wire_boundary, 1);
  EXPECT_NEAR(f[0].z(), k_n * 1e-3, 1e-12);
  EXPECT_NEAR(reactions.mean_force(0).z(), -k_n * 1e-3, 1e-12);
}

// A chain of 40 elements wanders over three random grains for 3000 substeps, moving up
// to several skins in all. The forces of the model as a run uses it (lists kept,
// contact-free pairs skipped, features tracked) equal those of a model built afresh at
// every substep, which searches all pairs and asks contact_segment_grain directly. The
// lists are rebuilt only every so often.
TEST(ContactModelSpeedPaths, ForcesEqualThoseOfAModelBuiltAfreshEverySubstep)
{
  std::mt19937_64 rng(5);
  std::vector<Spheropolyhedron> shapes;
  for (int g = 0; g < 3; ++g) shapes.push_back(make_random_grain(rng, 16, 0.03));
  std::vector<test::TestGrain> grains;
  for (int g = 0; g < 3; ++g) grains.push_back({100 + g, &shapes[g], place(shapes[g], Vec3(1.6 * g, 0, 0), nscd::test::random_rotation(rng))});
  const int n = 41;
  const double r_w = 0.02, skin = 0.05;
  std::vector<Vec3> x(n), v(n, Vec3::Zero());
  for (int k = 0; k < n; ++k) x[k] = Vec3(-0.5 + 0.1 * k, 0.05 * std::sin(0.7 * k), 0.62);
  ContactModel kept(test::frictionless(1e3), r_w, skin);
  kept.set_elements(test::chain_elements(n));
  std::normal_distribution<double> normal(0.0, 1.0);
  double worst = 0.0, largest = 0.0;
  int touching = 0;
  for (int step = 0; step < 3000; ++step) {
    if (step % 30 == 0) kept.begin_step(test::chain_scene(x, grains), 1e-3, false);
    ContactModel fresh(test::frictionless(1e3), r_w, skin);
    fresh.set_elements(test::chain_elements(n));
    fresh.begin_step(test::chain_scene(x, grains), 1e-3, false);
    std::vector<Vec3> f1(n, Vec3::Zero()), f2(n, Vec3::Zero());
    GrainForceAccumulator g1, g2;
    g1.reset(3);
    g2.reset(3);
    touching += kept.add_forces(x, v, 0.0, 1e-5, f1, g1).wire_grain > 0;
    fresh.add_forces(x, v, 0.0, 1e-5, f2, g2);
    for (int k = 0; k < n; ++k) {
      worst = std::max(worst, (f1[k] - f2[k]).norm());
      largest = std::max(largest, f2[k].norm());
    }
    // the chain sinks slowly into the grains, sways and drifts along x
    for (int k = 0; k < n; ++k)
      x[k] += Vec3(2e-4, 5e-5 * std::sin(1e-2 * step + k), -4e-5) + 2e-5 * Vec3(normal(rng), normal(rng), normal(rng));
  }
  EXPECT_GT(touching, 1000);
  EXPECT_GT(largest, 1.0);
  EXPECT_LT(worst, 1e-9 * largest);
  EXPECT_LT(kept.rebuilds(), 60);    // moved ~0.7 in all: about 2 skins per rebuild
  std::printf("largest force %.3g, worst difference %.2e, %d rebuilds in 3000 substeps\n", largest, worst, kept.rebuilds());
}

// Memories written out and read into a new model (a restart, another rank) continue the
// same friction forces.
TEST(ContactMemory, StoredMemoriesContinueTheSameForces)
{
  ElementOnBox first(Vec3(-0.2, 0, 0), Vec3(0.3, 0, 0));
  first.x[0].z() = first.x[1].z() = first.z;
  first.v = {Vec3(0, 0.1, 0), Vec3(0, 0.1, 0)};
  for (int k = 0; k < 50; ++k) first.substep();
  const std::vector<StoredContact> stored = first.model.memories();
  ASSERT_EQ(stored.size(), 1u);
  EXPECT_EQ(stored[0].key, (ContactKey{1, 2, 7, 0}));
  ElementOnBox second(first.x[0], first.x[1]);
  second.model.add_memories(stored);
  second.v = first.v;
  EXPECT_LT((first.substep() - second.substep()).norm(), 1e-12);
}

}    // namespace
}    // namespace nscd::wire
