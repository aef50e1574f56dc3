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

// The NSCD contact problem of one time step and its nonlinear Gauss-Seidel solver
// (Moreau-Jean time stepping, Signorini condition and exact Coulomb friction, no
// regularisation), with optional momentum acceleration and a coarse correction. See
// doc/Howto_nscd_solver.rst for the equations and doc/solver_speed.md for the measured
// effect of each option.
//
// Single rank:   fill bodies and contacts, then solve(problem, options).
// Under domain decomposition: prepare() on every rank, then iterate() with a
// SolverCommunication that exchanges ghost velocities and sums across ranks; iterate()
// makes every decision from globally reduced numbers, so all ranks take the same ones.
// Its loop, for drivers that keep their own (doc/Howto_nscd_solver.rst, "Across ranks"):
//   problem.prepare(options); exchange();
//   repeat {
//     terms = reduce(problem.residual_terms());     // at a check (every check_every sweeps)
//     decide (SolveControl): stop, remember/restore impulses, coarse correction, restart
//     problem.skip_separating_contacts();           // at a check, if options.skip_separating
//     problem.sweep();                              // one pass over the local contacts
//     problem.accelerate(sum(problem.acceleration_terms()));    // if options.acceleration
//     exchange();                                   // every exchange_every sweeps and before a check
//   } until converged or max_sweeps;
//   problem.finish();                               // impulses back into contacts
// exchange(): reverse communication adds each ghost's velocity_correction() and
// angular_velocity_correction() to its owner's velocity, the owner divides the summed
// correction by its share (see SolverBody::share), forward communication copies the
// owners' velocities to their ghosts, then every rank calls mark_synchronised(). Every
// method here changes velocities only through impulse changes of the local contacts, so
// this one exchange carries all of them.
// Ghost copies must enter prepare() with the same velocity and external impulses as
// their owners, so that every rank starts from the same free velocity.
#pragma once

#include "math/types.h"
#include "solver/local_coulomb.h"

#include <cstdint>
#include <functional>
#include <random>
#include <stdexcept>
#include <vector>

