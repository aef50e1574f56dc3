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

/* fix wire's input and output: LAMMPS' communication of wire nodes and grains (forward,
   reverse, with the periodic shift of positions), the per-atom Gear states (grow, copy,
   exchange, restart, rescaling to a new substep), the contacts' friction memories kept with
   the atoms that compute them, the global restart block, the memory use, the timing
   report after a run and the contact rows of compute wire/contacts. */

#include "fix_wire.h"
#include "fix_wire_lib.h"
#include "math/capacity_bytes.h"

#include "atom.h"
#include "atom_vec_spheropolyhedron.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "nscd_checks.h"
#include "nscd_restart_blocks.h"
#include "nscd_timing.h"
#include "timer.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace NSCD_NS;
using nscd::Vec3;
namespace wire = nscd::wire;

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

/* The subcycle's exchange of node copies: on several ranks straight between the ranks that
   own and hold the copies (nscd_copy_exchange.h), on one rank through LAMMPS' comm (periodic
   images only; it keeps one rank's trajectory to the last bit as it was). The doubles a
   LAMMPS exchange of 6 + 3 per ghost atom of any kind would carry are counted for the report. */
void FixWire::exchange_copies(bool reverse)
{
  if (!direct_exchange()) return communicate(reverse ? Comm::node_force : Comm::node_state, reverse, true);
  wire::WireNodeSet &nodes = lib->step.nodes;
  auto flat = [](std::vector<Vec3> &v) { return v.empty() ? nullptr : v[0].data(); };    // 3 doubles a node
  if (reverse) timing[T_SENT] += node_copies.reverse(flat(nodes.forces), owned_nodes, comm_counts, COMM_SUBSTEP);
  else
    timing[T_SENT] += node_copies.forward({flat(nodes.positions), flat(nodes.velocities)}, owned_nodes, comm_counts,
                                          COMM_SUBSTEP);
  timing[T_SENT_ALL_ATOMS] += (reverse ? 3.0 : 6.0) * atom->nghost;
}

bool FixWire::direct_exchange() const { return comm->nprocs > 1; }

/* After a neighbour build on several ranks: each ghost node learns its owner's rank and node
   index and the shift of its image (one LAMMPS forward_comm, which relays ghosts of ghosts
   and adds up their shifts as it does for positions), and the exchange is planned from them. */
void FixWire::plan_copy_exchange()
{
  if (!direct_exchange()) return;
  const int nall = atom->nlocal + atom->nghost;
  origin_buffer.assign(6 * (size_t) nall, 0.0);
  for (int k = 0; k < owned_nodes; k++) {
    double *o = &origin_buffer[6 * (size_t) atom_of_node[k]];
    o[3] = comm->me;
    o[4] = k;
  }
  communicate(Comm::node_origin, false);
  std::vector<NSCDCopyExchange::Origin> origins;
  for (size_t k = owned_nodes; k < atom_of_node.size(); k++) {
    const double *o = &origin_buffer[6 * (size_t) atom_of_node[k]];
    origins.push_back({(int) o[3], (int) o[4], {o[0], o[1], o[2]}});
  }
  node_copies.plan(origins, world, comm_counts, COMM_STEP);
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
    case Comm::node_origin: field[0] = &origin_buffer[6 * (size_t) i], field[1] = field[0] + 3; return grain ? 0 : 2;
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
  comm_counts.packed(buf);
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
  comm_counts.unpacked(counting_comm ? COMM_SUBSTEP : COMM_STEP, n, m, buf);
}

int FixWire::pack_reverse_comm(int n, int first, double *buf)
{
  comm_counts.packed(buf);
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
  comm_counts.unpacked(counting_comm ? COMM_SUBSTEP : COMM_STEP, n, m, buf);
}

/* ---------------------------------------------------------------------- per-atom state */

/* Per atom: the Gear state (GEAR_COLUMNS values) and the friction memories of the contacts
   the atom computes (lib->atom_memories, while they are kept with the atoms). */
void FixWire::grow_arrays(int nmax)
{
  memory->grow(gear, nmax, GEAR_COLUMNS, "wire:gear");
  lib->atom_memories.grow(nmax);
}

