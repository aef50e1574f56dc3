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

/* The restart formats of this package's styles (nscd_restart_blocks.h). */

#include "nscd_restart_blocks.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <type_traits>

namespace LAMMPS_NS {
namespace NSCD_NS {
namespace {

static_assert(sizeof(nscd::ImpulseRecord) == 48, "fix nscd's restart record layout changed");
static_assert(sizeof(nscd::wire::StoredContact) == 4 * 8 + 2 * 4 * 8 + 2 * 8, "fix wire's restart record layout changed");
constexpr double OLD_WIRE_FORMAT = -2.0;    // fix wire's format 2 began with this double

std::string number(double x)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", x);
  return text;
}

template <class T> void append(std::string &bytes, const T &x)
{
  bytes.append(reinterpret_cast<const char *>(&x), sizeof(T));
}

template <class Record> void append_records(std::string &bytes, const std::vector<Record> &records)
{
  if (!records.empty()) bytes.append(reinterpret_cast<const char *>(records.data()), records.size() * sizeof(Record));
}

std::string with_header(std::int32_t format, const std::string &payload)
{
  return sized_header(format, payload.size()) + payload;
}

// The block's format from its mark, refused if newer than this build's; from `sized_since`
// on, the reader is limited to the size the block states.
std::int32_t open_block(BlockReader &in, std::int32_t newest, std::int32_t sized_since)
{
  const std::int32_t format = in.version();
  if (format > newest)
    throw Damaged("format " + std::to_string(format) + " is newer than this build's " + std::to_string(newest) +
                  "; use a newer build");
  if (format >= sized_since) in.limit_to_stated_size();
  return format;
}

// A timestep (or substep) as a run writes it: 0 (not known) or within 1e-100 .. 1e100. Stored
// impulses and Gear states are rescaled by the ratio of the run's step to it, so a damaged
// one (a denormal, say) would turn them into inf.
void require_step(double dt, const std::string &what)
{
  if (!(dt == 0.0 || (dt >= 1e-100 && dt <= 1e100)))
    throw Damaged(what + " is " + number(dt) + ", not 0 or within 1e-100..1e100");
}

void require_finite(double x, const std::string &what)
{
  if (!std::isfinite(x)) throw Damaged(what + " is " + number(x) + ", not finite");
}

void check_impulse_record(const nscd::ImpulseRecord &r, std::size_t k)
{
  const std::string which = "contact record " + std::to_string(k + 1);
  // atom IDs are positive, walls and plates negative; a contact joins two different bodies
  if (r.tag_i == 0 || r.tag_j == 0 || r.tag_i == r.tag_j)
    throw Damaged(which + " joins the bodies " + std::to_string(r.tag_i) + " and " + std::to_string(r.tag_j) +
                  ", which no contact can");
  for (int d = 0; d < 3; d++) require_finite(r.impulse[d], which + "'s impulse");
}

void check_stored_contact(const nscd::wire::StoredContact &c, std::size_t k)
{
  const std::string which = "wire contact memory " + std::to_string(k + 1);
  // the first id is the node whose owner computes the contact (an atom ID, > 0)
  if (c.key[0] <= 0)
    throw Damaged(which + " belongs to node ID " + std::to_string(c.key[0]) + ", not an atom ID");
  for (int end = 0; end < 2; end++) {
    for (double x : c.memory.spring[end].xi) require_finite(x, which + "'s friction spring");
    const double s = c.memory.spring[end].sliding, w = c.memory.weight[end];
    if (s != 0.0 && s != 1.0)
      throw Damaged(which + " has a sliding flag " + number(s) + ", not 0 or 1");
    if (!(w >= 0.0 && w <= 1.0))
      throw Damaged(which + " has an end weight " + number(w) + " outside [0, 1]");
  }
}

}    // namespace

// ---------------------------------------------------------------------- fix nscd

std::string solver_block(const SolverBlock &state)
{
  std::string payload;
  append(payload, (std::int64_t) state.records.size());
  append(payload, state.dt);
  append_records(payload, state.records);
  return with_header(SOLVER_FORMAT, payload);
}

SolverBlock read_solver_block(const char *block, std::size_t available)
{
  BlockReader in(block, available);
  SolverBlock out;
  out.format = open_block(in, SOLVER_FORMAT, 3);    // 3 and 4: one layout
  if (out.format < 3) {    // no size: the stored count cannot be checked
    out.read = false;
    return out;
  }
  const auto count = in.value<std::int64_t>("the record count");
  out.dt = in.value<double>("the timestep");
  require_step(out.dt, "the impulses' timestep");
  out.records = in.records<nscd::ImpulseRecord>(count, "contact records");
  in.expect_end();
  for (std::size_t k = 0; k < out.records.size(); k++) check_impulse_record(out.records[k], k);
  return out;
}

namespace {
// How one kind of per-atom record is named in the messages of read_atom_records.
struct AtomRecordNames {
  const char *values;     // "warm-start values"
  const char *held;       // "its warm-start impulses"
  const char *records;    // "warm-start records"
  const char *record;     // "warm-start record"
};

// {format, count, count records} of one atom (nscd_restart_blocks.h, "per atom").
template <class Record> void write_atom_records(std::int32_t format, const std::vector<Record> &records, double *out)
{
  out[0] = format;
  out[1] = (double) records.size();
  if (!records.empty()) std::memcpy(out + 2, records.data(), records.size() * sizeof(Record));
}

// What write_atom_records wrote, `available` values, for the atom of ID `tag`: each record
// checked by check(record, index) and belonging to that atom (owner(record) == tag).
template <class Record, class Check, class Owner>
std::vector<Record> read_atom_records(const double *values, std::size_t available, std::int64_t tag,
                                      std::int32_t format_read, const AtomRecordNames &names, Check check,
                                      Owner owner)
{
  constexpr int per_record = (int) (sizeof(Record) / sizeof(double));
  const std::string atom = "atom ID " + std::to_string(tag);
  if (available < 2)
    throw Damaged(atom + " has " + std::to_string(available) + " " + names.values + ", fewer than the 2 of its header");
  const double format = values[0], count = values[1];
  if (format != format_read)
    throw Damaged(atom + " holds " + names.held + " in format " + number(format) +
                  (format > format_read && format <= NEWEST_KNOWN && format == std::floor(format)
                       ? ", this build reads format " + std::to_string(format_read) + "; use a newer build"
                       : ", which no build writes"));
  if (!(count >= 0.0) || count != std::floor(count) || count > (double) (available - 2) / per_record ||
      2 + per_record * (std::size_t) count != available)
    throw Damaged(atom + " states " + number(count) + " " + names.records + " in " + std::to_string(available) +
                  " values");
  std::vector<Record> records((std::size_t) count);
  // Bytes into constructed records: valid for a trivially copyable Record; through void *
  // because GCC's -Wclass-memaccess asks for a trivial one.
  static_assert(std::is_trivially_copyable<Record>::value, "a record is read back as bytes");
  if (!records.empty())
    std::memcpy(static_cast<void *>(records.data()), values + 2, records.size() * sizeof(Record));
  for (std::size_t k = 0; k < records.size(); k++) {
    check(records[k], k);
    if (owner(records[k]) != tag)
      throw Damaged(atom + "'s " + names.record + " " + std::to_string(k + 1) + " belongs to atom ID " +
                    std::to_string(owner(records[k])));
  }
  return records;
}
}    // namespace

void write_atom_impulses(const std::vector<nscd::ImpulseRecord> &records, double *out)
{
  write_atom_records(ATOM_IMPULSES_FORMAT, records, out);
}

std::vector<nscd::ImpulseRecord> read_atom_impulses(const double *values, std::size_t available, std::int64_t tag)
{
  static const AtomRecordNames names{"warm-start values", "its warm-start impulses", "warm-start records",
                                     "warm-start record"};
  return read_atom_records<nscd::ImpulseRecord>(values, available, tag, ATOM_IMPULSES_FORMAT, names,
                                                check_impulse_record,
                                                [](const nscd::ImpulseRecord &r) { return r.tag_i; });
}

// ---------------------------------------------------------------------- fix wire

std::string wire_block(const WireBlock &state)
{
  std::string payload;
  append(payload, state.dt);
  append(payload, (std::int64_t) state.memories.size());
  append_records(payload, state.memories);
  return with_header(WIRE_FORMAT, payload);
}

namespace {
void check_wire_step(double dt)
{
  require_step(dt, "the Gear states' substep");
}
}    // namespace

WireBlock read_wire_block(const char *block, std::size_t available)
{
  WireBlock out;
  {
    BlockReader first(block, available);
    if (first.value<double>("its first number") == OLD_WIRE_FORMAT) {    // format 2: {-2, dt, count, records}
      out.format = 2;
      out.memories_read = false;
      out.dt = first.value<double>("the substep");
      check_wire_step(out.dt);
      return out;
    }
  }
  BlockReader in(block, available);
  out.format = open_block(in, WIRE_FORMAT, 3);
  if (out.format < 3)    // formats 1 and 2 had no mark: this one is not ours
    throw Damaged("format " + std::to_string(out.format) + " of fix wire never had this mark");
  out.dt = in.value<double>("the substep");
  check_wire_step(out.dt);
  const auto count = in.value<std::int64_t>("the memory count");
  out.memories = in.records<nscd::wire::StoredContact>(count, "contact memories");
  in.expect_end();
  for (std::size_t k = 0; k < out.memories.size(); k++) check_stored_contact(out.memories[k], k);
  return out;
}

void write_atom_memories(const std::vector<nscd::wire::StoredContact> &memories, double *out)
{
  write_atom_records(ATOM_MEMORIES_FORMAT, memories, out);
}

std::vector<nscd::wire::StoredContact> read_atom_memories(const double *values, std::size_t available,
                                                          std::int64_t tag)
{
  static const AtomRecordNames names{"wire memory values", "its wire friction memories", "wire friction memories",
                                     "wire friction memory"};
  return read_atom_records<nscd::wire::StoredContact>(values, available, tag, ATOM_MEMORIES_FORMAT, names,
                                                      check_stored_contact,
                                                      [](const nscd::wire::StoredContact &c) { return c.key[0]; });
}

// ---------------------------------------------------------------------- fix nscd/wall

std::string wall_block(const WallBlock &state)
{
  std::string payload;
  append(payload, state.cylinder ? 1.0 : 0.0);
  for (double x : state.point) append(payload, x);
  return with_header(WALL_FORMAT, payload);
}

WallBlock read_wall_block(const char *block, std::size_t available)
{
  BlockReader in(block, available);
  WallBlock out;
  out.format = open_block(in, WALL_FORMAT, 2);
  const double kind = in.value<double>("the wall's kind");
  if ((kind != 0.0 && kind != 1.0) || std::signbit(kind))    // exactly as written (not -0)
    throw Damaged("the wall's kind is " + number(kind) + ", not 0 (plane) or 1 (cylinder)");
  out.cylinder = kind == 1.0;
  for (double &x : out.point) {
    x = in.value<double>("the wall's position");
    require_finite(x, "the wall's position");
  }
  if (out.format >= 2) in.expect_end();
  return out;
}

// ---------------------------------------------------------------------- fix nscd/plate

std::string plate_block(const PlateBlock &state)
{
  std::string payload;
  for (double x : {state.z, state.vz, state.elapsed, state.z_start}) append(payload, x);
  return with_header(PLATE_FORMAT, payload);
}

PlateBlock read_plate_block(const char *block, std::size_t available)
{
  BlockReader in(block, available);
  PlateBlock out;
  out.format = open_block(in, PLATE_FORMAT, 2);
  const char *names[4] = {"the plate's z", "the plate's velocity", "the plate's loading time", "the plate's first z"};
  double *values[4] = {&out.z, &out.vz, &out.elapsed, &out.z_start};
  for (int k = 0; k < 4; k++) {
    *values[k] = in.value<double>(names[k]);
    require_finite(*values[k], names[k]);
  }
  if (out.elapsed < 0.0)
    throw Damaged("the plate's loading time is " + number(out.elapsed) + ", below 0");
  if (out.format >= 2) in.expect_end();
  return out;
}

// ---------------------------------------------------------------------- pair_style nscd

std::string pair_settings_bytes(const PairSettings &s)
{
  std::string bytes;
  append(bytes, MAGIC);
  append(bytes, PAIR_FORMAT);
  for (double x : {s.activation_given, s.activation_fraction, s.reach_given, s.reach_fraction}) append(bytes, x);
  return bytes;
}

std::string pair_coefficient_bytes(const PairCoefficient &c)
{
  std::string bytes;
  append(bytes, c.set);
  if (c.set) {
    append(bytes, c.friction);
    append(bytes, c.restitution);
  }
  return bytes;
}

void check_pair_settings(const PairSettings &s)
{
  // a distance given (>= 0) or none (-1, the fraction applies)
  auto distance = [](double x, const char *what) {
    if (x != -1.0 && !(x >= 0.0 && std::isfinite(x)))
      throw Damaged(std::string(what) + " " + number(x) + " is neither a distance >= 0 nor -1 (not given)");
  };
  auto fraction = [](double x, double largest, const char *what) {
    if (!(x >= 0.0 && x <= largest))
      throw Damaged(std::string(what) + " " + number(x) + " is outside [0, " + number(largest) +
                    "]");
  };
  distance(s.activation_given, "the activation");
  distance(s.reach_given, "the reach");
  fraction(s.activation_fraction, MAX_ACTIVATION_FRACTION, "the activation fraction");
  fraction(s.reach_fraction, MAX_REACH_FRACTION, "the reach fraction");
}

void check_pair_coefficient(const PairCoefficient &c)
{
  if (c.set != 0 && c.set != 1)
    throw Damaged("a type pair's flag is " + std::to_string(c.set) + ", not 0 or 1");
  if (!c.set) return;
  if (!(c.friction >= 0.0) || !std::isfinite(c.friction))
    throw Damaged("a friction coefficient is " + number(c.friction) + ", not a finite number >= 0");
  if (!(c.restitution >= 0.0 && c.restitution <= 1.0))
    throw Damaged("a restitution coefficient is " + number(c.restitution) + ", outside [0, 1]");
}

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS
