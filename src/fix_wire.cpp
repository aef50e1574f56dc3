/* fix wire: the wire subcycle of lib/wire driven from LAMMPS' post_force. */

#include "fix_wire.h"

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
#include "nscd_arrays.h"
#include "nscd_boundary.h"
#include "nscd_boundary_fix.h"
#include "nscd_contact.h"
#include "nscd_gather.h"
#include "neighbor.h"
#include "update.h"
#include "wire/contact_weights.h"
#include "wire/elastic_forces.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using nscd::Vec3;

namespace {
enum Diagnostic {
  E_AXIAL, E_BENDING, E_CONTACT, N_WIRE_WIRE, N_WIRE_GRAIN, SUBSTEPS, DT_SP, GRAIN_FX, GRAIN_FY,
  GRAIN_FZ, DT_SP_STABLE, N_WIRE_BOUNDARY, STEPS_TOO_FAST
};


// One contact history as written to restart files and sent between ranks.
struct StoredHistory {
  double key[4];    // tags, stored as doubles (exact up to 2^53)
  double history[nscd::wire::TangentialHistory::kNumDoubles];
};

StoredHistory stored(const FixWire::ContactKey &key, const nscd::wire::TangentialHistory &h)
{
  StoredHistory s;
  for (int d = 0; d < 4; d++) s.key[d] = (double) key[d];
  for (int d = 0; d < 3; d++) s.history[d] = h.xi[d];
  s.history[3] = h.sliding;
  return s;
}

FixWire::ContactKey key_of(const StoredHistory &s)
{
  return {(tagint) s.key[0], (tagint) s.key[1], (tagint) s.key[2], (tagint) s.key[3]};
}

nscd::wire::TangentialHistory history_of(const StoredHistory &s)
{
  nscd::wire::TangentialHistory h;
  for (int d = 0; d < 3; d++) h.xi[d] = s.history[d];
  h.sliding = s.history[3];
  return h;
}
}    // namespace

/* fix ID group wire [k_n K] [gamma_n G] [k_t K] [gamma_t G] [mu_s M] [mu_d M] [radius R]
                     [damp C] [substeps N|auto] [dt_sp DT] [safety S] [contacts_per_node N] */
FixWire::FixWire(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  time_integrate = 1;
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  vector_flag = 1;
  size_vector = (int) diagnostics.size();
  global_freq = 1;
  extvector = 0;
  comm_forward = 6;
  comm_reverse = 6;

  int iarg = 3;
  while (iarg < narg) parse_option(narg, arg, iarg);
  // One coefficient given: static = dynamic. (With mu_d left at 0, a contact would lose all
  // friction after its first slip.)
  if (mu_s_given && !mu_d_given) law.mu_d = law.mu_s;
  if (mu_d_given && !mu_s_given) law.mu_s = law.mu_d;
  if (law.k_n > 0.0) {    // k_n = 0: no contacts at all, the other coefficients unused
    try {
      nscd::wire::validate(law);
    } catch (std::exception &e) {
      error->all(FLERR, "fix wire: {}", e.what());
    }
    if (!(wire_radius > 0.0))
      error->all(FLERR, "fix wire: contacts (k_n {}) need a wire radius > 0: elements of radius 0 "
                 "never touch; give 'radius R' (or k_n 0 for a wire without contacts)", law.k_n);
  }
  corrector = nscd::wire::gear5_corrector_coefficients(nscd::wire::GearCorrector::ThreeSixteenths);

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
}

void FixWire::parse_option(int narg, char **arg, int &iarg)
{
  const std::string key = arg[iarg];
  if (iarg + 1 >= narg) error->all(FLERR, "fix wire: keyword '{}' needs a value", key);
  const char *value = arg[iarg + 1];
  auto positive_or_zero = [&](double x) {
    if (!(x >= 0.0) || !std::isfinite(x))
      error->all(FLERR, "fix wire: {} = {} must be a finite number >= 0", key, x);
    return x;
  };
  const double x = key == "substeps" ? 0.0 : utils::numeric(FLERR, value, false, lmp);
  if (key == "k_n") law.k_n = positive_or_zero(x);
  else if (key == "gamma_n") law.gamma_n = positive_or_zero(x);
  else if (key == "k_t") law.k_t = positive_or_zero(x);
  else if (key == "gamma_t") law.gamma_t = positive_or_zero(x);
  else if (key == "mu_s") law.mu_s = positive_or_zero(x), mu_s_given = true;
  else if (key == "mu_d") law.mu_d = positive_or_zero(x), mu_d_given = true;
  else if (key == "radius") wire_radius = positive_or_zero(x);
  else if (key == "damp") node_damping = positive_or_zero(x);
  else if (key == "dt_sp") {
    requested_dt_sp = positive_or_zero(x);
    requested_substeps = 0;
  } else if (key == "safety") {
    safety = x;
    if (!(safety > 0.0 && safety <= 1.0)) error->all(FLERR, "fix wire: safety {} must be in (0, 1]", safety);
  } else if (key == "contacts_per_node") contacts_per_node = positive_or_zero(x);
  else if (key == "substeps") {
    requested_dt_sp = 0.0;
    requested_substeps = strcmp(value, "auto") == 0 ? 0 : utils::inumeric(FLERR, value, false, lmp);
    if (requested_substeps < 0)
      error->all(FLERR, "fix wire: substeps {} must be >= 1 (or auto)", requested_substeps);
  } else {
    error->all(FLERR, "fix wire: unknown keyword '{}' (expected k_n, gamma_n, k_t, gamma_t, mu_s, "
               "mu_d, radius, damp, substeps, dt_sp, safety, contacts_per_node)", key);
  }
  iarg += 2;
}

int FixWire::setmask()
{
  return POST_FORCE;
}

/* ---------------------------------------------------------------------- setup */

