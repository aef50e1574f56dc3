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

/* fix wire's setup and step. Setup: the checks of the partners (pair, bonds, angles, fixes
   acting on the nodes), the boundaries, the substep plan and the contact model. The step, in
   post_force: gathers the wire nodes, grains and boundaries, runs lib/wire's step
   (wire_step.h: Gear-5 subcycle, elastic forces, contact_model.h), which integrates the nodes,
   stores their positions and velocities, and hands the mean wire forces to the grains and the
   boundaries. Communication, per-atom arrays, restart and output: fix_wire_io.cpp; breaking:
   fix_wire_break.cpp. The physics is in lib/wire (doc/Howto_nscd_wire_model.rst). */

#include "fix_wire.h"
#include "nscd_checks.h"
#include "nscd_args.h"
#include "nscd_units.h"
#include "fix_wire_lib.h"

#include "angle_wire.h"
#include "atom.h"
#include "atom_vec_spheropolyhedron.h"
#include "bond_wire.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "nscd_arrays.h"
#include "nscd_boundary.h"
#include "nscd_boundary_fix.h"
#include "nscd_contact.h"
#include "nscd_gather.h"
#include "timer.h"
#include "update.h"
#include "wire/contact_model.h"
#include "wire/stability.h"
#include "wire/wire_overlap.h"
#include "wire/wire_step.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

using namespace LAMMPS_NS;
using namespace NSCD_NS;
using namespace FixConst;
using nscd::Vec3;
namespace wire = nscd::wire;

namespace {
// A step of more wire substeps than this never ends in practice; more than the ratio times
// what stability needs is warned about.
constexpr int MAX_SUBSTEPS = 1000000, WARN_SUBSTEPS_RATIO = 10;

enum Diagnostic {
  E_AXIAL, E_BENDING, E_CONTACT, N_WIRE_WIRE, N_WIRE_GRAIN, SUBSTEPS, DT_SP, GRAIN_FX, GRAIN_FY,
  GRAIN_FZ, DT_SP_STABLE, N_WIRE_BOUNDARY, STEPS_TOO_FAST
};

}    // namespace


/* fix ID group wire [k_n K] [gamma_n G] [k_t K] [gamma_t G] [mu_s M] [mu_d M] [mu_ww_s M] [mu_ww_d M]
                     [grain_friction TYPES MU_S MU_D] [radius R]
                     [damp C] [substeps N|auto|stable] [dt_sp DT] [safety S] [contacts_per_node N]
                     [skin S] [inertia S] [grain_springs carried|held] */
FixWire::FixWire(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), lib(new Lib(this)), gear(nullptr), state_dt(0.0), mu_s_given(false),
    mu_d_given(false), k_n_given(false), mu_ww_s(-1.0), mu_ww_d(-1.0), contacts_recorded(false),
    wire_radius(0.0), node_damping(0.0), contact_skin(-1.0), requested_substeps(0), fastest_stable(false),
    springs_held(false), requested_dt_sp(0.0), safety(0.9), contacts_per_node(2.0), inertia_scale(1.0), bond(nullptr),
    angle(nullptr), avec(nullptr), stable_dt_sp(0.0), owned_nodes(0), grains_anywhere(false), indexed_at(-1),
    memories_with_atoms(false), longest_element(0.0), comm_mode(Comm::node_state), counting_comm(false),
    comm_counts(N_COMM_KINDS), migrated(), diagnostics(), largest_tension(0.0), largest_tension_in_run(0.0),
    strength(0.0), strength_spread(0.0), strength_seed(0.0), breaks_file(nullptr), breaks_given(false),
    elements_broken(0), topology_changed(false), specials_stale(false), warned_fast_motion(false), timing(),
    substeps_run(0), rebuilds_at_start(0)
{
  time_integrate = restart_global = restart_peratom = create_attribute = 1;
  maxexchange_dynamic = 1;    // the friction memories travel with their nodes
  maxexchange = GEAR_COLUMNS + 1;
  vector_flag = global_freq = 1;
  size_vector = (int) diagnostics.size();
  extvector = 0;
  comm_forward = comm_reverse = 6;
  for (int iarg = 3; iarg < narg; iarg += 2) parse_option(narg, arg, iarg);
  wire::SoftContactLaw &law = lib->law;
  // One friction coefficient given: static = dynamic (with mu_d left at 0 a contact would
  // lose all friction after its first slip).
  if (mu_s_given && !mu_d_given) law.mu_d = law.mu_s;
  if (mu_d_given && !mu_s_given) law.mu_s = law.mu_d;
  // Wire-wire friction: the same pairing; neither given: the wire-grain values.
  if (mu_ww_s < 0.0 && mu_ww_d < 0.0) mu_ww_s = law.mu_s, mu_ww_d = law.mu_d;
  else if (mu_ww_d < 0.0) mu_ww_d = mu_ww_s;
  else if (mu_ww_s < 0.0) mu_ww_s = mu_ww_d;
  if (law.k_n > 0.0) {    // k_n = 0: no contacts at all, the other coefficients unused
    try {
      wire::validate(law);
    } catch (std::exception &e) {
      error->all(FLERR, "fix wire: {}", e.what());
    }
    if (mu_ww_d > mu_ww_s)
      error->all(FLERR, "fix wire: wire-wire dynamic friction mu_ww_d = {} exceeds the static mu_ww_s = {}; "
                 "use mu_ww_d <= mu_ww_s", mu_ww_d, mu_ww_s);
    if (!(wire_radius > 0.0))
      error->all(FLERR, "fix wire: contacts (k_n {}) need a wire radius > 0; "
                 "give 'radius R' (or k_n 0 for a wire without contacts)", law.k_n);
    if (contacts_per_node < 1.0)
      error->all(FLERR, "fix wire: contacts_per_node {} with contacts (k_n {}); give "
                 "contacts_per_node >= 1 (doc/fix_wire.rst, Errors)", contacts_per_node, law.k_n);
  }
  // A wire of S times the inertia is the same wire in slow motion by sqrt(S) when its
  // dashpots grow by sqrt(S): damping ratios (a contact's restitution) stay as given.
  const double dashpot_scale = std::sqrt(inertia_scale);
  law.gamma_n *= dashpot_scale;
  law.gamma_t *= dashpot_scale;
  node_damping *= dashpot_scale;
  if ((strength_spread > 0.0) != (strength_seed > 0.0) || (strength_spread > 0.0 && !(strength > 0.0)))
    error->all(FLERR, "fix wire: strength_spread goes with 'strength T' "
               "and 'seed S' (S > 0); give all three, or strength alone");
  if (strength_seed != std::floor(strength_seed))
    error->all(FLERR, "fix wire: seed {} must be a positive integer", strength_seed);
  if (breaks_given && !(strength > 0.0))
    error->all(FLERR, "fix wire: 'breaks FILE' but no 'strength' makes any "
               "break; give 'strength T' (the tension an element breaks at)");
  // a break changes the bond list: it is rebuilt at the next step (Fix leaves next_reneighbor unset)
  next_reneighbor = -1;
  if (strength > 0.0) force_reneighbor = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixWire::~FixWire()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(gear);
  if (breaks_file) fclose(breaks_file);
}

