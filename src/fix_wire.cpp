/* fix wire: the wire subcycle of lib/wire driven from LAMMPS' post_force. Gathers the wire
   nodes, grains and boundaries, calls lib/wire (wire_step.h: Gear-5 subcycle, elastic
   forces, contact_model.h), scatters the forces; LAMMPS' communication, restart and
   output. The physics is in lib/wire (doc/wire_model.md). */

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
#include "wire/wire_step.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

using namespace LAMMPS_NS;
using namespace FixConst;
using nscd::Vec3;
namespace wire = nscd::wire;

namespace {
enum Diagnostic {
  E_AXIAL, E_BENDING, E_CONTACT, N_WIRE_WIRE, N_WIRE_GRAIN, SUBSTEPS, DT_SP, GRAIN_FX, GRAIN_FY,
  GRAIN_FZ, DT_SP_STABLE, N_WIRE_BOUNDARY, STEPS_TOO_FAST
};
constexpr double kRestartVersion = -2.0;    // first number of the global restart block

// A wall or the plate as the wire's contact model sees it.
struct BoundaryView final : wire::NodeBoundary {
  NSCDBoundary *boundary = nullptr;
  int groupbit = 0;    // the nodes it touches: those of its fix group
  wire::BoundaryLink link{};
  nscd::ContactPoint touch_sphere(const Vec3 &c, double r, double tau) const override
  {
    return boundary->touch_sphere(c, r, tau);
  }
  Vec3 surface_velocity() const override { return boundary->surface_velocity(); }
};
}    // namespace

struct FixWire::Lib : wire::Exchange {
  FixWire *fix;
  wire::SoftContactLaw law;
  std::unique_ptr<wire::ContactModel> contacts;
  wire::SubcyclePlan plan;
  std::array<double, 6> corrector = wire::gear5_corrector_coefficients(wire::GearCorrector::ThreeSixteenths);
  wire::WireStep step;    // owned nodes, then their ghost copies; this rank's elements and joints
  wire::StepTiming timing;
  std::vector<BoundaryView> boundaries;
  std::vector<Vec3> step_start;
  std::vector<wire::StoredContact> restored;    // from a restart file, for the contact model
  explicit Lib(FixWire *f) : fix(f) {}
  // The subcycle's communication, wire nodes only: positions and velocities to the ghost
  // copies, their forces back to the owners.
  void share_copies(wire::WireNodeSet &) override { fix->communicate(Comm::node_state, false, true); }
  void return_copy_forces(wire::WireNodeSet &) override { fix->communicate(Comm::node_force, true, true); }
};

/* fix ID group wire [k_n K] [gamma_n G] [k_t K] [gamma_t G] [mu_s M] [mu_d M] [radius R]
                     [damp C] [substeps N|auto] [dt_sp DT] [safety S] [contacts_per_node N]
                     [skin S] */
