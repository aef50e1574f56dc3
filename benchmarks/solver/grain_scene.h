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

// Time-stepped scenes of rigid spheropolyhedra for the solver-method benchmark
// (solver_methods.cpp): boxes, spheres and random grains between plane walls, an optional
// loading plate (translation along z only, no rotation), contacts from lib/geometry, warm
// start by contact key, Moreau-Jean steps with the lib/solver solve(). No LAMMPS.
#pragma once

#include "geometry/contact.h"
#include "shape/spheropolyhedron.h"
#include "solver/contact_problem.h"
#include "solver/warm_start.h"

#include <string>
#include <vector>

namespace nscd::bench {

struct SceneBody {
  int shape = 0;                       // index into GrainScene::shapes
  Pose pose;
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
  double mass = 1.0;
  Vec3 moments = Vec3::Ones();         // principal moments, body frame
  bool plate = false;                  // translation along z only, rotation locked
  Vec3 force = Vec3::Zero();           // extra constant force (a plate's load)
};

struct GrainScene {
  std::string name;
  std::vector<Spheropolyhedron> shapes;
  std::vector<SceneBody> bodies;
  std::vector<PlaneWall> walls;
  std::vector<double> wall_friction;   // one per wall
  double friction = 0.5;               // between bodies
  Vec3 gravity = Vec3(0.0, 0.0, -1.0);
  double activation = 0.05;            // contacts are reported up to this gap
  bool warm_start = true;
  double load_factor = 1.0;            // multiplies gravity and the bodies' extra forces
  int sort_by_height = 0;              // order of the contacts: 0 as found, 1 bottom up, -1 top down
  WarmStartCache cache;

  // Adds a body of `shape` with density 1 (mass and moments from the shape).
  int add_body(int shape, const Pose &pose, double density = 1.0);

  // Contacts of the current poses (all pairs within bounding spheres + activation).
  void build(ContactProblem &problem, double dt);
  // build, warm start, solve, store, advance poses.
  SolveReport step(ContactProblem &problem, const SolverOptions &options);
  double kinetic_energy() const;

  // Text snapshot of the bodies' state (shapes are rebuilt by the scene's constructor).
  void write_state(const std::string &path) const;
  bool read_state(const std::string &path);
};

// Scenes (each at rest or settling; gravity -1 along z unless said otherwise).
GrainScene box_tower(int levels, double mu);
GrainScene box_pyramid(int levels, double mu);
// A column of spheres (diameter 1, mass ~0.52) in a channel between walls x = +-w/2:
// width 1 is a 1-D column; width 3 alternates rows of 3 and 2 in hexagonal order (2-D).
// A plate of `plate_mass_ratio` times a sphere's mass rests on top.
GrainScene sphere_column(int layers, int width, double plate_mass_ratio, double mu);
// Random ballast-like grains (diameters 0.8-1.2, axes 1 : 0.8 : 0.6, r = 0.02) dropped from a
// lattice into a box (floor friction mu, frictionless side walls). Not settled.
GrainScene random_grain_pour(int nx, int ny, int nz, double box, double mu);
// Adds a plate (translation along z only) of `mass` over the whole box, its bottom at the
// top of the highest grain (it lands within a few steps).
void add_plate_over_pile(GrainScene &scene, double box, double mass);

}    // namespace nscd::bench
