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

/* fix nscd: gathers bodies and contacts from LAMMPS, runs lib/solver's Gauss-Seidel with
   ghost exchanges between sweeps, and moves the grains (Moreau-Jean). */

#include "fix_nscd.h"
#include "nscd_checks.h"
#include "nscd_args.h"
#include "nscd_units.h"

#include "atom.h"
#include "atom_vec_spheropolyhedron.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "domain.h"
#include "modify.h"
#include "nscd_arrays.h"
#include "nscd_atom_impulses.h"
#include "nscd_restart_blocks.h"
#include "nscd_timing.h"
#include "neighbor.h"
#include "nscd_boundary.h"
#include "nscd_contact.h"
#include "nscd_boundary_fix.h"
#include "pair_nscd.h"
#include "timer.h"
#include "update.h"

#include "solver/contact_problem.h"
#include "solver/problem_file.h"
#include "solver/rigid_motion.h"
#include "solver/warm_start.h"
#include "math/capacity_bytes.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

using namespace LAMMPS_NS;
using namespace NSCD_NS;
using namespace FixConst;

namespace {
enum Diagnostic {
  SWEEPS, RESIDUAL, MAX_INTERPENETRATION, CONTACTS, ACTIVE, STICKING, SLIDING, CONVERGED,
  KE_TRANSLATION, KE_ROTATION, NDIAGNOSTICS
};

// Cell size of the coarse correction (nscd::SolverOptions::coarse_cell) in grain sizes:
// "no" = off, "yes" = 2 (the size measured best, doc/solver_speed.md), or a number > 0.
double coarse_cell_of(const std::string &value, LAMMPS *lmp)
{
  if (value == "no") return 0.0;
  if (value == "yes") return 2.0;
  char *end = nullptr;
  const double cell = std::strtod(value.c_str(), &end);
  if (end == value.c_str() || *end != '\0' || !std::isfinite(cell) || cell <= 0.0)
    lmp->error->all(FLERR, "fix nscd: coarse '{}' must be no, yes or a cell size > 0 (in grain "
                    "sizes)", value);
  return cell;
}
}    // namespace

struct FixNSCD::Solver {
  nscd::SolverOptions options;
  nscd::ContactProblem problem;
  nscd::SolveReport report;    // of the last step
  nscd::WarmStartCache warm_start;       // this rank's contacts of the last solve
  NSCDAtomImpulses atom_impulses;        // the same kept with the atoms, while they move

  // This run's time per part (contact detection is pair nscd's, from LAMMPS' timer) and
  // its solver statistics, reported after the run.
  enum Part { DETECTION, BOUNDARIES, SETUP, SWEEPS, SWEEP_COMM, UPDATE };
  NSCDPartTimes times{{"contact detection (pair)", "boundary contacts", "solver setup", "sweeps",
                       "sweep communication", "motion and hand-back"}};
  struct RunStats {
    bigint steps = 0, unconverged = 0, max_sweeps_step = -1, deepest_step = -1;
    double sweeps = 0.0, max_sweeps = 0.0, deepest = 0.0;
  } run;
};

/* fix ID group nscd [theta T] [tolerance TOL] [max_sweeps N] [relaxation W] [check N]
                     [order as_given|shuffled|forward_backward] [seed S] [exchange N] [warn N]
                     [method gs|nesterov|nncg|anderson] [coarse no|yes|C] [overlap_speed V]
                     [interpenetration F] [skip_separating yes|no] [slip_guess yes|no] [write_problem STEP FILE] */
FixNSCD::FixNSCD(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), solver(std::make_unique<Solver>()), exchange_every(1), warn_every(1000),
    interpenetration_warning(0.2), smallest_rounding(0.0), warned_depth(0.0), dt(0.0), problem_step(-1),
    pair(nullptr), avec(nullptr), pair_count(0), impulses_with_atoms(false), solved_since_filing(false),
    records_sent(0.0), values_sent(0.0), records_migrated(0.0), values_migrated(0.0), records_received(0.0),
    comm_counts(N_COMM_KINDS), exchanges_run(0), reductions_run(0), exchange_mode(Exchange::state),
    copies_planned_at(-1), plans_run(0), unconverged_steps(0), last_warning_step(-1), last_speed_warning_step(-1),
    max_step_travel(0.0),
    kinetic_translational(0.0), kinetic_rotational(0.0), warm_start_dt(0.0)
{
  time_integrate = 1;
  restart_global = 1;
  vector_flag = 1;
  size_vector = NDIAGNOSTICS;
  global_freq = 1;
  extvector = 0;
  comm_forward = 12;
  comm_reverse = std::max(6, ghost_records_slot());
  // The contact forces are known only after the solve: their virial is this fix's.
  virial_global_flag = virial_peratom_flag = 1;
  thermo_virial = 1;

  // Defaults (doc/fix_nscd.rst): theta = 1 lets no impact sink into an obstacle (with theta
  // < 1 the old velocity carries a grain (1 - theta) dt |v| into it); the residual is
  // checked every 4 sweeps (it costs about a sweep); Nesterov momentum needs fewer sweeps
  // than plain Gauss-Seidel on every measured scene, at no communication cost
  // (doc/Howto_nscd_solver.rst, "Acceleration"); tolerance 1e-4 converged at every step of
  // every benchmark scene at its usual timestep within 220 sweeps (doc/BENCHMARKS.md), so
  // max_sweeps 1000 stops only steps that are going wrong, while 1e-6 left most loaded steps
  // unconverged at several times the cost for no smaller overlap (doc/BENCHMARKS.md,
  // "Tolerance against error").
  solver->options.tolerance = 1e-4;
  solver->options.max_sweeps = 1000;
  solver->options.theta = 1.0;
  solver->options.check_every = 4;
  solver->options.acceleration = nscd::Acceleration::nesterov;
  for (int iarg = 3; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (iarg + 1 >= narg) error->all(FLERR, "fix nscd: keyword '{}' needs a value", key);
    const char *value = arg[iarg + 1];
    if (key == "write_problem") {
      if (iarg + 2 >= narg)
        error->all(FLERR, "fix nscd: write_problem needs a step and a file name (write_problem STEP FILE)");
      problem_step = NSCD_NS::whole(lmp, "fix nscd", key, value, 0, MAXBIGINT);
      problem_file = arg[iarg + 2];
      ++iarg;
    } else if (!set_option(key, value)) {
      error->all(FLERR, "fix nscd: unknown keyword '{}'; the "
                 "keywords are listed in doc/fix_nscd.rst, Syntax", key);
    }
  }
  solver->options.dt = 1.0;    // validated for real in init(), with the run's timestep
  check_options();
  // The warm-start impulses as per-atom data: they move with their atoms and are written
  // per atom to restart files (as fix neigh/history keeps pair granular's shear history).
  restart_peratom = 1;
  create_attribute = 1;
  maxexchange_dynamic = 1;
  FixNSCD::grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

/* One solver keyword of the fix line or of fix_modify: false if KEY is none of them. */
bool FixNSCD::set_option(const std::string &key, const char *value)
{
  if (key == "theta") solver->options.theta = NSCD_NS::number(lmp, "fix nscd", key, value);
  else if (key == "tolerance") solver->options.tolerance = NSCD_NS::number(lmp, "fix nscd", key, value);
  else if (key == "max_sweeps") solver->options.max_sweeps = (int) NSCD_NS::whole(lmp, "fix nscd", key, value, INT_MIN, INT_MAX);
  else if (key == "relaxation") solver->options.relaxation = NSCD_NS::number(lmp, "fix nscd", key, value);
  else if (key == "seed") solver->options.seed = (std::uint64_t) NSCD_NS::whole(lmp, "fix nscd", key, value);
  else if (key == "exchange") exchange_every = (int) NSCD_NS::whole(lmp, "fix nscd", key, value, INT_MIN, INT_MAX);
  else if (key == "check") solver->options.check_every = (int) NSCD_NS::whole(lmp, "fix nscd", key, value, INT_MIN, INT_MAX);
  else if (key == "warn") warn_every = (int) NSCD_NS::whole(lmp, "fix nscd", key, value, INT_MIN, INT_MAX);
  else if (key == "overlap_speed") solver->options.overlap_speed = NSCD_NS::number(lmp, "fix nscd", key, value);
  else if (key == "interpenetration") interpenetration_warning = NSCD_NS::number(lmp, "fix nscd", key, value);
  else if (key == "order") {
    const std::string order = value;
    if (order == "as_given") solver->options.order = nscd::SweepOrder::as_given;
    else if (order == "shuffled") solver->options.order = nscd::SweepOrder::shuffled;
    else if (order == "forward_backward") solver->options.order = nscd::SweepOrder::forward_backward;
    else
      error->all(FLERR, "fix nscd: unknown order '{}' (expected as_given, shuffled or "
                 "forward_backward)", order);
  } else if (key == "method") {
    const std::string method = value;
    if (method == "gs") solver->options.acceleration = nscd::Acceleration::none;
    else if (method == "nesterov") solver->options.acceleration = nscd::Acceleration::nesterov;
    else if (method == "nncg") solver->options.acceleration = nscd::Acceleration::nncg;
    else if (method == "anderson") solver->options.acceleration = nscd::Acceleration::anderson;
    else
      error->all(FLERR, "fix nscd: unknown method '{}' (expected gs, nesterov, nncg or anderson)", method);
  } else if (key == "coarse") {
    solver->options.coarse_cell = coarse_cell_of(value, lmp);
  } else if (key == "skip_separating") {
    solver->options.skip_separating = yes_or_no(lmp, "fix nscd", key, value);
  } else if (key == "slip_guess") {
    solver->options.slip_guess = yes_or_no(lmp, "fix nscd", key, value);
  } else {
    return false;
  }
  return true;
}

void FixNSCD::check_options()
{
  if (exchange_every < 1) error->all(FLERR, "fix nscd: exchange {} must be >= 1", exchange_every);
  // Momentum and mixing extrapolate each rank's sweeps on ghost velocities that are stale
  // between exchanges: on the papers' column exchange 2 took 1.6 times the sweeps and
  // exchange 4 stalled at max_sweeps (doc/fix_nscd.rst, "Ghost exchange").
  if (exchange_every > 1 && comm->nprocs > 1 && solver->options.acceleration != nscd::Acceleration::none &&
      comm->me == 0)
    error->warning(FLERR, "fix nscd: exchange {} with an accelerated method needs more sweeps on several ranks; "
                   "use exchange 1", exchange_every);
  if (warn_every < 1) error->all(FLERR, "fix nscd: warn {} must be >= 1", warn_every);
  if (!(interpenetration_warning >= 0.0) || !std::isfinite(interpenetration_warning))
    error->all(FLERR, "fix nscd: interpenetration {} must be a finite fraction >= 0 of the rounding radius "
               "(0: no warning)", interpenetration_warning);
  try {
    solver->options.validate();
  } catch (std::exception &e) {
    error->all(FLERR, "fix nscd: {}", e.what());
  }
}

/* fix_modify ID KEY VALUE: any keyword of the fix line but write_problem, for the next runs
   (e.g. a looser tolerance for a deposit, then the default for the relaxations). */
int FixNSCD::modify_param(int narg, char **arg)
{
  const std::string key = arg[0];
  if (key == "write_problem")
    error->all(FLERR, "fix_modify {}: write_problem is set on the fix nscd line only", id);
  if (narg < 2) error->all(FLERR, "fix_modify {}: keyword '{}' needs a value", id, key);
  if (!set_option(key, arg[1])) return 0;
  check_options();
  return 2;
}

FixNSCD::~FixNSCD()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
}