namespace nscd {

// Bad solver input (the message names the offending value and the fix).
class SolverError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// body_j of a contact with the motionless or driven environment (e.g. an analytic wall).
constexpr int kEnvironment = -1;

// A rigid body as the solver sees it (local owned bodies and ghost copies alike).
// Bodies of infinite mass (walls, fixed grains) have inv_mass = 0 and inv_inertia = 0;
// their (prescribed) velocity is never changed by the solver.
// Locked translation axes (e.g. a loading plate that moves only along z): the inverse mass
// matrix is inv_mass diag(inv_mass_axes), world frame. A zero factor locks that axis: the
// velocity component along it is prescribed (kept) and the lock carries the reactions along
// it. Rotations are locked the same way by zero rows of inv_inertia. All axes locked and
// inv_inertia = 0 is the same as infinite mass.
struct SolverBody {
  Vec3 position = Vec3::Zero();            // centre of mass, world frame
  Vec3 velocity = Vec3::Zero();            // in: start of step; after solve: end of step
  Vec3 angular_velocity = Vec3::Zero();    // world frame, same life cycle
  // dt * F_ext and dt * (T_ext + gyroscopic torque), world frame; prepare() adds
  // M^-1 times these to the velocities (the free velocity).
  Vec3 external_impulse = Vec3::Zero();
  Vec3 external_angular_impulse = Vec3::Zero();
  double inv_mass = 0.0;
  Vec3 inv_mass_axes = Vec3::Ones();      // factors of inv_mass per world axis, >= 0 (1 or 0)
  Mat3 inv_inertia = Mat3::Zero();         // world frame, see world_inverse_inertia()
  // Mass splitting under domain decomposition: the number of copies of this body (owner and
  // ghosts, over all ranks) that carry contacts. Each copy's contacts see the body with
  // inverse mass and inertia times `share`, and an exchange averages the copies'
  // corrections instead of summing them. The sum of their effects is then exactly
  // M^-1 times the sum of all impulses, so a converged solution is the whole system's; with
  // plain summing, k copies each stopping the same body overshoot k-fold and the sweeps
  // diverge for k >= 3 (doc/Howto_nscd_solver.rst). 1 everywhere on one rank without images.
  double share = 1.0;
};

// Persistent identity of a contact for warm starting: the two bodies' global ids (tags)
// and a feature code chosen by the geometry (which vertex/edge/face pair touches). The
// feature must not depend on which body is called i (see WarmStartCache).
struct ContactKey {
  std::int64_t tag_i = 0;
  std::int64_t tag_j = 0;
  std::uint64_t feature = 0;
};

struct Contact {
  int body_i = 0;                  // index into ContactProblem::bodies
  int body_j = kEnvironment;       // index, or kEnvironment
  Vec3 point = Vec3::Zero();       // world contact point
  Vec3 normal = Vec3::UnitZ();     // unit normal, pointing from j to i
  double gap = 0.0;                // signed distance along the normal, < 0 = overlap
  double friction = 0.0;           // Coulomb coefficient mu >= 0
  double restitution = 0.0;        // Newton normal restitution e in [0, 1]
  Vec3 wall_velocity = Vec3::Zero();    // velocity of the environment at the point (j < 0)
  ContactKey key;
  // In: warm-start impulse on body i (world frame). Out (finish()): the solved impulse.
  Vec3 impulse = Vec3::Zero();
  ContactRegime regime = ContactRegime::open;    // out (finish())
};

enum class SweepOrder : unsigned char {
  as_given,            // contacts in the order of the contacts vector
  shuffled,            // a new random permutation every sweep (seeded, reproducible)
  forward_backward,    // alternate forward and backward passes (symmetric Gauss-Seidel)
};

// Momentum on the Gauss-Seidel sweeps (doc/Howto_nscd_solver.rst, "Acceleration"). After each
// sweep every impulse moves on by beta times its change since the last sweep (projected
// onto its cone), beta >= 0 growing while the iteration goes well:
enum class Acceleration : unsigned char {
  none,        // plain nonlinear Gauss-Seidel
  nesterov,    // beta = (k - 1) / (k + 2), k = sweeps since the last restart; restarts when
               // the residual grew between two checks. No communication of its own.
  nncg,        // nonsmooth nonlinear conjugate gradient (Silcowitz, Niebe, Erleben 2010):
               // Fletcher-Reeves beta = |dP_k|^2 / |dP_k-1|^2 from the sweeps' impulse
               // changes (one global sum per sweep), restarts when beta > 1 or the
               // residual grew
  anderson,    // Anderson mixing (Walker and Ni 2011) of the last anderson_memory sweeps:
               // the impulses become the combination of the sweeps' results whose
               // impulse changes cancel best (least squares), projected onto the cones.
               // One global sum of 2 m + 1 numbers per sweep; restarts when a sweep's
               // change grew or the residual grew
};

struct SolverOptions {
  double dt = 0.0;             // time step, > 0
  double theta = 0.5;          // theta of the theta-method, in (0, 1]
  double relaxation = 1.0;     // omega in (0, 1]: P = omega P_local + (1 - omega) P_old
  SweepOrder order = SweepOrder::as_given;
  std::uint64_t seed = 12345;  // for SweepOrder::shuffled
  // Between two residual checks the sweeps skip the contacts that are open and separating
  // at the check (no impulse, normal velocity admissible without one): a sweep would leave
  // them unchanged unless a neighbour's impulse turns them around, and the next check
  // (which evaluates every contact) puts those back. The solution meets the same tolerance
  // on every contact; the path to it changes, and so does the trajectory: off by default
  // until its effect on the column's outcome is settled (doc/solver_speed.md, "Skipping
  // separating contacts"). false: every sweep relaxes every contact.
  bool skip_separating = false;
  // A sliding contact's local solve starts Newton from its last slip direction instead of
  // sampling all 16 brackets (solve_local_coulomb's slip_guess): the same local solution
  // to round-off where it is unique, cheaper; the trajectory changes at round-off, so off by
  // default until its effect on the outcome is settled (doc/solver_speed.md, "Slip guess").
  bool slip_guess = false;
  double tolerance = 1e-6;     // on the scale-free residual (see ResidualTerms)
  int max_sweeps = 1000;
  // solve() evaluates the residual (about the cost of a sweep) before the first sweep and
  // then only every check_every sweeps (and at max_sweeps), so it may do up to
  // check_every - 1 sweeps more than needed. 1 = check after every sweep.
  int check_every = 1;
  // Overlapping contacts (gap < 0 at the start of the step) separate at up to this normal
  // speed, enough to remove the overlap within the step if it is small. 0 (the default):
  // overlap is kept, not pushed out. The separation speed stays with the grains: it adds
  // kinetic energy (at most m V^2 / 2 per grain and step), so keep V small.
  double overlap_speed = 0.0;
  Acceleration acceleration = Acceleration::none;
  // Sweeps Acceleration::anderson combines (its memory m), 1 to kMaxAndersonMemory.
  int anderson_memory = 5;
  static constexpr int kMaxAndersonMemory = 32;
  // Coarse correction (doc/Howto_nscd_solver.rst, "Coarse correction"): the contacts of
  // this rank are grouped into cubic cells of coarse_cell grain sizes (a grain size = twice
  // the mean lever arm of the contacts); each group's normal impulses are scaled and
  // shifted by common amounts solved from a small linear system. 0 = off. Applied at a
  // residual check at most every coarse_every sweeps. It must keep paying: when the
  // residual has not halved over the last max(coarse_patience, 2 coarse_every) sweeps, the
  // solve goes on without it, from the impulses of the best residual so far.
  double coarse_cell = 0.0;
  int coarse_every = 1;
  int coarse_patience = 10;

