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
  int points = 0;     // of the last substep, touching
  double tau = 0.0;   // into the grain step, at the end of the last substep (set 0 at a new step)

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
    tau += dt;
    const ContactTotals t = model.add_forces(x, v, tau, dt, f, reactions);
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

// Two crossing elements pressed together (f_n = k_n overlap) and the upper one dragged
// along the lower: the friction force is k_t times the drag while below mu_s f_n, drops to
// mu_d f_n once it slips, with the wire-wire coefficients (set apart from the wire-grain
// ones, which would hold up to 0.5 f_n); a model left at its defaults uses the wire-grain
// coefficients for both.
TEST(WireWireContact, SlidingThresholdFollowsTheWireWireFriction)
{
  const double r_w = 0.05, overlap = 2e-3, dt = 1e-5;
  SoftContactLaw law = sticky_law();    // wire-grain mu_s = mu_d = 0.5
  const double fn = law.k_n * overlap;
  // The x force on the lower element after dragging the upper one by `drag` along x, with
  // the wire-wire friction (mu_s, mu_d) if `separate`, else left at its default.
  auto friction_after = [&](bool separate, double drag) {
    ContactModel model(law, r_w, 0.1);
    if (separate) model.set_wire_wire_friction(0.2, 0.1);
    std::vector<Vec3> x = {Vec3(-0.5, 0, 0), Vec3(0.5, 0, 0), Vec3(0, -0.5, 2 * r_w - overlap),
                           Vec3(0, 0.5, 2 * r_w - overlap)};
    ContactScene scene = test::chain_scene(x, {});
    scene.elements = {{0, 1, 1, 2, true}, {2, 3, 3, 4, true}};
    model.set_elements({{1, 2}, {3, 4}});
    model.begin_step(scene, 1e-3, false);
    const int steps = 200;
    const Vec3 u(drag / (steps * dt), 0, 0);
    std::vector<Vec3> v = {Vec3::Zero(), Vec3::Zero(), u, u}, f;
    GrainForceAccumulator none;
    none.reset(0);
    for (int k = 0; k < steps; ++k) {
      x[2] += u * dt, x[3] += u * dt;
      f.assign(4, Vec3::Zero());
      model.add_forces(x, v, k * dt, dt, f, none);
    }
    return (f[0] + f[1]).x();
  };
  const bool separate = true, same = false;
  const double slip = 0.2 * fn / law.k_t;    // drag at which the wire-wire contact slips
  EXPECT_NEAR(friction_after(separate, 0.9 * slip) / fn, 0.18, 1e-9);    // sticking: k_t drag
  EXPECT_NEAR(friction_after(separate, 1.1 * slip) / fn, 0.1, 1e-9);     // slipped: mu_d f_n
  EXPECT_NEAR(friction_after(separate, 20.0 * slip) / fn, 0.1, 1e-9);
  EXPECT_NEAR(friction_after(same, 1.1 * slip) / fn, 0.22, 1e-9);        // mu_s 0.5: still sticking
  EXPECT_NEAR(friction_after(same, 20.0 * slip) / fn, 0.5, 1e-9);
  ContactModel model(law, r_w, 0.1);
  EXPECT_THROW(model.set_wire_wire_friction(0.1, 0.2), std::invalid_argument);    // mu_d > mu_s
  EXPECT_THROW(model.set_wire_wire_friction(-0.1, 0.0), std::invalid_argument);
}