void FixWire::init()
{
  for (Fix *other : modify->get_fix_list())
    if (other != this && dynamic_cast<FixWire *>(other))
      error->all(FLERR, "fix wire: only one fix wire may be defined ({} and {}); one fix handles "
                 "all wire nodes and their contacts", other->id, id);
  if (!force->newton_bond)
    error->all(FLERR, "fix wire needs newton_bond on (each element once in the bond list); use "
               "'newton on' or 'newton off on'");
  avec = AtomVecSpheropolyhedron::find(lmp, "fix wire");
  check_partners();
  find_boundaries();
  plan_substeps();
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

  tagint first_grain = MAXTAGINT, any_grain;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && avec->shape[i] != 0) first_grain = std::min(first_grain, atom->tag[i]);
  MPI_Allreduce(&first_grain, &any_grain, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (any_grain != MAXTAGINT)
    error->all(FLERR, "fix wire: atom ID {} in group '{}' is a grain (shape != 0); the group must "
               "hold wire nodes (shape 0) only, grains belong to fix nscd", any_grain,
               group->names[igroup]);

  // post_force fixes after this one would change node forces the subcycle has already used
  bool after = false;
  for (int f = 0; f < modify->nfix; f++) {
    if (modify->fix[f] == this) after = true;
    else if (after && (modify->fmask[f] & POST_FORCE) && acts_on_nodes(modify->fix[f]) && comm->me == 0)
      error->warning(FLERR, "fix wire: fix {} ({}) is defined after fix wire and acts in "
                     "post_force: the wire subcycle does not see its forces; define it before fix wire",
                     modify->fix[f]->id, modify->fix[f]->style);
  }
}

/* True if fix `other` has wire nodes of this fix's group in its own group (on any rank). */
bool FixWire::acts_on_nodes(const Fix *other) const
{
  int mine = 0, any = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && (atom->mask[i] & other->groupbit)) mine = 1;
  MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
  return any != 0;
}

/* The walls and the plate: fix wire computes their soft contacts with the nodes of their
   groups, with its own law and the boundary's friction (mu_s = mu_d). fix nscd solves the
   step in final_integrate, after this post_force: it sees the wire's forces of the step on
   the grains and on the plate whatever the order of the fixes. */
void FixWire::find_boundaries()
{
  boundaries.clear();
  for (Fix *other : modify->get_fix_list()) {
    auto *boundary_fix = dynamic_cast<NSCDBoundaryFix *>(other);
    if (!boundary_fix) continue;
    NSCDBoundary *b = &boundary_fix->boundary();
    nscd::wire::SoftContactLaw with_friction = law;
    with_friction.mu_s = with_friction.mu_d = b->friction_coefficient();
    boundaries.push_back({b, other->groupbit, (tagint) (boundary_tag(other->id) >> 34), with_friction});
  }
}

nscd::wire::WireStiffness FixWire::stiffness() const
{
  nscd::wire::WireStiffness w;
  double mass = INFINITY, length = INFINITY, k_elo = 0.0, k_rot = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && avec->shape[i] == 0) mass = std::min(mass, avec->rmass[i]);
  MPI_Allreduce(&mass, &w.node_mass, 1, MPI_DOUBLE, MPI_MIN, world);
  if (bond)
    for (int t = 1; t <= atom->nbondtypes; t++) {
      length = std::min(length, bond->rest_length(t));
      k_elo = std::max(k_elo, bond->law(t).k_elo);
    }
  if (angle)
    for (int t = 1; t <= atom->nangletypes; t++) k_rot = std::max(k_rot, angle->k_rot(t));
  w.element_length = std::isfinite(length) ? length : 1.0;
  w.k_elo = k_elo;
  w.k_rot = k_rot;
  w.k_n = law.k_n;
  w.gamma_contact = std::max(law.gamma_n, law.gamma_t);
  w.contacts_per_node = contacts_per_node;
  w.node_damping = node_damping;
  return w;
}

/* n substeps from the options and the stability limit of lib/wire/stability.h; a named
   error when the chosen dt_SP is above it. */
void FixWire::plan_substeps()
{
  const nscd::wire::WireStiffness w = stiffness();
  if (!std::isfinite(w.node_mass)) {    // no node in the group: nothing to integrate
    plan = {1, update->dt};
    stable_dt_sp = INFINITY;
    return;
  }
  if (!(w.node_mass > 0.0))
    error->all(FLERR, "fix wire: a wire node has mass {}; give every node a mass with 'shapes "
               "assign GROUP shape 0 mass M'", w.node_mass);
  const auto kind = nscd::wire::GearCorrector::ThreeSixteenths;
  try {
    stable_dt_sp = nscd::wire::max_stable_wire_step(w, kind, safety);
    if (requested_dt_sp > 0.0) {
      nscd::wire::check_wire_step(requested_dt_sp, w, kind, safety);
      plan = nscd::wire::plan_subcycle(update->dt, requested_dt_sp);
    } else {
      plan = nscd::wire::plan_subcycle(update->dt, stable_dt_sp, requested_substeps);
    }
    nscd::wire::check_wire_step(plan.dt_sp, w, kind, safety);
  } catch (std::exception &e) {
    error->all(FLERR, "fix wire: dt_SP above the wire stability limit dt_SP max = {:.6g}: {}. Ways "
               "out: fix wire option 'substeps auto' (default), a larger 'substeps N', a smaller "
               "'dt_sp', or a smaller timestep", stable_dt_sp, e.what());
  }
}

void FixWire::setup(int /*vflag*/)
{
  // Atoms may have changed rank since the last step (balance, a box change) while the
  // neighbour build of this setup keeps the last step's time stamp: hand over anyway.
  histories_placed_at = -1;
  gather_elements();
  check_ghost_cutoff();
  rescale_states(plan.dt_sp);
  diagnostics[SUBSTEPS] = plan.substeps;
  diagnostics[DT_SP] = plan.dt_sp;
  diagnostics[DT_SP_STABLE] = stable_dt_sp;
  diagnostics[STEPS_TOO_FAST] = 0.0;
  warned_fast_motion = false;
}

void FixWire::reset_dt()
{
  plan_substeps();
  rescale_states(plan.dt_sp);
}

