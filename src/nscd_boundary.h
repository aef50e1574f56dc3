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

/* What fix nscd and fix wire need from a boundary (a wall, the loading plate) of the contact
   problem. A fix that puts one there derives from NSCDBoundaryFix (nscd_boundary_fix.h) and
   hands out an object with this interface, which it owns. */

#ifndef LMP_NSCD_BOUNDARY_H
#define LMP_NSCD_BOUNDARY_H

#include "lmptype.h"

#include "geometry/contact.h"
#include "solver/contact_problem.h"

#include <vector>

namespace LAMMPS_NS {
class AtomVecSpheropolyhedron;
class LAMMPS;

namespace NSCD_NS {

class NSCDBoundary {
 public:

  // Appends the contacts of the boundary with OWNED grains (so each contact is on exactly
  // one rank). body_i is the local atom index, body_j = nscd::kEnvironment. Each grain's
  // activation is speculative_activation(activation, its closing speed, dt).
  virtual void append_contacts(std::vector<nscd::Contact> &contacts, double activation, double dt) = 0;

  // After the solve: the contacts this boundary appended, with their solved impulses, in
  // the order it appended them; dt turns impulses into forces. Called on every rank.
  virtual void take_impulses(const nscd::Contact *first, int count, double dt) = 0;

  // Moves the boundary by one step (prescribed velocity), after the grains have moved.
  virtual void advance(double dt) = 0;

  // A boundary with a body of its own (finite mass, e.g. the loading plate) puts that body
  // into the problem: the same body on every rank, after the atoms, at the index it is told;
  // its contacts use that index as body_j. After the solve it gets the body back.
  virtual bool has_body() const { return false; }
  virtual nscd::SolverBody body(double /*dt*/) const { return nscd::SolverBody(); }
  virtual void set_body_index(int /*index*/) {}
  virtual void take_body(const nscd::SolverBody & /*solved*/, double /*dt*/, double /*theta*/) {}

  // --- fix wire's soft contacts with the wire nodes of the boundary's group ---
  // The contact of a sphere (a node dilated by the wire radius) with the boundary as it
  // stands `tau` into the current step: it translates at surface_velocity() until fix nscd
  // moves it at the end of the step.
  virtual nscd::ContactPoint touch_sphere(const nscd::Vec3 &centre, double radius, double tau) const = 0;
  virtual nscd::Vec3 surface_velocity() const = 0;
  virtual double friction_coefficient() const = 0;
  // The deepest overlap of a grain in `pose` with the boundary as it stands, over the points
  // of their contact with a gap up to `within` (negative: the smallest gap; -infinity when
  // none is that near). For create_grains, which leaves out grains placed into a boundary,
  // and the boundaries' own start-of-run checks.
  virtual double deepest_overlap(const nscd::Spheropolyhedron &shape, const nscd::Pose &pose, double within) = 0;

  // The force of the wire on the boundary in step `step`, averaged over its substeps and
  // summed over the ranks: fix wire gives it on every rank in post_force, before fix nscd
  // solves the step. Zero for a step without it (no fix wire, or it was unfixed).
  void take_wire_force(const nscd::Vec3 &force, bigint step)
  {
    wire_force = force;
    wire_force_step = step;
  }
  nscd::Vec3 wire_force_in(bigint step) const
  {
    return step == wire_force_step ? wire_force : nscd::Vec3::Zero();
  }

 protected:
  NSCDBoundary() : wire_force(nscd::Vec3::Zero()), wire_force_step(-1) {}
  ~NSCDBoundary() = default;    // its fix owns it, never deleted through this interface

 private:
  nscd::Vec3 wire_force;
  bigint wire_force_step;
};

// The grain of the group (groupbit) reaching deepest into `boundary` as it stands, over all
// ranks: its depth relative to its bounding radius (share), depth, bounding radius and atom
// ID; all zero when no grain overlaps it. For the boundaries' start-of-run checks, which warn
// or stop past a fifth of the bounding radius (the depth at which fix nscd warns about
// grains inside grains). Collective: every rank must call it.
struct GrainInBoundary {
  double share, depth, bounding_radius;
  tagint id;
};
GrainInBoundary deepest_grain_in(LAMMPS *lmp, NSCDBoundary &boundary, const AtomVecSpheropolyhedron &avec,
                                 int groupbit);

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
