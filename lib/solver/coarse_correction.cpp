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

// Coarse correction of the contact impulses (ContactProblem::coarse_correction), see
// doc/Howto_nscd_solver.rst, "Coarse correction".
//
// Gauss-Seidel moves load along a column or under a heavy plate by one contact per sweep,
// so its error there is a smooth change of the normal impulses over many contacts. The
// coarse step corrects such changes in one go: contacts are grouped by position (cubic
// cells), and every group of loaded contacts gets two unknowns, a factor on its normal
// impulses (keeps the group's load pattern, changes its size) and a uniform normal
// increment (changes the pattern; taken out where it nearly repeats the factor). The
// unknowns minimise the energy 1/2 P^T W P + P^T u_free of the problem along these
// directions, a small dense system; friction impulses are kept and every impulse is
// projected onto its cone afterwards.
#include "solver/contact_problem.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace nscd {
namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;

// Below this relative pivot (after Jacobi scaling) a coarse direction is a state of
// self-stress (impulses that move no body), which the energy does not fix and a solve
// would blow up; it is left out. Long-wavelength modes are far above it (a column of n
// grains under a plate of mass ratio R: about 1 / (2 n R)).
constexpr double kSelfStressPivot = 1e-10;

// An increment that is this close (sin^2 of the angle) to the group's factor direction is
// dropped: the two would be nearly the same unknown.
constexpr double kDependentDirections = 1e-2;

// One coarse unknown's generalized impulse (force, torque; world frame) on one body.
struct UnknownOnBody {
  int body;
  int unknown;
  Vec6 g;
};

Vec6 generalized(const Mat3 &frame, const Mat3 &angular, const Vec3 &local)
{
  Vec6 out;
  out.head<3>() = frame.transpose() * local;
  out.tail<3>() = angular.transpose() * local;
  return out;
}

// Solves A x = b for symmetric positive semidefinite A with the pseudo-inverse of its
// pivoted LDLT factor (pivots below kSelfStressPivot count as zero).
Eigen::VectorXd solve_semidefinite(const Eigen::MatrixXd &A, const Eigen::VectorXd &b)
{
  const Eigen::Index n = A.rows();
  Eigen::VectorXd scale(n);
  for (Eigen::Index k = 0; k < n; ++k) scale[k] = A(k, k) > 0.0 ? 1.0 / std::sqrt(A(k, k)) : 0.0;
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(scale.asDiagonal() * A * scale.asDiagonal());
  Eigen::VectorXd x = ldlt.transpositionsP() * scale.cwiseProduct(b);
  ldlt.matrixL().solveInPlace(x);
  const Eigen::VectorXd d = ldlt.vectorD();
  const double largest = d.cwiseAbs().maxCoeff();
  for (Eigen::Index k = 0; k < n; ++k) x[k] = d[k] > kSelfStressPivot * largest ? x[k] / d[k] : 0.0;
  ldlt.matrixU().solveInPlace(x);
  x = ldlt.transpositionsP().transpose() * x;
  return scale.cwiseProduct(x);
}

// Minimises 1/2 y^T K y + r^T y subject to y_k >= lower_k: solve with the free unknowns,
// fix those below their bound at it, repeat (a few rounds; the bounds rarely bind).
Eigen::VectorXd minimise_bounded(const Eigen::MatrixXd &K, const Eigen::VectorXd &r,
                                 const std::vector<double> &lower)
{
  constexpr int kRounds = 4;
  const int m = static_cast<int>(r.size());
  std::vector<bool> fixed(m, false);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(m);
  for (int round = 0; round < kRounds; ++round) {
    std::vector<int> free;
    for (int k = 0; k < m; ++k)
      if (!fixed[k]) free.push_back(k);
    const int n = static_cast<int>(free.size());
    Eigen::MatrixXd A(n, n);
    Eigen::VectorXd b(n);
    for (int a = 0; a < n; ++a) {
      b[a] = -r[free[a]];
      for (int k = 0; k < m; ++k)
        if (fixed[k]) b[a] -= K(free[a], k) * y[k];
      for (int c = 0; c < n; ++c) A(a, c) = K(free[a], free[c]);
    }
    const Eigen::VectorXd x = n > 0 ? solve_semidefinite(A, b) : Eigen::VectorXd();
    bool changed = false;
    for (int a = 0; a < n; ++a) {
      y[free[a]] = x[a];
      if (!(x[a] >= lower[free[a]])) {
        fixed[free[a]] = true;
        y[free[a]] = lower[free[a]];
        changed = true;
      }
    }
    if (!changed) break;
  }
  return y;
}

}    // namespace

void ContactProblem::build_groups()
{
  group_.assign(rows_.size(), 0);
  group_count_ = 0;
  if (!(options_.coarse_cell > 0.0) || rows_.empty()) return;
  double lever = 0.0;
  for (const Contact &contact : contacts)
    lever += (contact.point - bodies[contact.body_i].position).norm();
  double size = options_.coarse_cell * 2.0 * lever / static_cast<double>(contacts.size());
  // Cells twice as wide (an eighth as many) until there are at most kMaxCoarseGroups.
  while (group_contacts_by_cell(size) > kMaxCoarseGroups && size > 0.0) size *= 2.0;
}

