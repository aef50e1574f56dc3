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

// Exact solution of the single-contact Signorini-Coulomb problem with a full 3x3 Delassus
// block (the inner step of the nonlinear Gauss-Seidel).
//
// Local frame (n, t1, t2); P = (P_n, P_t) is the impulse on body i, u = W P + u_free the
// (shifted) relative velocity of i with respect to j. Unknown P must satisfy
//   Signorini:  P_n >= 0, u_n >= 0, P_n u_n = 0
//   Coulomb:    |P_t| <= mu P_n; u_t = 0 (stick) or P_t = -mu P_n u_t / |u_t| (slip).
#pragma once

#include "math/types.h"

namespace nscd {

enum class ContactRegime : unsigned char { open, stick, slip };

struct LocalSolution {
  Vec3 impulse = Vec3::Zero();
  ContactRegime regime = ContactRegime::open;
  // False only if no exact slip solution was found (never seen for SPD W; the impulse is
  // then the projection of the stick impulse onto the cone and the failure is counted).
  bool exact = true;
};

// W: symmetric positive definite Delassus block, W_inverse: its inverse, mu >= 0.
// Order of the cases: open if u_free_n >= 0 (no impulse is needed), else stick if the stick
// impulse -W^-1 u_free lies in the cone, else slip. The slip case is solved exactly: along
// the slip direction s = (cos phi, sin phi), P = P_n (1, -mu s) and u_n = 0 give P_n in
// closed form; u_t parallel to s is then a trigonometric polynomial of degree 2 in phi
// (at most 4 roots). Fast path: its sign changes on 16 sample angles bracket the roots,
// each refined by safeguarded Newton to machine precision. If that yields no admissible
// root (two roots closer than the sampling, i.e. a near-tangent case), all roots are taken
// at once from the eigenvalues of a degree-4 companion matrix and polished by Newton. When
// several roots are admissible (possible only when mu |W_nt| is comparable to W_nn) the one
// with the smallest normal impulse is taken.
// slip_guess (optional, SolverOptions::slip_guess): the contact's impulse when it last
// slid. Newton then starts from its slip direction (along -P_t) and, if that converges to
// an admissible root, takes it without sampling: the same solution to round-off where the
// slip solution is unique, a few times cheaper; where several are admissible, the one
// continuing the last (not necessarily the smallest normal impulse).
LocalSolution solve_local_coulomb(const Mat3 &W, const Mat3 &W_inverse, const Vec3 &u_free,
                                  double mu, const Vec3 *slip_guess = nullptr);

// Projection onto the Coulomb cone K_mu = {x : |x_t| <= mu x_n}.
Vec3 project_on_coulomb_cone(const Vec3 &x, double mu);

// De Saxce's natural-map residual of the local law, in velocity units:
//   Q = s P,  u_hat = (u_n + mu |u_t|, u_t),  r = Q - proj_K(Q - u_hat),  returns |r|
// with u = W P + u_free and s > 0 any impulse-to-velocity scale (the solver uses W_nn).
// Zero exactly when P solves the law; the global convergence test sums its squares.
double coulomb_residual(const Mat3 &W, const Vec3 &u_free, double mu, const Vec3 &P, double s);

}    // namespace nscd