void FixWire::parse_option(int narg, char **arg, int &iarg)
{
  const std::string key = arg[iarg];
  const char *value = iarg + 1 < narg ? arg[iarg + 1] : "";
  if (key == "grain_friction") return parse_grain_friction(narg, arg, iarg);
  wire::SoftContactLaw &law = lib->law;
  const std::map<std::string, double *> plain = {
      {"k_n", &law.k_n}, {"gamma_n", &law.gamma_n}, {"k_t", &law.k_t}, {"gamma_t", &law.gamma_t},
      {"mu_s", &law.mu_s}, {"mu_d", &law.mu_d}, {"radius", &wire_radius}, {"damp", &node_damping},
      {"contacts_per_node", &contacts_per_node}, {"dt_sp", &requested_dt_sp}, {"safety", &safety},
      {"skin", &contact_skin}, {"mu_ww_s", &mu_ww_s}, {"mu_ww_d", &mu_ww_d}, {"inertia", &inertia_scale},
      {"strength", &strength}, {"strength_spread", &strength_spread}, {"seed", &strength_seed}};
  const bool known = plain.count(key) || key == "substeps" || key == "breaks" || key == "grain_springs";
  if (!known)
    error->all(FLERR, "fix wire: unknown keyword '{}'; the keywords are listed in doc/fix_wire.rst, Syntax", key);
  if (iarg + 1 >= narg) error->all(FLERR, "fix wire: keyword '{}' needs a value (doc/fix_wire.rst, Syntax)", key);
  if (plain.count(value) || strcmp(value, "substeps") == 0 || strcmp(value, "breaks") == 0 ||
      strcmp(value, "grain_friction") == 0 || strcmp(value, "grain_springs") == 0)
    error->all(FLERR, "fix wire: keyword '{}' needs a value, but the next word is the keyword '{}' "
               "(doc/fix_wire.rst, Syntax)", key, value);
  if (key == "breaks") {
    breaks_given = true;
    if (comm->me == 0 && !breaks_file) {
      breaks_file = fopen(value, "w");
      if (!breaks_file)
        error->one(FLERR, "fix wire: cannot open the breaks file '{}' for writing: {}", value, utils::getsyserror());
      fprintf(breaks_file, "# step node_id_1 node_id_2 tension x y z   (fix wire %s: broken elements)\n", id);
    }
    return;
  }
  if (key == "grain_springs") {
    springs_held = strcmp(value, "held") == 0;
    if (!springs_held && strcmp(value, "carried") != 0)
      error->all(FLERR, "fix wire: grain_springs {} is neither carried (the default) nor held "
                 "(doc/fix_wire.rst, Syntax)", value);
    return;
  }
  if (key == "substeps") {
    requested_dt_sp = 0.0;
    fastest_stable = strcmp(value, "stable") == 0;
    const bool automatic = fastest_stable || strcmp(value, "auto") == 0;    // 0 inside: choose
    requested_substeps = automatic ? 0 : (int) NSCD_NS::whole(lmp, "fix wire", key, value, INT_MIN, INT_MAX);
    if (!automatic && requested_substeps < 1)
      error->all(FLERR, "fix wire: substeps {} must be >= 1 (or auto, or stable)", requested_substeps);
    return;
  }
  const auto option = plain.find(key);
  const double x = NSCD_NS::number(lmp, "fix wire", key, value);
  if (!(x >= 0.0) || !std::isfinite(x)) error->all(FLERR, "fix wire: {} = {} must be a finite number >= 0", key, x);
  if (key == "safety" && !(x > 0.0 && x <= 1.0)) error->all(FLERR, "fix wire: safety {} must be in (0, 1]", x);
  if (key == "skin" && !(x > 0.0)) error->all(FLERR, "fix wire: skin {} must be a finite number > 0", x);
  if (key == "strength" && !(x > 0.0))
    error->all(FLERR, "fix wire: strength {} must be > 0 (the tension at which an element breaks; leave it out "
               "for a wire that never breaks)", x);
  if (key == "inertia" && !(x >= 1.0))
    error->all(FLERR, "fix wire: inertia {} must be >= 1 (the factor on the nodes' inertia; 1: none)", x);
  *option->second = x;
  mu_s_given = mu_s_given || key == "mu_s";
  mu_d_given = mu_d_given || key == "mu_d";
  if (key == "dt_sp" && !(x > 0.0))
    error->all(FLERR, "fix wire: dt_sp {} must be > 0; for the automatic substep give 'substeps auto' (the default)", x);
  k_n_given = k_n_given || key == "k_n";
  if (key == "dt_sp") requested_substeps = 0;
}

/* grain_friction TYPES MU_S MU_D: the wire-grain friction of the grains of these types (a
   type or a range, as in pair_coeff); the other grains keep mu_s, mu_d. */