/* The wire's topology on every rank: a contact pair is found on the rank owning the first
   node of its lower element, and that rank must see the other element whatever rank
   stores its bond. newton_bond on: each element is in exactly one rank's bond list. */
void FixWire::gather_elements()
{
  std::vector<std::array<tagint, 2>> mine;
  double longest = 0.0;
  if (bond)
    for (int n = 0; n < neighbor->nbondlist; n++) {
      const int *b = neighbor->bondlist[n];
      const tagint p = atom->tag[b[0]], q = atom->tag[b[1]];
      mine.push_back({std::min(p, q), std::max(p, q)});
      longest = std::max({longest, bond->rest_length(b[2]), (vec3(atom->x[b[0]]) - vec3(atom->x[b[1]])).norm()});
    }
  MPI_Allreduce(&longest, &longest_element, 1, MPI_DOUBLE, MPI_MAX, world);
  elements = gather_records(mine, world, true);
  std::sort(elements.begin(), elements.end());
  elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
}

FixWire::ContactKey FixWire::history_key(const Candidate &c, int slot)
{
  if (c.kind != Candidate::Kind::wire_grain) return c.key;
  return {c.key[0], c.key[1], c.key[2], slot};
}

/* True if nodes p and q are the same node or the two ends of one element. */
bool FixWire::joined(tagint p, tagint q) const
{
  return p == q || std::binary_search(elements.begin(), elements.end(),
                                      std::array<tagint, 2>{std::min(p, q), std::max(p, q)});
}

/* The rank computing a contact (owner of the first node of the lower element) must hold as
   ghosts every grain and node that contact can reach within a step: from that node, a
   grain's centre lies within L + r_w + R + skin and the other element's nodes within
   2 L + 2 r_w + skin. Needed across ranks and across periodic boundaries. */
void FixWire::check_ghost_cutoff()
{
  const bool periodic = domain->xperiodic || domain->yperiodic || domain->zperiodic;
  if (!periodic && comm->nprocs == 1) return;
  if (elements.empty() || law.k_n == 0.0) return;    // no contacts: LAMMPS checks the bonds
  double reach = 0.0, largest_grain;
  for (int i = 0; i < atom->nlocal; i++)
    if (avec->shape[i] != 0) reach = std::max(reach, avec->radius[i]);
  MPI_Allreduce(&reach, &largest_grain, 1, MPI_DOUBLE, MPI_MAX, world);
  const double L = longest_element;
  const double needed = std::max(largest_grain + L + wire_radius, 2.0 * L + 2.0 * wire_radius) +
      neighbor->skin;
  const double have = std::max(neighbor->cutneighmax, comm->cutghostuser);
  if (have < needed)
    error->all(FLERR, "fix wire: ghost cutoff {:.6g} is below the reach {:.6g} of a wire contact "
               "(max(largest grain radius {:.6g} + L + r_w, 2 L + 2 r_w) + skin, with element length "
               "L = {:.6g}, r_w = {:.6g}) across {}; use 'comm_modify cutoff {:.6g}'", have, needed,
               largest_grain, L, wire_radius, comm->nprocs > 1 ? "MPI ranks" : "a periodic boundary",
               needed);
}

void FixWire::rescale_states(double new_dt)
{
  if (state_dt > 0.0 && state_dt != new_dt)
    for (int i = 0; i < atom->nlocal; i++) {
      if (gear[i][kGearColumns - 1] == 0.0) continue;
      nscd::wire::Gear5State s;
      s.unpack(gear[i]);
      nscd::wire::gear5_change_step(s, state_dt, new_dt);
      s.pack(gear[i]);
    }
  state_dt = new_dt;
}

/* ---------------------------------------------------------------------- the step */

void FixWire::post_force(int /*vflag*/)
{
  const int ntotal = atom->nlocal + atom->nghost;
  fbuf.assign(6 * (size_t) ntotal, 0.0);
  vbuf.assign(3 * (size_t) ntotal, 0.0);
  load_nodes();
  measure_external_forces();
  hand_over_histories();
  find_candidates();
  grain_forces.reset(ntotal + (int) boundaries.size());    // boundary k at ntotal + k
  nscd::wire::run_subcycle(plan, corrector, nodes, grain_forces,
      [&](const nscd::wire::SubstepInfo &info, const std::vector<Vec3> &x,
          const std::vector<Vec3> &v, std::vector<Vec3> &f, nscd::wire::GrainForceAccumulator &) {
        substep_forces(info, x, v, f);
      });
  check_motion_within_skin();
  store_nodes();
  hand_forces_to_grains();
  hand_forces_to_boundaries();
  keep_histories();
  sum_diagnostics_over_ranks();
}

/* Contacts are looked for once per step, among bodies closer than the neighbour skin. A
   pair closing by more than the skin within one step is missed (a wire can pass through a
   grain): count such steps (output 13) and warn once per run. Closing speed bound: the
   largest node displacement of the step plus the larger of it and the largest grain
   motion (at the velocities the subcycle moves the grains with). */
void FixWire::check_motion_within_skin()
{
  if (law.k_n == 0.0) return;    // no contacts to miss
  double largest[2] = {0.0, 0.0};    // node, grain
  for (int k = 0; k < nodes.size(); k++)
    largest[0] = std::max(largest[0], (nodes.state[k].position() - step_start[k]).norm());
  for (int j = 0; j < atom->nlocal; j++)
    if (avec->shape[j] != 0)
      largest[1] = std::max(largest[1], (vec3(atom->v[j]).norm() + vec3(avec->omega[j]).norm() * avec->radius[j]) *
                                            update->dt);
  MPI_Allreduce(MPI_IN_PLACE, largest, 2, MPI_DOUBLE, MPI_MAX, world);
  if (largest[0] + std::max(largest[0], largest[1]) <= neighbor->skin) return;
  diagnostics[STEPS_TOO_FAST] += 1.0;
  if (warned_fast_motion) return;
  warned_fast_motion = true;
  if (comm->me == 0)
    error->warning(FLERR, "fix wire: at step {} a wire node moved {:.4g} and a grain {:.4g} in one step, "
                   "closing by more than the neighbour skin {:.4g}: contacts can be missed (output 13 "
                   "counts such steps). Use a smaller timestep or a larger skin ('neighbor {:.4g} bin')",
                   update->ntimestep, largest[0], largest[1], neighbor->skin,
                   2.0 * (largest[0] + std::max(largest[0], largest[1])));
}

