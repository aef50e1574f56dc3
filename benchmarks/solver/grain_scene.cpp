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

#include "grain_scene.h"

#include "shape/random_grain.h"
#include "solver/rigid_motion.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <random>

namespace nscd::bench {
namespace {

Spheropolyhedron box_shape(const Vec3 &half)
{
  std::vector<Vec3> corners;
  for (const double sx : {-1.0, 1.0})
    for (const double sy : {-1.0, 1.0})
      for (const double sz : {-1.0, 1.0}) corners.emplace_back(sx * half.x(), sy * half.y(), sz * half.z());
  return make_spheropolyhedron(corners, 0.0);
}

Spheropolyhedron sphere_shape(double radius) { return make_spheropolyhedron({Vec3::Zero()}, radius); }

Pose at(const Vec3 &position)
{
  Pose pose;
  pose.position = position;
  return pose;
}

void add_wall(GrainScene &scene, const Vec3 &point, const Vec3 &normal, double mu)
{
  scene.walls.push_back({point, normal});
  scene.wall_friction.push_back(mu);
}

int add_plate(GrainScene &scene, const Vec3 &half, double bottom, double mass,
              double x = 0.0, double y = 0.0)
{
  scene.shapes.push_back(box_shape(half));
  const int b = scene.add_body(static_cast<int>(scene.shapes.size()) - 1,
                               at(Vec3(x, y, bottom + half.z())));
  scene.bodies[b].plate = true;
  scene.bodies[b].mass = mass;
  return b;
}

}    // namespace

int GrainScene::add_body(int shape, const Pose &pose, double density)
{
  SceneBody body;
  body.shape = shape;
  body.pose = pose;
  body.mass = density * shapes[shape].volume;
  body.moments = density * shapes[shape].principal_inertia;
  bodies.push_back(body);
  return static_cast<int>(bodies.size()) - 1;
}

void GrainScene::build(ContactProblem &problem, double dt)
{
  problem.bodies.clear();
  problem.contacts.clear();
  for (const SceneBody &body : bodies) {
    SolverBody solver;
    solver.position = body.pose.position;
    solver.velocity = body.velocity;
    solver.angular_velocity = body.angular_velocity;
    solver.inv_mass = 1.0 / body.mass;
    solver.external_impulse = dt * load_factor * (body.mass * gravity + body.force);
    if (body.plate) {
      solver.inv_mass_axes = Vec3(0.0, 0.0, 1.0);
    } else {
      solver.inv_inertia = world_inverse_inertia(body.moments, body.pose.orientation);
      solver.external_angular_impulse =
          dt * gyroscopic_torque(body.moments, body.pose.orientation, body.angular_velocity);
    }
    problem.bodies.push_back(solver);
  }
  ContactWorkspace workspace;
  auto add = [&](const ContactPoint &point, int i, int j, std::int64_t tag_j, double mu) {
    Contact contact;
    contact.body_i = i;
    contact.body_j = j;
    contact.point = point.point;
    contact.normal = point.normal;
    contact.gap = point.gap;
    contact.friction = mu;
    contact.key = {i, tag_j, point.key};
    problem.contacts.push_back(contact);
  };
  const int n = static_cast<int>(bodies.size());
  for (int i = 0; i < n; ++i) {
    const SceneBody &a = bodies[i];
    const Spheropolyhedron &shape_a = shapes[a.shape];
    for (int j = 0; j < i; ++j) {
      const SceneBody &b = bodies[j];
      const Spheropolyhedron &shape_b = shapes[b.shape];
      const double reach = shape_a.bounding_radius + shape_b.bounding_radius + activation;
      if ((a.pose.position - b.pose.position).squaredNorm() > reach * reach) continue;
      for (const ContactPoint &point :
           contact_grains(shape_a, a.pose, shape_b, b.pose, activation, workspace))
        add(point, i, j, j, friction);
    }
    if (a.plate) continue;    // the plate's locked axes carry any wall reaction
    for (std::size_t w = 0; w < walls.size(); ++w) {
      const double distance = (a.pose.position - walls[w].point).dot(walls[w].normal);
      if (distance > shape_a.bounding_radius + activation) continue;
      for (const ContactPoint &point :
           contact_grain_plane(shape_a, a.pose, walls[w], activation, workspace))
        add(point, i, kEnvironment, -1 - static_cast<std::int64_t>(w), wall_friction[w]);
    }
  }
}

SolveReport GrainScene::step(ContactProblem &problem, const SolverOptions &options)
{
  build(problem, options.dt);
  if (sort_by_height != 0)
    std::stable_sort(problem.contacts.begin(), problem.contacts.end(),
                     [this](const Contact &a, const Contact &b) {
                       return sort_by_height * a.point.z() < sort_by_height * b.point.z();
                     });
  if (warm_start) cache.apply(problem.contacts);
  const SolveReport report = solve(problem, options);
  cache.store(problem.contacts);
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    SceneBody &body = bodies[k];
    const SolverBody &solved = problem.bodies[k];
    advance_pose(body.pose, body.velocity, body.angular_velocity, solved.velocity,
                 solved.angular_velocity, options.dt, options.theta);
    body.velocity = solved.velocity;
    body.angular_velocity = solved.angular_velocity;
  }
  return report;
}