void FixWire::parse_grain_friction(int narg, char **arg, int &iarg)
{
  if (iarg + 3 >= narg)
    error->all(FLERR, "fix wire: grain_friction needs three values, TYPES MU_S MU_D (e.g. 'grain_friction 2 0.3 "
               "0.2'), got {}", narg - iarg - 1);
  GrainFriction g{};
  utils::bounds(FLERR, arg[iarg + 1], 1, atom->ntypes, g.lo, g.hi, error);
  g.mu_s = NSCD_NS::number(lmp, "fix wire", "grain_friction mu_s", arg[iarg + 2]);
  g.mu_d = NSCD_NS::number(lmp, "fix wire", "grain_friction mu_d", arg[iarg + 3]);
  if (!(g.mu_s >= 0.0 && std::isfinite(g.mu_s)) || !(g.mu_d >= 0.0 && g.mu_d <= g.mu_s))
    error->all(FLERR, "fix wire: grain_friction {}: mu_s {} and mu_d {} must be finite with 0 <= mu_d <= mu_s",
               arg[iarg + 1], g.mu_s, g.mu_d);
  grain_friction.push_back(g);
  iarg += 2;    // three values: the caller steps over two
}

int FixWire::setmask() { return POST_FORCE | PRE_EXCHANGE; }
double FixWire::compute_vector(int n)
{
  if (n != TENSION_DIAGNOSTIC && n != RUN_TENSION_DIAGNOSTIC) return diagnostics[n];
  double mine = n == TENSION_DIAGNOSTIC ? largest_tension : largest_tension_in_run, all = 0.0;
  MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  return all;
}

void *FixWire::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "radius") == 0) return &wire_radius;
  if (strcmp(name, "k_n") == 0) return &lib->law.k_n;
  return nullptr;
}

/* ---------------------------------------------------------------------- setup */

void FixWire::init()
{
  NSCD_NS::refuse_second_instance<FixWire>(lmp, this, "one fix handles all wire nodes and their contacts");
  NSCD_NS::refuse_migration_before(lmp, this, "its contacts' friction memories");
  if (update->whichflag == 2)
    error->all(FLERR, "fix wire cannot take part in 'minimize'; unfix it "
               "before minimize, or relax the wire with a damped run ('damp')");
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "fix wire does not work with 'run_style {}'; use 'run_style verlet' "
               "(option 'substeps' sets the wire's inner steps)", update->integrate_style);
  NSCD_NS::require_plain_mechanics(lmp, "fix wire");
  if (!force->newton_bond)
    error->all(FLERR, "fix wire needs newton_bond on (each element once in the bond list); use "
               "'newton on' or 'newton off on'");
  avec = AtomVecSpheropolyhedron::find(lmp, "fix wire");
  if (inertia_scale > 1.0 && comm->me == 0)
    error->warning(FLERR, "fix wire: inertia {}: the wire moves {:.3g} times slower; for quasi-static "
                   "phases only (doc/fix_wire.rst, Errors)", inertia_scale, std::sqrt(inertia_scale));
  check_partners();
  find_boundaries();
  check_contacts_possible();
  plan_substeps();
  make_contact_model();
}

void FixWire::check_partners()
{
  bond = dynamic_cast<BondWire *>(force->bond);
  if (atom->nbonds > 0 && !bond)
    error->all(FLERR, "fix wire needs bond_style wire for its elements (bond_style is '{}')",
               force->bond_style ? force->bond_style : "none");
  angle = dynamic_cast<AngleWire *>(force->angle);
  if (atom->nangles > 0 && !angle)
    error->all(FLERR, "fix wire needs angle_style wire for its joints (angle_style is '{}')",
               force->angle_style ? force->angle_style : "none");
  const tagint any_grain =
      NSCD_NS::lowest_tag_where(lmp, [&](int i) { return (atom->mask[i] & groupbit) && avec->shape[i] != 0; });
  if (any_grain)
    error->all(FLERR, "fix wire: atom ID {} in group '{}' is a grain (shape != 0); the "
               "group must hold wire nodes (shape 0) only", any_grain, group->names[igroup]);
  // post_force fixes after this one on its nodes change forces the subcycle has already used
  auto acts_on_nodes = [&](const Fix *other) {
    int mine = 0, any = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & groupbit) && (atom->mask[i] & other->groupbit)) mine = 1;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    return any != 0;
  };
  bool after = false;
  for (int f = 0; f < modify->nfix; f++) {
    if (modify->fix[f] == this) after = true;
    else if (after && (modify->fmask[f] & POST_FORCE) && acts_on_nodes(modify->fix[f]) && comm->me == 0)
      error->warning(FLERR, "fix wire: fix {} ({}) is defined after fix wire and acts in post_force, "
                     "unseen by the wire; define it before", modify->fix[f]->id, modify->fix[f]->style);
  }
}

/* The walls and the plate touch the wire nodes of their groups, with fix wire's law and the
   boundary's friction (mu_s = mu_d). fix nscd solves in final_integrate, after this
   post_force: it sees the wire's forces of the step whatever the order of the fixes. */
void FixWire::find_boundaries()
{
  lib->boundaries.clear();
  for (Fix *other : modify->get_fix_list()) {
    auto *boundary_fix = dynamic_cast<NSCDBoundaryFix *>(other);
    if (!boundary_fix) continue;
    BoundaryView b;
    b.boundary = &boundary_fix->boundary();
    b.groupbit = other->groupbit;
    b.link.law = lib->law;
    b.link.law.mu_s = b.link.law.mu_d = b.boundary->friction_coefficient();
    b.link.id = (tagint) (boundary_tag(other->id) >> 34);
    lib->boundaries.push_back(b);
  }
  if (lib->boundaries.size() > 32)
    error->all(FLERR, "fix wire: {} walls and plates; the wire can touch at most 32", lib->boundaries.size());
  for (BoundaryView &b : lib->boundaries) b.link.boundary = &b;
}