/* Energies and contact counts of the last substep, summed over the ranks. */
void FixWire::sum_diagnostics_over_ranks()
{
  static_assert(E_AXIAL == 0 && N_WIRE_GRAIN == 4, "the summed diagnostics come first");
  double sums[N_WIRE_GRAIN + 2];
  std::copy(&diagnostics[E_AXIAL], &diagnostics[N_WIRE_GRAIN] + 1, sums);
  sums[N_WIRE_GRAIN + 1] = diagnostics[N_WIRE_BOUNDARY];
  MPI_Allreduce(MPI_IN_PLACE, sums, N_WIRE_GRAIN + 2, MPI_DOUBLE, MPI_SUM, world);
  std::copy(sums, sums + N_WIRE_GRAIN + 1, &diagnostics[E_AXIAL]);
  diagnostics[N_WIRE_BOUNDARY] = sums[N_WIRE_GRAIN + 1];
}

/* The owned wire nodes (shape 0) into the node set: Gear state from the per-atom array, with
   position and velocity taken from LAMMPS (which may have remapped or changed them).
   Nodes outside the group are anchors: held where they are. */
void FixWire::load_nodes()
{
  node_atom.clear();
  for (int i = 0; i < atom->nlocal; i++)
    if (avec->shape[i] == 0) node_atom.push_back(i);
  const int n = (int) node_atom.size();
  nodes.state.resize(n);
  nodes.mass.resize(n);
  nodes.fixed.resize(n);
  step_start.resize(n);
  nodes.dt = plan.dt_sp;
  for (int k = 0; k < n; k++) {
    const int i = node_atom[k];
    nscd::wire::Gear5State &s = nodes.state[k];
    if (gear[i][kGearColumns - 1] != 0.0) s.unpack(gear[i]);
    else s = nscd::wire::gear5_start(vec3(atom->x[i]), vec3(atom->v[i]), Vec3::Zero(), plan.dt_sp);
    s.r[0] = step_start[k] = vec3(atom->x[i]);
    s.r[1] = vec3(atom->v[i]) * plan.dt_sp;
    nodes.mass[k] = avec->rmass[i];
    nodes.fixed[k] = (atom->mask[i] & groupbit) ? 0 : 1;
  }
  nscd::wire::prepare_wire_nodes(nodes, plan.dt_sp);
}

void FixWire::store_nodes()
{
  double **x = atom->x, **v = atom->v;
  for (int k = 0; k < nodes.size(); k++) {
    const int i = node_atom[k];
    if (nodes.fixed[k]) continue;
    const nscd::wire::Gear5State &s = nodes.state[k];
    for (int d = 0; d < 3; d++) {
      x[i][d] = s.position()[d];
      v[i][d] = s.velocity(plan.dt_sp)[d];
    }
    s.pack(gear[i]);
    gear[i][kGearColumns - 1] = 1.0;
  }
  share_node_state();    // ghosts at the final positions, for later fixes and output
}

/* External force on a node = LAMMPS' force (gravity, addforce, ...) minus what bond_style
   and angle_style wire put there, which the subcycle recomputes every substep. The same
   kernels at the same positions give the same numbers, so the difference is exact up to
   the order of summation. */
void FixWire::measure_external_forces()
{
  share_node_state();
  std::fill(fbuf.begin(), fbuf.end(), 0.0);
  double ea, eb;
  add_elastic_forces(&ea, &eb);
  sum_ghost_forces(3);
  external_force.resize(nodes.size());
  for (int k = 0; k < nodes.size(); k++) {
    const int i = node_atom[k];
    external_force[k] = vec3(atom->f[i]) - vec3(&fbuf[3 * (size_t) i]);
  }
}

void FixWire::substep_forces(const nscd::wire::SubstepInfo &info, const std::vector<Vec3> &x,
                             const std::vector<Vec3> &v, std::vector<Vec3> &f)
{
  for (int k = 0; k < nodes.size(); k++) {
    if (nodes.fixed[k]) continue;
    const int i = node_atom[k];
    for (int d = 0; d < 3; d++) {
      atom->x[i][d] = x[k][d];
      vbuf[3 * (size_t) i + d] = v[k][d];
    }
  }
  share_node_state();
  std::fill(fbuf.begin(), fbuf.end(), 0.0);
  add_elastic_forces(&diagnostics[E_AXIAL], &diagnostics[E_BENDING]);
  add_contact_forces(info.time, info.dt);
  sum_ghost_forces(3);
  for (int k = 0; k < nodes.size(); k++)
    f[k] = vec3(&fbuf[3 * (size_t) node_atom[k]]) + external_force[k] - node_damping * v[k];
}

/* Positions and velocities of the owned nodes to their ghost copies. */
void FixWire::share_node_state()
{
  comm_mode = Comm::node_state;
  comm->forward_comm(this, 6);
}

void FixWire::sum_ghost_forces(int columns)
{
  comm_mode = columns == 3 ? Comm::node_force : Comm::grain_force;
  comm->reverse_comm(this, columns);
}

/* Bond and angle forces of every element and joint, by the kernels of bond_style wire and
   angle_style wire, into fbuf (3 per local atom). */