int ContactProblem::group_contacts_by_cell(double size)
{
  using Cell = std::array<long, 3>;
  std::vector<std::pair<Cell, int>> cells(contacts.size());
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    Cell cell = {0, 0, 0};
    if (size > 0.0)
      for (int d = 0; d < 3; ++d) cell[d] = static_cast<long>(std::floor(contacts[c].point[d] / size));
    cells[c] = {cell, static_cast<int>(c)};
  }
  std::sort(cells.begin(), cells.end());
  group_count_ = 0;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (k > 0 && cells[k].first != cells[k - 1].first) ++group_count_;
    group_[cells[k].second] = group_count_;
  }
  return ++group_count_;
}

void ContactProblem::coarse_correction()
{
  if (group_count_ == 0) return;
  const auto loaded = [&](std::size_t c) {
    return !rows_[c].inert && rows_[c].impulse[0] > 0.0;
  };
  // Per group: the factor direction s_c = (P_n, 0, 0), the increment direction
  // a_c = (1, 0, 0) - alpha s_c, alpha chosen so that sum_c a_c . s_c = 0.
  std::vector<double> ss(group_count_, 0.0), as(group_count_, 0.0), aa(group_count_, 0.0);
  for (std::size_t c = 0; c < rows_.size(); ++c) {
    if (!loaded(c)) continue;
    const double normal = rows_[c].impulse[0];
    ss[group_[c]] += normal * normal;
    as[group_[c]] += normal;
    aa[group_[c]] += 1.0;
  }
  std::vector<double> alpha(group_count_, 0.0);
  std::vector<int> first_unknown(group_count_, -1), unknowns(group_count_, 0);
  std::vector<double> lower;
  int m = 0;
  for (int g = 0; g < group_count_; ++g) {
    if (!(ss[g] > 0.0)) continue;
    alpha[g] = as[g] / ss[g];
    const bool increment = 1.0 - as[g] * as[g] / (aa[g] * ss[g]) > kDependentDirections;
    first_unknown[g] = m;
    unknowns[g] = increment ? 2 : 1;
    lower.push_back(-1.0);    // the factor keeps P_n >= 0
    if (increment) lower.push_back(-std::numeric_limits<double>::infinity());
    m += unknowns[g];
  }
  if (m == 0) return;
  const auto direction = [&](std::size_t c, int which) {
    const int g = group_[c];
    const double normal = rows_[c].impulse[0];
    return Vec3(which == 0 ? normal : 1.0 - alpha[g] * normal, 0.0, 0.0);
  };

  // K = Phi^T W Phi through the bodies (W = J M^-1 J^T), r = Phi^T u.
  std::vector<UnknownOnBody> entries;
  Eigen::VectorXd r = Eigen::VectorXd::Zero(m);
  for (std::size_t c = 0; c < rows_.size(); ++c) {
    if (!loaded(c)) continue;
    const Row &row = rows_[c];
    const Vec3 u = local_velocity(row);
    const int g = group_[c];
    for (int which = 0; which < unknowns[g]; ++which) {
      const int k = first_unknown[g] + which;
      const Vec3 phi = direction(c, which);
      r[k] += phi.dot(u);
      entries.push_back({row.i, k, generalized(row.frame, row.angular_i, phi)});
      if (row.j != kEnvironment)
        entries.push_back({row.j, k, -generalized(row.frame, row.angular_j, phi)});
    }
  }
  std::sort(entries.begin(), entries.end(), [](const UnknownOnBody &a, const UnknownOnBody &b) {
    return a.body != b.body ? a.body < b.body : a.unknown < b.unknown;
  });
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(m, m);
  for (std::size_t first = 0; first < entries.size();) {
    std::size_t last = first;
    while (last < entries.size() && entries[last].body == entries[first].body) ++last;
    const SolverBody &body = bodies[entries[first].body];
    const Vec3 inv_mass = body.share * body.inv_mass * body.inv_mass_axes;
    const Mat3 inv_inertia = body.share * body.inv_inertia;
    for (std::size_t b = first; b < last; ++b) {
      Vec6 moved;
      moved.head<3>() = inv_mass.cwiseProduct(entries[b].g.head<3>());
      moved.tail<3>() = inv_inertia * entries[b].g.tail<3>();
      for (std::size_t a = first; a < last; ++a)
        K(entries[a].unknown, entries[b].unknown) += entries[a].g.dot(moved);
    }
    first = last;
  }
  K = 0.5 * (K + K.transpose()).eval();
  const Eigen::VectorXd y = minimise_bounded(K, r, lower);

  // New impulses first, so that a failed solve changes nothing.
  std::vector<Vec3> targets(rows_.size());
  for (std::size_t c = 0; c < rows_.size(); ++c) {
    targets[c] = rows_[c].impulse;
    if (!loaded(c)) continue;
    const int g = group_[c];
    for (int which = 0; which < unknowns[g]; ++which)
      targets[c] += y[first_unknown[g] + which] * direction(c, which);
    targets[c] = project_on_coulomb_cone(targets[c], rows_[c].mu);
    if (!targets[c].allFinite()) return;
  }
  for (std::size_t c = 0; c < rows_.size(); ++c) {
    if (!loaded(c)) continue;
    Row &row = rows_[c];
    apply_impulse_change(row, targets[c] - row.impulse);
    row.impulse = targets[c];
  }
  restart_acceleration();
}

}    // namespace nscd
