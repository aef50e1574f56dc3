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

/* One place that turns a geometric contact point into a contact of the NSCD problem, for
   every style that finds contacts (pair_style nscd, fix nscd/wall, fix nscd/plate), in the
   namespace of the package's helpers, NSCD_NS. */

#ifndef LMP_NSCD_CONTACT_H
#define LMP_NSCD_CONTACT_H

#include "geometry/contact.h"
#include "geometry/feature_key.h"
#include "solver/contact_problem.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace LAMMPS_NS {
namespace NSCD_NS {

// Speculative activation. Bodies closing at up to `closing_speed` (relative speed of their
// centres plus each one's spin times its bounding radius) close a gap of up to that times dt
// within the step; their contacts enter the problem as soon as the gap is below that, with a
// margin for what the step's forces add, so no contact is found after it has closed. An open
// contact only limits the approach to closing its gap (doc/Howto_nscd_solver.rst), so an
// early one adds no force. `base` is the smallest activation (a geometric tolerance). A speed
// that is not finite gives `base`: the solve then stops naming the body (fix nscd), rather
// than a geometric query failing on one rank.
constexpr double SPECULATIVE_MARGIN = 1.5;
inline double speculative_activation(double base, double closing_speed, double dt)
{
  const double ahead = SPECULATIVE_MARGIN * closing_speed * dt;
  return std::isfinite(ahead) ? std::max(base, ahead) : base;
}

// The closing speed of a grain on a boundary moving at `boundary_velocity`, for
// speculative_activation: its centre's relative speed plus its spin times its radius.
inline double closing_speed_on_boundary(const nscd::Vec3 &velocity, const nscd::Vec3 &omega, double radius,
                                        const nscd::Vec3 &boundary_velocity)
{
  return (velocity - boundary_velocity).norm() + omega.norm() * radius;
}

struct ContactLaw {
  double friction = 0.0;
  double restitution = 0.0;
};

// body_j < 0 (nscd::kEnvironment) for a wall. The warm-start key names the feature pair in
// the order of increasing ID, so that finding the pair as (j, i) later gives the same key.
inline nscd::Contact make_contact(const nscd::ContactPoint &p, int body_i, int body_j,
                                  std::int64_t id_i, std::int64_t id_j, const ContactLaw &law)
{
  nscd::Contact c;
  c.body_i = body_i;
  c.body_j = body_j;
  c.point = p.point;
  c.normal = p.normal;
  c.gap = p.gap;
  c.friction = law.friction;
  c.restitution = law.restitution;
  c.key.tag_i = id_i;
  c.key.tag_j = id_j;
  c.key.feature = id_i < id_j ? p.key : nscd::swapped_key(p.key);
  return c;
}

// A stable negative id for a boundary fix in contact keys (FNV-1a of the fix ID), so that
// warm starts survive other fixes being added or removed, and restarts.
inline std::int64_t boundary_tag(const char *fix_id)
{
  std::uint64_t h = 1469598103934665603ULL;
  for (const char *c = fix_id; *c; c++) h = (h ^ (unsigned char) *c) * 1099511628211ULL;
  return -(std::int64_t) (h >> 2) - 1;
}

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