FixWire::FixWire(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg), lib(new Lib(this))
{
  time_integrate = restart_global = restart_peratom = create_attribute = 1;
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
  if (law.k_n > 0.0) {    // k_n = 0: no contacts at all, the other coefficients unused
    try {
      wire::validate(law);
    } catch (std::exception &e) {
      error->all(FLERR, "fix wire: {}", e.what());
    }
    if (!(wire_radius > 0.0))
      error->all(FLERR, "fix wire: contacts (k_n {}) need a wire radius > 0: elements of radius 0 "
                 "never touch; give 'radius R' (or k_n 0 for a wire without contacts)", law.k_n);
  }
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
  wire::SoftContactLaw &law = lib->law;
  const std::map<std::string, double *> plain = {
      {"k_n", &law.k_n}, {"gamma_n", &law.gamma_n}, {"k_t", &law.k_t}, {"gamma_t", &law.gamma_t},
      {"mu_s", &law.mu_s}, {"mu_d", &law.mu_d}, {"radius", &wire_radius}, {"damp", &node_damping},
      {"contacts_per_node", &contacts_per_node}, {"dt_sp", &requested_dt_sp}, {"safety", &safety},
      {"skin", &contact_skin}};
  if (key == "substeps") {
    requested_dt_sp = 0.0;
    requested_substeps = strcmp(value, "auto") == 0 ? 0 : utils::inumeric(FLERR, value, false, lmp);
    if (requested_substeps < 0) error->all(FLERR, "fix wire: substeps {} must be >= 1 (or auto)", requested_substeps);
    return;
  }
  const auto option = plain.find(key);
  if (option == plain.end())
    error->all(FLERR, "fix wire: unknown keyword '{}' (expected k_n, gamma_n, k_t, gamma_t, mu_s, "
               "mu_d, radius, damp, substeps, dt_sp, safety, contacts_per_node, skin)", key);
  const double x = utils::numeric(FLERR, value, false, lmp);
  if (!(x >= 0.0) || !std::isfinite(x)) error->all(FLERR, "fix wire: {} = {} must be a finite number >= 0", key, x);
  if (key == "safety" && !(x > 0.0 && x <= 1.0)) error->all(FLERR, "fix wire: safety {} must be in (0, 1]", x);
  if (key == "skin" && !(x > 0.0)) error->all(FLERR, "fix wire: skin {} must be a finite number > 0", x);
  *option->second = x;
  mu_s_given = mu_s_given || key == "mu_s";
  mu_d_given = mu_d_given || key == "mu_d";
  if (key == "dt_sp") requested_substeps = 0;
}

int FixWire::setmask() { return POST_FORCE; }
double FixWire::substep() const { return lib->plan.dt_sp; }
int FixWire::substeps() const { return lib->plan.substeps; }
double FixWire::compute_vector(int n) { return diagnostics[n]; }

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
  tagint first_grain = MAXTAGINT, any_grain;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && avec->shape[i] != 0) first_grain = std::min(first_grain, atom->tag[i]);
  MPI_Allreduce(&first_grain, &any_grain, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (any_grain != MAXTAGINT)
    error->all(FLERR, "fix wire: atom ID {} in group '{}' is a grain (shape != 0); the group must "
               "hold wire nodes (shape 0) only, grains belong to fix nscd", any_grain, group->names[igroup]);
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
      error->warning(FLERR, "fix wire: fix {} ({}) is defined after fix wire and acts in post_force: "
                     "the wire subcycle does not see its forces; define it before fix wire",
                     modify->fix[f]->id, modify->fix[f]->style);
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

/* n substeps from the options and the stability limit of lib/wire/stability.h; a named
   error when the chosen dt_SP is above it. */
void FixWire::plan_substeps()
{
  wire::WireStiffness w;
  double mass = INFINITY, length = INFINITY;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && avec->shape[i] == 0) mass = std::min(mass, avec->rmass[i]);
  MPI_Allreduce(&mass, &w.node_mass, 1, MPI_DOUBLE, MPI_MIN, world);
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
  try {
    stable_dt_sp = wire::max_stable_wire_step(w, kind, safety);
    lib->plan = requested_dt_sp > 0.0 ? wire::plan_subcycle(update->dt, requested_dt_sp)
                                      : wire::plan_subcycle(update->dt, stable_dt_sp, requested_substeps);
    wire::check_wire_step(lib->plan.dt_sp, w, kind, safety);
  } catch (std::exception &e) {
    error->all(FLERR, "fix wire: dt_SP above the wire stability limit dt_SP max = {:.6g}: {}. Ways "
               "out: fix wire option 'substeps auto' (default), a larger 'substeps N', a smaller "
               "'dt_sp', or a smaller timestep", stable_dt_sp, e.what());
  }
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
  std::vector<wire::StoredContact> memories = lib->contacts ? lib->contacts->memories() : lib->restored;
  lib->contacts = std::make_unique<wire::ContactModel>(lib->law, wire_radius, skin);
  lib->contacts->add_memories(memories);
  lib->restored.clear();
  lib->step.contacts = lib->contacts.get();
}

