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

#include "wire/wire_overlap.h"

#include "geometry/contact.h"
#include "geometry/point_grid.h"

#include <algorithm>
#include <functional>
#include <set>
#include <utility>

namespace nscd::wire {
namespace {

Vec3 middle(const WirePieces &w, const WireElement &e)
{
  return 0.5 * (w.nodes[e.a] + w.nodes[e.b]);
}

double half_length(const WirePieces &w, const WireElement &e)
{
  return 0.5 * (w.nodes[e.b] - w.nodes[e.a]).norm();
}

double longest_half(const WirePieces &w)
{
  double longest = 0.0;
  for (const WireElement &e : w.elements) longest = std::max(longest, half_length(w, e));
  return longest;
}

// Visits every pair (element of `first`, element of `second` shifted by each shift) whose
// spherocylinders may overlap, with the overlap depth of those that do.
void for_each_overlap(const WirePieces &first, const WirePieces &second, double radius,
                      const std::vector<Vec3> &shifts,
                      const std::function<void(int, int, const Vec3 &, double)> &visit)
{
  if (first.elements.empty() || second.elements.empty()) return;
  std::vector<Vec3> middles;
  for (const WireElement &e : second.elements) middles.push_back(middle(second, e));
  const double half = longest_half(second);
  PointGrid grid;
  grid.build(middles, std::max(2.0 * half, 2.0 * radius) + 1e-300);
  for (int a = 0; a < (int) first.elements.size(); a++) {
    const WireElement &ea = first.elements[a];
    const Segment sa{first.nodes[ea.a], first.nodes[ea.b], radius};
    const double reach = half_length(first, ea) + half + 2.0 * radius;
    for (const Vec3 &shift : shifts) {
      // the second set moves by `shift`: look for its elements near this one moved back
      grid.for_each_near(middle(first, ea) - shift, reach, [&](int b) {
        const WireElement &eb = second.elements[b];
        const Segment sb{second.nodes[eb.a] + shift, second.nodes[eb.b] + shift, radius};
        const auto contact = contact_segments(sa, sb, 0.0);
        if (contact && contact->gap < 0.0) visit(a, b, shift, -contact->gap);
      });
    }
  }
}

void keep_deepest(ElementOverlap &deepest, int a, int b, const Vec3 &shift, double depth)
{
  if (depth > deepest.depth) deepest = {depth, a, b, shift};
}

}    // namespace

ElementOverlap deepest_overlap_within(const WirePieces &wire, double radius, const std::vector<Vec3> &shifts)
{
  // node -> its neighbours along elements, for "joined by a node or by one element"
  std::vector<std::set<int>> next(wire.nodes.size());
  for (const WireElement &e : wire.elements) {
    next[e.a].insert(e.b);
    next[e.b].insert(e.a);
  }
  auto joined = [&](const WireElement &p, const WireElement &q) {
    for (int u : {p.a, p.b})
      for (int v : {q.a, q.b})
        if (u == v || next[u].count(v)) return true;
    return false;
  };
  std::vector<Vec3> all_shifts = {Vec3::Zero()};
  for (const Vec3 &s : shifts)
    if (s.squaredNorm() > 0.0) all_shifts.push_back(s);
  ElementOverlap deepest;
  for_each_overlap(wire, wire, radius, all_shifts, [&](int a, int b, const Vec3 &shift, double depth) {
    const bool itself = shift.squaredNorm() == 0.0;
    if (itself && (a == b || joined(wire.elements[a], wire.elements[b]))) return;
    keep_deepest(deepest, a, b, shift, depth);
  });
  return deepest;
}

ElementOverlap deepest_overlap_with_grains(const WirePieces &wire, double radius, const std::vector<PlacedGrain> &grains,
                                           const std::vector<Vec3> &shifts)
{
  ElementOverlap deepest;
  if (wire.elements.empty()) return deepest;
  std::vector<Vec3> middles;
  for (const WireElement &e : wire.elements) middles.push_back(middle(wire, e));
  const double half = longest_half(wire);
  PointGrid grid;
  grid.build(middles, std::max(2.0 * half, 2.0 * radius) + 1e-300);
  std::vector<Vec3> all_shifts = {Vec3::Zero()};
  for (const Vec3 &s : shifts)
    if (s.squaredNorm() > 0.0) all_shifts.push_back(s);
  ContactWorkspace workspace;
  for (int g = 0; g < (int) grains.size(); g++) {
    const PlacedGrain &grain = grains[g];
    const double reach = grain.shape->bounding_radius + half + radius;
    for (const Vec3 &shift : all_shifts) {
      Pose shifted = grain.pose;
      shifted.position += shift;
      grid.for_each_near(shifted.position, reach, [&](int a) {
        const WireElement &e = wire.elements[a];
        const Segment segment{wire.nodes[e.a], wire.nodes[e.b], radius};
        for (const SegmentContact &p : contact_segment_grain(segment, *grain.shape, shifted, 0.0, workspace))
          if (p.gap < 0.0) keep_deepest(deepest, a, g, shift, -p.gap);
      });
    }
  }
  return deepest;
}

ElementOverlap deepest_overlap_between(const WirePieces &first, const WirePieces &second, double radius,
                                       const std::vector<Vec3> &shifts)
{
  std::vector<Vec3> all_shifts = {Vec3::Zero()};
  for (const Vec3 &s : shifts)
    if (s.squaredNorm() > 0.0) all_shifts.push_back(s);
  ElementOverlap deepest;
  for_each_overlap(first, second, radius, all_shifts,
                   [&](int a, int b, const Vec3 &shift, double depth) { keep_deepest(deepest, a, b, shift, depth); });
  return deepest;
}

Drop first_touch_drop(const std::function<double(double)> &depth, double max_drop, double step, double tolerance)
{
  Drop drop;
  if (depth(0.0) > 0.0) {
    drop.touched = true;
    return drop;
  }
  double clear = 0.0, touching = -1.0;
  while (clear < max_drop) {
    const double next = std::min(clear + step, max_drop);
    if (depth(next) > 0.0) {
      touching = next;
      break;
    }
    clear = next;
  }
  if (touching < 0.0) {
    drop.distance = max_drop;
    return drop;
  }
  while (touching - clear > tolerance) {
    const double middle = 0.5 * (clear + touching);
    (depth(middle) > 0.0 ? touching : clear) = middle;
  }
  drop.distance = clear;
  drop.touched = true;
  return drop;
}

}    // namespace nscd::wire
