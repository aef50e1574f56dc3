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

/* The contact points of fix nscd's last solve grouped by the pair of bodies they join (two
   grains, or a grain and a boundary fix), for the computes that report per pair: compute
   nscd/contacts `pairs` and compute fabric/atom. LAMMPS-free: it sees only the solver's
   contacts and which boundary each belongs to. */

#ifndef LMP_NSCD_CONTACT_PAIRS_H
#define LMP_NSCD_CONTACT_PAIRS_H

#include "solver/contact_problem.h"

#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

namespace LAMMPS_NS {
namespace NSCD_NS {

struct ContactPair {
  std::int64_t tag_i = 0;    // atom ID of grain i (the normals point from j to i)
  std::int64_t tag_j = 0;    // atom ID of grain j (boundary == 0 only)
  int boundary = 0;          // 0: two grains; k: grain i and the k-th boundary fix
  int points = 0;
  double normal_force = 0.0;                      // sum of the points' normal forces (>= 0)
  nscd::Vec3 force = nscd::Vec3::Zero();          // sum of the points' forces on i
  nscd::Vec3 normal = nscd::Vec3::UnitZ();        // the pair's unit normal, from j to i
  nscd::Vec3 point = nscd::Vec3::Zero();          // its mean contact point

  bool carries_force() const { return normal_force > 0.0; }
};

// One pair per (body i, body j, boundary) of the contact list: a pair of grains found
// through two periodic images gives two pairs, as they are two contacts. The pair's normal
// and point are the means of its points' weighted by their normal forces, the normal
// renormalised; a pair without force weighs its points equally. (A face-to-face patch has
// one normal at all points; a pair whose points differ in normal, e.g. rounded edges, gets
// the direction its total normal force acts along.) Forces are impulses / dt. Pairs come
// in the order of their first point. boundary_of(k) is the boundary of contact k (0: none).
template <class BoundaryOf>
std::vector<ContactPair> group_contact_pairs(const std::vector<nscd::Contact> &contacts, double dt,
                                             BoundaryOf boundary_of)
{
  std::vector<ContactPair> pairs;
  std::vector<nscd::Vec3> plain_normal, plain_point, first_normal;    // per pair
  std::map<std::tuple<int, int, int>, size_t> index;
  for (size_t k = 0; k < contacts.size(); k++) {
    const nscd::Contact &c = contacts[k];
    const int boundary = boundary_of(k);
    const auto key = std::make_tuple(c.body_i, c.body_j, boundary);
    auto found = index.find(key);
    if (found == index.end()) {
      found = index.emplace(key, pairs.size()).first;
      ContactPair p;
      p.tag_i = c.key.tag_i;
      p.tag_j = boundary == 0 ? c.key.tag_j : 0;
      p.boundary = boundary;
      p.normal = nscd::Vec3::Zero();
      pairs.push_back(p);
      plain_normal.push_back(nscd::Vec3::Zero());
      plain_point.push_back(nscd::Vec3::Zero());
      first_normal.push_back(c.normal);
    }
    ContactPair &p = pairs[found->second];
    const double fn = c.impulse.dot(c.normal) / dt;
    p.points++;
    p.normal_force += fn;
    p.force += c.impulse / dt;
    p.normal += fn * c.normal;    // force-weighted sums, divided below
    p.point += fn * c.point;
    plain_normal[found->second] += c.normal;
    plain_point[found->second] += c.point;
  }
  for (size_t n = 0; n < pairs.size(); n++) {
    ContactPair &p = pairs[n];
    if (p.carries_force()) {
      p.point /= p.normal_force;
    } else {
      p.normal = plain_normal[n];
      p.point = plain_point[n] / p.points;
    }
    const double length = p.normal.norm();
    // Normals that cancel (two opposite points: not a contact a convex pair can have) keep
    // the first point's normal rather than a zero vector.
    p.normal = length > 0.0 ? (p.normal / length).eval() : first_normal[n];
  }
  return pairs;
}

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