// A grain with its own friction (add_grain_friction) holds and lets an element slide by its
// own coefficients, the others by the model's: an element pressed onto a box's face and
// dragged along it carries k_t times the drag while sticking under either law, and
// mu_d f_n once slipped: 0.1 for the grain of law 1, the model's 0.5 for law 0.
TEST(WireGrainContact, GrainOfItsOwnFrictionSlidesAtItsCoefficient)
{
  const double dt = 1e-5;
  // The ratio |f_x| / f_z of the contact force on the element after dragging it by `drag`.
  auto ratio_after = [&](bool own_law, double drag) {
    ElementOnBox e(Vec3(-0.3, 0, 0), Vec3(0.3, 0, 0));
    e.x = {Vec3(-0.3, 0, e.z), Vec3(0.3, 0, e.z)};
    ContactScene scene = test::chain_scene(e.x, {{7, &e.box, place(e.box, Vec3::Zero())}});
    if (own_law) scene.grains[0].law = e.model.add_grain_friction(0.2, 0.1);
    e.model.begin_step(scene, 1e-3, true);
    const int steps = 200;
    const Vec3 u(drag / (steps * dt), 0, 0);
    e.v = {u, u};
    Vec3 f = Vec3::Zero();
    for (int k = 0; k < steps; ++k) f = e.substep();
    EXPECT_EQ(e.points, 1);    // the element touches the face (along its whole length)
    return std::abs(f.x()) / f.z();
  };
  const double depth = 1e-3, slip = 0.2 * sticky_law().k_n * depth / sticky_law().k_t;
  EXPECT_NEAR(ratio_after(true, 0.25 * slip), 0.05, 1e-6);       // sticking: k_t drag / (k_n depth)
  EXPECT_NEAR(ratio_after(false, 0.25 * slip), 0.05, 1e-6);
  EXPECT_NEAR(ratio_after(true, 20.0 * slip), 0.1, 1e-9);        // slipped at its mu_d
  EXPECT_NEAR(ratio_after(false, 20.0 * slip), 0.5, 1e-9);       // the model's mu_d
  ContactModel model(sticky_law(), 0.02, 0.05);
  EXPECT_THROW(model.add_grain_friction(0.1, 0.2), std::invalid_argument);    // mu_d > mu_s
  EXPECT_THROW(model.add_grain_friction(-0.1, 0.0), std::invalid_argument);
  EXPECT_EQ(model.add_grain_friction(0.3, 0.3), 1);
  ContactScene scene = test::chain_scene({Vec3(0, 0, 2), Vec3(1, 0, 2)}, {});
  const Spheropolyhedron box = make_box(0.5, 0.5, 0.5, 0.02);
  GrainCopy unknown;
  unknown.shape = &box;
  unknown.law = 2;    // only 0 and 1 exist
  scene.grains.push_back(unknown);
  model.set_elements(test::chain_elements(2));
  EXPECT_THROW(model.begin_step(scene, 1e-3, false), std::invalid_argument);
}

// The wire's subcycle holds a grain still while its velocity enters the contacts' relative
// velocity. Whatever the springs do within the step, they must hold the true relative
// displacement at the next: a grain whose velocity carried it by d over a step and one
// found moved by d without a velocity give their element the same friction force then,
// k_t times the element's drag minus d (the drag made first, on a grain at rest). Within
// the step, carried springs follow the grain's velocity (the force at the step's end is
// already the next step's), held springs pull by the held poses (the drag's force stays).
TEST(WireGrainContact, SpringHoldsTheGrainsTrueDisplacementWhateverItsHeldVelocity)
{
  for (const GrainSprings how : {GrainSprings::carried, GrainSprings::held}) {
  const double h = 1e-3, d = 2e-5, drag = 50 * 0.1 * 1e-5;
  const int substeps = 100;
  Vec3 before = Vec3::Zero();    // the friction force at the drag's end
  struct Forces {
    Vec3 step_end, next_step;
  };
  auto forces = [&](double held_speed) {
    ElementOnBox e(Vec3(-0.3, 0, 0), Vec3(0.3, 0, 0));
    e.model.set_grain_springs(how);
    e.x = {Vec3(-0.3, 0, e.z), Vec3(0.3, 0, e.z)};
    e.model.begin_step(test::chain_scene(e.x, {{7, &e.box, place(e.box, Vec3::Zero())}}), h, true);
    e.v = {Vec3(0.1, 0, 0), Vec3(0.1, 0, 0)};
    for (int k = 0; k < 50; ++k) before = e.substep();    // sticking (it slips at a drag of mu k_n depth / k_t = 5e-4)
    e.v = {Vec3::Zero(), Vec3::Zero()};
    test::TestGrain grain{7, &e.box, place(e.box, Vec3::Zero()), Vec3(held_speed, 0, 0)};
    e.model.begin_step(test::chain_scene(e.x, {grain}), h, false);
    e.tau = 0.0;
    Forces out;
    for (int k = 0; k < substeps; ++k) out.step_end = e.substep();    // (e.dt: the subcycle spans h)
    grain.pose = place(e.box, Vec3(d, 0, 0));
    grain.velocity = Vec3::Zero();
    e.model.begin_step(test::chain_scene(e.x, {grain}), h, false);
    e.tau = 0.0;
    out.next_step = e.substep();
    return out;
  };
  const Forces carried = forces(d / (substeps * 1e-5)), unseen = forces(0.0);
  const bool held = how == GrainSprings::held;
  std::printf("%s springs: friction force after the drag %.6g; at the step's end: grain carried by its velocity "
              "%.6g, moved unseen %.6g; at the next step: %.6g and %.6g\n", held ? "held" : "carried",
              before.x(), carried.step_end.x(), unseen.step_end.x(), carried.next_step.x(), unseen.next_step.x());
  EXPECT_NEAR(carried.step_end.x() / before.x(), held ? 1.0 : (drag - d) / drag, 1e-9);
  EXPECT_NEAR(unseen.step_end.x() / before.x(), 1.0, 1e-9);
  EXPECT_NEAR(carried.next_step.x() / before.x(), (drag - d) / drag, 1e-9);
  EXPECT_NEAR(unseen.next_step.x() / before.x(), (drag - d) / drag, 1e-9);
  }
}