/* A wire without contacts (k_n 0) passes through grains, walls and the plate: with any of
   them in the scene that is refused when k_n was not given (the default 0 is no choice) and
   warned about when 'k_n 0' was given. */
void FixWire::check_contacts_possible()
{
  if (lib->law.k_n > 0.0) return;
  int mine = 0, grains = 0;
  for (int i = 0; i < atom->nlocal && !mine; i++)
    if (avec->shape[i] != 0) mine = 1;
  MPI_Allreduce(&mine, &grains, 1, MPI_INT, MPI_MAX, world);
  if (!grains && lib->boundaries.empty()) return;
  const char *what = grains ? (lib->boundaries.empty() ? "grains" : "grains, walls and plate") : "walls and plate";
  if (!k_n_given)
    error->all(FLERR, "fix wire {}: no k_n given: the wire would pass through the {}; give 'k_n K' and 'radius R', "
               "or 'k_n 0'", id, what);
  if (comm->me == 0)
    error->warning(FLERR, "fix wire {}: k_n 0: the wire has no contacts and passes through the {} of this scene",
                   id, what);
}

/* n substeps from the options and the stability limit of lib/wire/stability.h; a named
   error when the chosen dt_SP is above it. */
void FixWire::plan_substeps()
{
  wire::WireStiffness w;
  double mass = INFINITY, length = INFINITY;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && avec->shape[i] == 0) mass = std::min(mass, avec->rmass[i]);
  MPI_Allreduce(&mass, &w.node_mass, 1, MPI_DOUBLE, MPI_MIN, world);
  w.node_mass *= inertia_scale;
  for (int t = 1; bond && t <= atom->nbondtypes; t++) {
    length = std::min(length, bond->rest_length(t));
    w.k_elo = std::max(w.k_elo, bond->law(t).k_elo);
  }
  for (int t = 1; angle && t <= atom->nangletypes; t++) w.k_rot = std::max(w.k_rot, angle->k_rot(t));
  w.element_length = std::isfinite(length) ? length : 1.0;
  w.k_n = lib->law.k_n;
  w.gamma_contact = std::max(lib->law.gamma_n, lib->law.gamma_t);
  w.contacts_per_node = contacts_per_node;
  w.node_damping = node_damping;
  if (!std::isfinite(w.node_mass)) {    // no node in the group: nothing to integrate
    lib->plan = {1, update->dt};
    stable_dt_sp = INFINITY;
    return;
  }
  if (!(w.node_mass > 0.0))
    error->all(FLERR, "fix wire: a wire node has mass {}; give every node a mass with 'shapes "
               "assign GROUP shape 0 mass M'", w.node_mass);
  const auto kind = wire::GearCorrector::ThreeSixteenths;
  int needed = 1;
  double automatic_dt_sp = 0.0;    // what substeps auto (or stable) takes
  try {
    stable_dt_sp = wire::max_stable_wire_step(w, kind, safety);
    automatic_dt_sp = fastest_stable ? stable_dt_sp : wire::accurate_wire_step(w, kind, safety);
    needed = wire::plan_subcycle(update->dt, stable_dt_sp).substeps;
  } catch (std::exception &e) {
    error->all(FLERR, "fix wire: {}", e.what());
  }
  refuse_absurd_substeps(needed);
  try {
    lib->plan = requested_dt_sp > 0.0 ? wire::plan_subcycle(update->dt, requested_dt_sp)
                                      : wire::plan_subcycle(update->dt, automatic_dt_sp, requested_substeps);
    wire::check_wire_step(lib->plan.dt_sp, w, kind, safety);
  } catch (std::exception &e) {
    error->all(FLERR, "fix wire: {} (stability limit dt_SP max = {:.6g}); use "
               "'substeps auto' (doc/fix_wire.rst, Errors)", e.what(), stable_dt_sp);
  }
  if (lib->plan.substeps > WARN_SUBSTEPS_RATIO * needed && comm->me == 0)
    error->warning(FLERR, "fix wire: {} asks for {} wire substeps per step, {:.0f} times the {} the stability limit needs; use "
                   "'substeps auto'",
                   requested_substeps_text(), lib->plan.substeps, (double) lib->plan.substeps / needed, needed);
}

/* More substeps than stability needs only cost time; far more is a mistake (a dt_sp meant
   for another timestep or unit system), and beyond MAX_SUBSTEPS a step never ends. */
void FixWire::refuse_absurd_substeps(int needed)
{
  const double asked = requested_dt_sp > 0.0 ? update->dt / requested_dt_sp : (double) requested_substeps;
  if (asked > MAX_SUBSTEPS && asked > needed)
    error->all(FLERR, "fix wire: {} asks for {:.6g} wire substeps per step, more than {}; the stability "
               "limit needs {} (substeps stable)", requested_substeps_text(), asked, MAX_SUBSTEPS, needed);
}

std::string FixWire::requested_substeps_text() const
{
  return requested_dt_sp > 0.0 ? fmt::format("dt_sp {}", requested_dt_sp) : fmt::format("substeps {}", requested_substeps);
}

/* The contact model lives across runs (it holds the friction memories); a new skin makes a
   new one, which takes the memories over. Default skin: 4 r_w, at most the neighbour skin
   (a wider skin only adds candidate pairs to watch every substep). */