const std::vector<nscd::Contact> &FixNSCD::contacts() const
{
  return solver->problem.contacts;
}

int FixNSCD::setmask()
{
  return POST_FORCE | FINAL_INTEGRATE | PRE_EXCHANGE;
}

void FixNSCD::init()
{
  avec = AtomVecSpheropolyhedron::find(lmp, "fix nscd");
  pair = dynamic_cast<PairNSCD *>(force->pair_match("^nscd", 0));
  if (!pair)
    error->all(FLERR, "fix nscd needs pair_style nscd (it finds the grain contacts); add "
               "'pair_style nscd' and 'pair_coeff * * FRICTION'");
  if (!pair->compute_flag)
    error->all(FLERR, "fix nscd: pair_modify compute no switches off contact detection; remove it");
  NSCD_NS::refuse_second_instance<FixNSCD>(lmp, this, "one solver handles all grains and boundaries");
  if (domain->dimension != 3) error->all(FLERR, "fix nscd works in 3d only");
  NSCD_NS::require_plain_mechanics(lmp, "fix nscd");
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "fix nscd does not work with run_style respa; use run_style verlet");
  if (update->whichflag == 2)
    error->all(FLERR, "fix nscd does not work with minimize: rigid grains "
               "have no potential energy; use 'run' (or unfix {} first)", id);
  dt = update->dt;
  if (!(dt > 0.0) || !std::isfinite(dt))
    error->all(FLERR, "fix nscd: timestep {} must be positive and finite; set it with 'timestep DT'", dt);
  find_partners();
  check_no_other_integrator();
  check_no_migration_before_this_fix();
  check_no_points_in_group();
  check_grains_are_consistent();
  check_overlap_speed();
}

/* overlap_speed pushes overlapping grains apart by up to V dt per step. Faster than contacts
   are looked for ahead (pair_style nscd activation + reach) the grains pushed apart run into
   others unseen, and a large V shoots them out of the box ("Lost atoms" was all a user saw
   of overlap_speed 1e6): refused, naming the speed that fits. */
void FixNSCD::check_overlap_speed()
{
  const double ahead = pair->activation_distance() + pair->reach_distance();
  const double speed = solver->options.overlap_speed;
  if (speed * dt <= ahead) return;
  error->all(FLERR, "fix nscd: overlap_speed {} separates grains by up to {:.4g} per step; "
             "use at most {:.4g} (doc/fix_nscd.rst, Errors)", speed, speed * dt, ahead / dt);
}

/* A grain also moved by another integrator (fix nve, fix rigid, ...) would move twice per
   step: it gains energy and sinks into its neighbours. */
void FixNSCD::check_no_other_integrator()
{
  for (Fix *other : modify->get_fix_list()) {
    if (other == this || !other->time_integrate) continue;
    const tagint any_shared = NSCD_NS::lowest_tag_where(lmp, [&](int i) {
      return (atom->mask[i] & groupbit) && (atom->mask[i] & other->groupbit) && avec->shape[i] != 0;
    });
    if (any_shared)
      error->all(FLERR, "fix nscd: fix {} ({}) also moves grain ID {}; remove fix {} or give "
                 "it a group without the grains", other->id, other->style, any_shared, other->id);
  }
}

/* Grains are rigid bodies moved by contacts only: a bond or angle pulling on one (e.g. a
   wire node bonded to a grain) is a deck error. Needs the run's bond lists. */
void FixNSCD::check_no_bonds_on_grains()
{
  if (!atom->molecular) return;
  tagint bad[2] = {MAXTAGINT, MAXTAGINT};
  auto note = [&](const int *atoms, int n) {
    for (int k = 0; k < n; k++)
      if (avec->shape[atoms[k]] != 0 && atom->tag[atoms[k]] < bad[0]) {
        bad[0] = atom->tag[atoms[k]];
        bad[1] = atom->tag[atoms[k == 0 ? 1 : 0]];
      }
  };
  // (LAMMPS builds the lists of a kind only when its style is defined: without one, such
  // bonds exert no force)
  if (force->bond)
    for (int n = 0; n < neighbor->nbondlist; n++) note(neighbor->bondlist[n], 2);
  if (force->angle)
    for (int n = 0; n < neighbor->nanglelist; n++) note(neighbor->anglelist[n], 3);
  const tagint grain = NSCD_NS::lowest_tag_of_all(world, bad[0]);
  if (grain == MAXTAGINT) return;
  const tagint partner = NSCD_NS::lowest_tag_of_all(world, bad[0] == grain ? bad[1] : MAXTAGINT);
  error->all(FLERR, "fix nscd: grain ID {} is in a bond or angle (with atom ID "
             "{}); bonds and angles join wire nodes (shape 0) only", grain, partner);
}

/* Overlap present at the start is not pushed apart by the solver (contacts only stop
   further approach): grains that overlap by more than a fifth of the smaller one's bounding
   radius, or by more than their two rounding radii (their polyhedral cores intersect: the
   contact then has one normal, the penetration axis, which need not be the way the grains
   came together), were placed wrongly. */
