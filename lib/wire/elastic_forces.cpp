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

#include "wire/elastic_forces.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace nscd::wire {

namespace {

[[noreturn]] __attribute__((noinline, cold)) void throw_bad_length(double length, const char *what)
{
  std::ostringstream msg;
  msg << "wire: " << what << " has length " << length
      << " (its two nodes coincide or are not finite); check the wire's initial "
         "coordinates or reduce the wire time step if it blew up";
  throw std::invalid_argument(msg.str());
}

// Dot product and length with the sums in a fixed order, (x + y) + z: the order Eigen's
// dot() and norm() of a Vec3 take in the default build, written out so that the laws
// below and ElasticKernel's arrays round alike whatever Eigen vectorises.
inline double dot3(const Vec3 &u, const Vec3 &w) { return (u.x() * w.x() + u.y() * w.y()) + u.z() * w.z(); }
inline double length3(const Vec3 &u) { return std::sqrt(dot3(u, u)); }

// The check is inline and the message out of line: these kernels run every substep.
inline double checked_length(const Vec3 &d, const char *what)
{
  const double length = length3(d);
  if (!(length > 0.0 && length < std::numeric_limits<double>::infinity())) throw_bad_length(length, what);
  return length;
}

// Unit vector along v, or zero if v vanishes (the wire is exactly straight or folded).
Vec3 unit_or_zero(const Vec3 &v)
{
  const double n = v.norm();
  return n > 0.0 ? Vec3(v / n) : Vec3::Zero();
}

// atan(y) for 0 <= |y| <= tan(pi/8): y + y z P(z), z = y^2, P near-minimax (coefficients
// from tools/wire_atan_coefficients.py: error within 1.02 x 2^-53 of atan(y)). T is double
// or an Eigen array (ElasticKernel: two joints at a time, the same operations on each).
template <class T> __attribute__((always_inline)) inline T atan_small(const T &y)
{
  static constexpr double c[] = {-0.3333333333333333,   0.1999999999999552,   -0.14285714284666542,
                                 0.11111111015256361,   -0.09090904578123903, 0.07692183190826087,
                                 -0.06664511447381948,  0.0585814891280221,   -0.0508544973794026,
                                 0.03923165829558719,   -0.01917688711906226};
  // Estrin's scheme: a quarter of Horner's chain of dependent operations.
  const T z = y * y, z2 = z * z, z4 = z2 * z2, z8 = z4 * z4;
  const T p01 = c[0] + c[1] * z, p23 = c[2] + c[3] * z, p45 = c[4] + c[5] * z, p67 = c[6] + c[7] * z,
          p89 = c[8] + c[9] * z;
  const T p = (p01 + p23 * z2) + (p45 + p67 * z2) * z4 + (p89 + c[10] * z2) * z8;
  return y + y * z * p;
}

// Multiples of pi/4 as a double and the rest, so that hi + (lo + x) rounds once.
constexpr double kPiHi = 3.141592653589793, kPiLo = 1.2246467991473532e-16;
constexpr double kHalfPiHi = 1.5707963267948966, kHalfPiLo = 6.123233995736766e-17;
constexpr double kQuarterPiHi = 0.7853981633974483, kQuarterPiLo = 3.061616997868383e-17;
constexpr double kThreeQuarterPiHi = 2.356194490192345, kThreeQuarterPiLo = 9.184850993605148e-17;
constexpr double kTanEighthPi = 0.41421356237309503;

// In each eighth of [0, pi] around a multiple m pi/4 (the two ends: a sixteenth), the angle
// is m pi/4 + atan(y) with |y| <= tan(pi/8), y formed from sine and cosine with one
// division: tan(nu - pi/4) = (s - c) / (s + c), tan(nu - 3 pi/4) = (s + c) / (c - s).
__attribute__((always_inline)) inline double node_angle(double sine, double cosine)
{
  const double s = sine, c = cosine, t = kTanEighthPi;
  if (s <= t * c) return c > 0.0 ? atan_small<double>(s / c) : 0.0;    // (0, 0) -> 0, as atan2
  if (t * s <= c) return kQuarterPiHi + (kQuarterPiLo + atan_small<double>((s - c) / (s + c)));
  if (-t * s <= c) return kHalfPiHi + (kHalfPiLo - atan_small<double>(c / s));
  if (-t * c <= s) return kThreeQuarterPiHi + (kThreeQuarterPiLo + atan_small<double>((s + c) / (c - s)));
  return kPiHi + (kPiLo - atan_small<double>(s / -c));
}

}    // namespace