  // Throws SolverError naming the bad option.
  void validate() const;
};

// Per-rank contributions to the convergence test and the diagnostics. Every field is a
// sum or a maximum so ranks can reduce them (MPI_SUM / MPI_MAX) and call residual().
struct ResidualTerms {
  double error_squared = 0.0;   // sum over contacts of |r_c|^2, r_c = De Saxce residual
  double scale_squared = 0.0;   // sum over contacts of |W_nn P_c|^2 (velocity scale)
  double max_interpenetration = 0.0;    // max over contacts of -(predicted end-of-step gap)
  long contacts = 0;
  long active = 0;              // P_n > 0
  long sticking = 0;
  long sliding = 0;             // includes active frictionless contacts
  long local_failures = 0;      // local solves that found no exact slip root (expect 0)
  // iterate() sums these across ranks as one array of this many values (error_squared,
  // scale_squared, then the counts), in one SolverCommunication::sum call per check.
  static constexpr int kSummed = 7;

  void merge(const ResidualTerms &other);
  // sqrt(error_squared / scale_squared): a relative velocity error, independent of units,
  // masses and dt. 0 when there is nothing to solve; +inf when a contact that must push
  // has no impulse yet.
  double residual() const;
};

struct SolveReport {
  int sweeps = 0;
  double residual = 0.0;
  bool converged = false;
  ResidualTerms terms;
  int coarse_corrections = 0;    // applied
  bool coarse_dropped = false;   // it stopped paying (SolverOptions::coarse_patience)
};

namespace detail {
// Data of one contact precomputed by prepare(): local velocity u = F v_i + A_i w_i
// - (F v_j + A_j w_j) + offset, and an impulse change dP moves v_i by M_i^-1 F^T dP and
// w_i by B_i dP (opposite for j), with B = I^-1 A^T and M^-1 = diag(inv_mass_i) (world).
// W = sum over bodies of F M^-1 F^T + A B.
struct ContactRow {
  Mat3 frame;             // F: rows n, t1, t2
  Mat3 angular_i, angular_j;              // A = -F [r]x, r = lever arm from the centre
  Mat3 spin_i, spin_j;                    // B
  Mat3 delassus, delassus_inverse;
  Vec3 offset;            // environment velocity and the Signorini shift (see doc)
  Vec3 impulse;           // local frame
  Vec3 inv_mass_i, inv_mass_j;            // diagonal of M^-1, world frame
  double mu;
  double gap_start;       // gap + (1 - theta) dt u_n^- : predicted gap with u_n^+ = 0
  double normal_shift;    // u_min: Signorini holds for u_n - u_min
  int i, j;               // body indices, j may be kEnvironment
  bool inert;             // W_nn = 0 (e.g. both bodies immobile): nothing to solve
  bool normal_only;       // W_nt = W_tt = 0 (locked axes): u_t cannot change
  ContactRegime regime;
  Vec3 step;              // impulse change of the last sweep (local frame)
  Vec3 direction;         // momentum: impulse change since the previous sweep
};
}    // namespace detail

class ContactProblem {
 public:
  std::vector<SolverBody> bodies;
  std::vector<Contact> contacts;

  // Validates input, turns velocities into free velocities, builds the per-contact
  // frames, lever-arm Jacobians and Delassus blocks, and applies the warm-start impulses
  // (projected onto the Coulomb cone). Call once per time step. Reuses its buffers, so
  // steady-state steps do not allocate.
  void prepare(const SolverOptions &options);