// A grain found farther from where its velocity would have taken it than its own size is
// another image of it, or was placed by hand between runs: its contacts' springs are left
// as they were (a 4 x 4 face, bounding radius 2.9, found moved by 3 under a sticking
// element: the friction force stays; taking the move would have slipped the contact).
TEST(WireGrainContact, SpringIgnoresAGrainFoundMovedBeyondItsSize)
{
  const double r = 0.02, r_w = 0.02, depth = 1e-3, dt = 1e-5;
  const Spheropolyhedron slab = make_box(2.0, 2.0, 0.5, r);
  ContactModel model(sticky_law(), r_w, 0.05);
  model.set_elements(test::chain_elements(2));
  const double z = 0.5 + r + r_w - depth;
  std::vector<Vec3> x{Vec3(1.2, 0, z), Vec3(1.8, 0, z)};
  const std::vector<Vec3> v(2, Vec3(0.1, 0, 0)), still(2, Vec3::Zero());
  auto substep = [&](const std::vector<Vec3> &u) {
    for (int k = 0; k < 2; ++k) x[k] += u[k] * dt;
    std::vector<Vec3> f(2, Vec3::Zero());
    GrainForceAccumulator reactions;
    reactions.reset(1);
    model.add_forces(x, u, 0.0, dt, f, reactions);
    return f[0] + f[1];
  };
  model.begin_step(test::chain_scene(x, {{7, &slab, place(slab, Vec3::Zero())}}), 1e-3, false);
  Vec3 before = Vec3::Zero();
  for (int k = 0; k < 50; ++k) before = substep(v);    // dragged by 5e-5, sticking
  ASSERT_GT(slab.bounding_radius, 2.0);
  ASSERT_LT(slab.bounding_radius, 3.0);
  model.begin_step(test::chain_scene(x, {{7, &slab, place(slab, Vec3(3.0, 0, 0))}}), 1e-3, true);
  x = {Vec3(4.2, 0, z), Vec3(4.8, 0, z)};    // the element where it lay on the face
  const Vec3 after = substep(still);
  EXPECT_NEAR(after.x(), before.x(), 1e-9 * std::abs(before.x()));
  EXPECT_NEAR(after.z(), before.z(), 1e-9 * std::abs(before.z()));
}

// A grain on a held element, moved by the test's own grain step as fix nscd moves it
// (V += h F / m with F the wire's force averaged over the subcycle, then X += h V), at the
// column's law and step: k_t h = 7.5 > 2 gamma_t = 2. Kicked along the element, its
// sticking contact rings at about sqrt(K / m) (K = k_t w, w the contact's summed weight).
struct Ringing {
  double weight = 0.0, stiffness_ratio = 0.0;    // w; h^2 K / m
  double kicked = 0.0, energy = 0.0, dashpot_only = 0.0, largest = 0.0;
};