double angle_from_sine_cosine(double sine, double cosine) { return node_angle(sine, cosine); }

double angle_between(const Vec3 &u, const Vec3 &w)
{
  return std::atan2(u.cross(w).norm(), u.dot(w));
}

namespace {

void check_rest_length(double rest_length)
{
  if (rest_length > 0.0) return;
  std::ostringstream msg;
  msg << "wire: element rest length " << rest_length << " must be > 0";
  throw std::invalid_argument(msg.str());
}

// The axial law for an element of the given length along d (d = b - a, |d| = length): the
// force on b (on a: its opposite) and strain, tension and energy into out. False for a slack
// string (no force).
__attribute__((always_inline)) inline bool axial_law(const AxialLaw &law, double rest_length, const Vec3 &d, double length, AxialForces &out)
{
  out.strain = (length - rest_length) / rest_length;
  if (out.strain < 0.0 && !law.resists_compression) return false;    // slack string
  out.tension = law.k_elo * out.strain;
  out.energy = 0.5 * law.k_elo * rest_length * out.strain * out.strain;
  // dE/dL = k_elo * strain = tension; a tensile element pulls b towards a.
  out.on_b = -out.tension / length * d;
  return true;
}

// The rotational spring between elements of unit directions uh, wh and inverse lengths
// inv_lu, inv_lw, turn rest_turn at rest: forces on the outer nodes a and c (on b: minus
// their sum), returns nu.
__attribute__((always_inline)) inline double bending_law(double k_rot, double rest_turn, const Vec3 &uh, double inv_lu, const Vec3 &wh,
                                                        double inv_lw, Vec3 &on_a, Vec3 &on_c)
{
  const double cosine = dot3(uh, wh);
  const double sine = length3(uh.cross(wh));
  const double angle = node_angle(sine, cosine);
  // dnu/du = -p_u / |u| and dnu/dw = +p_w / |w| with the unit in-plane perpendiculars
  // p_u = unit(wh - cos uh) (towards w, normal to u) and p_w = unit(uh - cos wh). Both
  // vectors are sin(nu) long, so dividing by the sine from the cross product makes them
  // unit to round-off (1e-16 / sin relative): cheap and exact enough while sin > 1e-6.
  // Closer to 0 or pi each is normalised by its own length, which keeps |F_a| = k nu / |u|
  // exact; at nu == pi exactly every perpendicular is equally steep and unit_or_zero
  // returns zero, the symmetric choice (so does nu == 0 exactly, where a rest turn's cone
  // has its tip). angle - 0.0 is angle: a straight rest shape keeps every bit.
  const double moment = k_rot * (angle - rest_turn);
  Vec3 p_u = wh - cosine * uh, p_w = uh - cosine * wh;
  if (sine > 1e-6) {
    p_u *= 1.0 / sine;
    p_w *= 1.0 / sine;
  } else {
    p_u = unit_or_zero(p_u);
    p_w = unit_or_zero(p_w);
  }
  on_a = -(moment * inv_lu) * p_u;
  on_c = (moment * inv_lw) * p_w;
  return angle;
}

}    // namespace

AxialForces axial_element_forces(const AxialLaw &law, double rest_length, const Vec3 &a,
                                 const Vec3 &b)
{
  check_rest_length(rest_length);
  const Vec3 d = b - a;
  AxialForces out;
  if (axial_law(law, rest_length, d, checked_length(d, "an element"), out)) out.on_a = -out.on_b;
  return out;
}

BendingForces bending_node_forces(double k_rot, const Vec3 &a, const Vec3 &b, const Vec3 &c, double rest_turn)
{
  const Vec3 u = b - a;
  const Vec3 w = c - b;
  const double inv_lu = 1.0 / checked_length(u, "the element before a bent node");
  const double inv_lw = 1.0 / checked_length(w, "the element after a bent node");
  BendingForces out;
  out.angle = bending_law(k_rot, rest_turn, u * inv_lu, inv_lu, w * inv_lw, inv_lw, out.on_a, out.on_c);
  const double bend = out.angle - rest_turn;
  out.energy = 0.5 * k_rot * bend * bend;
  out.on_b = -(out.on_a + out.on_c);
  return out;
}