void FixWire::make_contact_model()
{
  if (lib->law.k_n == 0.0) return;
  const double skin = contact_skin > 0.0 ? contact_skin : std::min(neighbor->skin, 4.0 * wire_radius);
  if (!(skin > 0.0))
    error->all(FLERR, "fix wire: contacts need a skin > 0 for their candidate lists; give 'neighbor "
               "SKIN bin' or fix wire's 'skin S'");
  std::vector<wire::StoredContact> memories;
  if (lib->contacts) memories = lib->contacts->take_memories();
  lib->contacts = std::make_unique<wire::ContactModel>(lib->law, wire_radius, skin);
  try {
    lib->contacts->set_wire_wire_friction(mu_ww_s, mu_ww_d);
  } catch (std::exception &e) {
    error->all(FLERR, "fix wire: mu_ww_s {} and mu_ww_d {}: {}", mu_ww_s, mu_ww_d, e.what());
  }
  // Per grain type: the law's index in the contact model (0: mu_s, mu_d); a later
  // grain_friction for a type replaces an earlier one.
  grain_law_of_type.assign(atom->ntypes + 1, 0);
  for (const GrainFriction &g : grain_friction) {
    const int law = lib->contacts->add_grain_friction(g.mu_s, g.mu_d);
    for (int t = g.lo; t <= g.hi; t++) grain_law_of_type[t] = law;
  }
  lib->contacts->set_grain_springs(springs_held ? wire::GrainSprings::held : wire::GrainSprings::carried);
  lib->contacts->add_memories(memories);
  lib->contacts->record_contacts(contacts_recorded);
  lib->step.contacts = lib->contacts.get();
}

/* Atoms may have changed rank since the last step (balance, a box change) while the
   neighbour build of this setup keeps the last step's time stamp: index again. */
void FixWire::setup(int /*vflag*/)
{
  indexed_at = -1;
  gather_elements();
  warn_about_elements_inside_grains();
  warn_about_strained_elements();
  rescale_states(lib->plan.dt_sp);
  if (lib->contacts) lib->contacts->forget_shapes();
  diagnostics[SUBSTEPS] = lib->plan.substeps;
  diagnostics[DT_SP] = lib->plan.dt_sp;
  diagnostics[DT_SP_STABLE] = stable_dt_sp;
  diagnostics[STEPS_TOO_FAST] = 0.0;
  warned_fast_motion = false;
  timing.fill(0.0);
  lib->timing = wire::StepTiming();
  substeps_run = 0;
  comm_counts.clear();
  migrated.fill(0.0);
  rebuilds_at_start = lib->contacts ? lib->contacts->rebuilds() : 0;
}

/* Elements inside grains at the start of a run (placed by hand, 'create_wire ... overlap
   ignore', a data file): their contacts push them out at about depth x sqrt(k_n / node mass)
   within the first substeps. Warned about, as fix nscd warns about grains inside grains,
   when deeper than half the wire radius (a wire laid by create_wire overlaps by at most 0.1
   of it; one at rest, by its weight over k_n). Each rank tests the elements in its bond list
   against the grains it holds (owned and ghost). */
void FixWire::warn_about_elements_inside_grains()
{
  if (!lib->contacts || !bond) return;
  wire::WirePieces pieces;
  std::vector<std::array<int, 2>> ends;
  for (int n = 0; n < neighbor->nbondlist; n++) {
    const int i = neighbor->bondlist[n][0], j = neighbor->bondlist[n][1];
    if (!(atom->mask[i] & groupbit) && !(atom->mask[j] & groupbit)) continue;
    const int first = (int) pieces.nodes.size();
    pieces.nodes.push_back(vec3(atom->x[i]));
    pieces.nodes.push_back(vec3(atom->x[j]));
    pieces.elements.push_back({first, first + 1, 0.0});
    ends.push_back({i, j});
  }
  std::vector<wire::PlacedGrain> grains;
  std::vector<int> grain_atom;
  for (int i = 0; i < atom->nlocal + atom->nghost; i++)
    if (avec->shape[i] != 0) {
      grains.push_back({&avec->shape_of(i), avec->pose(i)});
      grain_atom.push_back(i);
    }
  const wire::ElementOverlap o = wire::deepest_overlap_with_grains(pieces, wire_radius, grains, {});
  struct {
    double depth;
    int rank;
  } mine{o.b >= 0 ? o.depth : 0.0, comm->me}, worst;
  MPI_Allreduce(&mine, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, world);
  if (!(worst.depth > 0.5 * wire_radius)) return;
  double found[4] = {0.0, 0.0, 0.0, INFINITY};    // node IDs, grain ID, the lighter node's mass
  if (comm->me == worst.rank) {
    const auto &e = ends[o.a];
    found[0] = (double) atom->tag[e[0]];
    found[1] = (double) atom->tag[e[1]];
    found[2] = (double) atom->tag[grain_atom[o.b]];
    found[3] = std::min(avec->rmass[e[0]], avec->rmass[e[1]]);
  }
  MPI_Bcast(found, 4, MPI_DOUBLE, worst.rank, world);
  if (comm->me == 0)
    error->warning(FLERR, "fix wire {}: element {}-{} lies inside grain ID {} by {:.4g} ({:.3g} wire radii) at the start (doc/fix_wire.rst, "
                   "Errors)",
                   id, (tagint) found[0], (tagint) found[1], (tagint) found[2], worst.depth, worst.depth / wire_radius);
}

/* Elements far from their rest length at the start of a run (two wires joined by
   create_bonds with one long element of a shared bond type, 'create_wire ... strained yes'
   with a wrong rest length, a hand-made data file): such an element pulls its nodes with
   k_elo x strain from the first substep and can fling them, and the grains they touch. Warned
   about when the length is more than STRAIN_WARNING (10 %) off the rest length: far beyond
   what the examples' loads stretch (k_elo 5000: a strain of 1e-3 is a tension of 5) and what
   'strained yes' is meant for (a ring's chord a few % off). newton_bond on (fix wire's
   restriction): each element is in exactly one rank's bond list. */