double FixWire::add_elastic_forces(double *energy_axial, double *energy_bending)
{
  double **x = atom->x;
  *energy_axial = *energy_bending = 0.0;
  if (bond)
    for (int n = 0; n < neighbor->nbondlist; n++) {
      const int *b = neighbor->bondlist[n];
      const nscd::wire::AxialForces e = bond->element(b[2], x[b[0]], x[b[1]]);
      add_to(&fbuf[3 * (size_t) b[0]], e.on_a);
      add_to(&fbuf[3 * (size_t) b[1]], e.on_b);
      *energy_axial += e.energy;
    }
  if (angle)
    for (int n = 0; n < neighbor->nanglelist; n++) {
      const int *a = neighbor->anglelist[n];
      const nscd::wire::BendingForces e = angle->joint(a[3], x[a[0]], x[a[1]], x[a[2]]);
      add_to(&fbuf[3 * (size_t) a[0]], e.on_a);
      add_to(&fbuf[3 * (size_t) a[1]], e.on_b);
      add_to(&fbuf[3 * (size_t) a[2]], e.on_c);
      *energy_bending += e.energy;
    }
  return *energy_axial + *energy_bending;
}

/* ---------------------------------------------------------------------- contacts */

/* Element pairs and element-grain pairs close enough to touch during this step (bounding
   spheres plus the neighbour skin), found once per LAMMPS step on a grid. Owner rule: a
   pair is computed by the rank owning the first node of its lower element (elements
   ordered by their tags), with the other bodies' closest images; so each pair is computed
   exactly once over all ranks, and across periodic boundaries. Elements sharing a node or
   joined by one element are skipped: their contact is the wire's own bending. */
void FixWire::find_candidates()
{
  std::vector<Candidate> found;
  if (law.k_n > 0.0 && !elements.empty()) {    // the same on every rank: the collective is safe
    share_grain_velocities();
    locate_element_images();
    const bool computes_some = std::any_of(images.begin(), images.end(),
                                           [&](const ElementImage &e) { return e.a < atom->nlocal; });
    if (computes_some) {
      find_wire_grain_candidates(found);
      find_wire_wire_candidates(found);
    }
  }
  if (law.k_n > 0.0) find_wire_boundary_candidates(found);
  for (Candidate &c : found)
    for (int slot = 0; slot < slots_of(c); slot++) {
      const auto it = histories.find(history_key(c, slot));
      if (it != histories.end()) c.history[slot] = it->second;
    }
  candidates.swap(found);

  // rigid motion of the grains over the step at their current velocities
  motion.resize(atom->nlocal + atom->nghost);
  for (const Candidate &c : candidates)
    if (c.kind == Candidate::Kind::wire_grain) {
      const int j = c.b1;
      motion[j].start = avec->pose(j);
      motion[j].velocity = vec3(atom->v[j]);
      motion[j].angular_velocity = vec3(avec->omega[j]);
    }
}

/* Every copy of every element whose nodes this rank holds; images[k].a < nlocal marks the
   copies this rank computes contacts for. */
void FixWire::locate_element_images()
{
  images.clear();
  double **x = atom->x;
  const int ntotal = atom->nlocal + atom->nghost;
  for (int i = 0; i < ntotal; i++) {
    if (avec->shape[i] != 0) continue;
    const std::array<tagint, 2> from{atom->tag[i], 0}, to{atom->tag[i], MAXTAGINT};
    const auto first = std::lower_bound(elements.begin(), elements.end(), from);
    const auto last = std::upper_bound(first, elements.end(), to);
    for (auto e = first; e != last; ++e) {
      const int j = domain->closest_image(i, atom->map((*e)[1]));
      if (j < 0) {
        if (i < atom->nlocal)
          error->one(FLERR, "fix wire: node ID {} of the element {}-{} is missing on the rank "
                     "owning node ID {}; increase the ghost cutoff with 'comm_modify cutoff'",
                     (*e)[1], (*e)[0], (*e)[1], (*e)[0]);
        continue;
      }
      const Vec3 xa = vec3(x[i]), xb = vec3(x[j]);
      images.push_back({i, j, (int) (e - elements.begin()), 0.5 * (xa + xb), 0.5 * (xb - xa).norm()});
    }
  }
}

void FixWire::find_wire_grain_candidates(std::vector<Candidate> &found)
{
  double **x = atom->x;
  tagint *tag = atom->tag;
  const double margin = neighbor->skin;
  grain_atom.clear();
  std::vector<Vec3> centres;
  double largest = 0.0, longest_half = 0.0;
  for (int j = 0; j < atom->nlocal + atom->nghost; j++)
    if (avec->shape[j] != 0) {
      grain_atom.push_back(j);
      centres.push_back(vec3(x[j]));
      largest = std::max(largest, avec->radius[j]);
    }
  if (centres.empty()) return;
  for (const ElementImage &e : images) longest_half = std::max(longest_half, e.half);
  grain_grid.build(centres, 2.0 * longest_half + wire_radius + largest + margin);
  for (const ElementImage &e : images) {
    if (e.a >= atom->nlocal) continue;
    grain_grid.for_each_near(e.centre, e.half + wire_radius + largest + margin, [&](int g) {
      const int j = grain_atom[g];
      if (domain->closest_image(e.a, atom->map(tag[j])) != j) return;    // one image per grain
      const double reach = e.half + wire_radius + avec->radius[j] + margin;
      if ((vec3(x[j]) - e.centre).squaredNorm() > reach * reach) return;
      found.push_back({Candidate::Kind::wire_grain, e.a, e.b, j, -1, {tag[e.a], tag[e.b], tag[j], 0}, {}});
    });
  }
}

void FixWire::find_wire_wire_candidates(std::vector<Candidate> &found)
{
  tagint *tag = atom->tag;
  const double margin = neighbor->skin;
  std::vector<Vec3> centres;
  double longest_half = 0.0;
  for (const ElementImage &e : images) {
    centres.push_back(e.centre);
    longest_half = std::max(longest_half, e.half);
  }
  image_grid.build(centres, 4.0 * longest_half + 2.0 * wire_radius + margin);
  for (const ElementImage &A : images) {
    if (A.a >= atom->nlocal) continue;
    const tagint ta[2] = {tag[A.a], tag[A.b]};
    image_grid.for_each_near(A.centre, A.half + longest_half + 2.0 * wire_radius + margin, [&](int k) {
      const ElementImage &B = images[k];
      if (B.element <= A.element) return;    // the pair belongs to the lower element's owner
      if (domain->closest_image(A.a, atom->map(tag[B.a])) != B.a) return;    // one image per element
      const double reach = A.half + B.half + 2.0 * wire_radius + margin;
      if ((A.centre - B.centre).squaredNorm() > reach * reach) return;
      const tagint tb[2] = {tag[B.a], tag[B.b]};
      for (tagint s : ta)
        for (tagint t : tb)
          if (joined(s, t)) return;
      found.push_back({Candidate::Kind::wire_wire, A.a, A.b, B.a, B.b, {ta[0], ta[1], tb[0], tb[1]}, {}});
    });
  }
}