void FixNSCD::warn_if_grains_overlap()
{
  double worst[4] = {0.0, 0.0, 0.0, 0.0};    // overlap / smaller radius, the two IDs, overlap
  for (const nscd::Contact &c : pair->contacts()) {
    const double smaller = std::min(avec->radius[c.body_i], avec->radius[c.body_j]);
    const double rounding = avec->shape_of(c.body_i).radius + avec->shape_of(c.body_j).radius;
    const double depth = -c.gap / smaller;
    const bool wrong = depth > 0.2 || -c.gap > rounding;
    if (wrong && depth > worst[0])
      worst[0] = depth, worst[1] = (double) c.key.tag_i, worst[2] = (double) c.key.tag_j, worst[3] = -c.gap;
  }
  std::vector<double> all(4 * comm->nprocs);
  MPI_Allgather(worst, 4, MPI_DOUBLE, all.data(), 4, MPI_DOUBLE, world);
  for (int r = 0; r < comm->nprocs; r++)
    if (all[4 * r] > worst[0]) std::copy(&all[4 * r], &all[4 * r + 4], worst);
  if (worst[0] > 0.0 && comm->me == 0)
    error->warning(FLERR, "fix nscd: grains ID {} and {} overlap by {:.3g} ({:.3g} of the smaller one's bounding "
                   "radius); doc/fix_nscd.rst, Errors",
                   (tagint) worst[1], (tagint) worst[2], worst[3], worst[0]);
}

/* Every atom of the group must be a grain: points (wire nodes) belong to the wire fix.
   Also catches points made during a run (fix pour/deposit create shape 0). */
void FixNSCD::check_no_points_in_group()
{
  const tagint any_point =
      NSCD_NS::lowest_tag_where(lmp, [&](int i) { return (atom->mask[i] & groupbit) && avec->shape[i] == 0; });
  if (any_point)
    error->all(FLERR, "fix nscd: atom ID {} in group '{}' is a point (shape 0); give it a shape "
               "('shapes assign') or use a group of grains", any_point, group->names[igroup]);
}

/* Core commands can change mass or radius behind the shape library's back (`set mass`,
   `set diameter`, `set density`): refuse grains whose data no longer match their shape. */
void FixNSCD::check_grains_are_consistent()
{
  const tagint any_bad = NSCD_NS::lowest_tag_where(lmp, [&](int i) {
    if (!(atom->mask[i] & groupbit) || avec->shape[i] == 0) return false;
    const nscd::Spheropolyhedron &s = avec->shape_of(i);
    const double density = avec->rmass[i] / s.volume;
    bool ok = std::abs(avec->radius[i] - s.bounding_radius) <= 1e-12 * s.bounding_radius;
    for (int k = 0; k < 3; k++)
      ok = ok && std::abs(avec->inertia[i][k] - density * s.principal_inertia[k]) <=
              1e-10 * density * s.principal_inertia.maxCoeff();
    return !ok;
  });
  if (any_bad)
    error->all(FLERR, "fix nscd: grain ID {} has a mass, inertia or radius unlike "
               "its shape; set both with 'shapes assign ... density|mass'", any_bad);
}

void FixNSCD::find_partners()
{
  boundaries.clear();
  boundary_fixes.clear();
  for (Fix *other : modify->get_fix_list())
    if (auto *b = dynamic_cast<NSCDBoundaryFix *>(other)) {
      boundaries.push_back(&b->boundary());
      boundary_fixes.push_back(other);
    }
}

/* A run can start without init() (run ... pre no): partners may have changed. The contact
   virial of the setup step is zero: nothing is solved before the first step. */
void FixNSCD::setup(int vflag)
{
  find_partners();
  check_no_bonds_on_grains();
  warn_if_grains_overlap();
  records_sent = values_sent = records_migrated = values_migrated = records_received = 0.0;
  comm_counts.clear();
  exchanges_run = reductions_run = plans_run = 0;
  solver->times.clear();
  solver->run = Solver::RunStats();
  find_smallest_rounding();
  warned_depth = 0.0;
  copies_planned_at = -1;    // atoms may have moved (balance) under the last step's time stamp
  post_force(vflag);
  measure_kinetic_energy();
}

/* On a list rebuild, before atoms change rank: the impulses go with them. */
void FixNSCD::pre_exchange()
{
  keep_impulses_with_atoms();
}

void FixNSCD::post_force(int vflag)
{
  v_init(vflag);
  if (!vflag_atom) return;
  // Fix::v_setup sizes and zeroes vatom for owned atoms; contacts also tally into ghosts.
  if (atom->nmax > maxvatom) {
    maxvatom = atom->nmax;
    memory->destroy(vatom);
    memory->create(vatom, maxvatom, 6, "nscd:vatom");
  }
  for (int i = 0; i < atom->nlocal + atom->nghost; i++)
    for (int k = 0; k < 6; k++) vatom[i][k] = 0.0;
}

/* One Moreau-Jean step: contacts at the current positions (found in this step's force
   phase), impulses solved, then velocities and positions of the group's grains updated. */
void FixNSCD::final_integrate()
{
  NSCDPartTimes &times = solver->times;
  double t0 = platform::walltime();
  auto lap = [&](int part) {
    const double now = platform::walltime();
    times[part] += now - t0;
    t0 = now;
  };
  dt = update->dt;
  if (neighbor->ago == 0) check_no_points_in_group();
  exchange_mode = Exchange::state;
  comm->forward_comm(this, 12);
  build_bodies();
  lap(Solver::SETUP);
  gather_contacts();
  count_shares();
  if (direct_exchange() && neighbor->lastcall != copies_planned_at) plan_grain_copies();
  prepare_problem();
  lap(Solver::SETUP);
  solve();
  lap(Solver::SWEEPS);
  move_grains();
  exchange_mode = Exchange::motion;    // ghosts' new velocities: next step's activations
  comm->forward_comm(this, 6);
  hand_back_forces();
  solver->warm_start.store(solver->problem.contacts);
  solved_since_filing = true;
  warn_if_unconverged();
  measure_kinetic_energy();
  warn_if_contacts_can_be_missed();
  count_run_statistics();
  warn_if_interpenetrating();
  lap(Solver::UPDATE);
}

/* The run's sweeps, unconverged steps and deepest interpenetration (global values). */
void FixNSCD::count_run_statistics()
{
  Solver::RunStats &run = solver->run;
  const nscd::SolveReport &report = solver->report;
  run.steps++;
  run.sweeps += report.sweeps;
  if (report.sweeps > run.max_sweeps) run.max_sweeps = report.sweeps, run.max_sweeps_step = update->ntimestep;
  if (!report.converged) run.unconverged++;
  if (report.terms.max_interpenetration > run.deepest)
    run.deepest = report.terms.max_interpenetration, run.deepest_step = update->ntimestep;
}

/* The rounding radius is what lets two grains overlap without their cores meeting: the
   interpenetration warning measures depths against the smallest one in the group. */
void FixNSCD::find_smallest_rounding()
{
  double mine = std::numeric_limits<double>::infinity(), all = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && avec->shape[i] != 0 && avec->shape_of(i).radius > 0.0)
      mine = std::min(mine, avec->shape_of(i).radius);
  MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_MIN, world);
  smallest_rounding = std::isfinite(all) ? all : 0.0;
}

/* A converged step can still leave grains sunk into each other: the tolerance is relative,
   and under a heavy load its leftover impulse errors add up step after step (a silo under
   load at tolerance 1e-4: 0.035-0.048 deep with rounding 0.05; at 1e-5: 0.0019). Warned once
   per run, and again each time the depth has grown by half since the last warning. */
void FixNSCD::warn_if_interpenetrating()
{
  const double depth = solver->report.terms.max_interpenetration;
  if (interpenetration_warning <= 0.0 || smallest_rounding <= 0.0) return;
  if (!(depth > interpenetration_warning * smallest_rounding) || !(depth > 1.5 * warned_depth)) return;
  warned_depth = depth;
  if (comm->me != 0) return;
  const double tolerance = solver->options.tolerance;
  error->warning(FLERR, "fix nscd: step {}: grains interpenetrate by {:.3g}, {:.2f} of the smallest rounding radius {:.3g}; use "
                 "tolerance {:.3g}",
                 update->ntimestep, depth, depth / smallest_rounding, smallest_rounding, tolerance / 10.0);
}

