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

// Fuzz targets: the readers of the global restart blocks of fix nscd, fix wire, fix
// nscd/wall and fix nscd/plate (src/nscd_restart_blocks.h), one target per block, chosen by
// NSCD_RESTART_BLOCK at compile time. The input is a block as LAMMPS hands it to
// Fix::restart(), with its true size (which LAMMPS does not pass: the fixes rely on the
// size the block states). Any input may be refused with NSCD_NS::Damaged; anything else
// is a bug: a crash, a read outside the input (AddressSanitizer), another exception, or an
// accepted block whose values a run could not use or that does not write back to the bytes
// it was read from.
#include "fuzz_util.h"
#include "nscd_restart_blocks.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS::NSCD_NS;
using nscd_fuzz::violated;

namespace {

// The block as LAMMPS allocates it: exactly `size` bytes on the heap, so that ASan sees
// any read past them.
std::vector<char> exact_copy(const std::uint8_t *data, std::size_t size)
{
  return std::vector<char>(data, data + size);
}

// An accepted block of the current format is what the writer writes for its contents: the
// header and payload it stated (trailing bytes after the stated size are not the block's).
void expect_written_back(const std::string &written, const std::uint8_t *data, std::size_t size)
{
  if (written.size() > size || std::memcmp(written.data(), data, written.size()) != 0)
    violated("an accepted block does not write back to its own bytes");
}

inline void check(const SolverBlock &b, const std::uint8_t *data, std::size_t size)
{
  if (!b.read) return;    // an older format: nothing read
  if (!(b.dt == 0.0 || (b.dt >= 1e-100 && b.dt <= 1e100))) violated("accepted timestep is neither 0 nor a usable step");
  for (const auto &r : b.records) {
    if (r.tag_i == 0 || r.tag_j == 0 || r.tag_i == r.tag_j) violated("accepted record joins impossible bodies");
    for (double x : r.impulse)
      if (!std::isfinite(x)) violated("accepted impulse is not finite");
  }
  if (b.format == SOLVER_FORMAT) expect_written_back(solver_block(b), data, size);    // format 3 is written as 4
}

inline void check(const WireBlock &b, const std::uint8_t *data, std::size_t size)
{
  if (!(b.dt == 0.0 || (b.dt >= 1e-100 && b.dt <= 1e100))) violated("accepted substep is neither 0 nor a usable step");
  if (!b.memories_read) {
    if (!b.memories.empty()) violated("memories of an older format were kept");
    return;
  }
  for (const auto &m : b.memories) {
    if (m.key[0] <= 0) violated("accepted memory of a node ID <= 0");
    for (int end = 0; end < 2; end++) {
      if (!(m.memory.weight[end] >= 0.0 && m.memory.weight[end] <= 1.0)) violated("accepted weight outside [0, 1]");
      for (double x : m.memory.spring[end].xi)
        if (!std::isfinite(x)) violated("accepted spring is not finite");
    }
  }
  if (b.format == WIRE_FORMAT) expect_written_back(wire_block(b), data, size);    // format 3 is written as 4
}

inline void check(const WallBlock &b, const std::uint8_t *data, std::size_t size)
{
  for (double x : b.point)
    if (!std::isfinite(x)) violated("accepted wall position is not finite");
  if (b.format == WALL_FORMAT) expect_written_back(wall_block(b), data, size);
}

inline void check(const PlateBlock &b, const std::uint8_t *data, std::size_t size)
{
  for (double x : {b.z, b.vz, b.elapsed, b.z_start})
    if (!std::isfinite(x)) violated("accepted plate value is not finite");
  if (b.elapsed < 0.0) violated("accepted negative loading time");
  if (b.format == PLATE_FORMAT) expect_written_back(plate_block(b), data, size);
}

template <class Block> bool same_contents(const Block &a, const Block &b, std::string (*write)(const Block &))
{
  return write(a) == write(b);
}

}    // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  const std::vector<char> bytes = exact_copy(data, size);
  const char *block = bytes.empty() ? nullptr : bytes.data();
  std::vector<char> empty_guard;
  if (!block) {    // LAMMPS never hands an empty block; a zero-size allocation still has an address
    empty_guard.resize(1);
    block = empty_guard.data();
  }
  try {
#if NSCD_RESTART_BLOCK == 1
    const SolverBlock b = read_solver_block(block, size);
    check(b, data, size);
    if (b.read && !same_contents(b, read_solver_block(block, UNKNOWN_SIZE), solver_block))
      violated("the block reads differently without its size");
#elif NSCD_RESTART_BLOCK == 2
    const WireBlock b = read_wire_block(block, size);
    check(b, data, size);
    if (b.memories_read && !same_contents(b, read_wire_block(block, UNKNOWN_SIZE), wire_block))
      violated("the block reads differently without its size");
#elif NSCD_RESTART_BLOCK == 3
    const WallBlock b = read_wall_block(block, size);
    check(b, data, size);
    if (!same_contents(b, read_wall_block(block, UNKNOWN_SIZE), wall_block))
      violated("the block reads differently without its size");
#elif NSCD_RESTART_BLOCK == 4
    const PlateBlock b = read_plate_block(block, size);
    check(b, data, size);
    if (!same_contents(b, read_plate_block(block, UNKNOWN_SIZE), plate_block))
      violated("the block reads differently without its size");
#else
#error "NSCD_RESTART_BLOCK must be 1 (fix nscd), 2 (fix wire), 3 (wall) or 4 (plate)"
#endif
  } catch (const Damaged &) {
    return 0;    // refused with a message: fine
  }
  return 0;
}