/* Owned nodes of the group near a wall or the plate (gap below the skin plus the
   boundary's travel in the step). A node's sphere is all of the wire a plane or a cylinder
   can touch (lib/geometry/contact.h), so each node is one contact per boundary. */
void FixWire::find_wire_boundary_candidates(std::vector<Candidate> &found)
{
  double **x = atom->x;
  for (int k = 0; k < (int) boundaries.size(); k++) {
    const BoundaryLink &b = boundaries[k];
    const double reach = neighbor->skin + b.boundary->surface_velocity().norm() * update->dt;
    for (int i = 0; i < atom->nlocal; i++) {
      if (avec->shape[i] != 0 || !(atom->mask[i] & groupbit) || !(atom->mask[i] & b.groupbit)) continue;
      if (b.boundary->touch_sphere(vec3(x[i]), wire_radius, 0.0).gap > reach) continue;
      found.push_back({Candidate::Kind::wire_boundary, i, -1, k, -1, {atom->tag[i], 0, b.key, 0}, {}});
    }
  }
}

/* Grains' velocities and angular velocities to their ghost copies: the subcycle moves
   ghost grains rigidly over the step (LAMMPS sends ghost velocities only with
   'comm_modify vel yes'). */
void FixWire::share_grain_velocities()
{
  comm_mode = Comm::grain_velocity;
  comm->forward_comm(this, 6);
}

/* After atoms have moved between ranks, each contact history goes to the rank that now
   computes its contact: the owner of the key's first node. Only histories whose node left
   travel (one gather over the ranks), and only on steps with a new neighbour build. */
void FixWire::hand_over_histories()
{
  if (neighbor->lastcall == histories_placed_at) return;
  histories_placed_at = neighbor->lastcall;
  auto owned_here = [&](tagint t) {
    const int i = atom->map(t);
    return i >= 0 && i < atom->nlocal;
  };
  // After read_restart every rank holds every history: keep the own ones.
  const bool send = comm->nprocs > 1 && !histories_on_every_rank;
  std::vector<StoredHistory> leaving;
  for (auto it = histories.begin(); it != histories.end();) {
    if (owned_here(it->first[0])) {
      ++it;
      continue;
    }
    if (send) leaving.push_back(stored(it->first, it->second));
    it = histories.erase(it);
  }
  histories_on_every_rank = false;
  if (!send) return;
  for (const StoredHistory &h : gather_records(leaving, world, true))
    if (owned_here((tagint) h.key[0])) histories[key_of(h)] = history_of(h);
}

void FixWire::add_contact_forces(double tau, double dt)
{
  double energy = 0.0;
  int wire_wire = 0, wire_grain = 0, wire_boundary = 0;
  for (Candidate &c : candidates) {
    switch (c.kind) {
      case Candidate::Kind::wire_wire: wire_wire += wire_wire_force(c, dt, energy); break;
      case Candidate::Kind::wire_grain: wire_grain += wire_grain_force(c, tau, dt, energy); break;
      case Candidate::Kind::wire_boundary: wire_boundary += wire_boundary_force(c, tau, dt, energy); break;
    }
  }
  diagnostics[E_CONTACT] = energy;
  diagnostics[N_WIRE_WIRE] = wire_wire;
  diagnostics[N_WIRE_GRAIN] = wire_grain;
  diagnostics[N_WIRE_BOUNDARY] = wire_boundary;
}

/* Element A = (a1, a2) against grain b1 at its pose after time tau: a soft contact at each
   point (the ends of the touching stretch), each with its own overlap and history slot,
   the two ends of a stretch weighted by lib/wire/contact_weights.h. The query reaches out
   by r_w, the ramp of those weights. */
bool FixWire::wire_grain_force(Candidate &c, double tau, double dt, double &energy)
{
  double **x = atom->x;
  const nscd::wire::GrainMotion &m = motion[c.b1];
  const nscd::Pose pose = m.pose_at(tau);
  const nscd::Segment segment{vec3(x[c.a1]), vec3(x[c.a2]), wire_radius};
  nscd::SegmentGrainContact contact;
  std::array<nscd::wire::LeverWeights, nscd::SegmentGrainContact::kMaxPoints> w{};
  try {
    contact = nscd::contact_segment_grain(segment, avec->shape_of(c.b1), pose, wire_radius, workspace);
    for (int k = 0; k < contact.count; k++) w[k] = nscd::wire::lever_weights(contact[k].s_i);
  } catch (std::exception &e) {
    error->one(FLERR, "fix wire: contact of the element of atoms {}-{} with grain ID {} failed: {}",
               atom->tag[c.a1], atom->tag[c.a2], atom->tag[c.b1], e.what());
  }
  const double stretch_weight = contact.count < 2 ? 1.0 :
      nscd::wire::stretch_end_weight((contact[1].s_i - contact[0].s_i) * (segment.p1 - segment.p0).norm(), wire_radius);
  std::array<bool, kSlots> closed{};
  for (int k = 0; k < contact.count; k++) {
    const nscd::SegmentContact &p = contact[k];
    if (p.gap >= 0.0) continue;
    // slots: the start sphere 0, the end sphere 1; inside, the far end of a stretch 3, else 2
    const nscd::SegmentPart part = nscd::segment_part_i(p);
    const int slot = part == nscd::SegmentPart::start ? 0 : part == nscd::SegmentPart::end ? 1 : (k == 1 ? 3 : 2);
    closed[slot] = true;
    const Vec3 v_wire = w[k].on_a * vec3(&vbuf[3 * (size_t) c.a1]) + w[k].on_b * vec3(&vbuf[3 * (size_t) c.a2]);
    const Vec3 v_rel = v_wire - m.point_velocity(p.point, tau);
    const nscd::wire::SoftContactForce r =
        nscd::wire::soft_contact_force(law, p.normal, -p.gap, v_rel, dt, c.history[slot]);
    const Vec3 force = stretch_weight * r.force;
    add_to(&fbuf[3 * (size_t) c.a1], w[k].on_a * force);
    add_to(&fbuf[3 * (size_t) c.a2], w[k].on_b * force);
    grain_forces.add(c.b1, -force, p.point - pose.position);
    energy += stretch_weight * r.elastic_energy;
  }
  bool any = false;
  for (int slot = 0; slot < kSlots; slot++) {
    if (!closed[slot]) c.history[slot] = {};
    any = any || closed[slot];
  }
  return any;
}