/* After a run: the solver's statistics and the time per part and rank. */
void FixNSCD::post_run()
{
  keep_impulses_with_atoms();    // between runs atoms may move (balance, delete_atoms, ...)
  const Solver::RunStats &run = solver->run;
  if (run.steps == 0) return;
  double sent = 0.0;
  MPI_Allreduce(&records_sent, &sent, 1, MPI_DOUBLE, MPI_SUM, world);
  double sent_values = 0.0;
  MPI_Allreduce(&values_sent, &sent_values, 1, MPI_DOUBLE, MPI_SUM, world);
  solver->times[Solver::DETECTION] = timer->get_wall(Timer::PAIR);
  const std::string table = solver->times.table(world, fmt::format("fix nscd {}: time per part", id),
                                                timer->get_wall(Timer::TOTAL));
  const std::string between_ranks = communication_report();
  if (comm->me != 0) return;
  utils::logmesg(lmp, "fix nscd {}: {} steps, sweeps per step {:.4g} on average, at most {:.0f} (step {}); "
                 "{} unconverged ({:.3g} %, tolerance {:.3g}); deepest interpenetration {:.4g} (step {})\n{}",
                 id, run.steps, run.sweeps / run.steps, run.max_sweeps, run.max_sweeps_step, run.unconverged,
                 100.0 * run.unconverged / run.steps, solver->options.tolerance, run.deepest, run.deepest_step,
                 table);
  if (comm->nprocs > 1)
    utils::logmesg(lmp, "fix nscd {}: warm start kept with the atoms: {:.0f} records packed for other ranks "
                   "over the run (ghosts' records to their owners, records of migrating atoms), {:.4g} MB with "
                   "their counts\n", id, sent, sent_values * sizeof(double) / 1048576.0);
  utils::logmesg(lmp, between_ranks);
}

/* Collective. After a run on several ranks: what fix nscd's exchanges carried between ranks
   (comm_count(), summed over the ranks; per rank, the average), per sweep exchange, per step
   and over the run (doc/scaling.md, "Counted"); the text on rank 0, empty on one rank. */
std::string FixNSCD::communication_report()
{
  if (comm->nprocs == 1) return "";
  const std::vector<NSCDCommCount::Tally> all = comm_counts.summed(world);
  double mine[3] = {records_received, records_migrated, values_migrated}, sums[3];
  MPI_Allreduce(mine, sums, 3, MPI_DOUBLE, MPI_SUM, world);
  if (comm->me != 0) return "";
  const double ranks = comm->nprocs, steps = (double) solver->run.steps;
  const double exchanges = std::max(1.0, (double) exchanges_run);
  const NSCDCommCount::Tally &sweep = all[COMM_SWEEP], &state = all[COMM_GHOST_STATE], &step = all[COMM_STEP],
                             &records = all[COMM_RECORDS];
  return fmt::format(
      "fix nscd {0}: between ranks (messages received from another rank; per rank: the average over {1:.0f}):\n"
      "fix nscd {0}: per sweep exchange: {4:.4g} messages, {5:.4g} bytes per rank ({2:.0f} exchanges, {3:.4g} per "
      "step)\n"
      "fix nscd {0}: per step: ghosts' state {7:.4g} messages, {8:.4g} bytes per rank ({6:.4g} ghosts from another "
      "rank); motion, shares and virial {9:.4g} messages, {10:.4g} bytes per rank; {11:.4g} solver reductions "
      "(MPI_Allreduce)\n"
      "fix nscd {0}: warm start over the run: {12:.0f} ghosts' records to their owners in {13:.0f} messages, "
      "{14:.4g} MB; {15:.0f} records with migrating atoms, {16:.4g} MB\n",
      id, ranks, (double) exchanges_run, exchanges_run / std::max(1.0, steps), sweep.messages / exchanges / ranks,
      sweep.bytes / exchanges / ranks, state.atoms / steps / ranks, state.messages / steps / ranks,
      state.bytes / steps / ranks, step.messages / steps / ranks, step.bytes / steps / ranks,
      reductions_run / std::max(1.0, steps), sums[0], records.messages, records.bytes / 1048576.0, sums[1],
      sums[2] * sizeof(double) / 1048576.0);
}

void FixNSCD::build_bodies()
{
  const int ntotal = atom->nlocal + atom->nghost;
  solver->problem.bodies.resize(ntotal);
  double **x = atom->x, **v = atom->v, **f = atom->f;
  for (int b = 0; b < ntotal; b++) {
    nscd::SolverBody &body = solver->problem.bodies[b];
    // From scratch: the slot may have held a boundary's body (the plate's, with locked x and
    // y axes) on an earlier step with fewer ghosts.
    body = nscd::SolverBody();
    body.position = vec3(x[b]);
    body.velocity = vec3(v[b]);
    body.angular_velocity = vec3(avec->omega[b]);
    const bool mobile = (atom->mask[b] & groupbit) && avec->shape[b] != 0;
    if (!mobile) continue;    // not integrated here: moves with its own velocity, infinite mass
    const nscd::Vec3 moments = vec3(avec->inertia[b]);
    const nscd::Quat q = quat_of(avec->quat[b]);
    body.inv_mass = 1.0 / avec->rmass[b];
    try {
      body.inv_inertia = nscd::world_inverse_inertia(moments, q);
    } catch (std::exception &e) {
      error->one(FLERR, "fix nscd: grain ID {}: {}", atom->tag[b], e.what());
    }
    body.external_impulse = dt * vec3(f[b]);
    body.external_angular_impulse =
        dt * (vec3(avec->torque[b]) + nscd::gyroscopic_torque(moments, q, body.angular_velocity));
  }
  global_bodies.clear();
  global_body_fixes.clear();
  for (size_t k = 0; k < boundaries.size(); k++) {
    NSCDBoundary *b = boundaries[k];
    if (!b->has_body()) continue;
    global_body_fixes.push_back(boundary_fixes[k]);
    b->set_body_index((int) solver->problem.bodies.size());
    global_bodies.push_back((int) solver->problem.bodies.size());
    solver->problem.bodies.push_back(b->body(dt));
  }
}

void FixNSCD::gather_contacts()
{
  solver->problem.contacts = pair->contacts();
  pair_count = solver->problem.contacts.size();
  boundary_counts.assign(boundaries.size(), 0);
  const double t0 = platform::walltime();
  for (size_t k = 0; k < boundaries.size(); k++) {
    const size_t before = solver->problem.contacts.size();
    boundaries[k]->append_contacts(solver->problem.contacts, pair->activation_distance(), dt);
    boundary_counts[k] = (int) (solver->problem.contacts.size() - before);
  }
  const double boundary_time = platform::walltime() - t0;
  solver->times[Solver::BOUNDARIES] += boundary_time;
  solver->times[Solver::SETUP] -= boundary_time;    // final_integrate counts all of this as setup
  warm_start_contacts();
  // Impulses scale with the step: after a `timestep` change, start from the same forces.
  if (warm_start_dt > 0.0 && warm_start_dt != dt)
    for (nscd::Contact &c : solver->problem.contacts) c.impulse *= dt / warm_start_dt;
  warm_start_dt = dt;
}

/* Impulses of the last step, by contact key: from the solver's cache, or, after the atoms
   moved (new neighbor lists, a restart), from the records their atoms brought along. */
void FixNSCD::warm_start_contacts()
{
  if (impulses_with_atoms) take_impulses_from_atoms();
  solver->warm_start.apply(solver->problem.contacts);
}

/* Collective. Before atoms move (pre_exchange on a list rebuild, the end of a run, a restart
   file) each record of the last solve goes to both of its atoms (a boundary contact's to
   its grain), as seen from that atom; records filed with ghosts go to their owners. The
   rank that solves a contact next owns at least one of its atoms, and so finds its record.
   Only the ghosts' records travel, to the neighbouring ranks: O(contacts across the
   sub-domain surfaces), not a gather. */
void FixNSCD::keep_impulses_with_atoms()
{
  if (!solved_since_filing) return;    // the atoms already hold the latest impulses (or none)
  solved_since_filing = false;
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) solver->atom_impulses.clear(i);
  for (const nscd::Contact &c : solver->problem.contacts) {
    const nscd::ImpulseRecord record = nscd::record_of(c);
    keep_record_with(c.body_i, record);
    if (record.tag_j > 0) keep_record_with(c.body_j, nscd::reversed(record));    // a grain, not a boundary
  }
  hand_ghost_records_to_owners();
  solver->warm_start.release();
  impulses_with_atoms = true;
  maxexchange = NSCDAtomImpulses::values_for(solver->atom_impulses.longest(0, atom->nlocal));
}