Ringing ring_on_a_held_element(double m, GrainSprings how)
{
  SoftContactLaw law;
  law.k_n = 2000.0, law.gamma_n = 2.0, law.k_t = 1500.0, law.gamma_t = 1.0, law.mu_s = law.mu_d = 1.0;
  const double r = 0.05, r_w = 0.05, depth = 2e-3, h = 0.005;
  const int substeps = 80;
  const Spheropolyhedron box = make_box(0.5, 0.5, 0.5, r);
  ContactModel model(law, r_w, 0.05);
  model.set_elements(test::chain_elements(2));
  model.set_grain_springs(how);
  const double z = 0.5 + r + r_w - depth;
  const std::vector<Vec3> x{Vec3(-0.3, 0, z), Vec3(0.3, 0, z)}, v(2, Vec3::Zero());
  Vec3 X = Vec3::Zero(), V(2e-3 * std::sqrt(0.43 / m), 0, 0);    // the same kick's energy
  Ringing out;
  const int steps = 200;
  for (int step = 0; step <= steps; ++step) {
    model.begin_step(test::chain_scene(x, {{7, &box, place(box, X), V}}), h, false);
    GrainForceAccumulator reactions;
    reactions.reset(1);
    double contact_energy = 0.0;
    for (int k = 0; k < substeps; ++k) {    // (tau: the end of the substep, as fix wire's subcycle gives it)
      std::vector<Vec3> f(2, Vec3::Zero());
      const ContactTotals t = model.add_forces(x, v, (k + 1) * h / substeps, h / substeps, f, reactions);
      reactions.count_substep();
      contact_energy = t.energy;
      if (step == 0 && k == 0) out.weight = t.normal_force / (law.k_n * depth);
    }
    const double tangential = contact_energy - out.weight * 0.5 * law.k_n * depth * depth;    // k_t xi^2 / 2
    if (step == 0) out.kicked = 0.5 * m * V.squaredNorm();
    out.energy = 0.5 * m * V.squaredNorm() + tangential;
    out.largest = std::max(out.largest, out.energy);
    V.x() += h * reactions.mean_force(0).x() / m;    // the grain slides along x only
    X.x() += h * V.x();
  }
  out.stiffness_ratio = h * h * law.k_t * out.weight / m;
  out.dashpot_only = out.kicked * std::exp(-law.gamma_t * out.weight * steps * h / m);
  std::printf("%s springs, grain of mass %.4g, h^2 K / m %.3g: energy %.4g after %d steps against %.4g at the kick, "
              "largest %.4g (dashpot alone: %.4g)\n",
              how == GrainSprings::held ? "held" : "carried", m, out.stiffness_ratio, out.energy, steps, out.kicked,
              out.largest, out.dashpot_only);
  return out;
}

// The column's grain (m 0.43, h^2 K / m 0.17) must come to rest at least as fast as its
// dashpot alone would damp it (energy factor exp(-gamma_t w t / m)). Springs that followed
// only the held velocity made each step's energy grow by ~(1 + h^2 K / 2 m) - 2 gamma_t h
// w / m: the grain rang at the friction limit (22 000-fold in 200 steps).
TEST(WireGrainContact, GrainRingingOnAHeldElementDiesAwayAtTheColumnsStep)
{
  for (const GrainSprings how : {GrainSprings::carried, GrainSprings::held}) {
    const Ringing r = ring_on_a_held_element(0.43, how);
    EXPECT_GT(r.weight, 0.5);
    EXPECT_LT(r.energy, r.dashpot_only);
  }
}

// A grain light for its contacts' stiffness (h^2 K / m = 3, as four grains touching the wire
// of a standing full-size column reach) comes to rest with held springs, below the explicit
// coupling's limit of about 4 for springs that pull by the held poses, and rings with
// carried springs, which act as if the grain were half a step further on: that halves the
// limit (the kick's energy grew 18 000-fold in 200 steps, 0.016 against 8.6e-7).
TEST(WireGrainContact, LightGrainRingingOnAHeldElementDiesAwayWithHeldSprings)
{
  const Ringing column = ring_on_a_held_element(0.43, GrainSprings::held);
  const double m = 0.43 * column.stiffness_ratio / 3.0;
  const Ringing held = ring_on_a_held_element(m, GrainSprings::held);
  const Ringing carried = ring_on_a_held_element(m, GrainSprings::carried);
  EXPECT_NEAR(held.stiffness_ratio, 3.0, 1e-9);
  EXPECT_LT(held.energy, 0.01 * held.kicked);
  EXPECT_GT(carried.energy, 100.0 * carried.kicked);
}