double GrainScene::kinetic_energy() const
{
  double energy = 0.0;
  for (const SceneBody &body : bodies) {
    const Vec3 w = body.pose.orientation.conjugate() * body.angular_velocity;
    energy += 0.5 * body.mass * body.velocity.squaredNorm();
    if (!body.plate) energy += 0.5 * w.dot(body.moments.cwiseProduct(w));
  }
  return energy;
}

void GrainScene::write_state(const std::string &path) const
{
  std::ofstream out(path);
  out << std::setprecision(17) << bodies.size() << '\n';
  for (const SceneBody &b : bodies) {
    const Quat &q = b.pose.orientation;
    out << b.pose.position.transpose() << ' ' << q.w() << ' ' << q.x() << ' ' << q.y() << ' '
        << q.z() << ' ' << b.velocity.transpose() << ' ' << b.angular_velocity.transpose() << '\n';
  }
}

bool GrainScene::read_state(const std::string &path)
{
  std::ifstream in(path);
  std::size_t count = 0;
  if (!(in >> count) || count != bodies.size()) return false;
  for (SceneBody &b : bodies) {
    double q[4];
    in >> b.pose.position.x() >> b.pose.position.y() >> b.pose.position.z() >> q[0] >> q[1] >>
        q[2] >> q[3] >> b.velocity.x() >> b.velocity.y() >> b.velocity.z() >>
        b.angular_velocity.x() >> b.angular_velocity.y() >> b.angular_velocity.z();
    b.pose.orientation = Quat(q[0], q[1], q[2], q[3]);
  }
  return static_cast<bool>(in);
}

GrainScene box_tower(int levels, double mu)
{
  GrainScene scene;
  scene.name = "box tower " + std::to_string(levels);
  scene.friction = mu;
  scene.shapes.push_back(box_shape(Vec3(0.5, 0.5, 0.5)));
  for (int k = 0; k < levels; ++k) scene.add_body(0, at(Vec3(0.0, 0.0, 0.5 + k)));
  add_wall(scene, Vec3::Zero(), Vec3::UnitZ(), mu);
  return scene;
}

GrainScene box_pyramid(int levels, double mu)
{
  // Bricks 1 x 1 x 0.5 with gaps of 0.1 within a row (no side contacts); each brick rests
  // on two below, overlapping each by 0.45.
  GrainScene scene;
  scene.name = "box pyramid " + std::to_string(levels);
  scene.friction = mu;
  scene.shapes.push_back(box_shape(Vec3(0.5, 0.5, 0.25)));
  const double pitch = 1.1;
  for (int level = 0; level < levels; ++level)
    for (int i = 0; i < levels - level; ++i)
      scene.add_body(0, at(Vec3((0.5 * level + i) * pitch, 0.0, 0.25 + 0.5 * level)));
  add_wall(scene, Vec3::Zero(), Vec3::UnitZ(), mu);
  return scene;
}