/* Collective. Reverse communication in rounds of at most RECORDS_PER_GHOST records per ghost
   (LAMMPS' variable-size reverse communication does not work with comm_style tiled), until
   no ghost holds any: each round moves records one hop towards their owners. */
void FixNSCD::hand_ghost_records_to_owners()
{
  exchange_mode = Exchange::records;
  while (true) {
    const bigint mine = (bigint) solver->atom_impulses.count(atom->nlocal, atom->nghost);
    bigint all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    if (all == 0) return;
    comm->reverse_comm(this, ghost_records_slot());
  }
}

/* Per ghost: its place in the message, its record count and records; a message adds one
   value (how many ghosts send), covered by the place of any one ghost. */
int FixNSCD::ghost_records_slot()
{
  return 1 + NSCDAtomImpulses::values_for(RECORDS_PER_GHOST) + 1;
}

/* The record goes to the atom at atom_index (the contact's body) if that is still the
   atom of record.tag_i, else to wherever the atom map puts that ID (a fix that added
   atoms before this one's pre_exchange moves the ghosts); a record whose atom this rank no
   longer has is dropped (that contact starts from zero). */
void FixNSCD::keep_record_with(int atom_index, const nscd::ImpulseRecord &record)
{
  const int nall = atom->nlocal + atom->nghost;
  if (atom_index < 0 || atom_index >= nall || atom->tag[atom_index] != record.tag_i)
    atom_index = atom->map((tagint) record.tag_i);
  if (atom_index >= 0 && atom_index < nall) solver->atom_impulses.add(atom_index, record);
}

/* The records of the owned atoms become the solver's cache (a contact both of whose atoms
   this rank owns comes twice and is kept once); the atoms' lists are emptied. */
void FixNSCD::take_impulses_from_atoms()
{
  std::vector<nscd::ImpulseRecord> held;
  solver->atom_impulses.move_all(0, atom->nlocal, held);
  solver->warm_start.store(held);
  impulses_with_atoms = false;
}

/* A restart file of format 3 holds every contact's record in the global block: each rank
   keeps those of its own atoms, as if they had been written per atom. */
void FixNSCD::keep_restored_records(const std::vector<nscd::ImpulseRecord> &records)
{
  std::unordered_map<tagint, int> owned;
  owned.reserve(atom->nlocal);
  for (int i = 0; i < atom->nlocal; i++) owned[atom->tag[i]] = i;
  for (const nscd::ImpulseRecord &r : records)
    for (const nscd::ImpulseRecord &side : {r, nscd::reversed(r)}) {
      const auto it = owned.find((tagint) side.tag_i);
      if (it != owned.end()) solver->atom_impulses.add(it->second, side);
    }
  impulses_with_atoms = true;
  maxexchange = NSCDAtomImpulses::values_for(solver->atom_impulses.longest(0, atom->nlocal));
}

/* A fix that migrates atoms in its pre_exchange (fix balance, ...) must come after this one:
   the records are filed by the local indices of the last solve, before anything moves. */
void FixNSCD::check_no_migration_before_this_fix()
{
  NSCD_NS::refuse_migration_before(lmp, this, "its warm-start impulses");
}

bool FixNSCD::owned_here(tagint tag) const
{
  const int i = atom->map(tag);
  return i >= 0 && i < atom->nlocal;
}

size_t FixNSCD::warm_start_records_held() const
{
  return solver->atom_impulses.count(0, atom->nlocal + atom->nghost) + solver->warm_start.size();
}

/* Ghosts hold no records (handed to their owners), and the cache holds this rank's own
   contacts. Needs an atom map. */
size_t FixNSCD::warm_start_records_of_other_ranks() const
{
  size_t foreign = solver->atom_impulses.count(atom->nlocal, atom->nghost);
  for (int i = 0; i < atom->nlocal; i++)
    for (const nscd::ImpulseRecord &r : solver->atom_impulses.of(i))
      if (!owned_here((tagint) r.tag_i)) foreign++;
  for (const nscd::ImpulseRecord &r : solver->warm_start.records())
    if (!owned_here((tagint) r.tag_i) && !(r.tag_j > 0 && owned_here((tagint) r.tag_j))) foreign++;
  return foreign;
}

/* Of the last solve's contacts: the pair style's list may be newer (a run's setup finds
   contacts at the positions after the last move). */
int FixNSCD::boundary_of(size_t contact) const
{
  size_t first = pair_count;
  if (contact < first) return 0;
  for (size_t k = 0; k < boundary_counts.size(); k++) {
    first += boundary_counts[k];
    if (contact < first) return (int) k + 1;
  }
  return 0;
}

/* Mass splitting (nscd::SolverBody::share): how many copies of each body, owner and ghosts
   over all ranks, carry contacts. Each copy counts 1 if a contact here touches it; reverse
   communication sums the counts into the owner (through intermediate ghosts), forward
   communication hands the owner's total to every ghost. A body every rank holds (the
   plate) sums over the ranks. */
void FixNSCD::count_shares()
{
  for (nscd::SolverBody &body : solver->problem.bodies) body.share = 0.0;
  for (const nscd::Contact &c : solver->problem.contacts) {
    solver->problem.bodies[c.body_i].share = 1.0;
    if (c.body_j >= 0) solver->problem.bodies[c.body_j].share = 1.0;
  }
  exchange_mode = Exchange::share;
  comm->reverse_comm(this, 1);
  comm->forward_comm(this, 1);
  for (int b : global_bodies) {
    double mine = solver->problem.bodies[b].share;
    MPI_Allreduce(&mine, &solver->problem.bodies[b].share, 1, MPI_DOUBLE, MPI_SUM, world);
  }
  for (nscd::SolverBody &body : solver->problem.bodies) body.share = std::max(1.0, body.share);
  split_owned.clear();
  for (int b = 0; b < atom->nlocal; b++)
    if (solver->problem.bodies[b].share != 1.0) split_owned.push_back(b);
}

/* The Delassus blocks and free velocities of the step's contacts. */
void FixNSCD::prepare_problem()
{
  solver->options.dt = dt;
  if (update->ntimestep == problem_step) write_problem();
  try {
    solver->problem.prepare(solver->options);
  } catch (std::exception &e) {    // the solver names local indices; say which grains
    const nscd::Contact &first = solver->problem.contacts.empty() ? nscd::Contact() : solver->problem.contacts[0];
    error->one(FLERR, "fix nscd: bad contact problem ({}); grains of the first contact: IDs {} "
               "and {}", e.what(), first.key.tag_i, first.key.tag_j);
  }
}

/* write_problem: this step's contact problem as the solver gets it (before prepare()), one
   file per rank, for benchmarks/solver/replay_problem (doc/Howto_nscd_solver.rst). */
void FixNSCD::write_problem()
{
  const std::string name = comm->nprocs > 1 ? fmt::format("{}.{}", problem_file, comm->me) : problem_file;
  std::ofstream out(name);
  nscd::write_problem(out, solver->problem, dt, solver->options.theta);
  out.close();
  if (!out) error->one(FLERR, "fix nscd: write_problem: cannot write {}", name);
  if (comm->me == 0)
    utils::logmesg(lmp, "fix nscd {}: step {}: contact problem written to {}{}\n", id, update->ntimestep,
                   problem_file, comm->nprocs > 1 ? ".RANK" : "");
}

/* Gauss-Seidel sweeps on this rank's contacts; between sweeps the velocity corrections of
   ghost grains go to their owners and the owners' velocities back to all copies, so every
   rank iterates on the same global velocities. The convergence test is global. */