WireTopology open_chain_topology(int num_nodes, double rest_length)
{
  if (num_nodes < 2) {
    std::ostringstream msg;
    msg << "wire: a chain needs at least 2 nodes, got " << num_nodes;
    throw std::invalid_argument(msg.str());
  }
  WireTopology topology;
  topology.elements.reserve(num_nodes - 1);
  topology.joints.reserve(num_nodes - 2);
  for (int i = 0; i + 1 < num_nodes; ++i) topology.elements.push_back({i, i + 1, rest_length});
  for (int i = 1; i + 1 < num_nodes; ++i) topology.joints.push_back({i - 1, i, i + 1});
  return topology;
}

namespace {

// One element of add_elastic_forces at the given positions, into axial; false for a slack
// string (no force).
__attribute__((always_inline)) inline bool element_law(const WireElement &e, const AxialLaw &law,
                                                       const std::vector<Vec3> &positions, AxialForces &axial)
{
  const Vec3 d = positions[e.b] - positions[e.a];
  return axial_law(law, e.rest_length, d, checked_length(d, "an element"), axial);
}

// One joint of add_elastic_forces (k_rot != 0): forces on a and c (on b: minus their sum),
// returns the node angle.
__attribute__((always_inline)) inline double joint_law(const WireJoint &j, double k_rot, double rest_turn,
                                                       const std::vector<Vec3> &positions, Vec3 &on_a, Vec3 &on_c)
{
  const Vec3 u = positions[j.b] - positions[j.a], w = positions[j.c] - positions[j.b];
  const double inv_lu = 1.0 / checked_length(u, "the element before a bent node");
  const double inv_lw = 1.0 / checked_length(w, "the element after a bent node");
  return bending_law(k_rot, rest_turn, u * inv_lu, inv_lu, w * inv_lw, inv_lw, on_a, on_c);
}

// The kernels' laws, inlined here without their result structs (whose zeroed vectors the
// compiler did not elide: 5 % of fix wire's time went to zeroing them).
template <class LawOf, class StiffnessOf, class RestTurnOf>
ElasticEnergy add_elastic_forces_with(const WireTopology &topology, const LawOf &law_of,
                                      const StiffnessOf &k_rot_of, const RestTurnOf &rest_turn_of,
                                      const std::vector<Vec3> &positions, std::vector<Vec3> &forces)
{
  ElasticEnergy energy;
  AxialForces axial;
  for (const WireElement &e : topology.elements) {
    check_rest_length(e.rest_length);
    if (!element_law(e, law_of(e), positions, axial)) continue;
    forces[e.a] += -axial.on_b;
    forces[e.b] += axial.on_b;
    energy.axial += axial.energy;
  }
  for (const WireJoint &j : topology.joints) {
    const double k_rot = k_rot_of(j);
    if (k_rot == 0.0) continue;    // a string: no bending work
    Vec3 on_a, on_c;
    const double rest_turn = rest_turn_of(j);
    const double bend = joint_law(j, k_rot, rest_turn, positions, on_a, on_c) - rest_turn;
    forces[j.a] += on_a;
    forces[j.b] += -(on_a + on_c);
    forces[j.c] += on_c;
    energy.bending += 0.5 * k_rot * bend * bend;
  }
  return energy;
}

}    // namespace

ElasticEnergy add_elastic_forces(const WireTopology &topology, const AxialLaw &axial,
                                 double k_rot, const std::vector<Vec3> &positions,
                                 std::vector<Vec3> &forces)
{
  return add_elastic_forces_with(
      topology, [&](const WireElement &) { return axial; }, [&](const WireJoint &) { return k_rot; },
      [](const WireJoint &) { return 0.0; }, positions, forces);
}

ElasticEnergy add_elastic_forces(const WireTopology &topology, const std::vector<Vec3> &positions,
                                 std::vector<Vec3> &forces)
{
  return add_elastic_forces_with(
      topology, [](const WireElement &e) { return e.law; }, [](const WireJoint &j) { return j.k_rot; },
      [](const WireJoint &j) { return j.rest_turn; }, positions, forces);
}

