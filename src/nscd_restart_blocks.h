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

/* The restart formats of this package's styles, written and read in one place
   (nscd_restart.h has the header and the bounded reader). Each reader checks every count
   against the block's size and every value against what the style itself accepts, and
   throws NSCD_NS::Damaged naming the problem; the styles add their name and ID.
   Plain C++ (no LAMMPS header): tests/fuzz reads blocks with these functions. */

#ifndef LMP_NSCD_RESTART_BLOCKS_H
#define LMP_NSCD_RESTART_BLOCKS_H

#include "nscd_restart.h"

#include "solver/warm_start.h"
#include "wire/contact_model.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace LAMMPS_NS {
namespace NSCD_NS {

// ---- fix nscd: the timestep of the warm-start impulses (and, up to format 3, the impulses).
// Format 4 (sized): {int64 count, double dt (the timestep they were solved with, 0 if not
// known), count ImpulseRecords}; fix nscd writes count 0: the impulses are kept per atom
// (below). Format 3: the same layout with every contact's record (files written before the
// impulses were kept with the atoms; read, and each rank keeps those of its own atoms).
// Formats 1 and 2 (no size: their count cannot be checked) are recognised and not read.
constexpr std::int32_t SOLVER_FORMAT = 4;
struct SolverBlock {
  std::int32_t format = SOLVER_FORMAT;    // as found in the block
  bool read = true;                        // false: an older format, nothing read
  double dt = 0.0;
  std::vector<nscd::ImpulseRecord> records;
};
std::string solver_block(const SolverBlock &state);
SolverBlock read_solver_block(const char *block, std::size_t available);

// ---- fix nscd, per atom: the warm-start impulses of the atom's contacts, each record seen
// from the atom (tag_i = its ID; a contact between two grains is kept by both).
// Format 1: {double format, double count, count x 6 doubles (the 48 bytes of an
// ImpulseRecord)}. LAMMPS adds the number of values in front (Fix::pack_restart).
constexpr std::int32_t ATOM_IMPULSES_FORMAT = 1;
constexpr int VALUES_PER_IMPULSE_RECORD = sizeof(nscd::ImpulseRecord) / sizeof(double);
constexpr int atom_impulses_values(std::size_t count) { return 2 + VALUES_PER_IMPULSE_RECORD * (int) count; }
// Writes the atom's records to `out` (atom_impulses_values(records.size()) doubles).
void write_atom_impulses(const std::vector<nscd::ImpulseRecord> &records, double *out);
// Reads what write_atom_impulses wrote, `available` values, for the atom of ID `tag`.
std::vector<nscd::ImpulseRecord> read_atom_impulses(const double *values, std::size_t available, std::int64_t tag);

// ---- fix wire: the step of the stored Gear states (and, up to format 3, the contacts'
// friction memories). Format 4 (sized): {double dt, int64 count, count StoredContacts}; fix
// wire writes count 0: the memories are kept per atom (below). Format 3: the same layout
// with every contact's memory (files written before the memories were kept with the atoms;
// read, and each rank keeps those of the nodes it owns). Format 2 (before the common
// header: the double -2, dt, the count as a double, the records) is recognised: dt is read,
// the memories are not.
constexpr std::int32_t WIRE_FORMAT = 4;
struct WireBlock {
  std::int32_t format = WIRE_FORMAT;
  bool memories_read = true;
  double dt = 0.0;
  std::vector<nscd::wire::StoredContact> memories;
};
std::string wire_block(const WireBlock &state);
WireBlock read_wire_block(const char *block, std::size_t available);

// ---- fix wire, per atom, after the atom's Gear state: the friction memories of the contacts
// the atom computes (key[0] = its ID: an element's first node, or a node on a boundary).
// Format 1: {double format, double count, count x 14 doubles (the 112 bytes of a
// StoredContact)}. Files of wire format 3 and older hold the Gear state alone.
constexpr std::int32_t ATOM_MEMORIES_FORMAT = 1;
constexpr int VALUES_PER_STORED_CONTACT = sizeof(nscd::wire::StoredContact) / sizeof(double);
constexpr int atom_memories_values(std::size_t count) { return 2 + VALUES_PER_STORED_CONTACT * (int) count; }
void write_atom_memories(const std::vector<nscd::wire::StoredContact> &memories, double *out);
std::vector<nscd::wire::StoredContact> read_atom_memories(const double *values, std::size_t available,
                                                          std::int64_t tag);

// ---- fix nscd/wall: the wall's kind (0 plane, 1 cylinder) and reference point.
// Format 2 (sized): 4 doubles; format 1: the same 4 doubles without the size.
constexpr std::int32_t WALL_FORMAT = 2;
struct WallBlock {
  std::int32_t format = WALL_FORMAT;
  bool cylinder = false;
  std::array<double, 3> point{0.0, 0.0, 0.0};
};
std::string wall_block(const WallBlock &state);
WallBlock read_wall_block(const char *block, std::size_t available);

// ---- fix nscd/plate: z, vz, the time its load has grown for, z at the start.
// Format 2 (sized): 4 doubles; format 1: the same without the size.
constexpr std::int32_t PLATE_FORMAT = 2;
struct PlateBlock {
  std::int32_t format = PLATE_FORMAT;
  double z = 0.0, vz = 0.0, elapsed = 0.0, z_start = 0.0;
};
std::string plate_block(const PlateBlock &state);
PlateBlock read_plate_block(const char *block, std::size_t available);

// ---- pair_style nscd: LAMMPS gives a pair style the file, not a block. Settings:
// {MAGIC, 1}, then activation given (-1: not given), activation fraction, reach given (-1),
// reach fraction; then per type pair i <= j: int setflag (0 or 1), and if set friction and
// restitution. Read by `Source` (a BlockReader, or the pair's file reader), which has
// version() and value<T>().
constexpr std::int32_t PAIR_FORMAT = 1;
constexpr double MAX_ACTIVATION_FRACTION = 1.0;    // of the smallest grain's bounding radius
constexpr double MAX_REACH_FRACTION = 20.0;
struct PairSettings {
  double activation_given = -1.0, activation_fraction = 0.1, reach_given = -1.0, reach_fraction = 0.5;
};
struct PairCoefficient {
  std::int32_t set = 0;
  double friction = 0.0, restitution = 0.0;
};
std::string pair_settings_bytes(const PairSettings &settings);
std::string pair_coefficient_bytes(const PairCoefficient &c);
void check_pair_settings(const PairSettings &s);        // throws Damaged
void check_pair_coefficient(const PairCoefficient &c);    // throws Damaged

template <class Source> PairSettings read_pair_settings(Source &in)
{
  const std::int32_t format = in.version();
  if (format > PAIR_FORMAT)
    throw Damaged("the settings' format " + std::to_string(format) + " is newer than this build's " +
                  std::to_string(PAIR_FORMAT) + "; use a newer build");
  PairSettings s;
  s.activation_given = in.template value<double>("the activation");
  s.activation_fraction = in.template value<double>("the activation fraction");
  s.reach_given = in.template value<double>("the reach");
  s.reach_fraction = in.template value<double>("the reach fraction");
  check_pair_settings(s);
  return s;
}

template <class Source> PairCoefficient read_pair_coefficient(Source &in)
{
  PairCoefficient c;
  c.set = in.template value<std::int32_t>("a type pair's flag");
  if (c.set == 1) {
    c.friction = in.template value<double>("a friction coefficient");
    c.restitution = in.template value<double>("a restitution coefficient");
  }
  check_pair_coefficient(c);
  return c;
}

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