void FixNSCD::solve()
{
  // lib/solver's loop, its communication done by exchange_velocities() (ghost velocities) and
  // MPI_Allreduce, so every decision (stop, restart, coarse correction) is global.
  // The communication's time (waiting for the other ranks included) is counted apart from
  // the sweeps' (final_integrate counts the whole solve as sweeps).
  double comm_time = 0.0;
  auto timed = [&comm_time](auto &&work) {
    const double t0 = platform::walltime();
    work();
    comm_time += platform::walltime() - t0;
  };
  nscd::SolverCommunication communication;
  communication.exchange = [&](nscd::ContactProblem &) {
    exchanges_run++;
    timed([&] { exchange_velocities(); });
  };
  communication.sum = [&](double *values, int n) {
    reductions_run++;
    timed([&] { MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_SUM, world); });
  };
  communication.max = [&](double *values, int n) {
    reductions_run++;
    timed([&] { MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_MAX, world); });
  };
  communication.exchange_every = exchange_every;
  solver->report = nscd::iterate(solver->problem, solver->options, communication);
  solver->times[Solver::SWEEP_COMM] += comm_time;
  solver->times[Solver::SWEEPS] -= comm_time;
  if (!std::isfinite(solver->report.residual)) stop_on_non_finite_problem();
}

/* A residual of inf or NaN: some external force or velocity is not finite or so large that
   the impulses overflow. Name the body with the largest external impulse. */
void FixNSCD::stop_on_non_finite_problem()
{
  const std::vector<nscd::SolverBody> &bodies = solver->problem.bodies;
  double mine[2] = {-1.0, -1.0};    // |external impulse| (inf if not finite), body
  auto consider = [&](int b) {
    const double size = bodies[b].external_impulse.allFinite() && bodies[b].velocity.allFinite()
        ? bodies[b].external_impulse.norm() : INFINITY;
    if (size > mine[0]) mine[0] = size, mine[1] = b < atom->nlocal ? (double) atom->tag[b] : -1.0 - b;
  };
  for (int b = 0; b < atom->nlocal; b++) consider(b);
  if (comm->me == 0)
    for (int b : global_bodies) consider(b);
  double worst[2];
  MPI_Allreduce(mine, worst, 1, MPI_2DOUBLE_PRECISION, MPI_MAXLOC, world);
  std::string culprit = fmt::format("grain ID {}", (tagint) worst[1]);
  if (worst[1] < 0.0) {    // a boundary's own body: which fix?
    const int index = (int) (-1.0 - worst[1]);
    for (size_t k = 0; k < global_bodies.size(); k++)
      if (global_bodies[k] == index) culprit = fmt::format("fix {}'s body", global_body_fixes[k]->id);
  }
  error->all(FLERR, "fix nscd: step {}: no finite solution (residual {}); the largest impulse, {:.3g}, acts on {} "
             "(doc/fix_nscd.rst, Errors)", update->ntimestep, solver->report.residual, worst[0], culprit);
}

void FixNSCD::exchange_velocities()
{
  exchange_copies(Exchange::correction);
  // The owners now hold the sum of their copies' corrections; with mass splitting their
  // velocity changes by the mean.
  for (int b : split_owned) {
    nscd::SolverBody &body = solver->problem.bodies[b];
    const double excess = 1.0 - 1.0 / body.share;
    body.velocity -= excess * solver->problem.velocity_correction(b);
    body.angular_velocity -= excess * solver->problem.angular_velocity_correction(b);
  }
  exchange_copies(Exchange::velocity);
  // A body every rank holds takes the corrections of all ranks' contacts.
  for (int b : global_bodies) {
    nscd::SolverBody &body = solver->problem.bodies[b];
    double mine[6], all[6];
    const nscd::Vec3 dv = solver->problem.velocity_correction(b), dw = solver->problem.angular_velocity_correction(b);
    for (int d = 0; d < 3; d++) {
      mine[d] = dv[d];
      mine[3 + d] = dw[d];
    }
    MPI_Allreduce(mine, all, 6, MPI_DOUBLE, MPI_SUM, world);
    for (int d = 0; d < 3; d++) {
      body.velocity[d] += all[d] / body.share - mine[d];
      body.angular_velocity[d] += all[3 + d] / body.share - mine[3 + d];
    }
  }
  solver->problem.mark_synchronised();
}

/* The sweeps' exchange on several ranks goes straight between the ranks owning and holding
   copies of grains, one message per pair of ranks and direction, grains only (the wire's
   nodes are most of the ghosts on the papers' column); on one rank (periodic images only)
   through LAMMPS' comm, which keeps one rank's trajectory to the last bit as it was.
   `correction`: the copies' velocity changes added to their owners; `velocity`: the owners'
   velocities to their copies. */
void FixNSCD::exchange_copies(Exchange mode)
{
  exchange_mode = mode;
  const bool reverse = mode == Exchange::correction;
  if (!direct_exchange()) {
    if (reverse) comm->reverse_comm(this, 6);
    else comm->forward_comm(this, 6);
    return;
  }
  nscd::ContactProblem &problem = solver->problem;
  auto put = [](const nscd::Vec3 &a, const nscd::Vec3 &b, double *out) {
    for (int d = 0; d < 3; d++) out[d] = a[d], out[3 + d] = b[d];
  };
  if (reverse) {
    auto pack = [&](int c, double *out) {
      put(problem.velocity_correction(copy_atoms[c]), problem.angular_velocity_correction(copy_atoms[c]), out);
    };
    auto add = [&](int i, const double *in) {
      nscd::SolverBody &body = problem.bodies[i];
      for (int d = 0; d < 3; d++) body.velocity[d] += in[d], body.angular_velocity[d] += in[3 + d];
    };
    grain_copies.reverse_values(6, pack, add, comm_counts, COMM_SWEEP);
  } else {
    auto pack = [&](int i, double *out) { put(problem.bodies[i].velocity, problem.bodies[i].angular_velocity, out); };
    auto take = [&](int c, const double *in) {
      nscd::SolverBody &body = problem.bodies[copy_atoms[c]];
      for (int d = 0; d < 3; d++) body.velocity[d] = in[d], body.angular_velocity[d] = in[3 + d];
    };
    grain_copies.forward_values(6, pack, take, comm_counts, COMM_SWEEP);
  }
}

bool FixNSCD::direct_exchange() const { return comm->nprocs > 1; }

/* After a neighbour build on several ranks: each ghost grain learns its owner's rank and atom
   index there (one LAMMPS forward_comm, which relays ghosts of ghosts), and the sweeps'
   exchange is planned from them. */
void FixNSCD::plan_grain_copies()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  origin_buffer.assign(2 * (size_t) nall, -1.0);
  for (int i = 0; i < nlocal; i++) origin_buffer[2 * (size_t) i] = comm->me, origin_buffer[2 * (size_t) i + 1] = i;
  exchange_mode = Exchange::origin;
  comm->forward_comm(this, 2);
  std::vector<NSCDCopyExchange::Origin> origins;
  copy_atoms.clear();
  for (int i = nlocal; i < nall; i++) {
    if (!in_sweep_exchange(i)) continue;
    const double *o = &origin_buffer[2 * (size_t) i];
    copy_atoms.push_back(i);
    origins.push_back({(int) o[0], (int) o[1], {0.0, 0.0, 0.0}});
  }
  grain_copies.plan(origins, world, comm_counts, COMM_STEP);
  copies_planned_at = neighbor->lastcall;
  plans_run++;
}

void FixNSCD::move_grains()
{
  double **x = atom->x, **v = atom->v;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || avec->shape[i] == 0) continue;
    const nscd::SolverBody &body = solver->problem.bodies[i];
    nscd::Pose pose;
    pose.position = vec3(x[i]);
    pose.orientation = quat_of(avec->quat[i]);
    nscd::advance_pose(pose, vec3(v[i]), vec3(avec->omega[i]), body.velocity,
                       body.angular_velocity, dt, solver->options.theta);
    store(pose.position, x[i]);
    avec->quat[i][0] = pose.orientation.w();
    avec->quat[i][1] = pose.orientation.x();
    avec->quat[i][2] = pose.orientation.y();
    avec->quat[i][3] = pose.orientation.z();
    store(body.velocity, v[i]);
    store(body.angular_velocity, avec->omega[i]);
  }
  size_t next_body = 0;    // global bodies were added in boundary order
  for (NSCDBoundary *b : boundaries) {
    if (b->has_body()) b->take_body(solver->problem.bodies[global_bodies[next_body++]], dt, solver->options.theta);
    b->advance(dt);
  }
}

/* Solved impulses / dt are the contact forces of the step: their virial (this fix's, for
   pressure and compute stress/atom) and the boundaries' reactions. */
