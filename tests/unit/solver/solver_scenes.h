// Hand-built scenes for the solver tests: axis-aligned boxes stacked on a floor (the
// contacts are the four bottom corners of each box), spheres, and a time-step driver.
// No geometry code: contacts are written down from the positions.
#pragma once

#include "solver/contact_problem.h"
#include "solver/rigid_motion.h"
#include "solver/warm_start.h"

#include <vector>

namespace nscd::test {

struct Box {
  double mass = 1.0;
  Vec3 half_extents = Vec3(0.5, 0.5, 0.5);
  Pose pose;
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();

  Vec3 principal_moments() const
  {
    const Vec3 h2 = half_extents.cwiseProduct(half_extents);
    return mass / 3.0 * Vec3(h2.y() + h2.z(), h2.x() + h2.z(), h2.x() + h2.y());
  }
};

inline SolverBody solver_body(const Box &box, const Vec3 &gravity, double dt)
{
  SolverBody body;
  body.position = box.pose.position;
  body.velocity = box.velocity;
  body.angular_velocity = box.angular_velocity;
  body.inv_mass = 1.0 / box.mass;
  body.inv_inertia = world_inverse_inertia(box.principal_moments(), box.pose.orientation);
  body.external_impulse = dt * box.mass * gravity;
  body.external_angular_impulse =
      dt * gyroscopic_torque(box.principal_moments(), box.pose.orientation, box.angular_velocity);
  return body;
}

// A column of boxes, box 0 on the floor z = 0, box k on box k-1. The boxes keep their
// initial (identity) orientation in these scenes; the tests check that they do.
struct BoxColumn {
  std::vector<Box> boxes;
  double floor_friction = 0.0;
  double box_friction = 0.0;
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);
  WarmStartCache cache;
  bool warm_start = true;

  // Places the boxes touching each other (all gaps zero), at rest.
  void stack(const std::vector<double> &masses, const Vec3 &half_extents)
  {
    boxes.clear();
    double z = 0.0;
    for (const double mass : masses) {
      Box box;
      box.mass = mass;
      box.half_extents = half_extents;
      box.pose.position = Vec3(0.0, 0.0, z + half_extents.z());
      z += 2.0 * half_extents.z();
      boxes.push_back(box);
    }
  }

  void add_corner_contacts(ContactProblem &problem, int upper, int lower) const
  {
    const Box &top = boxes[upper];
    const double bottom = top.pose.position.z() - top.half_extents.z();
    const double support =
        lower < 0 ? 0.0 : boxes[lower].pose.position.z() + boxes[lower].half_extents.z();
    int corner = 0;
    for (const double sx : {-1.0, 1.0})
      for (const double sy : {-1.0, 1.0}) {
        Contact contact;
        contact.body_i = upper;
        contact.body_j = lower < 0 ? kEnvironment : lower;
        contact.point = Vec3(top.pose.position.x() + sx * top.half_extents.x(),
                             top.pose.position.y() + sy * top.half_extents.y(), bottom);
        contact.normal = Vec3::UnitZ();
        contact.gap = bottom - support;
        contact.friction = lower < 0 ? floor_friction : box_friction;
        contact.key = {upper, lower, static_cast<std::uint64_t>(corner++)};
        problem.contacts.push_back(contact);
      }
  }

  void build(ContactProblem &problem, double dt) const
  {
    problem.bodies.clear();
    problem.contacts.clear();
    for (const Box &box : boxes) problem.bodies.push_back(solver_body(box, gravity, dt));
    for (int k = 0; k < static_cast<int>(boxes.size()); ++k) add_corner_contacts(problem, k, k - 1);
  }

  // One Moreau-Jean step; returns the solver report. problem keeps the solved contacts.
  SolveReport step(ContactProblem &problem, const SolverOptions &options)
  {
    build(problem, options.dt);
    if (warm_start) cache.apply(problem.contacts);
    const SolveReport report = solve(problem, options);
    cache.store(problem.contacts);
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      Box &box = boxes[k];
      const SolverBody &body = problem.bodies[k];
      advance_pose(box.pose, box.velocity, box.angular_velocity, body.velocity,
                   body.angular_velocity, options.dt, options.theta);
      box.velocity = body.velocity;
      box.angular_velocity = body.angular_velocity;
    }
    return report;
  }
};

// Sum of the world impulses of the contacts that push body_i = `upper`.
inline Vec3 impulse_on(const ContactProblem &problem, int upper)
{
  Vec3 sum = Vec3::Zero();
  for (const Contact &contact : problem.contacts)
    if (contact.body_i == upper) sum += contact.impulse;
  return sum;
}

}    // namespace nscd::test