/* delflag: atom i is deleted (exchange, delete_atoms): its memories move, not copy. */
void FixWire::copy_arrays(int i, int j, int delflag)
{
  std::copy(gear[i], gear[i] + GEAR_COLUMNS, gear[j]);
  lib->atom_memories.copy(i, j);
  if (delflag && i != j) lib->atom_memories.clear(i);
}

void FixWire::set_arrays(int i)
{
  std::fill(gear[i], gear[i] + GEAR_COLUMNS, 0.0);
  lib->atom_memories.clear(i);
}

int FixWire::pack_exchange(int i, double *buf)
{
  std::copy(gear[i], gear[i] + GEAR_COLUMNS, buf);
  const int values = lib->atom_memories.pack(i, buf + GEAR_COLUMNS);
  migrated[0] += (double) lib->atom_memories.of(i).size();
  migrated[1] += values;
  return GEAR_COLUMNS + values;
}

int FixWire::unpack_exchange(int nlocal, double *buf)
{
  std::copy(buf, buf + GEAR_COLUMNS, gear[nlocal]);
  lib->atom_memories.clear(nlocal);
  const int m = GEAR_COLUMNS + lib->atom_memories.unpack_append(nlocal, buf + GEAR_COLUMNS);
  maxexchange = std::max(maxexchange, m);    // this rank may pass the atom on before the next filing
  return m;
}

/* Per atom in restart files: {number of values (LAMMPS' convention), the Gear state, the
   atom's friction memories in the per-atom format of nscd_restart_blocks.h}. */
int FixWire::size_restart(int i)
{
  return 1 + GEAR_COLUMNS + NSCD_NS::atom_memories_values(lib->atom_memories.of(i).size());
}

int FixWire::maxsize_restart()
{
  const int mine = 1 + GEAR_COLUMNS + NSCD_NS::atom_memories_values(lib->atom_memories.longest(0, atom->nlocal));
  int all = mine;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MAX, world);
  return all;
}

int FixWire::pack_restart(int i, double *buf)
{
  buf[0] = size_restart(i);    // LAMMPS convention: the count includes this slot
  std::copy(gear[i], gear[i] + GEAR_COLUMNS, buf + 1);
  NSCD_NS::write_atom_memories(lib->atom_memories.of(i), buf + 1 + GEAR_COLUMNS);
  return (int) buf[0];
}

/* The atom's values of the nth fix in atom->extra, each fix's preceded by its count (this
   fix's: 1 + GEAR_COLUMNS, then the memories' values; files of wire format 3 and older
   have no memories per atom). A count, state or memory that cannot be is refused, naming
   the atom. */
void FixWire::unpack_restart(int nlocal, int nth)
{
  const double *extra = atom->extra[nlocal];
  const int width = atom->nextra_store;
  constexpr int gear_only = 1 + GEAR_COLUMNS, least_with_memories = gear_only + NSCD_NS::atom_memories_values(0);
  int m = 0;
  for (int k = 0; k <= nth; k++) {
    const double count = m < width ? extra[m] : 0.0;
    const bool mine = k == nth;
    if (!(count >= 1.0 && count <= width - m) || count != std::floor(count) ||
        (mine && count != gear_only && count < least_with_memories))
      error->one(FLERR, "fix wire {}: restart per-atom values of atom ID {} are damaged (a count of {} "
                 "where {} fit); doc/fix_wire.rst, Errors", id, atom->tag[nlocal], count,
                 mine ? fmt::format("{} or {} to {}", gear_only, least_with_memories, width - m)
                      : fmt::format("{}", width - m));
    if (!mine) m += (int) count;
  }
  const double *state = extra + m + 1;
  const double started = state[GEAR_COLUMNS - 1];
  for (int c = 0; c < GEAR_COLUMNS; c++)
    if (!std::isfinite(state[c]) || (c == GEAR_COLUMNS - 1 && started != 0.0 && started != 1.0))
      error->one(FLERR, "fix wire {}: the restart file's Gear state of atom ID {} holds {} (value {} of "
                 "{}); see doc/fix_wire.rst, Errors", id, atom->tag[nlocal], state[c], c + 1, GEAR_COLUMNS);
  std::copy(state, state + GEAR_COLUMNS, gear[nlocal]);
  if (extra[m] == gear_only) return;    // wire format 3 or older: restart() kept the atom's memories
  try {
    const auto values = (std::size_t) extra[m] - gear_only;
    lib->atom_memories.set(nlocal, NSCD_NS::read_atom_memories(state + GEAR_COLUMNS, values, atom->tag[nlocal]));
  } catch (NSCD_NS::Damaged &e) {
    error->one(FLERR, "fix wire {}: restart file's friction memories refused: {} (doc/fix_wire.rst, Errors)", id,
               e.what());
  }
  maxexchange = std::max(maxexchange, GEAR_COLUMNS + lib->atom_memories.values(nlocal));
  memories_with_atoms = true;
}