void FixWire::warn_about_strained_elements()
{
  constexpr double STRAIN_WARNING = 0.1;
  if (!bond) return;
  double worst[2] = {0.0, (double) comm->me};    // |strain|, rank
  std::array<double, 4> found = {0.0, 0.0, 0.0, 0.0};    // node IDs, length, rest length
  bigint count = 0;
  for (int n = 0; n < neighbor->nbondlist; n++) {
    const int i = neighbor->bondlist[n][0], j = neighbor->bondlist[n][1], type = neighbor->bondlist[n][2];
    if (!(atom->mask[i] & groupbit) && !(atom->mask[j] & groupbit)) continue;
    const double length = (vec3(atom->x[i]) - vec3(atom->x[j])).norm(), rest = bond->rest_length(type);
    const double strain = length / rest - 1.0;
    const wire::AxialLaw law = bond->law(type);
    if (strain < 0.0 && !law.resists_compression) continue;    // a slack string pulls nothing
    if (!(std::abs(strain) > STRAIN_WARNING)) continue;
    count++;
    if (std::abs(strain) > worst[0]) {
      worst[0] = std::abs(strain);
      found = {(double) atom->tag[i], (double) atom->tag[j], length, rest};
    }
  }
  bigint total = 0;
  MPI_Allreduce(&count, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (total == 0) return;
  double deepest[2];
  MPI_Allreduce(worst, deepest, 1, MPI_2DOUBLE_PRECISION, MPI_MAXLOC, world);
  MPI_Bcast(found.data(), 4, MPI_DOUBLE, (int) deepest[1], world);
  if (comm->me == 0)
    error->warning(FLERR, "fix wire {}: {} elements start over {:.0f} % from rest length, worst {:.3g} x "
                   "(IDs {}-{}); doc/fix_wire.rst, Errors", id, total, 100.0 * STRAIN_WARNING,
                   found[2] / found[3], (tagint) found[0], (tagint) found[1]);
}

void FixWire::reset_dt()
{
  plan_substeps();
  rescale_states(lib->plan.dt_sp);
}

/* The wire's topology on every rank: a contact pair is found on the rank owning the first
   node of its lower element, and that rank must see the other element whatever rank stores
   its bond (newton_bond on: each element is in exactly one rank's bond list). That rank
   must also hold as ghosts every grain and node the contact can reach within a step: from
   that node, a grain's centre within L + r_w + R + skin and the other element's nodes
   within 2 L + 2 r_w + skin; checked across ranks and periodic boundaries. */
void FixWire::gather_elements()
{
  std::vector<std::array<tagint, 2>> mine;
  double longest[2] = {0.0, 0.0};    // element, grain radius
  for (int n = 0; bond && n < neighbor->nbondlist; n++) {
    const int *b = neighbor->bondlist[n];
    const tagint p = atom->tag[b[0]], q = atom->tag[b[1]];
    mine.push_back({std::min(p, q), std::max(p, q)});
    longest[0] = std::max({longest[0], bond->rest_length(b[2]), (vec3(atom->x[b[0]]) - vec3(atom->x[b[1]])).norm()});
  }
  for (int i = 0; i < atom->nlocal; i++)
    if (avec->shape[i] != 0) longest[1] = std::max(longest[1], avec->radius[i]);
  MPI_Allreduce(MPI_IN_PLACE, longest, 2, MPI_DOUBLE, MPI_MAX, world);
  elements = gather_records(mine, world, true);
  std::sort(elements.begin(), elements.end());
  elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
  if (!lib->contacts || elements.empty()) return;
  std::vector<std::array<std::int64_t, 2>> all;
  for (const auto &e : elements) all.push_back({e[0], e[1]});
  lib->contacts->set_elements(std::move(all));

  if (!(domain->xperiodic || domain->yperiodic || domain->zperiodic) && comm->nprocs == 1) return;
  const double L = longest[0], R = longest[1];
  const double needed = std::max(R + L + wire_radius, 2.0 * L + 2.0 * wire_radius) + neighbor->skin;
  const double have = std::max(neighbor->cutneighmax, comm->cutghostuser);
  if (have < needed)
    error->all(FLERR, "fix wire: ghost cutoff {:.6g} is below the reach {:.6g} of a wire contact across {}; use "
               "'comm_modify cutoff {:.6g}'",
               have, needed, comm->nprocs > 1 ? "MPI ranks" : "a periodic boundary", needed);
}

/* ---------------------------------------------------------------------- the step */

void FixWire::post_force(int /*vflag*/)
{
  const double wall_start = platform::walltime(), cpu_start = platform::cputime();
  check_element_tensions();
  const bool reindexed = neighbor->lastcall != indexed_at;
  if (reindexed) {
    index_atoms();
    plan_copy_exchange();
  }
  if (topology_changed && reindexed) {    // this step's neighbour build dropped the broken elements
    gather_elements();
    topology_changed = false;
  }
  load_nodes();
  if (lib->contacts) update_scene(reindexed);
  else lib->step.reactions.reset((int) lib->boundaries.size());
  if (lib->contacts && memories_with_atoms) take_memories_from_atoms();
  try {
    const wire::StepTotals t = lib->step.run(lib->plan, lib->corrector, *lib, lib->timing);
    const double values[6] = {t.elastic.axial, t.elastic.bending, t.contacts.energy, (double) t.contacts.wire_wire,
                              (double) t.contacts.wire_grain, (double) t.contacts.wire_boundary};
    const int index[6] = {E_AXIAL, E_BENDING, E_CONTACT, N_WIRE_WIRE, N_WIRE_GRAIN, N_WIRE_BOUNDARY};
    double sums[6];
    MPI_Allreduce(values, sums, 6, MPI_DOUBLE, MPI_SUM, world);
    for (int k = 0; k < 6; k++) diagnostics[index[k]] = sums[k];
  } catch (std::exception &e) {
    error->one(FLERR, "fix wire: step {}: {}", update->ntimestep, e.what());
  }
  check_motion_within_skin();
  store_nodes();
  hand_forces();
  substeps_run += lib->plan.substeps;
  timing[T_TOTAL] += platform::walltime() - wall_start;
  timing[T_CPU] += platform::cputime() - cpu_start;
}

/* After a neighbour build: node indices of the local atoms (owned nodes first, each part
   in the order of atom IDs, so the nodes of a wire numbered along it lie side by side in
   memory), the grains, and this rank's elements and joints in node indices with the law of
   their bond and angle types. */
void FixWire::index_atoms()
{
  const int ntotal = atom->nlocal + atom->nghost;
  node_of_atom.assign(ntotal, -1);
  atom_of_node.clear();
  atom_of_grain.clear();
  for (int i = 0; i < ntotal; i++) (avec->shape[i] == 0 ? atom_of_node : atom_of_grain).push_back(i);
  owned_nodes = (int) (std::lower_bound(atom_of_node.begin(), atom_of_node.end(), atom->nlocal) - atom_of_node.begin());
  auto by_tag = [&](int i, int j) { return atom->tag[i] < atom->tag[j]; };
  std::sort(atom_of_node.begin(), atom_of_node.begin() + owned_nodes, by_tag);
  std::sort(atom_of_node.begin() + owned_nodes, atom_of_node.end(), by_tag);
  for (size_t k = 0; k < atom_of_node.size(); k++) node_of_atom[atom_of_node[k]] = (int) k;
  indexed_at = neighbor->lastcall;
  int grains_here = atom_of_grain.empty() ? 0 : 1, grains = 0;
  MPI_Allreduce(&grains_here, &grains, 1, MPI_INT, MPI_MAX, world);
  grains_anywhere = grains != 0;

  wire::WireTopology &t = lib->step.topology;
  t.elements.clear();
  t.joints.clear();
  auto node = [&](int i) {
    if (node_of_atom[i] < 0)
      error->one(FLERR, "fix wire: atom ID {} is a grain but belongs to a wire "
                 "bond or angle; these join wire nodes (shape 0) only", atom->tag[i]);
    return node_of_atom[i];
  };
  for (int n = 0; bond && n < neighbor->nbondlist; n++) {
    const int *b = neighbor->bondlist[n];
    t.elements.push_back({node(b[0]), node(b[1]), bond->rest_length(b[2]), bond->law(b[2])});
  }
  for (int n = 0; angle && n < neighbor->nanglelist; n++) {
    const int *a = neighbor->anglelist[n];
    t.joints.push_back({node(a[0]), node(a[1]), node(a[2]), angle->k_rot(a[3]), angle->rest_turn(a[3])});
  }
  std::sort(t.elements.begin(), t.elements.end(), [](const auto &p, const auto &q) { return p.a < q.a; });
  std::sort(t.joints.begin(), t.joints.end(), [](const auto &p, const auto &q) { return p.b < q.b; });
}

/* The owned nodes' Gear states from the per-atom array, with position and velocity taken
   from LAMMPS (which may have remapped or changed them); nodes outside the group are
   anchors, held where they are. Then the external force on each node: LAMMPS' force
   (gravity, addforce, ...) minus what bond_style and angle_style wire put there, which the
   subcycle recomputes every substep (the same kernels at the same positions, so the
   difference is exact up to the order of summation). */
void FixWire::load_nodes()
{
  wire::WireStep &step = lib->step;
  wire::WireNodeSet &nodes = step.nodes;
  const double dt = lib->plan.dt_sp;
  nodes.state.resize(owned_nodes);
  nodes.mass.resize(owned_nodes);
  nodes.fixed.resize(owned_nodes);
  nodes.copies = (int) atom_of_node.size() - owned_nodes;
  nodes.dt = dt;
  lib->step_start.resize(owned_nodes);
  for (int k = 0; k < owned_nodes; k++) {
    const int i = atom_of_node[k];
    wire::Gear5State &s = nodes.state[k];
    if (gear[i][GEAR_COLUMNS - 1] != 0.0) s.unpack(gear[i]);
    else s = wire::gear5_start(vec3(atom->x[i]), vec3(atom->v[i]), Vec3::Zero(), dt);
    s.r[0] = lib->step_start[k] = vec3(atom->x[i]);
    s.r[1] = vec3(atom->v[i]) * dt;
    nodes.mass[k] = inertia_scale * avec->rmass[i];    // the weight stays rmass g
    nodes.fixed[k] = (atom->mask[i] & groupbit) ? 0 : 1;
  }
  wire::prepare_wire_nodes(nodes, dt);

  for (size_t k = 0; k < atom_of_node.size(); k++) nodes.positions[k] = vec3(atom->x[atom_of_node[k]]);
  try {
    step.elastic_forces_now();
  } catch (std::exception &e) {
    error->one(FLERR, "fix wire: step {}: {}", update->ntimestep, e.what());
  }
  communicate(Comm::node_force, true);
  step.external.resize(owned_nodes);
  for (int k = 0; k < owned_nodes; k++) step.external[k] = vec3(atom->f[atom_of_node[k]]) - nodes.forces[k];
  step.damping = node_damping;
}

void FixWire::store_nodes()
{
  const wire::WireNodeSet &nodes = lib->step.nodes;
  for (int k = 0; k < owned_nodes; k++) {
    if (nodes.fixed[k]) continue;
    const int i = atom_of_node[k];
    store(nodes.state[k].position(), atom->x[i]);
    store(nodes.state[k].velocity(lib->plan.dt_sp), atom->v[i]);
    nodes.state[k].pack(gear[i]);
    gear[i][GEAR_COLUMNS - 1] = 1.0;
  }
  communicate(Comm::node_position, false);    // ghosts at the final positions, for output
}

/* The local copy of node `tag` that is the other end of an element starting at local atom
   i: the image nearest to i's position (elements are shorter than half the box), or -1.
   The copy nearest to i among those present is not enough: near the edge of the ghost
   region (a ghost cutoff above a quarter of a periodic box, 2 ranks along it) that image
   may be absent while one a box length away is present, and an element from i to it
   would lie along the wire and push on it. */
int FixWire::element_partner(int i, tagint tag) const
{
  const int j = domain->closest_image(i, atom->map(tag));
  if (j < 0) return -1;
  double nearest[3];
  domain->closest_image(atom->x[i], atom->x[j], nearest);
  const double tolerance = 1e-9 * (domain->xprd + domain->yprd + domain->zprd);
  return (vec3(nearest) - vec3(atom->x[j])).norm() <= tolerance ? j : -1;
}

/* The contact model's scene of the step. After a neighbour build: the node ids, which nodes
   may touch which boundary, and the copies of the elements (each element whose first node,
   or an image of it, is here, with the image of its second node closest to it); every step
   the grains' poses and velocities and the boundaries' speeds. */
void FixWire::update_scene(bool reindexed)
{
  wire::ContactScene scene = lib->contacts->take_scene();
  const int nodes = (int) atom_of_node.size();
  for (int k = 0; k < nodes && reindexed; k++) {
    if (k == 0) {
      scene.node_id.resize(nodes);
      scene.node_boundaries.assign(nodes, 0u);
      scene.elements.clear();
    }
    const int i = atom_of_node[k];
    scene.node_id[k] = atom->tag[i];
    for (size_t b = 0; b < lib->boundaries.size() && i < atom->nlocal; b++)
      if ((atom->mask[i] & groupbit) && (atom->mask[i] & lib->boundaries[b].groupbit)) scene.node_boundaries[k] |= 1u << b;
    const std::array<tagint, 2> from{atom->tag[i], 0}, to{atom->tag[i], MAXTAGINT};
    for (auto e = std::lower_bound(elements.begin(), elements.end(), from); e != elements.end() && *e <= to; ++e) {
      const int j = element_partner(i, (*e)[1]);
      if ((j < 0 || node_of_atom[j] < 0) && i < atom->nlocal)
        error->one(FLERR, "fix wire: node ID {} of the element {}-{} is missing on the rank of "
                   "node ID {}; raise 'comm_modify cutoff'", (*e)[1], (*e)[0], (*e)[1], (*e)[0]);
      if (j >= 0 && node_of_atom[j] >= 0) scene.elements.push_back({k, node_of_atom[j], (*e)[0], (*e)[1], i < atom->nlocal});
    }
  }
  if (grains_anywhere) communicate(Comm::grain_velocity, false);    // ghost grains' v and omega
  scene.grains.resize(atom_of_grain.size());
  for (size_t g = 0; g < atom_of_grain.size(); g++) {
    const int i = atom_of_grain[g];
    scene.grains[g] = {atom->tag[i], &avec->shape_of(i), avec->pose(i), vec3(atom->v[i]), vec3(avec->omega[i]),
                       grain_law_of_type[atom->type[i]]};
  }
  scene.boundaries.clear();
  for (BoundaryView &b : lib->boundaries) {
    b.link.speed = b.boundary->surface_velocity().norm();
    scene.boundaries.push_back(b.link);
  }
  lib->step.reactions.reset((int) (scene.grains.size() + scene.boundaries.size()));
  lib->contacts->begin_step(std::move(scene), update->dt, reindexed);
}

/* The subcycle rebuilds its candidate lists when something moved too far
   (lib/wire/contact_model.h), but only atoms within the ghost cutoff are there to be found:
   a pair closing by more than the neighbour skin in a step may lie beyond it. Such steps
   are counted (output 13) and warned about once per run. Closing bound: the largest node
   displacement of the step plus the larger of it and the largest grain motion. */
void FixWire::check_motion_within_skin()
{
  if (!lib->contacts) return;
  double largest[2] = {lib->step.largest_displacement(lib->step_start), 0.0};    // node, grain
  for (int j = 0; j < atom->nlocal; j++)
    if (avec->shape[j] != 0)
      largest[1] = std::max(largest[1], (vec3(atom->v[j]).norm() + vec3(avec->omega[j]).norm() * avec->radius[j]) * update->dt);
  MPI_Allreduce(MPI_IN_PLACE, largest, 2, MPI_DOUBLE, MPI_MAX, world);
  const double closing = largest[0] + std::max(largest[0], largest[1]);
  if (closing <= neighbor->skin) return;
  diagnostics[STEPS_TOO_FAST] += 1.0;
  if (!warned_fast_motion && comm->me == 0)
    error->warning(FLERR, "fix wire: step {}: a node moved {:.4g}, a grain {:.4g}: over the skin {:.4g}; "
                   "lower the timestep or use neighbor {:.4g}", update->ntimestep, largest[0], largest[1],
                   neighbor->skin, 2.0 * closing);
  warned_fast_motion = true;
}

/* Mean wire->grain force and torque over the substeps, added to the owners' f and torque
   (ghost grains' shares summed onto their owners first); the mean forces on the walls and
   the plate, summed over the ranks, to each boundary before fix nscd solves the step. */
void FixWire::hand_forces()
{
  const wire::GrainForceAccumulator &reactions = lib->step.reactions;
  const int grains = lib->contacts ? (int) atom_of_grain.size() : 0;
  grain_force_buffer.assign(6 * (size_t) (atom->nlocal + atom->nghost), 0.0);
  double total[3] = {0.0, 0.0, 0.0};
  for (int g = 0; g < grains; g++) {
    double *b = &grain_force_buffer[6 * (size_t) atom_of_grain[g]];
    store(reactions.mean_force(g), b);
    store(reactions.mean_torque(g), b + 3);
    for (int d = 0; d < 3; d++) total[d] += b[d];
  }
  MPI_Allreduce(total, &diagnostics[GRAIN_FX], 3, MPI_DOUBLE, MPI_SUM, world);
  const bool exchanged = lib->contacts && grains_anywhere;    // the same on every rank
  if (exchanged) communicate(Comm::grain_force, true);
  for (int i = 0; i < atom->nlocal && exchanged; i++) {
    if (avec->shape[i] == 0) continue;
    add_to(atom->f[i], vec3(&grain_force_buffer[6 * (size_t) i]));
    add_to(avec->torque[i], vec3(&grain_force_buffer[6 * (size_t) i + 3]));
  }
  const size_t n = lib->boundaries.size();
  if (n == 0) return;
  std::vector<double> mine(3 * n), all(3 * n);
  for (size_t k = 0; k < n; k++) store(reactions.mean_force(reactions.num_grains() - (int) (n - k)), &mine[3 * k]);
  MPI_Allreduce(mine.data(), all.data(), (int) all.size(), MPI_DOUBLE, MPI_SUM, world);
  for (size_t k = 0; k < n; k++) lib->boundaries[k].boundary->take_wire_force(vec3(&all[3 * k]), update->ntimestep);
}