  // One nonlinear Gauss-Seidel pass over the contacts of this problem (all of them, or
  // those skip_separating_contacts() kept).
  void sweep();
  // Sets the contacts the sweeps relax until the next check: all of them but those open
  // and separating now (SolverOptions::skip_separating).
  void skip_separating_contacts();
  // The contacts the sweeps relax now (all, or those skip_separating_contacts() kept).
  std::size_t swept_contacts() const { return swept_.size(); }

  // Per contact, the error and the scale that residual_terms() sums (for diagnostics: where
  // the residual comes from).
  void contact_residuals(std::vector<double> &error, std::vector<double> &scale) const;

  // This problem's part of the squared size of the last sweep's impulse change, the sum
  // over its contacts of |dP|^2 (impulse units, local frame).
  double sweep_change() const { return sweep_change_; }
  // After each sweep: this problem's part of the sums over ranks that accelerate()
  // needs, to be summed element-wise over ranks (empty for none and nesterov; nncg:
  // sweep_change(); anderson: 2 m + 1 dot products of this sweep's and the remembered
  // sweeps' impulse changes, after storing this sweep in the memory).
  const std::vector<double> &acceleration_terms();
  // The step of options.acceleration after a sweep, on this problem's contacts (the same
  // call on every rank, with acceleration_terms() summed over ranks): momentum moves each
  // impulse on by beta times its change since the previous sweep, Anderson mixing
  // replaces it by the best combination of the remembered sweeps' results; each impulse is
  // projected onto its cone and the bodies' velocities follow (ghosts send the change at
  // the next exchange, as after a sweep). Does nothing without acceleration.
  void accelerate(const std::vector<double> &global_terms = {});
  // Start the momentum again from zero (when the residual grew, or after a jump of the
  // impulses that was not a sweep).
  void restart_acceleration();

  // Coarse correction (SolverOptions::coarse_cell) of this problem's contacts: each group
  // (cell) of loaded contacts gets two unknowns, a factor on its normal impulses and a
  // uniform normal increment; they minimise the quadratic energy of the contact problem
  // restricted to these directions (K y = -r, K = Phi^T W Phi, r = Phi^T u; directions of
  // self-stress, K y = 0, are left out), then each impulse is projected onto its cone.
  // Velocities follow like after a sweep. No communication; restarts the momentum.
  void coarse_correction();

  // A copy of the impulses (of the best residual so far) and the way back to it; the
  // bodies' velocities follow the change like after a sweep.
  void remember_impulses();
  void restore_remembered_impulses();

  // Residual contributions of this problem's contacts at the current velocities.
  ResidualTerms residual_terms() const;

  // Writes the world impulse (on body i) and the regime of each contact into contacts.
  void finish();

  int sweeps_done() const { return sweeps_done_; }
  // Coarse groups of this problem (0 without the coarse correction); at most
  // kMaxCoarseGroups: the coarse system is dense (2 unknowns per group, cubic cost), and
  // 256 unknowns cost under 3 ms (at most 4 LDLTs of 0.66 ms), while a rank holding 10^5
  // grains in cells of 2 grain sizes would need 25 000 (a 5 GB matrix). A rank with more
  // cells gets cells twice as wide, until they are few enough.
  static constexpr int kMaxCoarseGroups = 128;
  int coarse_groups() const { return group_count_; }

  // Velocity change of body b caused by this problem's contacts since prepare() (before
  // the warm start) or since the last mark_synchronised(): what a ghost sends its owner.
  Vec3 velocity_correction(int b) const { return bodies[b].velocity - synced_velocity_[b]; }
  Vec3 angular_velocity_correction(int b) const
  {
    return bodies[b].angular_velocity - synced_angular_velocity_[b];
  }
  // Call once the velocities of all bodies (owned and ghost) agree across ranks. After
  // prepare() it re-marks only the bodies with a finite mass or inertia: the others' velocities
  // change by no impulse, so an exchange must leave them as they are (copies of such a body
  // agree already).
  void mark_synchronised();

  // Bytes this problem holds on the heap (bodies, contacts, the rows and the sweep's
  // scratch), at capacity: what stays allocated between steps.
  std::size_t memory_bytes() const;

 private:
  using Row = detail::ContactRow;

  void build_row(const Contact &contact, std::size_t index, Row &row) const;
  double lowest_normal_velocity(const Contact &contact, double u_n_start,
                                double gap_theta) const;
  void relax(Row &row);
  Vec3 local_velocity(const Row &row) const;
  double contact_error(const Row &row, const Vec3 &u) const;
  double round_off_velocity(const Row &row, const Vec3 &u_free) const;
  void apply_impulse_change(const Row &row, const Vec3 &dP);