/* Element A = (a1, a2) against element B = (b1, b2); the force on A, minus on B, each
   split over its nodes by the lever rule. */
bool FixWire::wire_wire_force(Candidate &c, double dt, double &energy)
{
  double **x = atom->x;
  const nscd::Segment A{vec3(x[c.a1]), vec3(x[c.a2]), wire_radius};
  const nscd::Segment B{vec3(x[c.b1]), vec3(x[c.b2]), wire_radius};
  const auto contact = nscd::contact_segments(A, B, 0.0);
  if (!contact || contact->gap >= 0.0) {
    c.history[0] = {};
    return false;
  }
  auto node_v = [&](int i) { return vec3(&vbuf[3 * (size_t) i]); };
  const nscd::wire::LeverWeights wa = nscd::wire::lever_weights(contact->s_i);
  const nscd::wire::LeverWeights wb = nscd::wire::lever_weights(contact->s_j);
  const Vec3 v_rel = (wa.on_a * node_v(c.a1) + wa.on_b * node_v(c.a2)) -
      (wb.on_a * node_v(c.b1) + wb.on_b * node_v(c.b2));
  const nscd::wire::SoftContactForce r =
      nscd::wire::soft_contact_force(law, contact->normal, -contact->gap, v_rel, dt, c.history[0]);
  add_to(&fbuf[3 * (size_t) c.a1], wa.on_a * r.force);
  add_to(&fbuf[3 * (size_t) c.a2], wa.on_b * r.force);
  add_to(&fbuf[3 * (size_t) c.b1], -wb.on_a * r.force);
  add_to(&fbuf[3 * (size_t) c.b2], -wb.on_b * r.force);
  energy += r.elastic_energy;
  return true;
}

/* Node c.a1 against boundary c.b1 where it stands after time tau. The boundary's share is
   kept in grain_forces after the grains (index nlocal + nghost + c.b1). */
bool FixWire::wire_boundary_force(Candidate &c, double tau, double dt, double &energy)
{
  const BoundaryLink &b = boundaries[c.b1];
  const nscd::ContactPoint p = b.boundary->touch_sphere(vec3(atom->x[c.a1]), wire_radius, tau);
  if (p.gap >= 0.0) {
    c.history[0] = {};
    return false;
  }
  const Vec3 v_rel = vec3(&vbuf[3 * (size_t) c.a1]) - b.boundary->surface_velocity();
  const nscd::wire::SoftContactForce r =
      nscd::wire::soft_contact_force(b.law, p.normal, -p.gap, v_rel, dt, c.history[0]);
  add_to(&fbuf[3 * (size_t) c.a1], r.force);
  grain_forces.add(atom->nlocal + atom->nghost + c.b1, -r.force, Vec3::Zero());
  energy += r.elastic_energy;
  return true;
}

/* Mean wire forces on the walls and the plate over the substeps, summed over the ranks, to
   each boundary (on every rank) before fix nscd solves the step. */
void FixWire::hand_forces_to_boundaries()
{
  if (boundaries.empty()) return;
  const int first = atom->nlocal + atom->nghost;
  std::vector<double> mine(3 * boundaries.size()), all(3 * boundaries.size());
  for (size_t k = 0; k < boundaries.size(); k++) store(grain_forces.mean_force(first + (int) k), &mine[3 * k]);
  MPI_Allreduce(mine.data(), all.data(), (int) all.size(), MPI_DOUBLE, MPI_SUM, world);
  for (size_t k = 0; k < boundaries.size(); k++)
    boundaries[k].boundary->take_wire_force(vec3(&all[3 * k]), update->ntimestep);
}

/* Mean wire->grain force and torque over the substeps, added to the owners' f and torque
   (ghost grains' shares summed onto their owners first). */
void FixWire::hand_forces_to_grains()
{
  const int ntotal = atom->nlocal + atom->nghost;
  std::fill(fbuf.begin(), fbuf.end(), 0.0);
  Vec3 total = Vec3::Zero();
  for (int j = 0; j < ntotal; j++) {
    if (avec->shape[j] == 0) continue;
    const Vec3 force = grain_forces.mean_force(j), torque = grain_forces.mean_torque(j);
    for (int d = 0; d < 3; d++) {
      fbuf[6 * (size_t) j + d] = force[d];
      fbuf[6 * (size_t) j + 3 + d] = torque[d];
    }
    total += force;
  }
  double mine[3] = {total.x(), total.y(), total.z()}, all[3];
  MPI_Allreduce(mine, all, 3, MPI_DOUBLE, MPI_SUM, world);
  for (int d = 0; d < 3; d++) diagnostics[GRAIN_FX + d] = all[d];
  sum_ghost_forces(6);
  for (int i = 0; i < atom->nlocal; i++) {
    if (avec->shape[i] == 0) continue;
    const double *g = &fbuf[6 * (size_t) i];
    for (int d = 0; d < 3; d++) {
      atom->f[i][d] += g[d];
      avec->torque[i][d] += g[3 + d];
    }
  }
}