/* Atoms may have changed rank since the last step (balance, a box change) while the
   neighbour build of this setup keeps the last step's time stamp: index again. */
void FixWire::setup(int /*vflag*/)
{
  indexed_at = -1;
  gather_elements();
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
  rebuilds_at_start = lib->contacts ? lib->contacts->rebuilds() : 0;
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
    error->all(FLERR, "fix wire: ghost cutoff {:.6g} is below the reach {:.6g} of a wire contact "
               "(max(largest grain radius {:.6g} + L + r_w, 2 L + 2 r_w) + skin, with element length "
               "L = {:.6g}, r_w = {:.6g}) across {}; use 'comm_modify cutoff {:.6g}'", have, needed, R, L,
               wire_radius, comm->nprocs > 1 ? "MPI ranks" : "a periodic boundary", needed);
}

void FixWire::rescale_states(double new_dt)
{
  for (int i = 0; i < atom->nlocal && state_dt > 0.0 && state_dt != new_dt; i++) {
    if (gear[i][kGearColumns - 1] == 0.0) continue;
    wire::Gear5State s;
    s.unpack(gear[i]);
    wire::gear5_change_step(s, state_dt, new_dt);
    s.pack(gear[i]);
  }
  state_dt = new_dt;
}

/* ---------------------------------------------------------------------- the step */

void FixWire::post_force(int /*vflag*/)
{
  const double wall_start = platform::walltime(), cpu_start = platform::cputime();
  const bool reindexed = neighbor->lastcall != indexed_at;
  if (reindexed) index_atoms();
  load_nodes();
  if (lib->contacts) update_scene(reindexed);
  else lib->step.reactions.reset((int) lib->boundaries.size());
  if (lib->contacts && reindexed) hand_over_memories();
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

  wire::WireTopology &t = lib->step.topology;
  t.elements.clear();
  t.joints.clear();
  auto node = [&](int i) {
    if (node_of_atom[i] < 0)
      error->one(FLERR, "fix wire: atom ID {} is a grain but belongs to a wire bond or angle; wire "
                 "elements and joints join wire nodes (shape 0) only", atom->tag[i]);
    return node_of_atom[i];
  };
  for (int n = 0; bond && n < neighbor->nbondlist; n++) {
    const int *b = neighbor->bondlist[n];
    t.elements.push_back({node(b[0]), node(b[1]), bond->rest_length(b[2]), bond->law(b[2])});
  }
  for (int n = 0; angle && n < neighbor->nanglelist; n++) {
    const int *a = neighbor->anglelist[n];
    t.joints.push_back({node(a[0]), node(a[1]), node(a[2]), angle->k_rot(a[3])});
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
    if (gear[i][kGearColumns - 1] != 0.0) s.unpack(gear[i]);
    else s = wire::gear5_start(vec3(atom->x[i]), vec3(atom->v[i]), Vec3::Zero(), dt);
    s.r[0] = lib->step_start[k] = vec3(atom->x[i]);
    s.r[1] = vec3(atom->v[i]) * dt;
    nodes.mass[k] = avec->rmass[i];
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
    gear[i][kGearColumns - 1] = 1.0;
  }
  communicate(Comm::node_position, false);    // ghosts at the final positions, for output
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
      const int j = domain->closest_image(i, atom->map((*e)[1]));
      if ((j < 0 || node_of_atom[j] < 0) && i < atom->nlocal)
        error->one(FLERR, "fix wire: node ID {} of the element {}-{} is missing on the rank owning node ID "
                   "{}; increase the ghost cutoff with 'comm_modify cutoff'", (*e)[1], (*e)[0], (*e)[1], (*e)[0]);
      if (j >= 0 && node_of_atom[j] >= 0) scene.elements.push_back({k, node_of_atom[j], (*e)[0], (*e)[1], i < atom->nlocal});
    }
  }
  if (!atom_of_grain.empty()) communicate(Comm::grain_velocity, false);    // ghost grains' v and omega
  scene.grains.resize(atom_of_grain.size());
  for (size_t g = 0; g < atom_of_grain.size(); g++) {
    const int i = atom_of_grain[g];
    scene.grains[g] = {atom->tag[i], &avec->shape_of(i), avec->pose(i), vec3(atom->v[i]), vec3(avec->omega[i])};
  }
  scene.boundaries.clear();
  for (BoundaryView &b : lib->boundaries) {
    b.link.speed = b.boundary->surface_velocity().norm();
    scene.boundaries.push_back(b.link);
  }
  lib->step.reactions.reset((int) (scene.grains.size() + scene.boundaries.size()));
  lib->contacts->begin_step(std::move(scene), update->dt, reindexed);
}