/* ---------------------------------------------------------------------- ElasticKernel */

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "two nodes' forces are read as six numbers in a row");

template <int L> using Lanes = Eigen::Array<double, L, 1>;
template <int L> __attribute__((always_inline)) inline Lanes<L> lanes(const double *p) { return Eigen::Map<const Lanes<L>>(p); }
template <int L> __attribute__((always_inline)) inline void put(const Lanes<L> &v, double *p)
{
  Eigen::Map<Lanes<L>> to(p);
  to = v;
}

bool same(const WireElement &p, const WireElement &q)
{
  return p.a == q.a && p.b == q.b && p.rest_length == q.rest_length && p.law.k_elo == q.law.k_elo &&
         p.law.resists_compression == q.law.resists_compression;
}
bool same(const WireJoint &p, const WireJoint &q)
{
  return p.a == q.a && p.b == q.b && p.c == q.c && p.k_rot == q.k_rot && p.rest_turn == q.rest_turn;
}

[[noreturn]] void throw_bad_index(int index)
{
  std::ostringstream msg;
  msg << "wire: node index " << index << " in the topology must be >= 0";
  throw std::invalid_argument(msg.str());
}

}    // namespace

bool ElasticKernel::prepared_for(const WireTopology &topology) const
{
  const auto &e = topology.elements, &f = topology_.elements;
  const auto &j = topology.joints, &k = topology_.joints;
  if (e.size() != f.size() || j.size() != k.size()) return false;
  for (std::size_t i = 0; i < e.size(); ++i)
    if (!same(e[i], f[i])) return false;
  for (std::size_t i = 0; i < j.size(); ++i)
    if (!same(j[i], k[i])) return false;
  return true;
}

