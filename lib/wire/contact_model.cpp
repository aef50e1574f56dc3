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

#include "wire/contact_model.h"

#include "math/capacity_bytes.h"

#include "wire/contact_weights.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace nscd::wire {

namespace {

bool spring_is_zero(const TangentialHistory &h)
{
  return h.xi[0] == 0.0 && h.xi[1] == 0.0 && h.xi[2] == 0.0 && h.sliding == 0.0;
}

// The spring of one point that the two ends of the last evaluation become: their
// weighted sum (see ContactMemory).
TangentialHistory merged(const ContactMemory &m)
{
  TangentialHistory h;
  for (int e = 0; e < 2; ++e) {
    for (int d = 0; d < 3; ++d) h.xi[d] += m.weight[e] * m.spring[e].xi[d];
    if (m.weight[e] > 0.0) h.sliding = std::max(h.sliding, m.spring[e].sliding);
  }
  return h;
}

// Largest rotation angle between two orientations.
double turned_by(const Quat &from, const Quat &to)
{
  const Quat d = from.conjugate() * to;
  return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

// Axis times angle (in [0, pi]) of a unit quaternion.
Vec3 rotation_vector(const Quat &q)
{
  const double sign = q.w() < 0.0 ? -1.0 : 1.0;
  const Vec3 axis = sign * q.vec();
  const double s = axis.norm();
  return s == 0.0 ? Vec3::Zero() : Vec3((2.0 * std::atan2(s, sign * q.w()) / s) * axis);
}

// Squared distance the farther of two nodes moved from where it was seen.
double farther_squared(const Vec3 &x1, const Vec3 &seen1, const Vec3 &x2, const Vec3 &seen2)
{
  return std::max((x1 - seen1).squaredNorm(), (x2 - seen2).squaredNorm());
}

// The smallest threshold of a group's watches, NaN if one is (a NaN threshold is no
// reason to skip a pair).
template <class Watch> double smallest_threshold(const std::vector<Watch> &watch, int first, int count)
{
  double smallest = std::numeric_limits<double>::infinity();
  for (int k = first; k < first + count; ++k)
    if (!(watch[k].threshold >= smallest)) smallest = watch[k].threshold;
  return smallest;
}

bool lower_element(const ElementCopy &a, const ElementCopy &b)
{
  return a.id_a < b.id_a || (a.id_a == b.id_a && a.id_b < b.id_b);
}

}    // namespace

bool ContactMemory::empty() const
{
  return spring_is_zero(spring[0]) && spring_is_zero(spring[1]);
}

ContactModel::ContactModel(const SoftContactLaw &law, double wire_radius, double skin)
    : law_(law), wire_wire_law_(law), grain_laws_{law}, radius_(wire_radius), skin_(skin)
{
  validate(law_);
  if (!(wire_radius > 0.0) || !std::isfinite(wire_radius) || !(skin > 0.0) || !std::isfinite(skin)) {
    std::ostringstream msg;
    msg << "wire contacts: radius " << wire_radius << " and skin " << skin << " must be finite and > 0";
    throw std::invalid_argument(msg.str());
  }
}

namespace {
// The law with other friction coefficients; `what` names the contacts in an error.
SoftContactLaw with_friction(SoftContactLaw law, double mu_s, double mu_d, const char *what)
{
  law.mu_s = mu_s;
  law.mu_d = mu_d;
  try {
    validate(law);
  } catch (const std::invalid_argument &e) {
    throw std::invalid_argument(std::string(what) + ": " + e.what());
  }
  return law;
}
}    // namespace

void ContactModel::set_wire_wire_friction(double mu_s, double mu_d)
{
  wire_wire_law_ = with_friction(law_, mu_s, mu_d, "wire-wire friction");
}

int ContactModel::add_grain_friction(double mu_s, double mu_d)
{
  grain_laws_.push_back(with_friction(law_, mu_s, mu_d, "wire-grain friction"));
  return (int) grain_laws_.size() - 1;
}

void ContactModel::set_elements(std::vector<std::array<std::int64_t, 2>> all_elements)
{
  for (auto &e : all_elements)
    if (e[0] > e[1]) std::swap(e[0], e[1]);
  std::sort(all_elements.begin(), all_elements.end());
  all_elements.erase(std::unique(all_elements.begin(), all_elements.end()), all_elements.end());
  all_elements_ = std::move(all_elements);
  lists_valid_ = false;
}

bool ContactModel::joined(std::int64_t p, std::int64_t q) const
{
  return p == q || std::binary_search(all_elements_.begin(), all_elements_.end(),
                                      std::array<std::int64_t, 2>{std::min(p, q), std::max(p, q)});
}

const ShapeFeatures &ContactModel::features_of(const Spheropolyhedron &shape)
{
  std::unique_ptr<ShapeFeatures> &f = features_[&shape];
  if (!f) f = std::make_unique<ShapeFeatures>(shape);
  return *f;
}

void ContactModel::begin_step(ContactScene scene, double dt_step, bool reindexed)
{
  for (const GrainCopy &g : scene.grains)
    if (g.law < 0 || g.law >= (int) grain_laws_.size())
      throw std::invalid_argument("wire contacts: grain " + std::to_string(g.id) + " asks for friction law " +
                                  std::to_string(g.law) + ", but only " + std::to_string(grain_laws_.size()) +
                                  " are defined (add_grain_friction)");
  if (reindexed) carry_memories();
  // A grain moved since the last step brings its pairs' last gaps closer by as much.
  if (lists_valid_ && scene.grains.size() == grains_last_step_.size()) {
    std::vector<double> moved(scene.grains.size());
    for (size_t g = 0; g < moved.size(); ++g) {
      const Pose &now = scene.grains[g].pose, &then = grains_last_step_[g].pose;
      moved[g] = (now.position - then.position).norm() +
                 turned_by(then.orientation, now.orientation) * scene.grains[g].shape->bounding_radius;
    }
    for (size_t k = 0; k < grain_pairs_.size(); ++k) {
      grain_watch_[k].threshold -= moved[grain_pairs_[k].grain];
      grain_pairs_[k].seen_gap -= moved[grain_pairs_[k].grain];
    }
    for (WatchGroup &g : grain_groups_) g.threshold = smallest_threshold(grain_watch_, g.first, g.count);
  }
  records_.clear();
  record_of_.clear();
  recorded_substeps_ = 0;
  measure_unseen_motion(scene);
  unseen_pending_ = true;
  boundary_travel_ += fastest_boundary_ * step_;    // the boundaries moved over the last step
  step_ = dt_step;
  scene_ = std::move(scene);
  grains_last_step_ = scene_.grains;
  fastest_boundary_ = 0.0;
  for (const BoundaryLink &b : scene_.boundaries) fastest_boundary_ = std::max(fastest_boundary_, b.speed);
  frames_.clear();
  grain_features_.clear();
  for (const GrainCopy &g : scene_.grains) {
    frames_.emplace_back(g.pose);
    grain_features_.push_back(&features_of(*g.shape));
  }
  // Grains moved between the steps (they hold still within one).
  other_moved_ = 0.0;
  if (lists_valid_ && grains_built_at_.size() == scene_.grains.size())
    for (size_t g = 0; g < scene_.grains.size(); ++g) {
      const Pose &now = scene_.grains[g].pose, &then = grains_built_at_[g];
      other_moved_ = std::max(other_moved_, (now.position - then.position).norm() +
                                                turned_by(then.orientation, now.orientation) * scene_.grains[g].shape->bounding_radius);
    }
  else
    lists_valid_ = false;
}

// Each copy of the new scene against the last scene's copy of its grain: the same index if
// it holds the same grain (no re-indexing), else the copy of that id nearest to it (periodic
// images lie a box apart). A grain new here (a new ghost, the first step of a run after a
// restart) has nothing to take, nor one that moved beyond its size unseen (the copy found is
// another image, or the grain was placed by hand between runs).
void ContactModel::measure_unseen_motion(const ContactScene &next)
{
  const std::vector<GrainCopy> &last = grains_last_step_;
  unseen_.assign(next.grains.size(), UnseenMotion{});
  if (last.empty() || !(step_ > 0.0)) return;
  std::vector<std::pair<std::int64_t, int>> by_id;    // built at the first copy that needs it
  for (size_t g = 0; g < next.grains.size(); ++g) {
    const GrainCopy &now = next.grains[g];
    const GrainCopy *then = g < last.size() && last[g].id == now.id ? &last[g] : nullptr;
    if (!then) {
      if (by_id.empty()) {
        for (size_t k = 0; k < last.size(); ++k) by_id.emplace_back(last[k].id, (int) k);
        std::sort(by_id.begin(), by_id.end());
      }
      double nearest = std::numeric_limits<double>::infinity();
      for (auto it = std::lower_bound(by_id.begin(), by_id.end(), std::make_pair(now.id, -1));
           it != by_id.end() && it->first == now.id; ++it) {
        const double d = (last[it->second].pose.position - now.pose.position).squaredNorm();
        if (d < nearest) nearest = d, then = &last[it->second];
      }
      if (!then) continue;
    }
    const Vec3 shift = now.pose.position - then->pose.position - step_ * then->velocity;
    if (shift.norm() > now.shape->bounding_radius) continue;    // another image, or a grain placed by hand
    unseen_[g].shift = shift;
    unseen_[g].turn = rotation_vector(now.pose.orientation * then->pose.orientation.conjugate()) -
                      step_ * then->angular_velocity;
  }
}

// The lists miss no pair that can touch while every pair closed by less than the skin
// since they were built. Keeps each node's displacement since then, for the watches.
bool ContactModel::lists_outdated(const std::vector<Vec3> &x, double tau)
{
  if (!lists_valid_ || x.size() != built_at_.size()) return true;
  double node = 0.0;
  moved_.resize(x.size());
  for (size_t k = 0; k < x.size(); ++k) {
    moved_[k] = (x[k] - built_at_[k]).norm();
    node = std::max(node, moved_[k]);
  }
  largest_moved_ = node;
  const double other = std::max(other_moved_, boundary_travel_ + fastest_boundary_ * tau);
  return node + std::max(node, other) > skin_;
}

void ContactModel::carry_memories()
{
  auto carry = [&](const auto &pairs) {
    for (const auto &p : pairs)
      if (!p.memory.empty()) carried_[p.key] = p.memory;
  };
  carry(grain_pairs_);
  carry(wire_pairs_);
  carry(boundary_pairs_);
  grain_pairs_.clear();
  grain_watch_.clear();
  grain_groups_.clear();
  wire_pairs_.clear();
  wire_watch_.clear();
  wire_groups_.clear();
  boundary_pairs_.clear();
  lists_valid_ = false;
}

template <class Pair> void ContactModel::recall(Pair &pair)
{
  const auto it = carried_.find(pair.key);
  if (it == carried_.end()) return;
  pair.memory = it->second;
  carried_.erase(it);
}

void ContactModel::rebuild(const std::vector<Vec3> &x, double tau)
{
  carry_memories();
  find_grain_pairs(x);
  find_wire_pairs(x);
  find_boundary_pairs(x, tau);
  for (GrainPair &p : grain_pairs_) recall(p);
  for (WirePair &p : wire_pairs_) recall(p);
  for (BoundaryPair &p : boundary_pairs_) recall(p);
  carried_.clear();    // contacts that are no candidates any more are open
  built_at_ = x;
  moved_.assign(x.size(), 0.0);
  largest_moved_ = 0.0;
  grains_built_at_.clear();
  for (const GrainCopy &g : scene_.grains) grains_built_at_.push_back(g.pose);
  boundary_travel_ = -fastest_boundary_ * tau;
  other_moved_ = 0.0;
  lists_valid_ = true;
  ++rebuilds_;
}

// Element copies computed here against grain copies within the skin of touching
// (bounding spheres), one copy per grain: the one closest to the element's first node.
void ContactModel::find_grain_pairs(const std::vector<Vec3> &x)
{
  const std::vector<GrainCopy> &grains = scene_.grains;
  if (grains.empty()) return;
  centres_.clear();
  double largest = 0.0, longest_half = 0.0;
  for (const GrainCopy &g : grains) {
    centres_.push_back(g.pose.position);
    largest = std::max(largest, g.shape->bounding_radius);
  }
  for (const ElementCopy &e : scene_.elements)
    if (e.computes) longest_half = std::max(longest_half, 0.5 * (x[e.b] - x[e.a]).norm());
  grid_.build(centres_, 2.0 * longest_half + radius_ + largest + skin_);
  struct Found {
    std::int64_t id;
    double distance;
    int grain;
  };
  std::vector<Found> found;
  for (const ElementCopy &e : scene_.elements) {
    if (!e.computes) continue;
    const Vec3 centre = 0.5 * (x[e.a] + x[e.b]);
    const double half = 0.5 * (x[e.b] - x[e.a]).norm();
    found.clear();
    grid_.for_each_near(centre, half + radius_ + largest + skin_, [&](int g) {
      const double reach = half + radius_ + grains[g].shape->bounding_radius + skin_;
      if ((grains[g].pose.position - centre).squaredNorm() > reach * reach) return;
      found.push_back({grains[g].id, (grains[g].pose.position - x[e.a]).squaredNorm(), g});
    });
    std::sort(found.begin(), found.end(), [](const Found &p, const Found &q) {
      return p.id != q.id ? p.id < q.id : p.distance < q.distance;
    });
    const int first = static_cast<int>(grain_pairs_.size());
    for (size_t k = 0; k < found.size(); ++k) {
      if (k > 0 && found[k].id == found[k - 1].id) continue;    // a farther copy
      GrainPair p{};
      p.a = e.a;
      p.b = e.b;
      p.grain = found[k].grain;
      p.key = {e.id_a, e.id_b, found[k].id, 0};
      grain_pairs_.push_back(p);
      grain_watch_.push_back({e.a, e.b, 0.0});
    }
    const int count = static_cast<int>(grain_pairs_.size()) - first;
    if (count > 0) grain_groups_.push_back({e.a, e.b, first, count, 0.0});
  }
}

// Element pairs within the skin of touching, each once: computed with the lower element's
// copy (by node ids), against the higher one's copy closest to it; never joined ones.
void ContactModel::find_wire_pairs(const std::vector<Vec3> &x)
{
  const std::vector<ElementCopy> &elements = scene_.elements;
  if (elements.empty()) return;
  centres_.clear();
  double longest_half = 0.0;
  for (const ElementCopy &e : elements) {
    centres_.push_back(0.5 * (x[e.a] + x[e.b]));
    longest_half = std::max(longest_half, 0.5 * (x[e.b] - x[e.a]).norm());
  }
  grid_.build(centres_, 4.0 * longest_half + 2.0 * radius_ + skin_);
  struct Found {
    std::int64_t id_a, id_b;
    double distance;
    int element;
  };
  std::vector<Found> found;
  for (size_t i = 0; i < elements.size(); ++i) {
    const ElementCopy &A = elements[i];
    if (!A.computes) continue;
    const double half_a = 0.5 * (x[A.b] - x[A.a]).norm();
    found.clear();
    grid_.for_each_near(centres_[i], half_a + longest_half + 2.0 * radius_ + skin_, [&](int k) {
      const ElementCopy &B = elements[k];
      if (!lower_element(A, B)) return;
      const double reach = half_a + 0.5 * (x[B.b] - x[B.a]).norm() + 2.0 * radius_ + skin_;
      if ((centres_[k] - centres_[i]).squaredNorm() > reach * reach) return;
      if (joined(A.id_a, B.id_a) || joined(A.id_a, B.id_b) || joined(A.id_b, B.id_a) || joined(A.id_b, B.id_b)) return;
      found.push_back({B.id_a, B.id_b, (x[B.a] - x[A.a]).squaredNorm(), k});
    });
    std::sort(found.begin(), found.end(), [](const Found &p, const Found &q) {
      if (p.id_a != q.id_a) return p.id_a < q.id_a;
      if (p.id_b != q.id_b) return p.id_b < q.id_b;
      return p.distance < q.distance;
    });
    const int first = static_cast<int>(wire_pairs_.size());
    for (size_t k = 0; k < found.size(); ++k) {
      if (k > 0 && found[k].id_a == found[k - 1].id_a && found[k].id_b == found[k - 1].id_b) continue;
      const ElementCopy &B = elements[found[k].element];
      WirePair p{};
      p.a1 = A.a;
      p.a2 = A.b;
      p.b1 = B.a;
      p.b2 = B.b;
      p.key = {A.id_a, A.id_b, B.id_a, B.id_b};
      wire_pairs_.push_back(p);
      wire_watch_.push_back({A.a, A.b, B.a, B.b, 0.0});
    }
    const int count = static_cast<int>(wire_pairs_.size()) - first;
    if (count > 0) wire_groups_.push_back({A.a, A.b, first, count, 0.0});
  }
}

// Nodes within the skin of a boundary they may touch.
void ContactModel::find_boundary_pairs(const std::vector<Vec3> &x, double tau)
{
  const std::vector<std::uint32_t> &touches = scene_.node_boundaries;
  for (size_t k = 0; k < touches.size() && k < x.size(); ++k) {
    if (touches[k] == 0) continue;
    for (size_t b = 0; b < scene_.boundaries.size(); ++b) {
      if (!(touches[k] & (1u << b))) continue;
      if (scene_.boundaries[b].boundary->touch_sphere(x[k], radius_, tau).gap > skin_) continue;
      BoundaryPair p{};
      p.node = static_cast<int>(k);
      p.boundary = static_cast<int>(b);
      p.key = {scene_.node_id[k], 0, scene_.boundaries[b].id, 0};
      boundary_pairs_.push_back(p);
    }
  }
}

ContactTotals ContactModel::add_forces(const std::vector<Vec3> &x, const std::vector<Vec3> &v, double tau, double dt,
                                       std::vector<Vec3> &f, GrainForceAccumulator &reactions)
{
  if (lists_outdated(x, tau)) rebuild(x, tau);
  recorded_substeps_ += recording_ ? 1 : 0;
  ContactTotals out;
  const double *moved = moved_.data();
  for (WatchGroup &g : grain_groups_) {
    const double element_moved = std::max(moved[g.a], moved[g.b]);    // (each watch's a and b are the group's)
    if (element_moved < g.threshold) continue;                         // no pair of it can touch yet
    double smallest = std::numeric_limits<double>::infinity();
    for (int k = g.first; k < g.first + g.count; ++k) {
      GrainWatch &w = grain_watch_[k];
      if (!(element_moved < w.threshold)) {    // else it cannot touch yet
        GrainPair &p = grain_pairs_[k];
        if (!(p.seen_gap > 0.0 && farther_squared(x[p.a], p.seen[0], x[p.b], p.seen[1]) < p.seen_gap * p.seen_gap))
          out.wire_grain += grain_contact(p, w, x, v, tau, dt, f, reactions, out);
      }
      if (!(w.threshold >= smallest)) smallest = w.threshold;    // (NaN stays)
    }
    g.threshold = smallest;
  }
  for (WatchGroup &g : wire_groups_) {
    const double element_moved = std::max(moved[g.a], moved[g.b]);    // (each watch's a1 and a2 are the group's)
    // (a + largest >= a + b in floating point too: rounding keeps the order)
    if (element_moved + largest_moved_ < g.threshold) continue;
    double smallest = std::numeric_limits<double>::infinity();
    for (int k = g.first; k < g.first + g.count; ++k) {
      WireWatch &w = wire_watch_[k];
      if (!(element_moved + std::max(moved[w.b1], moved[w.b2]) < w.threshold)) {
        WirePair &p = wire_pairs_[k];
        if (!(p.seen_gap > 0.0 && std::sqrt(farther_squared(x[p.a1], p.seen[0], x[p.a2], p.seen[1])) +
                                          std::sqrt(farther_squared(x[p.b1], p.seen[2], x[p.b2], p.seen[3])) <
                                      p.seen_gap))
          out.wire_wire += wire_contact(p, w, x, v, dt, f, out);
      }
      if (!(w.threshold >= smallest)) smallest = w.threshold;
    }
    g.threshold = smallest;
  }
  for (BoundaryPair &p : boundary_pairs_) out.wire_boundary += boundary_contact(p, x, v, tau, dt, f, reactions, out);
  unseen_pending_ = false;
  return out;
}

// Element (a, b) against a grain held still: a soft contact at each end of the touching
// stretch (or at its one point), each with its own overlap and spring, weighed by
// stretch_end_weight; the query reaches r_w beyond touching, the length of that ramp.
bool ContactModel::grain_contact(GrainPair &p, GrainWatch &watch, const std::vector<Vec3> &x,
                                 const std::vector<Vec3> &v, double tau, double dt, std::vector<Vec3> &f,
                                 GrainForceAccumulator &reactions, ContactTotals &totals)
{
  const Vec3 &xa = x[p.a], &xb = x[p.b];
  const TrackedSegmentContact t = contact_segment_grain_tracked({xa, xb, radius_}, *grain_features_[p.grain],
                                                                frames_[p.grain], radius_, p.hint, workspace_);
  watch.threshold = t.clearance - std::max(moved_[p.a], moved_[p.b]);
  ++grain_evaluations_;
  grain_from_hint_ += t.from_hint;
  p.seen_gap = t.clearance;
  if (t.clearance > 0.0) {
    p.seen = {xa, xb};
    p.memory = ContactMemory{};
    return false;
  }
  const SegmentGrainContact &c = t.contact;
  std::array<TangentialHistory, 2> spring = p.memory.spring;
  if (c.count < 2) spring[0] = merged(p.memory);
  const double weight = c.count < 2 ? 1.0 : stretch_end_weight((c[1].s_i - c[0].s_i) * (xb - xa).norm(), radius_);
  const GrainCopy &g = scene_.grains[p.grain];
  bool closed = false;
  for (int k = 0; k < c.count; ++k) {
    const SegmentContact &point = c[k];
    if (point.gap >= 0.0) {
      spring[k] = TangentialHistory{};
      continue;
    }
    closed = true;
    const LeverWeights lever = lever_weights(point.s_i);
    const Vec3 arm = point.point - g.pose.position;
    if (unseen_pending_) {
      const UnseenMotion &u = unseen_[p.grain];
      follow_other_body(spring[k], u.shift + u.turn.cross(arm), point.normal);
    }
    const Vec3 surface = g.velocity + g.angular_velocity.cross(arm);
    const Vec3 v_rel = lever.on_a * v[p.a] + lever.on_b * v[p.b] - surface;
    // Held springs: the grain's velocity carries the history ahead of its held pose by tau v
    // without stretching the spring (see soft_contact_force); a contact new at this substep
    // starts from that history at the substep's start, its spring unstretched.
    Vec3 ahead = Vec3::Zero();
    if (grain_springs_ == GrainSprings::held) {
      ahead = -tau * surface;
      if (spring_is_zero(spring[k])) {
        const Vec3 before = ahead + dt * surface;
        soft_contact_detail::store(before - before.dot(point.normal) * point.normal, spring[k]);
      }
    }
    const SoftContactForce r =
        soft_contact_force(grain_laws_[g.law], point.normal, -point.gap, v_rel, dt, spring[k], ahead);
    const Vec3 force = weight * r.force;
    if (recording_) record(p.key, ContactRecord::wire_grain, k, point, weight, r);
    f[p.a] += lever.on_a * force;
    f[p.b] += lever.on_b * force;
    reactions.add(p.grain, -force, arm);
    totals.energy += weight * r.elastic_energy;
    totals.normal_force += weight * r.normal_force;
  }
  if (c.count < 2) {
    p.memory.spring = {spring[0], spring[0]};
    p.memory.weight = {0.5, 0.5};
  } else {
    p.memory.spring = spring;
    p.memory.weight = {weight, weight};
  }
  return closed;
}

// Element A = (a1, a2) against element B = (b1, b2); the force on A, minus on B, each
// split over its nodes by the lever rule.
bool ContactModel::wire_contact(WirePair &p, WireWatch &watch, const std::vector<Vec3> &x,
                                const std::vector<Vec3> &v, double dt, std::vector<Vec3> &f, ContactTotals &totals)
{
  const std::optional<SegmentContact> c = contact_segments({x[p.a1], x[p.a2], radius_}, {x[p.b1], x[p.b2], radius_},
                                                           std::numeric_limits<double>::max());
  watch.threshold = c->gap - std::max(moved_[p.a1], moved_[p.a2]) - std::max(moved_[p.b1], moved_[p.b2]);
  p.seen_gap = c->gap;
  if (c->gap >= 0.0) {
    p.seen = {x[p.a1], x[p.a2], x[p.b1], x[p.b2]};
    p.memory = ContactMemory{};
    return false;
  }
  const LeverWeights wa = lever_weights(c->s_i), wb = lever_weights(c->s_j);
  const Vec3 v_rel = (wa.on_a * v[p.a1] + wa.on_b * v[p.a2]) - (wb.on_a * v[p.b1] + wb.on_b * v[p.b2]);
  const SoftContactForce r = soft_contact_force(wire_wire_law_, c->normal, -c->gap, v_rel, dt, p.memory.spring[0]);
  p.memory.weight[0] = 1.0;
  if (recording_) record(p.key, ContactRecord::wire_wire, 0, *c, 1.0, r);
  f[p.a1] += wa.on_a * r.force;
  f[p.a2] += wa.on_b * r.force;
  f[p.b1] -= wb.on_a * r.force;
  f[p.b2] -= wb.on_b * r.force;
  totals.energy += r.elastic_energy;
  totals.normal_force += r.normal_force;
  return true;
}

// A node against a boundary where it stands tau into the step. A chain of spherocylinders
// touches a plane or the inside of a cylinder only with its node spheres
// (lib/geometry/contact.h), so each node is one contact per boundary.
bool ContactModel::boundary_contact(BoundaryPair &p, const std::vector<Vec3> &x, const std::vector<Vec3> &v, double tau,
                                    double dt, std::vector<Vec3> &f, GrainForceAccumulator &reactions,
                                    ContactTotals &totals)
{
  const BoundaryLink &b = scene_.boundaries[p.boundary];
  const ContactPoint c = b.boundary->touch_sphere(x[p.node], radius_, tau);
  if (c.gap >= 0.0) {
    p.memory = ContactMemory{};
    return false;
  }
  const Vec3 v_rel = v[p.node] - b.boundary->surface_velocity();
  const SoftContactForce r = soft_contact_force(b.law, c.normal, -c.gap, v_rel, dt, p.memory.spring[0]);
  p.memory.weight[0] = 1.0;
  if (recording_) record(p.key, ContactRecord::wire_boundary, 0, SegmentContact{c.point, c.normal, c.gap}, 1.0, r);
  f[p.node] += r.force;
  reactions.add(static_cast<int>(scene_.grains.size()) + p.boundary, -r.force, Vec3::Zero());
  totals.energy += r.elastic_energy;
  totals.normal_force += r.normal_force;
  return true;
}

void ContactModel::record(const ContactKey &key, int kind, int end, const SegmentContact &point, double weight,
                          const SoftContactForce &r)
{
  auto found = record_of_.try_emplace(key, std::array<int, 2>{-1, -1}).first;
  int &slot = found->second[end];
  if (slot < 0) {
    slot = static_cast<int>(records_.size());
    records_.emplace_back();
    records_.back().key = key;
    records_.back().kind = kind;
    records_.back().end = end;
  }
  ContactRecord &c = records_[slot];
  c.point = point.point;
  c.normal = point.normal;
  c.overlap = -point.gap;
  c.normal_force += weight * r.normal_force;
  c.tangential_force += weight * r.tangential_force;
  c.sliding = r.slipped;
}

std::vector<ContactRecord> ContactModel::contact_records() const
{
  std::vector<ContactRecord> out = records_;
  const double per_substep = recorded_substeps_ > 0 ? 1.0 / recorded_substeps_ : 0.0;
  for (ContactRecord &c : out) {
    c.normal_force *= per_substep;
    c.tangential_force *= per_substep;
  }
  std::sort(out.begin(), out.end(), [](const ContactRecord &a, const ContactRecord &b) {
    return a.key != b.key ? a.key < b.key : a.end < b.end;
  });
  return out;
}

std::vector<StoredContact> ContactModel::memories() const
{
  std::vector<StoredContact> out;
  for (const auto &entry : carried_) out.push_back({entry.first, entry.second});
  auto add = [&](const auto &pairs) {
    for (const auto &p : pairs)
      if (!p.memory.empty()) out.push_back({p.key, p.memory});
  };
  add(grain_pairs_);
  add(wire_pairs_);
  add(boundary_pairs_);
  std::sort(out.begin(), out.end(), [](const StoredContact &a, const StoredContact &b) { return a.key < b.key; });
  return out;
}

std::vector<StoredContact> ContactModel::take_memories()
{
  carry_memories();
  std::vector<StoredContact> out;
  out.reserve(carried_.size());
  for (const auto &entry : carried_) out.push_back({entry.first, entry.second});
  carried_.clear();
  return out;
}

void ContactModel::add_memories(const std::vector<StoredContact> &stored)
{
  carry_memories();
  for (const StoredContact &s : stored) carried_[s.key] = s.memory;
}

std::size_t ContactModel::memory_bytes() const
{
  return capacity_bytes(records_) + capacity_bytes(record_of_) + capacity_bytes(all_elements_) +
      capacity_bytes(scene_.node_id) + capacity_bytes(scene_.node_boundaries) + capacity_bytes(scene_.elements) +
      capacity_bytes(scene_.grains) + capacity_bytes(scene_.boundaries) + capacity_bytes(frames_) +
      capacity_bytes(grain_features_) + capacity_bytes(grain_pairs_) + capacity_bytes(grain_watch_) +
      capacity_bytes(grain_groups_) + capacity_bytes(wire_pairs_) + capacity_bytes(wire_watch_) +
      capacity_bytes(wire_groups_) + capacity_bytes(boundary_pairs_) + capacity_bytes(carried_) +
      capacity_bytes(built_at_) + capacity_bytes(moved_) + capacity_bytes(grains_built_at_) +
      capacity_bytes(grains_last_step_) + capacity_bytes(unseen_) + capacity_bytes(centres_);
}

}    // namespace nscd::wire