/* After atoms moved between ranks, each contact memory goes to the rank that now computes
   its contact: the owner of the key's first node. Only the memories whose node left travel
   (one gather over the ranks). After read_restart every rank holds all: each keeps its own. */
void FixWire::hand_over_memories()
{
  auto owned_here = [&](std::int64_t t) {
    const int i = atom->map((tagint) t);
    return i >= 0 && i < atom->nlocal;
  };
  const bool send = comm->nprocs > 1 && !memories_on_every_rank;
  const std::vector<wire::StoredContact> leaving = lib->contacts->take_memories_unless(owned_here);
  memories_on_every_rank = false;
  if (!send) return;
  std::vector<wire::StoredContact> arriving;
  for (const wire::StoredContact &c : gather_records(leaving, world, true))
    if (owned_here(c.key[0])) arriving.push_back(c);
  lib->contacts->add_memories(arriving);
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
    error->warning(FLERR, "fix wire: at step {} a wire node moved {:.4g} and a grain {:.4g} in one step, "
                   "closing by more than the neighbour skin {:.4g}: contacts with atoms beyond the ghost "
                   "cutoff can be missed (output 13 counts such steps). Use a smaller timestep or a larger "
                   "skin ('neighbor {:.4g} bin')", update->ntimestep, largest[0], largest[1], neighbor->skin,
                   2.0 * closing);
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
  if (grains > 0) communicate(Comm::grain_force, true);
  for (int i = 0; i < atom->nlocal && grains > 0; i++) {
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

/* fix wire's share of the run, printed after it: time per node per substep, its split over
   contacts, elastic forces, integration and communication, and the bytes sent per substep. */
void FixWire::post_run()
{
  if (substeps_run == 0) return;
  const wire::StepTiming &t = lib->timing;
  timing[T_CONTACTS] = t.contacts;
  timing[T_ELASTIC] = t.elastic;
  timing[T_INTEGRATION] = t.integration;
  timing[T_COMM] = t.exchange + timing[T_COMM_STEP];
  timing[T_NODE_SUBSTEPS] = t.node_substeps;
  std::array<double, N_TIMING> sum;
  MPI_Allreduce(timing.data(), sum.data(), N_TIMING, MPI_DOUBLE, MPI_SUM, world);
  double slowest;
  MPI_Allreduce(&timing[T_TOTAL], &slowest, 1, MPI_DOUBLE, MPI_MAX, world);
  if (comm->me != 0) return;
  const double loop = timer->get_wall(Timer::TOTAL), total = sum[T_TOTAL], steps = (double) substeps_run;
  const double per = sum[T_NODE_SUBSTEPS] > 0.0 ? 1e9 / sum[T_NODE_SUBSTEPS] : 0.0;
  auto share = [&](double x) { return total > 0.0 ? 100.0 * x / total : 0.0; };
  std::string text = fmt::format(
      "fix wire {0}: {1:.4g} s of {2:.4g} s loop time ({3:.3g} %, slowest rank), {4} substeps, {5:.0f} nodes\n"
      "fix wire {0}: {6:.4g} ns per node per substep (time summed over ranks; cpu {7:.4g} ns)\n"
      "fix wire {0}: contacts {8:.3g} %, elastic forces {9:.3g} %, integration {10:.3g} %, communication "
      "{11:.3g} %, step setup and hand-over {12:.3g} %\n"
      "fix wire {0}: communication per substep (all ranks): {13:.0f} bytes of wire nodes; {14:.0f} bytes "
      "for 6 + 3 doubles per ghost atom of any kind\n",
      id, slowest, loop, loop > 0.0 ? 100.0 * slowest / loop : 0.0, substeps_run, sum[T_NODE_SUBSTEPS] / steps,
      total * per, sum[T_CPU] * per, share(sum[T_CONTACTS]), share(sum[T_ELASTIC]), share(sum[T_INTEGRATION]),
      share(sum[T_COMM]), share(total - sum[T_CONTACTS] - sum[T_ELASTIC] - sum[T_INTEGRATION] - sum[T_COMM]),
      8.0 * sum[T_SENT] / steps, 8.0 * sum[T_SENT_ALL_ATOMS] / steps);
  if (lib->contacts) {
    const wire::ContactModel &c = *lib->contacts;
    text += fmt::format("fix wire {}: rank 0: {} contact list builds, {} candidate pairs, {:.4g} % of {} "
                        "element-grain evaluations from the tracked feature\n", id, c.rebuilds() - rebuilds_at_start,
                        c.candidates(), 100.0 * c.grain_evaluations_from_hint() / std::max(1LL, c.grain_evaluations()),
                        c.grain_evaluations());
  }
  utils::logmesg(lmp, text);
}

/* ---------------------------------------------------------------------- comm */

/* counted: the subcycle's (timed by lib/wire and counted here), else once per step. */
void FixWire::communicate(Comm mode, bool reverse, bool counted)
{
  const double t0 = platform::walltime();
  comm_mode = mode;
  counting_comm = counted;
  if (reverse) comm->reverse_comm(this, mode == Comm::grain_force ? 6 : 3);
  else comm->forward_comm(this, mode == Comm::node_position ? 3 : 6);
  counting_comm = false;
  if (!counted) timing[T_COMM_STEP] += platform::walltime() - t0;
}

/* What the current mode sends of atom i: up to two vectors of 3 doubles, none for atoms of
   the other kind. Each mode sends wire nodes only or grains only: both sides know from the
   shape which atoms those are. A node's first vector is its position (periodic shift). */
int FixWire::comm_fields(int i, double *field[2])
{
  const bool grain = avec->shape[i] != 0;
  const int node = grain ? -1 : node_of_atom[i];
  wire::WireNodeSet &nodes = lib->step.nodes;
  switch (comm_mode) {
    case Comm::node_state: field[0] = nodes.positions[node].data(), field[1] = nodes.velocities[node].data(); return grain ? 0 : 2;
    case Comm::node_position: field[0] = atom->x[i]; return grain ? 0 : 1;
    case Comm::node_force: field[0] = nodes.forces[node].data(); return grain ? 0 : 1;
    case Comm::grain_velocity: field[0] = atom->v[i], field[1] = avec->omega[i]; return grain ? 2 : 0;
    case Comm::grain_force: field[0] = &grain_force_buffer[6 * (size_t) i], field[1] = field[0] + 3; return grain ? 2 : 0;
  }
  return 0;
}

int FixWire::pack_forward_comm(int n, int *list, double *buf, int pbc_flag, int *pbc)
{
  double shift[3] = {0.0, 0.0, 0.0};
  if (pbc_flag && comm_mode != Comm::grain_velocity) {
    shift[0] = pbc[0] * domain->xprd + (domain->triclinic ? pbc[5] * domain->xy + pbc[4] * domain->xz : 0.0);
    shift[1] = pbc[1] * domain->yprd + (domain->triclinic ? pbc[3] * domain->yz : 0.0);
    shift[2] = pbc[2] * domain->zprd;
  }
  int m = 0;
  double *field[2];
  for (int k = 0; k < n; k++)
    for (int f = 0, fields = comm_fields(list[k], field); f < fields; f++)
      for (int d = 0; d < 3; d++) buf[m++] = field[f][d] + (f == 0 ? shift[d] : 0.0);
  if (counting_comm) timing[T_SENT] += m, timing[T_SENT_ALL_ATOMS] += 6.0 * n;
  return m;
}

void FixWire::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  double *field[2];
  for (int i = first; i < first + n; i++)
    for (int f = 0, fields = comm_fields(i, field); f < fields; f++)
      for (int d = 0; d < 3; d++) field[f][d] = buf[m++];
}

int FixWire::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  double *field[2];
  for (int i = first; i < first + n; i++)
    for (int f = 0, fields = comm_fields(i, field); f < fields; f++)
      for (int d = 0; d < 3; d++) buf[m++] = field[f][d];
  if (counting_comm) timing[T_SENT] += m, timing[T_SENT_ALL_ATOMS] += 3.0 * n;
  return m;
}