/* The stored Gear states rescaled to a new substep (a new timestep or substep count). */
void FixWire::rescale_states(double new_dt)
{
  for (int i = 0; i < atom->nlocal && state_dt > 0.0 && state_dt != new_dt; i++) {
    if (gear[i][GEAR_COLUMNS - 1] == 0.0) continue;
    wire::Gear5State s;
    s.unpack(gear[i]);
    wire::gear5_change_step(s, state_dt, new_dt);
    s.pack(gear[i]);
  }
  state_dt = new_dt;
}

/* ---------------------------------------------------------------------- friction memories */

/* Before atoms move (pre_exchange on a list rebuild, the end of a run, a restart file):
   each friction memory of the contact model goes to the atom whose owner computes its
   contact, the node of its key's first ID, which this rank owns (it computed the contact).
   The memories then travel with their atoms (exchange, restart files): no communication of
   their own. */
void FixWire::keep_memories_with_atoms()
{
  if (!lib->contacts || memories_with_atoms) return;    // none, or the atoms hold them already
  const std::vector<wire::StoredContact> memories = lib->contacts->take_memories();
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) lib->atom_memories.clear(i);
  file_with_owned_nodes(memories);
}

/* After the atoms moved: the owned atoms' memories go back into the contact model, found by
   key at its next list build (ghost slots may hold copies of atoms that left: emptied). */
void FixWire::take_memories_from_atoms()
{
  std::vector<wire::StoredContact> held;
  lib->atom_memories.move_all(0, atom->nlocal, held);
  for (int i = atom->nlocal; i < atom->nlocal + atom->nghost; i++) lib->atom_memories.clear(i);
  lib->contacts->add_memories(held);
  memories_with_atoms = false;
}

/* Files each memory with the node of its key's first ID where this rank owns that node; the
   others are another rank's (a restart file of wire format 3 holds every contact's memory in
   the global block), or of an atom a fix deleted before this one's pre_exchange, which takes
   its contacts' memories along. */
void FixWire::file_with_owned_nodes(const std::vector<wire::StoredContact> &memories)
{
  for (const wire::StoredContact &c : memories) {
    const int i = atom->map((tagint) c.key[0]);
    if (i >= 0 && i < atom->nlocal) lib->atom_memories.add(i, c);
  }
  memories_with_atoms = true;
  maxexchange = GEAR_COLUMNS + lib->atom_memories.values_for(lib->atom_memories.longest(0, atom->nlocal));
}

bool FixWire::owned_here(tagint tag) const
{
  const int i = atom->map(tag);
  return i >= 0 && i < atom->nlocal;
}

size_t FixWire::wire_memories_held() const
{
  return lib->atom_memories.count(0, atom->nlocal + atom->nghost) +
      (lib->contacts ? lib->contacts->memories().size() : 0);
}

size_t FixWire::wire_memories_of_other_ranks() const
{
  size_t foreign = lib->atom_memories.count(atom->nlocal, atom->nghost);
  for (int i = 0; i < atom->nlocal; i++)
    for (const wire::StoredContact &c : lib->atom_memories.of(i))
      if (!owned_here((tagint) c.key[0])) foreign++;
  if (lib->contacts)
    for (const wire::StoredContact &c : lib->contacts->memories())
      if (!owned_here((tagint) c.key[0])) foreign++;
  return foreign;
}

/* The per-atom Gear states, the atom indices, the node arrays of the subcycle, the
   topology, the grain force buffer, the exchange of node copies and the contact model
   (candidates, records, memories), at capacity. */