void ElasticKernel::prepare(const WireTopology &topology)
{
  topology_ = topology;
  const std::vector<WireElement> &elements = topology_.elements;
  const std::vector<WireJoint> &joints = topology_.joints;
  nodes_ = 0;
  for (const WireElement &e : elements) {
    check_rest_length(e.rest_length);
    if (std::min(e.a, e.b) < 0) throw_bad_index(std::min(e.a, e.b));
    nodes_ = std::max({nodes_, e.a + 1, e.b + 1});
  }
  for (const WireJoint &j : joints) {
    if (std::min({j.a, j.b, j.c}) < 0) throw_bad_index(std::min({j.a, j.b, j.c}));
    nodes_ = std::max({nodes_, j.a + 1, j.b + 1, j.c + 1});
  }
  const int num_elements = static_cast<int>(elements.size()), num_joints = static_cast<int>(joints.size());
  rest_.resize(num_elements);
  k_elo_.resize(num_elements);
  resists_.resize(num_elements);
  for (int e = 0; e < num_elements; ++e) {
    rest_[e] = elements[e].rest_length;
    k_elo_[e] = elements[e].law.k_elo;
    resists_[e] = elements[e].law.resists_compression ? 1.0 : 0.0;
  }
  k_rot_.resize(num_joints);
  rest_turn_.resize(num_joints);
  for (int j = 0; j < num_joints; ++j) {
    k_rot_[j] = joints[j].k_rot;
    rest_turn_[j] = joints[j].rest_turn;
  }

  // Runs of elements (v, v + 1), (v + 1, v + 2), ... one after the other in the list.
  element_runs_.clear();
  single_elements_.clear();
  std::vector<int> element_from(nodes_, -1);    // the element (v, v + 1) by v; -2: more than one
  for (int e = 0; e < num_elements; ++e) {
    const int a = elements[e].a;
    if (elements[e].b != a + 1) {
      single_elements_.push_back(e);
      continue;
    }
    element_from[a] = element_from[a] == -1 ? e : -2;
    Run *last = element_runs_.empty() ? nullptr : &element_runs_.back();
    if (last && last->first + last->count == e && last->first_node + last->count == a) ++last->count;
    else element_runs_.push_back({e, 1, a, -1});
  }
  // Runs of joints (v, v + 1, v + 2), ... whose elements are (v, v + 1) and (v + 1, v + 2).
  joint_runs_.clear();
  single_joints_.clear();
  for (int j = 0; j < num_joints; ++j) {
    const WireJoint &joint = joints[j];
    const bool along = joint.b == joint.a + 1 && joint.c == joint.b + 1;
    const int eu = along ? element_from[joint.a] : -1;
    if (eu < 0 || element_from[joint.b] != eu + 1) {
      single_joints_.push_back(j);
      continue;
    }
    Run *last = joint_runs_.empty() ? nullptr : &joint_runs_.back();
    if (last && last->first + last->count == j && last->first_element + last->count == eu) ++last->count;
    else joint_runs_.push_back({j, 1, joint.a, eu});
  }

  // Each node's terms in add_elastic_forces' order: elements in the list's order, then joints.
  std::vector<std::vector<Share>> terms(nodes_);
  for (int e = 0; e < num_elements; ++e) {
    terms[elements[e].a].push_back({on_a_of_element, e});
    terms[elements[e].b].push_back({on_b_of_element, e});
  }
  for (int j = 0; j < num_joints; ++j) {
    terms[joints[j].a].push_back({on_a_of_joint, j});
    terms[joints[j].b].push_back({on_b_of_joint, j});
    terms[joints[j].c].push_back({on_c_of_joint, j});
  }
  // A node inside a chain: elements e - 1 and e, joints j - 1, j and j + 1 (at v - 1, v, v + 1).
  auto chain_node = [&](int v, int &e, int &j) {
    const std::vector<Share> &t = terms[v];
    if (t.size() != 5 || t[0].part != on_b_of_element || t[2].part != on_c_of_joint) return false;
    e = t[0].index;
    j = t[2].index;
    return t[1].part == on_a_of_element && t[1].index == e + 1 && t[3].part == on_b_of_joint && t[3].index == j + 1 &&
           t[4].part == on_a_of_joint && t[4].index == j + 2;
  };
  node_runs_.clear();
  single_nodes_.clear();
  first_share_.assign(1, 0);
  shares_.clear();
  for (int v = 0; v < nodes_; ++v) {
    int e, j;
    if (chain_node(v, e, j)) {
      NodeRun *last = node_runs_.empty() ? nullptr : &node_runs_.back();
      if (last && last->first_node + last->count == v && last->element + last->count == e &&
          last->joint + last->count == j)
        ++last->count;
      else
        node_runs_.push_back({v, 1, e, j});
      continue;
    }
    if (terms[v].empty()) continue;
    single_nodes_.push_back(v);
    shares_.insert(shares_.end(), terms[v].begin(), terms[v].end());
    first_share_.push_back(static_cast<int>(shares_.size()));
  }

  for (int c = 0; c < 3; ++c) {
    position_[c].resize(nodes_);
    direction_[c].resize(num_elements);
    on_b_[c].resize(num_elements);
    on_a_[c].resize(num_joints);
    on_c_[c].resize(num_joints);
  }
  inverse_length_.resize(num_elements);
  element_energy_.resize(num_elements);
  joint_energy_.resize(num_joints);
}

// The kernel's arrays as plain pointers for the loops (loaded once, kept in registers).
struct ElasticKernel::Columns {
  const double *x[3];
  double *direction[3], *inverse_length, *on_b[3], *on_a[3], *on_c[3];
  const double *rest, *k_elo, *resists, *k_rot, *rest_turn;
  double *element_energy, *joint_energy;    // null: no energies
};

ElasticKernel::Columns ElasticKernel::columns(bool with_energy)
{
  Columns a;
  for (int c = 0; c < 3; ++c) {
    a.x[c] = position_[c].data();
    a.direction[c] = direction_[c].data();
    a.on_b[c] = on_b_[c].data();
    a.on_a[c] = on_a_[c].data();
    a.on_c[c] = on_c_[c].data();
  }
  a.inverse_length = inverse_length_.data();
  a.rest = rest_.data();
  a.k_elo = k_elo_.data();
  a.resists = resists_.data();
  a.k_rot = k_rot_.data();
  a.rest_turn = rest_turn_.data();
  a.element_energy = with_energy ? element_energy_.data() : nullptr;
  a.joint_energy = with_energy ? joint_energy_.data() : nullptr;
  return a;
}

