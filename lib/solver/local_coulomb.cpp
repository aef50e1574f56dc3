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

#include "solver/local_coulomb.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>

namespace nscd {
namespace {

using Complex = std::complex<double>;

// g(phi) = a0 + a1 cos(phi) + b1 sin(phi) + a2 cos(2 phi) + b2 sin(2 phi)
struct TrigPolynomial2 {
  double a0 = 0, a1 = 0, b1 = 0, a2 = 0, b2 = 0;

  // From c = cos(phi), s = sin(phi): one sine and cosine per evaluation.
  double value(double c, double s) const
  {
    return a0 + a1 * c + b1 * s + a2 * (c * c - s * s) + b2 * 2.0 * s * c;
  }
  double derivative(double c, double s) const
  {
    return -a1 * s + b1 * c - 4.0 * a2 * s * c + 2.0 * b2 * (c * c - s * s);
  }
  double value(double phi) const { return value(std::cos(phi), std::sin(phi)); }
  double derivative(double phi) const { return derivative(std::cos(phi), std::sin(phi)); }
};

// Sliding along s = (c, s) means P = P_n d with d = (1, -mu c, -mu s). The normal row of
// u = W P + a with u_n = 0 gives P_n = -a_n / D, D = (W d)_n. The tangential velocity
// u_t = P_n (W d)_t + a_t must be parallel to s: s_perp . u_t = 0 with s_perp = (-s, c).
// Multiplied by D this is  -a_n s_perp.(W d)_t + D s_perp.a_t = 0, whose expansion in
// c, s is quadratic; rewritten with double angles it gives these Fourier coefficients.
TrigPolynomial2 slip_direction_condition(const Mat3 &W, const Vec3 &a, double mu)
{
  TrigPolynomial2 g;
  g.a0 = 0.5 * mu * (W(0, 2) * a[1] - W(0, 1) * a[2]);
  g.a1 = W(0, 0) * a[2] - a[0] * W(2, 0);
  g.b1 = a[0] * W(1, 0) - W(0, 0) * a[1];
  g.a2 = mu * (a[0] * W(1, 2) - 0.5 * (W(0, 1) * a[2] + W(0, 2) * a[1]));
  g.b2 = 0.5 * mu * (a[0] * (W(2, 2) - W(1, 1)) + W(0, 1) * a[1] - W(0, 2) * a[2]);
  return g;
}

// A slip direction (cos phi, sin phi) in the tangent plane.
struct Direction {
  double c = 1.0, s = 0.0;
};
using Directions = std::array<Direction, 4>;

// Real roots of g on [0, 2 pi): with z = exp(i phi), z^2 g(phi) is a polynomial of degree
// 4 in z whose roots on the unit circle are the wanted angles. Its coefficients are
// conjugate-symmetric, so the degree drops to 2 exactly when a2 = b2 = 0 (the common case
// of a contact whose lever arms are parallel to the normal, e.g. spheres).
int candidate_slip_angles(const TrigPolynomial2 &g, std::array<double, 4> &angles)
{
  const Complex i(0.0, 1.0);
  const Complex c4 = 0.5 * (g.a2 - i * g.b2);
  const Complex c3 = 0.5 * (g.a1 - i * g.b1);
  const Complex c2 = g.a0;
  const Complex c1 = std::conj(c3);
  const double scale = std::max({std::abs(c4), std::abs(c3), std::abs(c2)});
  if (scale == 0.0) return 0;

  std::array<Complex, 4> roots;
  int n_roots = 0;
  constexpr double negligible = 1e-13;
  if (std::abs(c4) > negligible * scale) {
    Eigen::Matrix4cd companion = Eigen::Matrix4cd::Zero();
    companion(1, 0) = companion(2, 1) = companion(3, 2) = 1.0;
    const Complex c0 = std::conj(c4);
    companion(0, 3) = -c0 / c4;
    companion(1, 3) = -c1 / c4;
    companion(2, 3) = -c2 / c4;
    companion(3, 3) = -c3 / c4;
    const Eigen::ComplexEigenSolver<Eigen::Matrix4cd> solver(companion, false);
    for (int k = 0; k < 4; ++k) roots[n_roots++] = solver.eigenvalues()[k];
  } else if (std::abs(c3) > negligible * scale) {
    // c3 z^2 + c2 z + c1 = 0
    const Complex root_disc = std::sqrt(c2 * c2 - 4.0 * c3 * c1);
    roots[n_roots++] = (-c2 + root_disc) / (2.0 * c3);
    roots[n_roots++] = (-c2 - root_disc) / (2.0 * c3);
  }

  int n_angles = 0;
  for (int k = 0; k < n_roots; ++k) {
    // A loose test: a double root splits off the circle by ~sqrt(eps); Newton and the
    // admissibility test below decide.
    if (std::abs(std::abs(roots[k]) - 1.0) < 1e-3) angles[n_angles++] = std::arg(roots[k]);
  }
  return n_angles;
}

// The direction `from` turned by psi, given as t = tan(psi / 2): cos psi = (1 - t^2) / (1 + t^2),
// sin psi = 2 t / (1 + t^2), no sine or cosine evaluated.
Direction turn(Direction from, double t)
{
  const double scale = 1.0 / (1.0 + t * t);
  const double cos_psi = (1.0 - t * t) * scale, sin_psi = 2.0 * t * scale;
  return Direction{from.c * cos_psi - from.s * sin_psi, from.s * cos_psi + from.c * sin_psi};
}

// Fast path: sign changes of g on 16 sample angles bracket its simple roots, each refined
// by Newton safeguarded with bisection. Roots closer together than the sample spacing
// (near-tangent cases) can be missed; the caller then falls back to the companion matrix.
// No sine or cosine is evaluated here (they were 16 % of a sliding wire run): within a
// bracket, phi = middle + psi with t = tan(psi / 2), and the direction is the middle's
// turned by cos psi = (1 - t^2) / (1 + t^2), sin psi = 2 t / (1 + t^2); Newton runs on t.
int bracketed_slip_directions(const TrigPolynomial2 &g, Directions &directions)
{
  constexpr int n_samples = 16;
  constexpr double spacing = 2.0 * 3.14159265358979323846 / n_samples;
  struct Samples {
    std::array<Direction, n_samples> at, middle;    // at k spacing and (k + 1/2) spacing
    double t_edge;                                  // tan(spacing / 4): t at a bracket's ends
  };
  static const Samples samples = [] {
    Samples table;
    for (int k = 0; k < n_samples; ++k) {
      table.at[k] = {std::cos(k * spacing), std::sin(k * spacing)};
      table.middle[k] = {std::cos((k + 0.5) * spacing), std::sin((k + 0.5) * spacing)};
    }
    table.t_edge = std::tan(0.25 * spacing);
    return table;
  }();
  std::array<double, n_samples + 1> values;
  for (int k = 0; k < n_samples; ++k) values[k] = g.value(samples.at[k].c, samples.at[k].s);
  values[n_samples] = values[0];

  int n_found = 0;
  for (int k = 0; k < n_samples && n_found < 4; ++k) {
    if (values[k] == 0.0) {
      directions[n_found++] = samples.at[k];
      continue;
    }
    if ((values[k] > 0.0) == (values[k + 1] > 0.0) || values[k + 1] == 0.0) continue;
    const Direction middle = samples.middle[k];
    double low = -samples.t_edge, high = samples.t_edge;
    const bool rising = values[k] < 0.0;
    // Start from the secant through the bracket ends (closer than the middle): psi / 2 is
    // within the bracket as |psi / 2| < tan(spacing / 4).
    double t = 0.5 * spacing * (values[k] / (values[k] - values[k + 1]) - 0.5);
    Direction d = turn(middle, t);
    for (int iteration = 0; iteration < 60; ++iteration) {
      const double value = g.value(d.c, d.s);
      if (value == 0.0) break;
      if ((value < 0.0) == rising) low = t; else high = t;
      const double slope = g.derivative(d.c, d.s) * 2.0 / (1.0 + t * t);    // dg/dt
      const double newton_step = slope != 0.0 ? -value / slope : high - low;
      if (std::abs(newton_step) <= 0.5e-15) {
        d = turn(middle, t + newton_step);    // converged: the step is below round-off of phi
        break;
      }
      const double next = t + newton_step;
      t = next > low && next < high ? next : 0.5 * (low + high);
      d = turn(middle, t);
    }
    directions[n_found++] = d;
  }
  return n_found;
}

// Newton on g from a guessed direction (the contact's slip direction of the sweep before),
// on t = tan(psi / 2) with phi = guess + psi as in bracketed_slip_directions. False if an
// iterate leaves |psi| < pi / 2 or 8 iterations do not converge: the caller then samples.
bool slip_direction_near(const TrigPolynomial2 &g, Direction guess, Direction &d)
{
  double t = 0.0;
  d = guess;
  for (int iteration = 0; iteration < 8; ++iteration) {
    const double value = g.value(d.c, d.s);
    if (value == 0.0) return true;
    const double slope = g.derivative(d.c, d.s) * 2.0 / (1.0 + t * t);    // dg/dt
    if (slope == 0.0) return false;
    const double newton_step = -value / slope;
    t += newton_step;
    if (!(std::abs(t) < 1.0)) return false;
    d = turn(guess, t);
    if (std::abs(newton_step) <= 0.5e-15) return true;
  }
  return false;
}

double polish_root(const TrigPolynomial2 &g, double phi)
{
  for (int iteration = 0; iteration < 12; ++iteration) {
    const double slope = g.derivative(phi);
    if (slope == 0.0) break;
    const double step = g.value(phi) / slope;
    phi -= step;
    if (std::abs(step) < 1e-15) break;
  }
  return phi;
}

// |(x_1, x_2)|: sqrt of the sum of squares, not std::hypot (whose overflow and underflow
// guards cost ~10 ns a call; impulses and velocities are far from 1e+-154).
inline double tangential_norm(const Vec3 &x) { return std::sqrt(x[1] * x[1] + x[2] * x[2]); }

struct SlipCandidate {
  Vec3 impulse;
  bool admissible = false;
};

// Checks the sliding conditions along direction (c, s): D > 0 (so P_n > 0), u_t parallel
// to it and pointing along it (slip velocity sigma >= 0, up to round-off).
SlipCandidate evaluate_slip(const Mat3 &W, const Vec3 &a, double mu, Direction d)
{
  const double c = d.c, s = d.s;
  const Vec3 direction(1.0, -mu * c, -mu * s);
  const Vec3 W_direction = W * direction;
  SlipCandidate candidate;
  if (!(W_direction[0] > 0.0)) return candidate;
  const double normal_impulse = -a[0] / W_direction[0];
  if (!(normal_impulse > 0.0)) return candidate;
  const double ut1 = normal_impulse * W_direction[1] + a[1];
  const double ut2 = normal_impulse * W_direction[2] + a[2];
  const double velocity_scale = a.norm();
  const double tolerance = 1e-9 * velocity_scale;
  const double slip_speed = c * ut1 + s * ut2;
  const double off_direction = -s * ut1 + c * ut2;
  candidate.impulse = normal_impulse * direction;
  candidate.admissible = slip_speed >= -tolerance && std::abs(off_direction) <= tolerance;
  return candidate;
}

// The admissible slip solution with the smallest normal impulse among the given
// directions; returns false if none is admissible.
bool best_slip(const Mat3 &W, const Vec3 &u_free, double mu, const Directions &directions,
               int n_directions, Vec3 &impulse)
{
  double best_normal = std::numeric_limits<double>::infinity();
  for (int k = 0; k < n_directions; ++k) {
    const SlipCandidate candidate = evaluate_slip(W, u_free, mu, directions[k]);
    if (candidate.admissible && candidate.impulse[0] < best_normal) {
      best_normal = candidate.impulse[0];
      impulse = candidate.impulse;
    }
  }
  return !std::isinf(best_normal);
}

LocalSolution solve_slip(const Mat3 &W, const Mat3 &W_inverse, const Vec3 &u_free, double mu,
                         const Vec3 *slip_guess)
{
  const TrigPolynomial2 g = slip_direction_condition(W, u_free, mu);
  LocalSolution best;
  best.regime = ContactRegime::slip;
  if (slip_guess != nullptr) {
    // The guess is an impulse P = P_n (1, -mu s): s is along -P_t.
    const double tangential = tangential_norm(*slip_guess);
    Direction near;
    if (tangential > 0.0 &&
        slip_direction_near(g, {-(*slip_guess)[1] / tangential, -(*slip_guess)[2] / tangential}, near)) {
      const SlipCandidate candidate = evaluate_slip(W, u_free, mu, near);
      if (candidate.admissible) {
        best.impulse = candidate.impulse;
        return best;
      }
    }
  }
  Directions directions;
  int n_directions = bracketed_slip_directions(g, directions);
  if (best_slip(W, u_free, mu, directions, n_directions, best.impulse)) return best;

  // Fallback (near-tangent roots): all roots from the companion matrix, polished.
  std::array<double, 4> angles;
  n_directions = candidate_slip_angles(g, angles);
  for (int k = 0; k < n_directions; ++k) {
    const double phi = polish_root(g, angles[k]);
    directions[k] = {std::cos(phi), std::sin(phi)};
  }
  if (!best_slip(W, u_free, mu, directions, n_directions, best.impulse)) {
    best.impulse = project_on_coulomb_cone(-(W_inverse * u_free), mu);
    best.exact = false;
  }
  return best;
}

}    // namespace

LocalSolution solve_local_coulomb(const Mat3 &W, const Mat3 &W_inverse, const Vec3 &u_free,
                                  double mu, const Vec3 *slip_guess)
{
  LocalSolution solution;
  if (u_free[0] >= 0.0) return solution;    // separating: open, P = 0

  if (mu == 0.0) {
    // Frictionless: the tangential velocity is free, only the normal row matters.
    solution.impulse = Vec3(-u_free[0] / W(0, 0), 0.0, 0.0);
    solution.regime = ContactRegime::slip;
    return solution;
  }

  const Vec3 stick = -(W_inverse * u_free);
  // |P_t| <= mu P_n compared squared: no hypot (its overflow guard costs ~10 ns here).
  if (stick[0] > 0.0 &&
      stick[1] * stick[1] + stick[2] * stick[2] <= (mu * stick[0]) * (mu * stick[0])) {
    solution.impulse = stick;
    solution.regime = ContactRegime::stick;
    return solution;
  }
  return solve_slip(W, W_inverse, u_free, mu, slip_guess);
}

Vec3 project_on_coulomb_cone(const Vec3 &x, double mu)
{
  const double tangential = tangential_norm(x);
  // x[0] >= 0 matters for mu = 0 only: with no tangential part, 0 <= 0 * x[0] holds for a
  // negative x[0] too, and that x is not on the cone (the ray P_t = 0, P_n >= 0).
  if (x[0] >= 0.0 && tangential <= mu * x[0]) return x;
  if (mu * tangential <= -x[0]) return Vec3::Zero();
  const double normal = (x[0] + mu * tangential) / (1.0 + mu * mu);
  const double ratio = mu * normal / tangential;
  return Vec3(normal, ratio * x[1], ratio * x[2]);
}

double coulomb_residual(const Mat3 &W, const Vec3 &u_free, double mu, const Vec3 &P, double s)
{
  const Vec3 u = W * P + u_free;
  const Vec3 u_hat(u[0] + mu * tangential_norm(u), u[1], u[2]);
  const Vec3 Q = s * P;
  return (Q - project_on_coulomb_cone(Q - u_hat, mu)).norm();
}

}    // namespace nscd