void FixNSCD::hand_back_forces()
{
  const std::vector<nscd::Contact> &c = solver->problem.contacts;
  if (vflag_global || vflag_atom) {    // (Fix::v_setup of this LAMMPS leaves vflag_either unset)
    for (const nscd::Contact &contact : c) {
      const nscd::Vec3 force = contact.impulse / dt;
      tally_virial(contact.body_i, contact.body_j, contact.point.data(), force.data());
    }
    if (vflag_atom) {    // ghosts' shares go to their owners
      exchange_mode = Exchange::virial;
      comm->reverse_comm(this, 6);
    }
  }
  size_t first = pair_count;
  for (size_t k = 0; k < boundaries.size(); k++) {
    boundaries[k]->take_impulses(c.data() + first, boundary_counts[k], dt);
    first += boundary_counts[k];
  }
}

/* Grain pair: (x_i - x_j) (x) F, half to each grain. Boundary (wall, plate): (x_i - contact
   point) (x) F, all to the grain, as LAMMPS' wall fixes do. */
void FixNSCD::tally_virial(int i, int j, const double *point, const double *force)
{
  if (j >= atom->nlocal + atom->nghost) j = nscd::kEnvironment;    // a boundary's own body
  const nscd::Vec3 d = vec3(atom->x[i]) - vec3(j >= 0 ? atom->x[j] : point);
  const nscd::Vec3 f = vec3(force);
  const double v[6] = {d.x() * f.x(), d.y() * f.y(), d.z() * f.z(),
                       d.x() * f.y(), d.x() * f.z(), d.y() * f.z()};
  if (vflag_global)
    for (int k = 0; k < 6; k++) virial[k] += v[k];
  if (!vflag_atom) return;
  const double share = j >= 0 ? 0.5 : 1.0;
  for (int k = 0; k < 6; k++) vatom[i][k] += share * v[k];
  if (j >= 0)
    for (int k = 0; k < 6; k++) vatom[j][k] += share * v[k];
}

void FixNSCD::warn_if_unconverged()
{
  if (solver->report.converged) return;
  unconverged_steps++;
  const bigint step = update->ntimestep;
  if (last_warning_step >= 0 && step - last_warning_step < warn_every) return;
  last_warning_step = step;
  if (comm->me == 0)
    error->warning(FLERR, "fix nscd: step {} ended unconverged: residual {:.3g} > tolerance {:.3g} after {} sweeps ({} such steps "
                   "so far)",
                   step, solver->report.residual, solver->options.tolerance, solver->report.sweeps, unconverged_steps);
}

/* Contacts are found at the start of a step for gaps below the activation distance. Two
   grains closing faster than that per step can meet unseen and overlap: say so. */
void FixNSCD::warn_if_contacts_can_be_missed()
{
  double mine = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && avec->shape[i] != 0)
      mine = std::max(mine, vec3(atom->v[i]).norm() + vec3(avec->omega[i]).norm() * avec->radius[i]);
  MPI_Allreduce(&mine, &max_step_travel, 1, MPI_DOUBLE, MPI_MAX, world);
  max_step_travel *= 2.0 * dt;    // two grains approaching each other
  const double needed = speculative_activation(pair->activation_distance(), max_step_travel / dt, dt);
  const double covered = pair->activation_distance() + pair->reach_distance();
  if (needed <= covered) return;
  const bigint step = update->ntimestep;
  if (last_speed_warning_step >= 0 && step - last_speed_warning_step < warn_every) return;
  last_speed_warning_step = step;
  if (comm->me == 0)
    error->warning(FLERR, "fix nscd: step {}: grains close gaps of up to {:.3g} per step, contacts are found {:.3g} "
                   "ahead; raise reach to {:.3g}",
                   step, max_step_travel, covered, needed - pair->activation_distance());
}

void FixNSCD::measure_kinetic_energy()
{
  double mine[2] = {0.0, 0.0};
  double **v = atom->v;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || avec->shape[i] == 0) continue;
    mine[0] += 0.5 * avec->rmass[i] * vec3(v[i]).squaredNorm();
    const nscd::Vec3 w_body = quat_of(avec->quat[i]).conjugate() * vec3(avec->omega[i]);
    mine[1] += 0.5 * w_body.dot(vec3(avec->inertia[i]).cwiseProduct(w_body));
  }
  double total[2];
  MPI_Allreduce(mine, total, 2, MPI_DOUBLE, MPI_SUM, world);
  kinetic_translational = total[0];
  kinetic_rotational = total[1];
}

double FixNSCD::compute_vector(int n)
{
  switch (n) {
    case SWEEPS: return solver->report.sweeps;
    case RESIDUAL: return solver->report.residual;
    case MAX_INTERPENETRATION: return solver->report.terms.max_interpenetration;
    case CONTACTS: return (double) solver->report.terms.contacts;
    case ACTIVE: return (double) solver->report.terms.active;
    case STICKING: return (double) solver->report.terms.sticking;
    case SLIDING: return (double) solver->report.terms.sliding;
    case CONVERGED: return solver->report.converged ? 1.0 : 0.0;
    case KE_TRANSLATION: return kinetic_translational;
    case KE_ROTATION: return kinetic_rotational;
  }
  return 0.0;
}

/* The contact problem (bodies, contacts, rows), the warm-start impulses (the solver's cache
   and those kept with the atoms) and the per-atom virial LAMMPS allocated for this fix: the
   bulk of a rank's memory in a dense pile (doc/scaling.md). */
double FixNSCD::memory_usage()
{
  const std::size_t bytes = solver->problem.memory_bytes() + solver->warm_start.memory_bytes() +
      solver->atom_impulses.memory_bytes() +
      nscd::capacity_bytes(boundary_counts) + nscd::capacity_bytes(global_bodies) + nscd::capacity_bytes(split_owned) +
      nscd::capacity_bytes(global_body_fixes) + nscd::capacity_bytes(boundaries) +
      nscd::capacity_bytes(boundary_fixes) + grain_copies.memory_bytes() + nscd::capacity_bytes(copy_atoms) +
      nscd::capacity_bytes(origin_buffer);
  return (double) bytes + (double) maxvatom * 6 * sizeof(double);
}

/* Communication: `state` sends v, omega, f, torque to ghosts before the solve; during it,
   `correction` sums ghost velocity changes into owners and `velocity` copies owners'
   solver velocities to their ghosts (through LAMMPS' comm on one rank only: on several,
   exchange_copies() sends them itself, and `origin` plans that). */
int FixNSCD::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  comm_counts.packed(buf);
  int m = 0;
  if (exchange_mode == Exchange::share) {
    for (int k = 0; k < n; k++) buf[m++] = solver->problem.bodies[list[k]].share;
    return m;
  }
  if (exchange_mode == Exchange::origin) {
    for (int k = 0; k < n; k++) {
      if (!in_sweep_exchange(list[k])) continue;
      const double *o = &origin_buffer[2 * (size_t) list[k]];
      buf[m++] = o[0];
      buf[m++] = o[1];
    }
    return m;
  }
  for (int k = 0; k < n; k++) {
    const int i = list[k];
    if (exchange_mode == Exchange::state) {
      for (double *a : {atom->v[i], avec->omega[i], atom->f[i], avec->torque[i]})
        for (int d = 0; d < 3; d++) buf[m++] = a[d];
    } else if (exchange_mode == Exchange::motion) {
      for (double *a : {atom->v[i], avec->omega[i]})
        for (int d = 0; d < 3; d++) buf[m++] = a[d];
    } else if (in_sweep_exchange(i)) {
      const nscd::SolverBody &body = solver->problem.bodies[i];
      for (int d = 0; d < 3; d++) buf[m++] = body.velocity[d];
      for (int d = 0; d < 3; d++) buf[m++] = body.angular_velocity[d];
    }
  }
  return m;
}

void FixNSCD::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    if (exchange_mode == Exchange::share) {
      solver->problem.bodies[i].share = buf[m++];
    } else if (exchange_mode == Exchange::origin) {
      if (!in_sweep_exchange(i)) continue;
      origin_buffer[2 * (size_t) i] = buf[m++];
      origin_buffer[2 * (size_t) i + 1] = buf[m++];
    } else if (exchange_mode == Exchange::state) {
      for (double *a : {atom->v[i], avec->omega[i], atom->f[i], avec->torque[i]})
        for (int d = 0; d < 3; d++) a[d] = buf[m++];
    } else if (exchange_mode == Exchange::motion) {
      for (double *a : {atom->v[i], avec->omega[i]})
        for (int d = 0; d < 3; d++) a[d] = buf[m++];
    } else if (in_sweep_exchange(i)) {
      nscd::SolverBody &body = solver->problem.bodies[i];
      for (int d = 0; d < 3; d++) body.velocity[d] = buf[m++];
      for (int d = 0; d < 3; d++) body.angular_velocity[d] = buf[m++];
    }
  }
  comm_counts.unpacked(comm_kind(), n, m, buf);
}

