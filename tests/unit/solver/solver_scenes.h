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

// Hand-built scenes for the solver tests: axis-aligned boxes stacked on a floor (the
// contacts are the four bottom corners of each box), a brick pyramid, a column of spheres
// under a loading plate, a time-step driver, and an independent check of the contact law.
// No geometry code: contacts are written down from the positions.
#pragma once

#include "solver/contact_problem.h"
#include "solver/rigid_motion.h"
#include "solver/warm_start.h"

#include <algorithm>
#include <cmath>
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
  double floor_restitution = 0.0;
  double box_restitution = 0.0;
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
        contact.restitution = lower < 0 ? floor_restitution : box_restitution;
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

// A brick pyramid of `levels` rows on the floor z = 0: bricks 1 x 1 x 0.5 of mass 1, 0.1
// apart within a row, each resting on the two below it (overlap 0.45 with each). Contacts:
// the four corners of each overlap rectangle (four under each bottom brick), all gaps zero.
inline ContactProblem brick_pyramid(int levels, double mu, double dt, double gravity = 9.81)
{
  const Vec3 half(0.5, 0.5, 0.25);
  const double pitch = 1.1;
  Box brick;
  brick.half_extents = half;
  ContactProblem problem;
  std::vector<std::vector<int>> rows(levels);
  for (int level = 0; level < levels; ++level)
    for (int i = 0; i < levels - level; ++i) {
      brick.pose.position = Vec3((0.5 * level + i) * pitch, 0.0, half.z() * (2 * level + 1));
      rows[level].push_back(static_cast<int>(problem.bodies.size()));
      problem.bodies.push_back(solver_body(brick, Vec3(0.0, 0.0, -gravity), dt));
    }
  auto corners = [&](int upper, int lower, double x0, double x1) {
    const double z = problem.bodies[upper].position.z() - half.z();
    int corner = 0;
    for (const double x : {x0, x1})
      for (const double y : {-half.y(), half.y()}) {
        Contact contact;
        contact.body_i = upper;
        contact.body_j = lower;
        contact.point = Vec3(x, y, z);
        contact.friction = mu;
        contact.key = {upper, lower, static_cast<std::uint64_t>(corner++)};
        problem.contacts.push_back(contact);
      }
  };
  for (int level = 0; level < levels; ++level)
    for (std::size_t i = 0; i < rows[level].size(); ++i) {
      const int b = rows[level][i];
      const double x = problem.bodies[b].position.x();
      if (level == 0) {
        corners(b, kEnvironment, x - half.x(), x + half.x());
      } else {
        corners(b, rows[level - 1][i], x - half.x(), x - 0.5 * pitch + half.x());
        corners(b, rows[level - 1][i + 1], x + 0.5 * pitch - half.x(), x + half.x());
      }
    }
  return problem;
}

// A straight column of `layers` spheres (radius 0.5, mass 1) on the floor z = 0 with a plate
// on top: mass `plate_mass`, translation along z only, no rotation (a loading plate). All
// gaps zero. The plate is the last body.
inline ContactProblem sphere_column_under_plate(int layers, double plate_mass, double mu,
                                                double dt, double gravity = 9.81)
{
  ContactProblem problem;
  for (int k = 0; k < layers; ++k) {
    SolverBody sphere;
    sphere.position = Vec3(0.0, 0.0, 0.5 + k);
    sphere.inv_mass = 1.0;
    sphere.inv_inertia = (1.0 / 0.1) * Mat3::Identity();    // 2/5 m r^2 = 0.1
    sphere.external_impulse = Vec3(0.0, 0.0, -gravity * dt);
    problem.bodies.push_back(sphere);
  }
  SolverBody plate;
  plate.position = Vec3(0.0, 0.0, layers + 0.1);
  plate.inv_mass = 1.0 / plate_mass;
  plate.inv_mass_axes = Vec3(0.0, 0.0, 1.0);
  plate.external_impulse = Vec3(0.0, 0.0, -gravity * dt * plate_mass);
  problem.bodies.push_back(plate);
  for (int k = 0; k <= layers; ++k) {
    Contact contact;
    contact.body_i = k;    // the plate for k = layers
    contact.body_j = k == 0 ? kEnvironment : k - 1;
    contact.point = Vec3(0.0, 0.0, static_cast<double>(k));
    contact.friction = mu;
    contact.key = {k, k - 1, 0};
    problem.contacts.push_back(contact);
  }
  return problem;
}

// Largest violation of the contact law by the solved impulses (contact.impulse after
// finish()) at the solved velocities, recomputed here from the bodies, for contacts that
// start closed and at rest (gap 0, no restitution: Signorini on u_n itself):
//   P_n >= 0, u_n >= 0, min(P_n, u_n) = 0, |P_t| <= mu P_n, and for a slipping contact
//   P_t = -mu P_n u_t / |u_t|.
// Impulse terms are divided by impulse_scale, velocity terms by velocity_scale.
inline double coulomb_violation(const ContactProblem &problem, double impulse_scale,
                                double velocity_scale)
{
  double worst = 0.0;
  auto velocity_at = [&](int b, const Vec3 &point) -> Vec3 {
    if (b == kEnvironment) return Vec3::Zero();
    const SolverBody &body = problem.bodies[b];
    return body.velocity + body.angular_velocity.cross(point - body.position);
  };
  for (const Contact &c : problem.contacts) {
    const Vec3 u = velocity_at(c.body_i, c.point) - velocity_at(c.body_j, c.point);
    const double u_n = u.dot(c.normal), P_n = c.impulse.dot(c.normal);
    const Vec3 u_t = u - u_n * c.normal, P_t = c.impulse - P_n * c.normal;
    const double p = P_n / impulse_scale, v = u_n / velocity_scale;
    worst = std::max({worst, -p, -v, std::min(std::abs(p), std::abs(v)),
                      (P_t.norm() - c.friction * P_n) / impulse_scale});
    if (u_t.norm() > velocity_scale * 1e-6 && P_n > 0.0)
      worst = std::max(worst, (P_t + c.friction * P_n * u_t.normalized()).norm() / impulse_scale);
  }
  return worst;
}

// The velocities M^-1 J^T P + v_free that the impulses of `solved` (after finish()) give to
// the bodies of `unsolved` (the problem as handed to prepare(), share 1): what the solver's
// incremental velocity updates must add up to.
inline std::vector<Vec3> velocities_from_impulses(const ContactProblem &unsolved,
                                                  const ContactProblem &solved)
{
  std::vector<Vec3> v(2 * unsolved.bodies.size());
  for (std::size_t b = 0; b < unsolved.bodies.size(); ++b) {
    const SolverBody &body = unsolved.bodies[b];
    const Vec3 inv_mass = body.inv_mass * body.inv_mass_axes;
    v[2 * b] = body.velocity + inv_mass.cwiseProduct(body.external_impulse);
    v[2 * b + 1] = body.angular_velocity + body.inv_inertia * body.external_angular_impulse;
  }
  for (const Contact &c : solved.contacts) {
    for (const int b : {c.body_i, c.body_j}) {
      if (b == kEnvironment) continue;
      const SolverBody &body = unsolved.bodies[b];
      const Vec3 P = b == c.body_i ? c.impulse : Vec3(-c.impulse);
      v[2 * b] += (body.inv_mass * body.inv_mass_axes).cwiseProduct(P);
      v[2 * b + 1] += body.inv_inertia * (c.point - body.position).cross(P);
    }
  }
  return v;
}

}    // namespace nscd::test