  void build_groups();
  int group_contacts_by_cell(double size);    // fills group_, returns the group count

  void store_anderson_sweep();
  void mix_anderson(const std::vector<double> &global_terms);

  std::vector<Row> rows_;
  std::vector<int> group_;          // coarse group of each contact
  int group_count_ = 0;
  std::vector<Vec3> remembered_;    // remember_impulses()
  std::vector<int> order_;
  std::vector<int> swept_;    // order_ less the contacts skipped until the next check
  std::vector<Vec3> synced_velocity_, synced_angular_velocity_;
  std::vector<int> movable_;    // bodies with a finite mass or inertia (mark_synchronised())
  SolverOptions options_;
  std::mt19937_64 random_;
  int sweeps_done_ = 0;
  long local_failures_ = 0;
  double sweep_change_ = 0.0;
  double previous_change_ = 0.0;    // nncg: global sweep change of the previous step
  int momentum_steps_ = 0;          // accelerate() calls since the last restart
  std::vector<double> acceleration_terms_;
  int terms_sweep_ = -1;            // the sweep acceleration_terms_ belong to
  // Anderson mixing: per remembered sweep (a ring of anderson_memory slots), the change
  // between consecutive sweeps of the swept impulses (dg) and of their impulse changes
  // (df), 3 numbers per contact; the last sweep's impulses and changes; the Gram matrix of
  // the df slots (summed over ranks).
  std::vector<double> anderson_dg_, anderson_df_, anderson_g_, anderson_f_;
  Eigen::MatrixXd anderson_gram_;
  Eigen::VectorXd anderson_mix_;    // sum_s gamma_s dg_s
  bool anderson_has_last_ = false;
  int anderson_count_ = 0;          // slots filled since the last restart
  int anderson_slot_ = 0;           // the slot this sweep wrote
  double anderson_last_change_ = 0.0;    // global |f|^2 of the previous sweep
};

// The decisions of the iteration that depend on the global residual only, so that every
// rank takes the same ones (iterate() uses it; a driver with its own loop can too).
class SolveControl {
 public:
  explicit SolveControl(const SolverOptions &options) : options_(options) {}
  struct Step {
    bool stop = false;              // converged, or max_sweeps reached
    bool remember = false;          // new best residual: remember_impulses()
    bool restore = false;           // restore_remembered_impulses(), exchange, check again
                                    // (the coarse correction stopped paying, best earlier)
    bool coarse = false;            // coarse_correction() before the next sweep
    bool restart = false;           // restart_acceleration()
  };
  // At a residual check, with the reduced residual after `sweeps` sweeps.
  Step at_check(double residual, int sweeps);
  // The residual to report: the best one when the last step restored it.
  double best_residual() const { return best_; }
  int coarse_corrections() const { return coarse_corrections_; }
  bool coarse_dropped() const { return coarse_dropped_; }

 private:
  SolverOptions options_;
  double previous_ = -1.0;          // residual of the last check (< 0: none yet)
  double best_ = -1.0;
  std::vector<std::pair<int, double>> checks_;    // (sweeps, residual) while coarse is on
  int last_coarse_ = -1;
  int coarse_corrections_ = 0;
  bool coarse_dropped_ = false;
};

// What iterate() needs from a distributed driver; on one rank everything stays empty.
struct SolverCommunication {
  // Ghost velocity exchange (see the top of this file), ending with mark_synchronised().
  std::function<void(ContactProblem &)> exchange;
  // In-place global sum (MPI_Allreduce, MPI_SUM) and maximum (MPI_MAX) of n doubles.
  std::function<void(double *values, int n)> sum;
  std::function<void(double *values, int n)> max;
  // Sweeps between exchanges; there is always one before a residual check.
  int exchange_every = 1;
};

// ResidualTerms summed (maximum for max_interpenetration) over ranks.
ResidualTerms reduce(const ResidualTerms &mine, const SolverCommunication &communication);

// The iteration after prepare(): exchange, then sweeps with the options' acceleration and
// coarse correction, the residual reduced over ranks every options.check_every sweeps
// (and at max_sweeps), until it is below the tolerance or max_sweeps; then finish().
SolveReport iterate(ContactProblem &problem, const SolverOptions &options,
                    const SolverCommunication &communication = {});

// Single-rank driver: prepare(options), then iterate().
SolveReport solve(ContactProblem &problem, const SolverOptions &options);

}    // namespace nscd