// Recorded contact points (for compute wire/contacts): the crossing of two elements is one
// point, at the crossing, normal from the upper element to the lower one (the computing
// one), its normal force averaged over the step's substeps: closed in the first of two
// substeps only, it shows half of k_n overlap.
TEST(WireWireContact, RecordedPointCarriesTheForceAveragedOverTheSubsteps)
{
  const double r_w = 0.05, overlap = 2e-3, k_n = 1e3;
  ContactModel model(test::frictionless(k_n), r_w, 0.1);
  std::vector<Vec3> x = {Vec3(-0.25, 0, 0), Vec3(0.75, 0, 0), Vec3(0, -0.6, 2 * r_w - overlap),
                         Vec3(0, 0.4, 2 * r_w - overlap)};
  ContactScene scene = test::chain_scene(x, {});
  scene.elements = {{0, 1, 1, 2, true}, {2, 3, 3, 4, true}};
  model.set_elements({{1, 2}, {3, 4}});
  model.record_contacts(true);
  model.begin_step(scene, 1e-3, false);
  std::vector<Vec3> f(4, Vec3::Zero()), v(4, Vec3::Zero());
  GrainForceAccumulator none;
  none.reset(0);
  model.add_forces(x, v, 0.0, 1e-5, f, none);
  x[2].z() += 2 * overlap, x[3].z() += 2 * overlap;    // lifted off
  model.add_forces(x, v, 1e-5, 1e-5, f, none);
  const std::vector<ContactRecord> records = model.contact_records();
  ASSERT_EQ(records.size(), 1u);
  const ContactRecord &c = records[0];
  EXPECT_EQ(c.kind, ContactRecord::wire_wire);
  EXPECT_EQ(c.key, (ContactKey{1, 2, 3, 4}));
  EXPECT_NEAR(c.normal_force, 0.5 * k_n * overlap, 1e-12);
  EXPECT_NEAR(c.overlap, overlap, 1e-12);    // at its last evaluation while closed
  EXPECT_NEAR((c.point - Vec3(0, 0, r_w - overlap / 2)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((c.normal - Vec3(0, 0, -1)).norm(), 0.0, 1e-12);
  EXPECT_FALSE(c.sliding);
  model.begin_step(scene, 1e-3, false);    // a new step starts empty
  EXPECT_TRUE(model.contact_records().empty());
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
// A model kept as in a run (begin_step every 30 substeps, lists and skip tests kept)
// against one built from scratch at every substep, on the same nodes and grains for 3000
// substeps: the nodes moved by move_nodes after every substep, the grains by move_grains
// before every step.
struct AgainstFresh {
  double worst = 0.0, largest = 0.0;
  int grain_touching = 0, wire_touching = 0, rebuilds = 0;
};

template <class MoveNodes, class MoveGrains>
AgainstFresh run_against_fresh(std::vector<Vec3> x, std::vector<test::TestGrain> grains, const MoveNodes &move_nodes,
                               const MoveGrains &move_grains)
{
  const int n = static_cast<int>(x.size());
  const double r_w = 0.02, skin = 0.05;
  const std::vector<Vec3> v(n, Vec3::Zero());
  ContactModel kept(test::frictionless(1e3), r_w, skin);
  kept.set_elements(test::chain_elements(n));
  AgainstFresh out;
  for (int step = 0; step < 3000; ++step) {
    if (step % 30 == 0) {
      if (step > 0) move_grains(grains);
      kept.begin_step(test::chain_scene(x, grains), 1e-3, false);
    }
    ContactModel fresh(test::frictionless(1e3), r_w, skin);
    fresh.set_elements(test::chain_elements(n));
    fresh.begin_step(test::chain_scene(x, grains), 1e-3, false);
    std::vector<Vec3> f1(n, Vec3::Zero()), f2(n, Vec3::Zero());
    GrainForceAccumulator g1, g2;
    g1.reset(static_cast<int>(grains.size()));
    g2.reset(static_cast<int>(grains.size()));
    const ContactTotals t = kept.add_forces(x, v, 0.0, 1e-5, f1, g1);
    out.grain_touching += t.wire_grain > 0;
    out.wire_touching += t.wire_wire > 0;
    fresh.add_forces(x, v, 0.0, 1e-5, f2, g2);
    for (int k = 0; k < n; ++k) {
      out.worst = std::max(out.worst, (f1[k] - f2[k]).norm());
      out.largest = std::max(out.largest, f2[k].norm());
    }
    move_nodes(step, x);
  }
  out.rebuilds = kept.rebuilds();
  return out;
}

std::vector<test::TestGrain> three_random_grains(std::mt19937_64 &rng, std::vector<Spheropolyhedron> &shapes)
{
  for (int g = 0; g < 3; ++g) shapes.push_back(make_random_grain(rng, 16, 0.03));
  std::vector<test::TestGrain> grains;
  for (int g = 0; g < 3; ++g) grains.push_back({100 + g, &shapes[g], place(shapes[g], Vec3(1.6 * g, 0, 0), nscd::test::random_rotation(rng))});
  return grains;
}

TEST(ContactModelSpeedPaths, ForcesEqualThoseOfAModelBuiltAfreshEverySubstep)
{
  std::mt19937_64 rng(5);
  std::vector<Spheropolyhedron> shapes;
  const std::vector<test::TestGrain> grains = three_random_grains(rng, shapes);
  const int n = 41;
  std::vector<Vec3> x(n);
  for (int k = 0; k < n; ++k) x[k] = Vec3(-0.5 + 0.1 * k, 0.05 * std::sin(0.7 * k), 0.62);
  std::normal_distribution<double> normal(0.0, 1.0);
  // the chain sinks slowly into the grains, sways and drifts along x
  const AgainstFresh r = run_against_fresh(
      x, grains,
      [&](int step, std::vector<Vec3> &y) {
        for (int k = 0; k < n; ++k)
          y[k] += Vec3(2e-4, 5e-5 * std::sin(1e-2 * step + k), -4e-5) + 2e-5 * Vec3(normal(rng), normal(rng), normal(rng));
      },
      [](std::vector<test::TestGrain> &) {});
  EXPECT_GT(r.grain_touching, 1000);
  EXPECT_GT(r.largest, 1.0);
  EXPECT_LT(r.worst, 1e-9 * r.largest);
  EXPECT_LT(r.rebuilds, 60);    // moved ~0.7 in all: about 2 skins per rebuild
  std::printf("largest force %.3g, worst difference %.2e, %d rebuilds in 3000 substeps\n", r.largest, r.worst, r.rebuilds);
}

// The same with grains that move between steps (towards the wire, turning: a pair's last
// gap must shrink by its grain's motion) and a chain that runs back across itself (pairs
// of elements opening and closing, each skipped while its nodes have moved less than its
// last gap).
TEST(ContactModelSpeedPaths, FreshModelAgreesWithMovingGrainsAndAChainCrossingItself)
{
  std::mt19937_64 rng(8);
  std::vector<Spheropolyhedron> shapes;
  const std::vector<test::TestGrain> grains = three_random_grains(rng, shapes);
  // 21 nodes along x over the grains, then 21 along y across the first pass at x = 1.6,
  // pressed onto it by 2e-3
  std::vector<Vec3> x;
  for (int k = 0; k <= 20; ++k) x.push_back(Vec3(0.16 * k, 0.0, 0.66));
  for (int k = 0; k <= 20; ++k) x.push_back(Vec3(1.6, -1.0 + 0.1 * k, 0.66 + 0.04 - 2e-3));
  const int n = static_cast<int>(x.size());
  std::normal_distribution<double> normal(0.0, 1.0);
  const AgainstFresh r = run_against_fresh(
      x, grains,
      [&](int step, std::vector<Vec3> &y) {
        for (int k = 0; k < n; ++k) {
          const double sway = 1e-4 * std::sin(2e-2 * step + 0.3 * k);
          const double lift = k <= 20 ? 0.0 : 5e-5 * std::cos(2e-2 * step);    // the crossing opens and closes
          y[k] += (k <= 20 ? Vec3(0.0, sway, -2e-5) : Vec3(sway, 0.0, -2e-5 + lift)) +
                  2e-5 * Vec3(normal(rng), normal(rng), normal(rng));
        }
      },
      [&](std::vector<test::TestGrain> &g) {
        for (test::TestGrain &grain : g) {
          grain.pose.position += Vec3(0.0, 0.0, 1.5e-3);
          grain.pose.orientation = (nscd::test::rotation_about(Vec3(1, 2, 3), 2e-3) * grain.pose.orientation).normalized();
        }
      });
  EXPECT_GT(r.grain_touching, 1000);
  EXPECT_GT(r.wire_touching, 300);
  EXPECT_GT(r.largest, 1.0);
  EXPECT_LT(r.worst, 1e-9 * r.largest);
  std::printf("largest force %.3g, worst difference %.2e, substeps touching grains %d, elements %d, %d rebuilds\n",
              r.largest, r.worst, r.grain_touching, r.wire_touching, r.rebuilds);
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