ElasticEnergy ElasticKernel::add_forces(const std::vector<Vec3> &positions, std::vector<Vec3> &forces, bool with_energy)
{
  if (static_cast<int>(std::min(positions.size(), forces.size())) < nodes_) {
    std::ostringstream msg;
    msg << "wire: " << positions.size() << " positions and " << forces.size() << " forces for a topology of "
        << nodes_ << " nodes";
    throw std::invalid_argument(msg.str());
  }
  for (int v = 0; v < nodes_; ++v)
    for (int c = 0; c < 3; ++c) position_[c][v] = positions[v][c];
  elements_in_runs(with_energy);
  for (int e : single_elements_) single_element(e, positions, with_energy);
  joints_in_runs(with_energy);
  for (int j : single_joints_) single_joint(j, positions, with_energy);
  sum_per_node(forces);
  ElasticEnergy energy;
  if (!with_energy) return energy;
  for (double e : element_energy_) energy.axial += e;
  for (double e : joint_energy_) energy.bending += e;
  return energy;
}

namespace {

// axial_law on L elements (v, v + 1) at once (e: the first one's index, v its node a).
// Returns the lengths, for the caller's check that all are finite and > 0.
template <int L, class Columns>
__attribute__((always_inline)) inline Lanes<L> element_lanes(const Columns &a, int e, int v)
{
  using T = Lanes<L>;
  const T dx = lanes<L>(a.x[0] + v + 1) - lanes<L>(a.x[0] + v), dy = lanes<L>(a.x[1] + v + 1) - lanes<L>(a.x[1] + v),
          dz = lanes<L>(a.x[2] + v + 1) - lanes<L>(a.x[2] + v);
  const T length = ((dx * dx + dy * dy) + dz * dz).sqrt();
  const T inverse = 1.0 / length;
  put<L>(inverse, a.inverse_length + e);
  put<L>(dx * inverse, a.direction[0] + e);
  put<L>(dy * inverse, a.direction[1] + e);
  put<L>(dz * inverse, a.direction[2] + e);
  const T rest_length = lanes<L>(a.rest + e), k = lanes<L>(a.k_elo + e);
  const T strain = (length - rest_length) / rest_length;
  const Eigen::Array<bool, L, 1> slack = (strain < 0.0) && (lanes<L>(a.resists + e) == 0.0);
  const T tension = k * strain;
  const T scale = slack.select(T::Zero(), (-tension) / length);
  put<L>(scale * dx, a.on_b[0] + e);
  put<L>(scale * dy, a.on_b[1] + e);
  put<L>(scale * dz, a.on_b[2] + e);
  if (a.element_energy) put<L>(slack.select(T::Zero(), 0.5 * k * rest_length * strain * strain), a.element_energy + e);
  return length;
}

// bending_law on L joints (v, v + 1, v + 2) at once from their elements' directions (j: the
// first joint's index, eu its element (v, v + 1)). Joints off the law's common branch
// (node angle above pi/8 or below 1e-6, or next to these bounds) are done one by one by
// bending_law itself.
template <int L, class Columns> __attribute__((always_inline)) inline void joint_lanes(const Columns &a, int j, int eu)
{
  using T = Lanes<L>;
  const T ux = lanes<L>(a.direction[0] + eu), uy = lanes<L>(a.direction[1] + eu), uz = lanes<L>(a.direction[2] + eu);
  const T wx = lanes<L>(a.direction[0] + eu + 1), wy = lanes<L>(a.direction[1] + eu + 1),
          wz = lanes<L>(a.direction[2] + eu + 1);
  const T cosine = (ux * wx + uy * wy) + uz * wz;
  const T cx = uy * wz - uz * wy, cy = uz * wx - ux * wz, cz = ux * wy - uy * wx;
  const T sine = ((cx * cx + cy * cy) + cz * cz).sqrt();
  const T angle = atan_small<T>(sine / cosine);
  const T k = lanes<L>(a.k_rot + j), rest_turn = lanes<L>(a.rest_turn + j);
  const T bend = angle - rest_turn;
  const T moment = k * bend;
  const T inverse_sine = 1.0 / sine;
  const T scale_a = -(moment * lanes<L>(a.inverse_length + eu)), scale_c = moment * lanes<L>(a.inverse_length + eu + 1);
  put<L>(scale_a * ((wx - cosine * ux) * inverse_sine), a.on_a[0] + j);
  put<L>(scale_a * ((wy - cosine * uy) * inverse_sine), a.on_a[1] + j);
  put<L>(scale_a * ((wz - cosine * uz) * inverse_sine), a.on_a[2] + j);
  put<L>(scale_c * ((ux - cosine * wx) * inverse_sine), a.on_c[0] + j);
  put<L>(scale_c * ((uy - cosine * wy) * inverse_sine), a.on_c[1] + j);
  put<L>(scale_c * ((uz - cosine * wz) * inverse_sine), a.on_c[2] + j);
  if (a.joint_energy) put<L>(0.5 * k * bend * bend, a.joint_energy + j);
  // sine <= tan(pi/8) cosine, cosine > 0 and sine > 1e-6 in every lane (a difference of
  // two numbers has the sign of their difference, so > 0 here is < or > there)
  if ((kTanEighthPi * cosine - sine).min(cosine).min(sine - 1e-6).minCoeff() > 0.0) return;
  for (int l = 0; l < L; ++l) {
    Vec3 on_a, on_c;
    const double nu = bending_law(k[l], rest_turn[l],
                                  Vec3(a.direction[0][eu + l], a.direction[1][eu + l], a.direction[2][eu + l]),
                                  a.inverse_length[eu + l],
                                  Vec3(a.direction[0][eu + l + 1], a.direction[1][eu + l + 1], a.direction[2][eu + l + 1]),
                                  a.inverse_length[eu + l + 1], on_a, on_c);
    for (int d = 0; d < 3; ++d) {
      a.on_a[d][j + l] = on_a[d];
      a.on_c[d][j + l] = on_c[d];
    }
    if (a.joint_energy) a.joint_energy[j + l] = 0.5 * k[l] * (nu - rest_turn[l]) * (nu - rest_turn[l]);
  }
}

}    // namespace