void FixWire::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  double *field[2];
  for (int k = 0; k < n; k++)
    for (int f = 0, fields = comm_fields(list[k], field); f < fields; f++)
      for (int d = 0; d < 3; d++) field[f][d] += buf[m++];
}

/* ---------------------------------------------------------------------- per-atom state */

void FixWire::grow_arrays(int nmax) { memory->grow(gear, nmax, kGearColumns, "wire:gear"); }
void FixWire::copy_arrays(int i, int j, int /*delflag*/) { std::copy(gear[i], gear[i] + kGearColumns, gear[j]); }
void FixWire::set_arrays(int i) { std::fill(gear[i], gear[i] + kGearColumns, 0.0); }
int FixWire::size_restart(int /*nlocal*/) { return kGearColumns + 1; }
int FixWire::maxsize_restart() { return kGearColumns + 1; }

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

/* Global restart: a version number, the step of the stored Gear states and the contact
   memories of all ranks (wire::StoredContact, plain numbers). */
void FixWire::write_restart(FILE *fp)
{
  std::vector<wire::StoredContact> mine;
  // Read from a restart and no step since: every rank holds them all; write them once.
  if (!memories_on_every_rank || comm->me == 0) mine = lib->contacts ? lib->contacts->memories() : lib->restored;
  const std::vector<wire::StoredContact> all = gather_records(mine, world, false);
  if (comm->me != 0) return;
  const double header[3] = {kRestartVersion, state_dt, (double) all.size()};
  const int size = (int) (sizeof(header) + all.size() * sizeof(wire::StoredContact));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(header, sizeof(double), 3, fp);
  fwrite(all.data(), sizeof(wire::StoredContact), all.size(), fp);
}

/* read_restart hands every rank the whole block; hand_over_memories() keeps the own ones. */
void FixWire::restart(char *buf)
{
  double header[3];
  std::memcpy(header, buf, sizeof(double));
  if (header[0] >= 0.0) {    // an older block without version: (dt, count, records)
    state_dt = header[0];
    if (comm->me == 0)
      error->warning(FLERR, "fix wire: restart file of an older fix wire: its contacts' friction springs "
                     "are not read (they start again from zero)");
    return;
  }
  std::memcpy(header, buf, sizeof(header));
  state_dt = header[1];
  lib->restored.resize((size_t) header[2]);
  std::memcpy(lib->restored.data(), buf + sizeof(header), lib->restored.size() * sizeof(wire::StoredContact));
  memories_on_every_rank = true;
}

double FixWire::memory_usage()
{
  const wire::WireNodeSet &nodes = lib->step.nodes;
  return (double) atom->nmax * kGearColumns * sizeof(double) + (double) nodes.positions.size() * 3 * sizeof(Vec3) +
      (double) nodes.state.size() * sizeof(wire::Gear5State) + (double) grain_force_buffer.size() * sizeof(double) +
      (lib->contacts ? (double) lib->contacts->candidates() * 256.0 : 0.0);
}