/* Whether atom i's copies take part in the exchanges between sweeps. Points (wire nodes)
   have no contact in the solver: their velocity corrections are zero and their solver
   velocities are read by nobody, so sending them would only cost (on the papers' column
   with closed rings, 703 of a rank's 1129 ghosts from the other rank are wire nodes).
   Owner and ghost decide alike: the shape travels with the atom's copies. */
bool FixNSCD::in_sweep_exchange(int i) const
{
  return avec->shape[i] != 0;
}

/* The kind of exchange the current mode counts as (comm_count()). */
FixNSCD::CommKind FixNSCD::comm_kind() const
{
  switch (exchange_mode) {
    case Exchange::correction:
    case Exchange::velocity: return COMM_SWEEP;
    case Exchange::state: return COMM_GHOST_STATE;
    case Exchange::records: return COMM_RECORDS;
    default: return COMM_STEP;
  }
}

int FixNSCD::pack_reverse_comm(int n, int first, double *buf)
{
  comm_counts.packed(buf);
  int m = 0;
  if (exchange_mode == Exchange::records) {    // the ghosts' last records go to their owners, and leave them
    if (n == 0) return 0;    // (a rank that receives for no atom expects nothing)
    m = 1;                   // {number of ghosts sending, then per ghost: its place k, its records}
    int sending = 0;
    for (int k = 0; k < n; k++) {
      if (solver->atom_impulses.of(first + k).empty()) continue;
      buf[m++] = k;
      const int packed = solver->atom_impulses.pack_last(first + k, RECORDS_PER_GHOST, buf + m);
      records_sent += (double) (packed - 1) / NSCDAtomImpulses::VALUES_PER_RECORD;
      m += packed;
      sending++;
    }
    buf[0] = sending;
    values_sent += m;
    return m;
  }
  if (exchange_mode == Exchange::virial) {
    for (int i = first; i < first + n; i++)
      for (int k = 0; k < 6; k++) {
        buf[m++] = vatom[i][k];
        vatom[i][k] = 0.0;
      }
    return m;
  }
  if (exchange_mode == Exchange::share) {
    for (int i = first; i < first + n; i++) buf[m++] = solver->problem.bodies[i].share;
    return m;
  }
  for (int i = first; i < first + n; i++) {
    if (!in_sweep_exchange(i)) continue;
    const nscd::Vec3 dv = solver->problem.velocity_correction(i), dw = solver->problem.angular_velocity_correction(i);
    for (int d = 0; d < 3; d++) buf[m++] = dv[d];
    for (int d = 0; d < 3; d++) buf[m++] = dw[d];
  }
  return m;
}

void FixNSCD::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  if (exchange_mode == Exchange::records) {
    if (n == 0) return;
    const int sending = (int) buf[m++];
    double records = 0.0;
    for (int e = 0; e < sending; e++) {
      const int k = (int) buf[m++];
      const int read = solver->atom_impulses.unpack_append(list[k], buf + m);
      records += (double) (read - 1) / NSCDAtomImpulses::VALUES_PER_RECORD;
      m += read;
    }
    if (comm_counts.unpacked(COMM_RECORDS, n, m, buf)) records_received += records;
    return;
  }
  for (int k = 0; k < n; k++) {
    if (exchange_mode == Exchange::virial) {
      for (int c = 0; c < 6; c++) vatom[list[k]][c] += buf[m++];
    } else if (exchange_mode == Exchange::share) {
      solver->problem.bodies[list[k]].share += buf[m++];
    } else if (in_sweep_exchange(list[k])) {
      nscd::SolverBody &body = solver->problem.bodies[list[k]];
      for (int d = 0; d < 3; d++) body.velocity[d] += buf[m++];
      for (int d = 0; d < 3; d++) body.angular_velocity[d] += buf[m++];
    }
  }
  comm_counts.unpacked(comm_kind(), n, m, buf);
}

/* Restart: the timestep of the last solved impulses; the impulses themselves are written
   per atom (pack_restart), after this call has handed them to the atoms. Format:
   nscd_restart_blocks.h. */
void FixNSCD::write_restart(FILE *fp)
{
  keep_impulses_with_atoms();
  NSCD_NS::SolverBlock block;
  block.dt = warm_start_dt;
  if (comm->me == 0) NSCD_NS::write_block(fp, NSCD_NS::solver_block(block));
}

/* read_restart hands every rank the block written above (without its size). A file of
   format 3 holds every contact's record here: each rank keeps its own atoms'. */
void FixNSCD::restart(char *bytes)
{
  NSCD_NS::SolverBlock block = NSCD_NS::read_restart_block(
      lmp, this, NSCD_NS::read_solver_block, bytes, "doc/fix_nscd.rst");
  if (!block.read) {
    NSCD_NS::warn_format_not_read(lmp, this, "warm start", block.format, "the first step starts from zero impulses",
                                  "doc/fix_nscd.rst");
    return;
  }
  // The impulses' timestep, so that a run at another `timestep` starts from the same forces
  // (gather_contacts).
  warm_start_dt = block.dt;
  if (!block.records.empty()) keep_restored_records(block.records);
}

void FixNSCD::grow_arrays(int nmax)
{
  solver->atom_impulses.grow(nmax);
}

void FixNSCD::copy_arrays(int i, int j, int /*delflag*/)
{
  solver->atom_impulses.copy(i, j);
}

void FixNSCD::set_arrays(int i)
{
  solver->atom_impulses.clear(i);
}

int FixNSCD::pack_exchange(int i, double *buf)
{
  const double records = (double) solver->atom_impulses.of(i).size();
  const int m = solver->atom_impulses.pack(i, buf);
  records_sent += records, records_migrated += records;
  values_sent += m, values_migrated += m;
  return m;
}

int FixNSCD::unpack_exchange(int nlocal, double *buf)
{
  solver->atom_impulses.clear(nlocal);
  const int m = solver->atom_impulses.unpack_append(nlocal, buf);
  maxexchange = std::max(maxexchange, m);    // this rank may pass the atom on before the next filing
  return m;
}

/* Per atom in restart files: {number of values (LAMMPS' convention), the atom's records in
   the per-atom format of nscd_restart_blocks.h}. */
int FixNSCD::pack_restart(int i, double *buf)
{
  const std::vector<nscd::ImpulseRecord> &records = solver->atom_impulses.of(i);
  buf[0] = NSCD_NS::atom_impulses_values(records.size()) + 1;
  NSCD_NS::write_atom_impulses(records, buf + 1);
  return (int) buf[0];
}

void FixNSCD::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;    // skip the values of the fixes stored before this one
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  const double size = extra[nlocal][m];
  std::vector<nscd::ImpulseRecord> records;
  try {
    if (!(size >= 1.0 && size <= (double) atom->nextra_store - m))
      throw NSCD_NS::Damaged("atom ID " + std::to_string(atom->tag[nlocal]) + " states " +
                             std::to_string(size) + " per-atom values for it: the file is damaged");
    records = NSCD_NS::read_atom_impulses(&extra[nlocal][m + 1], (std::size_t) size - 1, atom->tag[nlocal]);
  } catch (NSCD_NS::Damaged &e) {
    error->one(FLERR, "fix nscd {}: restart file's warm start refused: {} (doc/fix_nscd.rst, Errors)", id, e.what());
  }
  maxexchange = std::max(maxexchange, NSCDAtomImpulses::values_for(records.size()));
  solver->atom_impulses.set(nlocal, std::move(records));
  impulses_with_atoms = true;
}

int FixNSCD::size_restart(int i)
{
  return NSCD_NS::atom_impulses_values(solver->atom_impulses.of(i).size()) + 1;
}

int FixNSCD::maxsize_restart()
{
  const int mine = NSCD_NS::atom_impulses_values(solver->atom_impulses.longest(0, atom->nlocal)) + 1;
  int all = mine;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MAX, world);
  return all;
}