/* Histories of the contacts still closed at the end of the step, for the next one. */
void FixWire::keep_histories()
{
  histories.clear();
  for (const Candidate &c : candidates)
    for (int slot = 0; slot < slots_of(c); slot++) {
      const nscd::wire::TangentialHistory &h = c.history[slot];
      if (h.xi[0] != 0.0 || h.xi[1] != 0.0 || h.xi[2] != 0.0 || h.sliding != 0.0)
        histories[history_key(c, slot)] = h;
    }
}

double FixWire::compute_vector(int n)
{
  return diagnostics[n];
}

/* ---------------------------------------------------------------------- comm */

int FixWire::pack_forward_comm(int n, int *list, double *buf, int pbc_flag, int *pbc)
{
  if (comm_mode == Comm::grain_velocity) {
    int m = 0;
    for (int k = 0; k < n; k++) {
      for (int d = 0; d < 3; d++) buf[m++] = atom->v[list[k]][d];
      for (int d = 0; d < 3; d++) buf[m++] = avec->omega[list[k]][d];
    }
    return m;
  }
  double shift[3] = {0.0, 0.0, 0.0};
  if (pbc_flag) {
    shift[0] = pbc[0] * domain->xprd;
    shift[1] = pbc[1] * domain->yprd;
    shift[2] = pbc[2] * domain->zprd;
    if (domain->triclinic) {
      shift[0] += pbc[5] * domain->xy + pbc[4] * domain->xz;
      shift[1] += pbc[3] * domain->yz;
    }
  }
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int j = list[k];
    for (int d = 0; d < 3; d++) buf[m++] = atom->x[j][d] + shift[d];
    for (int d = 0; d < 3; d++) buf[m++] = vbuf[3 * (size_t) j + d];
  }
  return m;
}

void FixWire::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  if (comm_mode == Comm::grain_velocity) {
    for (int i = first; i < first + n; i++) {
      for (int d = 0; d < 3; d++) atom->v[i][d] = buf[m++];
      for (int d = 0; d < 3; d++) avec->omega[i][d] = buf[m++];
    }
    return;
  }
  for (int i = first; i < first + n; i++) {
    for (int d = 0; d < 3; d++) atom->x[i][d] = buf[m++];
    for (int d = 0; d < 3; d++) vbuf[3 * (size_t) i + d] = buf[m++];
  }
}

int FixWire::pack_reverse_comm(int n, int first, double *buf)
{
  const int cols = comm_mode == Comm::grain_force ? 6 : 3;
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int d = 0; d < cols; d++) buf[m++] = fbuf[(size_t) cols * i + d];
  return m;
}

void FixWire::unpack_reverse_comm(int n, int *list, double *buf)
{
  const int cols = comm_mode == Comm::grain_force ? 6 : 3;
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int d = 0; d < cols; d++) fbuf[(size_t) cols * list[k] + d] += buf[m++];
}

/* ---------------------------------------------------------------------- per-atom state */

void FixWire::grow_arrays(int nmax)
{
  memory->grow(gear, nmax, kGearColumns, "wire:gear");
}

void FixWire::copy_arrays(int i, int j, int /*delflag*/)
{
  std::copy(gear[i], gear[i] + kGearColumns, gear[j]);
}

void FixWire::set_arrays(int i)
{
  std::fill(gear[i], gear[i] + kGearColumns, 0.0);
}

int FixWire::pack_exchange(int i, double *buf)
{
  std::copy(gear[i], gear[i] + kGearColumns, buf);
  return kGearColumns;
}

int FixWire::unpack_exchange(int nlocal, double *buf)
{
  std::copy(buf, buf + kGearColumns, gear[nlocal]);
  return kGearColumns;
}

int FixWire::pack_restart(int i, double *buf)
{
  buf[0] = kGearColumns + 1;    // LAMMPS convention: the count includes this slot
  std::copy(gear[i], gear[i] + kGearColumns, buf + 1);
  return kGearColumns + 1;
}

void FixWire::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  std::copy(&extra[nlocal][m + 1], &extra[nlocal][m + 1] + kGearColumns, gear[nlocal]);
}

int FixWire::size_restart(int /*nlocal*/)
{
  return kGearColumns + 1;
}

int FixWire::maxsize_restart()
{
  return kGearColumns + 1;
}

/* Global restart: the step of the stored Gear states and the contact histories of all
   ranks. */
void FixWire::write_restart(FILE *fp)
{
  std::vector<StoredHistory> mine;
  // Read from a restart and no step since: every rank holds them all; write them once.
  if (!histories_on_every_rank || comm->me == 0)
    for (const auto &entry : histories) mine.push_back(stored(entry.first, entry.second));
  const std::vector<StoredHistory> all = gather_records(mine, world, false);
  if (comm->me == 0) {
    const double header[2] = {state_dt, (double) all.size()};
    const int size = (int) (sizeof(header) + all.size() * sizeof(StoredHistory));
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(header, sizeof(double), 2, fp);
    fwrite(all.data(), sizeof(StoredHistory), all.size(), fp);
  }
}

void FixWire::restart(char *buf)
{
  // read_restart hands every rank the whole block; hand_over_histories() keeps the own ones.
  double header[2];
  std::memcpy(header, buf, sizeof(header));
  state_dt = header[0];
  const size_t count = (size_t) header[1];
  histories.clear();
  for (size_t k = 0; k < count; k++) {
    StoredHistory h;
    std::memcpy(&h, buf + sizeof(header) + k * sizeof(StoredHistory), sizeof(StoredHistory));
    histories[key_of(h)] = history_of(h);
  }
  histories_on_every_rank = true;
}

double FixWire::memory_usage()
{
  return (double) atom->nmax * kGearColumns * sizeof(double) +
      (double) (fbuf.size() + vbuf.size()) * sizeof(double) +
      (double) candidates.size() * sizeof(Candidate);
}