double FixWire::memory_usage()
{
  using nscd::capacity_bytes;
  const wire::WireNodeSet &nodes = lib->step.nodes;
  std::size_t bytes = capacity_bytes(node_of_atom) + capacity_bytes(atom_of_node) + capacity_bytes(atom_of_grain) +
      capacity_bytes(elements) + capacity_bytes(grain_force_buffer) + capacity_bytes(nodes.state) +
      capacity_bytes(nodes.mass) + capacity_bytes(nodes.fixed) + capacity_bytes(nodes.positions) +
      capacity_bytes(nodes.velocities) + capacity_bytes(nodes.forces) + capacity_bytes(lib->step.external) +
      capacity_bytes(lib->step_start) + lib->atom_memories.memory_bytes() + capacity_bytes(origin_buffer) +
      node_copies.memory_bytes();
  for (const auto &r : nodes.arrays.r) bytes += capacity_bytes(r);
  if (lib->contacts) bytes += lib->contacts->memory_bytes();
  return (double) atom->nmax * GEAR_COLUMNS * sizeof(double) + (double) bytes;
}

/* Global restart: the step of the stored Gear states (format: nscd_restart_blocks.h); the
   friction memories are written per atom (pack_restart), after this call has handed them to
   the atoms. */
void FixWire::write_restart(FILE *fp)
{
  keep_memories_with_atoms();
  NSCD_NS::WireBlock block;
  block.dt = state_dt;
  if (comm->me == 0) NSCD_NS::write_block(fp, NSCD_NS::wire_block(block));
}

/* read_restart hands every rank the block written above (without its size). A file of
   format 3 holds every contact's memory here: each rank keeps those of its own nodes. */
void FixWire::restart(char *bytes)
{
  NSCD_NS::WireBlock block = NSCD_NS::read_restart_block(
      lmp, this, NSCD_NS::read_wire_block, bytes, "doc/fix_wire.rst");
  state_dt = block.dt;
  if (!block.memories_read) {
    NSCD_NS::warn_format_not_read(lmp, this, "wire contacts", block.format,
                                  "their friction springs start again from zero", "doc/fix_wire.rst");
    return;
  }
  if (!block.memories.empty()) file_with_owned_nodes(block.memories);
}

/* ---------------------------------------------------------------------- timing report */

/* fix wire's share of the run, printed after it: its time per part and rank (min, avg, max),
   the time per node per substep, and the bytes sent per substep. */
void FixWire::post_run()
{
  keep_memories_with_atoms();    // between runs atoms may move (balance, delete_atoms, ...)
  if (substeps_run == 0) return;
  const wire::StepTiming &t = lib->timing;
  timing[T_CONTACTS] = t.contacts;
  timing[T_ELASTIC] = t.elastic;
  timing[T_INTEGRATION] = t.integration;
  timing[T_COMM] = t.exchange + timing[T_COMM_STEP];
  timing[T_NODE_SUBSTEPS] = t.node_substeps;
  NSCDPartTimes parts({"wire contacts", "elastic forces", "integration", "communication",
                       "step setup and hand-over"});
  parts[0] = timing[T_CONTACTS];
  parts[1] = timing[T_ELASTIC];
  parts[2] = timing[T_INTEGRATION];
  parts[3] = timing[T_COMM];
  parts[4] = std::max(0.0, timing[T_TOTAL] - parts[0] - parts[1] - parts[2] - parts[3]);
  const double loop = timer->get_wall(Timer::TOTAL);
  std::string text = parts.table(world, fmt::format("fix wire {}: time per part", id), loop);
  std::array<double, N_TIMING> sum;
  MPI_Allreduce(timing.data(), sum.data(), N_TIMING, MPI_DOUBLE, MPI_SUM, world);
  const std::string between_ranks = communication_report();
  if (comm->me != 0) return;
  const double steps = (double) substeps_run;
  const double per = sum[T_NODE_SUBSTEPS] > 0.0 ? 1e9 / sum[T_NODE_SUBSTEPS] : 0.0;
  text += fmt::format(
      "fix wire {0}: {1} substeps, {2:.0f} nodes, {3:.4g} ns per node per substep (time summed over ranks; "
      "cpu {4:.4g} ns)\n"
      "fix wire {0}: communication per substep (all ranks): {5:.0f} bytes of wire nodes; {6:.0f} bytes "
      "for 6 + 3 doubles per ghost atom of any kind\n",
      id, substeps_run, sum[T_NODE_SUBSTEPS] / steps, sum[T_TOTAL] * per, sum[T_CPU] * per,
      8.0 * sum[T_SENT] / steps, 8.0 * sum[T_SENT_ALL_ATOMS] / steps);
  if (lib->contacts) {
    const wire::ContactModel &c = *lib->contacts;
    text += fmt::format("fix wire {}: rank 0: {} contact list builds, {} candidate pairs, {:.4g} % of {} "
                        "element-grain evaluations from the tracked feature\n", id, c.rebuilds() - rebuilds_at_start,
                        c.candidates(), 100.0 * c.grain_evaluations_from_hint() / std::max(1LL, c.grain_evaluations()),
                        c.grain_evaluations());
  }
  utils::logmesg(lmp, text + between_ranks);
}