void ElasticKernel::elements_in_runs(bool with_energy)
{
  const Columns a = columns(with_energy);
  // Lengths finite and > 0 (checked once at the end: 0 * length is NaN for inf or NaN)
  Lanes<2> shortest = Lanes<2>::Constant(1.0), nan = Lanes<2>::Zero();
  for (const Run &run : element_runs_) {
    int m = 0;
    for (; m + 2 <= run.count; m += 2) {
      const Lanes<2> length = element_lanes<2>(a, run.first + m, run.first_node + m);
      shortest = shortest.min(length);
      nan += 0.0 * length;
    }
    for (; m < run.count; ++m) {
      const double length = element_lanes<1>(a, run.first + m, run.first_node + m)[0];
      shortest[0] = std::min(shortest[0], length);
      nan[0] += 0.0 * length;
    }
  }
  if (shortest.minCoeff() > 0.0 && nan.sum() == 0.0) return;
  for (const Run &run : element_runs_)    // throws for the first bad element
    for (int m = 0; m < run.count; ++m) {
      const int v = run.first_node + m;
      checked_length(Vec3(a.x[0][v + 1] - a.x[0][v], a.x[1][v + 1] - a.x[1][v], a.x[2][v + 1] - a.x[2][v]), "an element");
    }
}

void ElasticKernel::joints_in_runs(bool with_energy)
{
  const Columns a = columns(with_energy);
  for (const Run &run : joint_runs_) {
    int m = 0;
    for (; m + 2 <= run.count; m += 2) joint_lanes<2>(a, run.first + m, run.first_element + m);
    for (; m < run.count; ++m) joint_lanes<1>(a, run.first + m, run.first_element + m);
  }
}

void ElasticKernel::single_element(int e, const std::vector<Vec3> &positions, bool with_energy)
{
  const WireElement &element = topology_.elements[e];
  AxialForces axial;
  const bool acts = element_law(element, element.law, positions, axial);
  for (int c = 0; c < 3; ++c) on_b_[c][e] = acts ? axial.on_b[c] : 0.0;
  if (with_energy) element_energy_[e] = acts ? axial.energy : 0.0;
}