GrainScene sphere_column(int layers, int width, double plate_mass_ratio, double mu)
{
  GrainScene scene;
  scene.name = std::string(width == 1 ? "1-D" : "2-D") + " sphere column " +
               std::to_string(layers) + " + plate x" + std::to_string(static_cast<int>(plate_mass_ratio));
  scene.friction = mu;
  scene.shapes.push_back(sphere_shape(0.5));
  const double row_height = width == 1 ? 1.0 : std::sqrt(0.75);
  double top = 0.0;
  for (int layer = 0; layer < layers; ++layer) {
    const double z = 0.5 + layer * row_height;
    if (width == 1) {
      scene.add_body(0, at(Vec3(0.0, 0.0, z)));
    } else {
      const bool even = layer % 2 == 0;
      const int count = even ? width : width - 1;
      for (int i = 0; i < count; ++i)
        scene.add_body(0, at(Vec3(-0.5 * (count - 1) + i, 0.0, z)));
    }
    top = z + 0.5;
  }
  const double half_width = 0.5 * width;
  add_wall(scene, Vec3::Zero(), Vec3::UnitZ(), mu);
  add_wall(scene, Vec3(-half_width, 0.0, 0.0), Vec3::UnitX(), mu);
  add_wall(scene, Vec3(half_width, 0.0, 0.0), -Vec3::UnitX(), mu);
  const double sphere_mass = scene.bodies[0].mass;
  add_plate(scene, Vec3(half_width - 0.05, 0.45, 0.1), top, plate_mass_ratio * sphere_mass);
  return scene;
}

GrainScene random_grain_pour(int nx, int ny, int nz, double box, double mu)
{
  GrainScene scene;
  scene.name = "random grain pile " + std::to_string(nx * ny * nz);
  scene.friction = mu;
  RandomGrainParams params;
  params.min_diameter = 0.8;
  params.max_diameter = 1.2;
  params.radius = 0.02;
  constexpr int kShapes = 24;
  for (int k = 0; k < kShapes; ++k) scene.shapes.push_back(random_grain(params, 2026, k));
  std::mt19937_64 random(4711);
  std::normal_distribution<double> normal;
  const double spacing = box / nx;
  int index = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        Pose pose;
        pose.position = Vec3((i + 0.5) * spacing, (j + 0.5) * spacing, 1.0 + k * 1.7);
        pose.orientation = Quat(normal(random), normal(random), normal(random), normal(random)).normalized();
        const int b = scene.add_body(index++ % kShapes, pose);
        scene.bodies[b].velocity = 0.05 * Vec3(normal(random), normal(random), normal(random));
      }
  add_wall(scene, Vec3::Zero(), Vec3::UnitZ(), mu);
  add_wall(scene, Vec3::Zero(), Vec3::UnitX(), 0.0);
  add_wall(scene, Vec3(box, 0.0, 0.0), -Vec3::UnitX(), 0.0);
  add_wall(scene, Vec3::Zero(), Vec3::UnitY(), 0.0);
  add_wall(scene, Vec3(0.0, box, 0.0), -Vec3::UnitY(), 0.0);
  return scene;
}

void add_plate_over_pile(GrainScene &scene, double box, double mass)
{
  double top = 0.0;
  for (const SceneBody &body : scene.bodies) {
    const Spheropolyhedron &shape = scene.shapes[body.shape];
    for (const Vec3 &vertex : shape.vertices)
      top = std::max(top, body.pose.to_world(vertex).z() + shape.radius);
  }
  const double half = 0.5 * box - 0.05;
  scene.name += " + plate";
  add_plate(scene, Vec3(half, half, 0.25), top, mass, 0.5 * box, 0.5 * box);
}

}    // namespace nscd::bench