/* Collective. After a run on several ranks: what fix wire's exchanges carried between ranks
   (comm_count(), summed over the ranks; per rank, the average), per substep, per step and,
   for the friction memories of migrating nodes, over the run (doc/scaling.md, "Counted");
   the text on rank 0, empty on one rank. */
std::string FixWire::communication_report() const
{
  if (comm->nprocs == 1) return "";
  const std::vector<NSCDCommCount::Tally> all = comm_counts.summed(world);
  std::array<double, 2> moved{};
  MPI_Allreduce(migrated.data(), moved.data(), 2, MPI_DOUBLE, MPI_SUM, world);
  if (comm->me != 0) return "";
  const double ranks = comm->nprocs, substeps = std::max<double>(1.0, (double) substeps_run);
  const double steps = std::max(1.0, (double) update->nsteps);
  const NSCDCommCount::Tally &sub = all[COMM_SUBSTEP], &step = all[COMM_STEP];
  return fmt::format(
      "fix wire {0}: between ranks (messages received from another rank; per rank: the average over {1:.0f}):\n"
      "fix wire {0}: per substep: {2:.4g} messages, {3:.4g} bytes per rank (72 bytes per ghost node from another "
      "rank: {4:.4g} of them per rank); per step outside the substeps: {5:.4g} messages, {6:.4g} bytes per rank\n"
      "fix wire {0}: friction memories with migrating nodes over the run: {7:.0f}, {8:.4g} MB\n",
      id, ranks, sub.messages / substeps / ranks, sub.bytes / substeps / ranks, sub.bytes / 72.0 / substeps / ranks,
      step.messages / steps / ranks, step.bytes / steps / ranks, moved[0], moved[1] * sizeof(double) / 1048576.0);
}

/* ---------------------------------------------------------------------- output */

/* Called by the compute's init(), which LAMMPS may run before or after this fix's. */
void FixWire::record_contacts()
{
  contacts_recorded = true;
  if (lib->contacts) lib->contacts->record_contacts(true);
}

/* id1 id2 other kind px py pz nx ny nz fn ftx fty ftz overlap status; a boundary is -k,
   k counting the wall and plate fixes this fix sees in the order they were defined. */
std::vector<double> FixWire::contact_rows() const
{
  std::vector<double> rows;
  if (!lib->contacts) return rows;
  for (const wire::ContactRecord &c : lib->contacts->contact_records()) {
    double other = (double) c.key[2];
    for (size_t b = 0; b < lib->boundaries.size() && c.kind == wire::ContactRecord::wire_boundary; b++)
      if (lib->boundaries[b].link.id == c.key[2]) other = -(double) (b + 1);
    const double row[CONTACT_COLUMNS] = {
        (double) c.key[0], (double) c.key[1], other, (double) c.kind, c.point.x(), c.point.y(), c.point.z(),
        c.normal.x(), c.normal.y(), c.normal.z(), c.normal_force, c.tangential_force.x(), c.tangential_force.y(),
        c.tangential_force.z(), c.overlap, c.sliding ? 1.0 : 0.0};
    rows.insert(rows.end(), row, row + CONTACT_COLUMNS);
  }
  return rows;
}