void ElasticKernel::single_joint(int j, const std::vector<Vec3> &positions, bool with_energy)
{
  const WireJoint &joint = topology_.joints[j];
  Vec3 a = Vec3::Zero(), c = Vec3::Zero();
  double bend = 0.0;
  if (joint.k_rot != 0.0) bend = joint_law(joint, joint.k_rot, joint.rest_turn, positions, a, c) - joint.rest_turn;    // else a string
  for (int d = 0; d < 3; ++d) {
    on_a_[d][j] = a[d];
    on_c_[d][j] = c[d];
  }
  if (with_energy) joint_energy_[j] = 0.5 * joint.k_rot * bend * bend;
}

Vec3 ElasticKernel::share(const Share &s) const
{
  const int i = s.index;
  switch (s.part) {
    case on_a_of_element: return -Vec3(on_b_[0][i], on_b_[1][i], on_b_[2][i]);
    case on_b_of_element: return Vec3(on_b_[0][i], on_b_[1][i], on_b_[2][i]);
    case on_a_of_joint: return Vec3(on_a_[0][i], on_a_[1][i], on_a_[2][i]);
    case on_b_of_joint: return -(Vec3(on_a_[0][i], on_a_[1][i], on_a_[2][i]) + Vec3(on_c_[0][i], on_c_[1][i], on_c_[2][i]));
    case on_c_of_joint: return Vec3(on_c_[0][i], on_c_[1][i], on_c_[2][i]);
  }
  return Vec3::Zero();
}

namespace {

// One coordinate of the forces on L nodes inside a chain: elements e - 1 and e, joints j - 1,
// j and j + 1 of the first node (e and j of the first node here: e, e + 1, j, j + 1, j + 2).
template <int L>
__attribute__((always_inline)) inline Lanes<L> chain_node_sum(Lanes<L> sum, const double *on_b, const double *on_a,
                                                              const double *on_c, int e, int j)
{
  sum += lanes<L>(on_b + e);
  sum += -lanes<L>(on_b + e + 1);
  sum += lanes<L>(on_c + j);
  sum += -(lanes<L>(on_a + j + 1) + lanes<L>(on_c + j + 1));
  sum += lanes<L>(on_a + j + 2);
  return sum;
}

}    // namespace

// Each node's terms added in add_elastic_forces' order: for a node inside a chain, elements
// (v - 1, v) and (v, v + 1), then the joints at v - 1, v and v + 1.
void ElasticKernel::sum_per_node(std::vector<Vec3> &forces) const
{
  const double *on_b[3] = {on_b_[0].data(), on_b_[1].data(), on_b_[2].data()};
  const double *on_a[3] = {on_a_[0].data(), on_a_[1].data(), on_a_[2].data()};
  const double *on_c[3] = {on_c_[0].data(), on_c_[1].data(), on_c_[2].data()};
  for (const NodeRun &run : node_runs_) {
    int k = 0;
    for (; k + 2 <= run.count; k += 2) {    // two nodes: their 6 numbers by coordinate and back
      double *f = forces[run.first_node + k].data();
      const Lanes<2> first = lanes<2>(f), middle = lanes<2>(f + 2), last = lanes<2>(f + 4);
      const int e = run.element + k, j = run.joint + k;
      const Lanes<2> x = chain_node_sum<2>(Lanes<2>(first[0], middle[1]), on_b[0], on_a[0], on_c[0], e, j);
      const Lanes<2> y = chain_node_sum<2>(Lanes<2>(first[1], last[0]), on_b[1], on_a[1], on_c[1], e, j);
      const Lanes<2> z = chain_node_sum<2>(Lanes<2>(middle[0], last[1]), on_b[2], on_a[2], on_c[2], e, j);
      put<2>(Lanes<2>(x[0], y[0]), f);
      put<2>(Lanes<2>(z[0], x[1]), f + 2);
      put<2>(Lanes<2>(y[1], z[1]), f + 4);
    }
    for (; k < run.count; ++k) {
      double *f = forces[run.first_node + k].data();
      for (int c = 0; c < 3; ++c)
        f[c] = chain_node_sum<1>(Lanes<1>::Constant(f[c]), on_b[c], on_a[c], on_c[c], run.element + k, run.joint + k)[0];
    }
  }
  for (std::size_t n = 0; n < single_nodes_.size(); ++n) {
    Vec3 &f = forces[single_nodes_[n]];
    for (int s = first_share_[n]; s < first_share_[n + 1]; ++s) f += share(shares_[s]);
  }
}

}    // namespace nscd::wire
