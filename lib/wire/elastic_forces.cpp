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

// The check is inline and the message out of line: these kernels run every substep.
inline double checked_length(const Vec3 &d, const char *what)
{
  const double length = d.norm();
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
// from tools/wire_atan_coefficients.py: error within 1.02 x 2^-53 of atan(y)).
__attribute__((always_inline)) inline double atan_small(double y)
{
  static constexpr double c[] = {-0.3333333333333333,   0.1999999999999552,   -0.14285714284666542,
                                 0.11111111015256361,   -0.09090904578123903, 0.07692183190826087,
                                 -0.06664511447381948,  0.0585814891280221,   -0.0508544973794026,
                                 0.03923165829558719,   -0.01917688711906226};
  // Estrin's scheme: a quarter of Horner's chain of dependent operations.
  const double z = y * y, z2 = z * z, z4 = z2 * z2, z8 = z4 * z4;
  const double p01 = c[0] + c[1] * z, p23 = c[2] + c[3] * z, p45 = c[4] + c[5] * z, p67 = c[6] + c[7] * z,
               p89 = c[8] + c[9] * z;
  const double p = (p01 + p23 * z2) + (p45 + p67 * z2) * z4 + (p89 + c[10] * z2) * z8;
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
  if (s <= t * c) return c > 0.0 ? atan_small(s / c) : 0.0;    // (0, 0) -> 0, as atan2
  if (t * s <= c) return kQuarterPiHi + (kQuarterPiLo + atan_small((s - c) / (s + c)));
  if (-t * s <= c) return kHalfPiHi + (kHalfPiLo - atan_small(c / s));
  if (-t * c <= s) return kThreeQuarterPiHi + (kThreeQuarterPiLo + atan_small((s + c) / (c - s)));
  return kPiHi + (kPiLo - atan_small(s / -c));
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
// inv_lu, inv_lw: forces on the outer nodes a and c (on b: minus their sum), returns nu.
__attribute__((always_inline)) inline double bending_law(double k_rot, const Vec3 &uh, double inv_lu, const Vec3 &wh, double inv_lw, Vec3 &on_a,
                          Vec3 &on_c)
{
  const double cosine = uh.dot(wh);
  const double sine = uh.cross(wh).norm();
  const double angle = node_angle(sine, cosine);
  // dnu/du = -p_u / |u| and dnu/dw = +p_w / |w| with the unit in-plane perpendiculars
  // p_u = unit(wh - cos uh) (towards w, normal to u) and p_w = unit(uh - cos wh). Both
  // vectors are sin(nu) long, so dividing by the sine from the cross product makes them
  // unit to round-off (1e-16 / sin relative): cheap and exact enough while sin > 1e-6.
  // Closer to 0 or pi each is normalised by its own length, which keeps |F_a| = k nu / |u|
  // exact; at nu == pi exactly every perpendicular is equally steep and unit_or_zero
  // returns zero, the symmetric choice.
  const double moment = k_rot * angle;
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

BendingForces bending_node_forces(double k_rot, const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
  const Vec3 u = b - a;
  const Vec3 w = c - b;
  const double inv_lu = 1.0 / checked_length(u, "the element before a bent node");
  const double inv_lw = 1.0 / checked_length(w, "the element after a bent node");
  BendingForces out;
  out.angle = bending_law(k_rot, u * inv_lu, inv_lu, w * inv_lw, inv_lw, out.on_a, out.on_c);
  out.energy = 0.5 * k_rot * out.angle * out.angle;
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

// The kernels' laws, inlined here without their result structs (whose zeroed vectors the
// compiler did not elide: 5 % of fix wire's time went to zeroing them).
template <class LawOf, class StiffnessOf>
ElasticEnergy add_elastic_forces_with(const WireTopology &topology, const LawOf &law_of,
                                      const StiffnessOf &k_rot_of, const std::vector<Vec3> &positions,
                                      std::vector<Vec3> &forces)
{
  ElasticEnergy energy;
  AxialForces axial;
  for (const WireElement &e : topology.elements) {
    check_rest_length(e.rest_length);
    const Vec3 d = positions[e.b] - positions[e.a];
    if (!axial_law(law_of(e), e.rest_length, d, checked_length(d, "an element"), axial)) continue;
    forces[e.a] += -axial.on_b;
    forces[e.b] += axial.on_b;
    energy.axial += axial.energy;
  }
  for (const WireJoint &j : topology.joints) {
    const double k_rot = k_rot_of(j);
    if (k_rot == 0.0) continue;    // a string: no bending work
    const Vec3 u = positions[j.b] - positions[j.a], w = positions[j.c] - positions[j.b];
    const double inv_lu = 1.0 / checked_length(u, "the element before a bent node");
    const double inv_lw = 1.0 / checked_length(w, "the element after a bent node");
    Vec3 on_a, on_c;
    const double angle = bending_law(k_rot, u * inv_lu, inv_lu, w * inv_lw, inv_lw, on_a, on_c);
    forces[j.a] += on_a;
    forces[j.b] += -(on_a + on_c);
    forces[j.c] += on_c;
    energy.bending += 0.5 * k_rot * angle * angle;
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
      positions, forces);
}

ElasticEnergy add_elastic_forces(const WireTopology &topology, const std::vector<Vec3> &positions,
                                 std::vector<Vec3> &forces)
{
  return add_elastic_forces_with(
      topology, [](const WireElement &e) { return e.law; }, [](const WireJoint &j) { return j.k_rot; },
      positions, forces);
}

}    // namespace nscd::wire
