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

/* Restart blocks of this package: a header that marks them as this package's and gives
   their format and size, and a reader that never reads past the size and refuses anything it cannot check.

   A global fix block, as LAMMPS writes it, is: the size in bytes of what follows (int,
   LAMMPS' own field), then our header {MAGIC, version} (two int32), then, from the
   "sized" format of each style on, the payload's size in bytes (int64), then the payload.
   LAMMPS hands Fix::restart() the bytes after its size field but not the size itself, so the
   block repeats it: every count inside the payload is checked against that size before
   anything is read or allocated, so a damaged count, size or mark is refused, never
   trusted. (Only a size and a count damaged alike, or LAMMPS' own size field, could still
   lead the reader astray; LAMMPS' own check of the file's end catches most of the latter.)
   Blocks that do not begin with MAGIC (damaged, or written before blocks carried a
   format) are refused; the one exception is fix wire's format 2, which began with the
   number -2 and is recognised by it (read_wire_block in nscd_restart_blocks.cpp).

   Plain C++ (no LAMMPS header): the fuzz targets of tests/fuzz read blocks with it. */

#ifndef LMP_NSCD_RESTART_H
#define LMP_NSCD_RESTART_H

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace LAMMPS_NS {
namespace NSCD_NS {

constexpr std::int32_t MAGIC = 0x4e534344;    // "NSCD" (as bytes on a little-endian machine: "DCSN")
constexpr std::size_t MARK_BYTES = 2 * sizeof(std::int32_t);                     // {MAGIC, version}
constexpr std::size_t SIZED_HEADER_BYTES = MARK_BYTES + sizeof(std::int64_t);    // and the payload size
constexpr std::int32_t NEWEST_KNOWN = 1000;    // a larger version number is damage, not a newer build
// LAMMPS does not tell a fix how many bytes its block holds: the reader then relies on the
// size the block states (the fuzz targets pass the true size).
constexpr std::size_t UNKNOWN_SIZE = std::numeric_limits<std::size_t>::max();

// A block that is damaged, foreign or of a format this build cannot check; the message says
// what is wrong with it (the caller adds the style and ID).
struct Damaged : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The header of a block with its payload size: {MAGIC, version, payload bytes}, then the
// payload (LAMMPS' own size field is written in front by write_block).
inline std::string sized_header(std::int32_t version, std::size_t payload_bytes)
{
  std::string bytes(SIZED_HEADER_BYTES, '\0');
  const std::int32_t mark[2] = {MAGIC, version};
  const std::int64_t size = (std::int64_t) payload_bytes;
  std::memcpy(&bytes[0], mark, MARK_BYTES);
  std::memcpy(&bytes[MARK_BYTES], &size, sizeof(size));
  return bytes;
}

// Writes a global fix block: LAMMPS' size field, then the block (header and payload).
inline void write_block(FILE *fp, const std::string &block)
{
  const int size = (int) block.size();
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(block.data(), 1, block.size(), fp);
}

// The format version of a block's mark {MAGIC, version}: refuses a block without the mark,
// or with a version number no build writes (< 1 or above NEWEST_KNOWN).
inline std::int32_t version_of_mark(const std::int32_t mark[2])
{
  auto hex = [](std::int32_t x) {
    char text[16];
    std::snprintf(text, sizeof(text), "%08x", (unsigned) x);
    return std::string(text);
  };
  if (mark[0] != MAGIC)
    throw Damaged("no package mark (0x" + hex(mark[0]) + ", expected 0x" + hex(MAGIC) + ")");
  if (mark[1] < 1 || mark[1] > NEWEST_KNOWN)
    throw Damaged("format number " + std::to_string(mark[1]) + ", which no build writes (1 to " +
                  std::to_string(NEWEST_KNOWN) + ")");
  return mark[1];
}

// Reads a block front to back within `available` bytes (UNKNOWN_SIZE: as many as the block
// states); every read past the end throws Damaged.
class BlockReader {
 public:
  BlockReader(const char *block, std::size_t available) : at_(block), left_(available) {}

  // The format version from the block's mark (version_of_mark).
  std::int32_t version()
  {
    std::int32_t mark[2];
    take(mark, sizeof(mark), "its mark and format number");
    return version_of_mark(mark);
  }

  // The payload size that follows the mark in sized formats: from here on, reads stop there.
  void limit_to_stated_size()
  {
    std::int64_t size;
    take(&size, sizeof(size), "its size");
    // LAMMPS stores a block's size as an int: no block is larger
    const std::int64_t largest = std::numeric_limits<int>::max() - (std::int64_t) SIZED_HEADER_BYTES;
    if (size < 0 || size > largest || (std::uint64_t) size > left_)
      throw Damaged("it states a payload of " + std::to_string(size) + " bytes, but " +
                    (left_ == UNKNOWN_SIZE ? std::string("that is impossible") : std::to_string(left_) + " follow"));
    left_ = (std::size_t) size;
  }

  template <class T> T value(const char *what)
  {
    static_assert(std::is_trivially_copyable<T>::value, "plain values only");
    T x;
    take(&x, sizeof(T), what);
    return x;
  }

  // `count` records, after checking that they fit in what is left (before allocating).
  template <class Record> std::vector<Record> records(std::int64_t count, const char *what)
  {
    static_assert(std::is_trivially_copyable<Record>::value, "plain records only");
    if (left_ == UNKNOWN_SIZE) throw std::logic_error("BlockReader: records of a block without a size");
    if (count < 0 || (std::uint64_t) count > left_ / sizeof(Record))
      throw Damaged("it counts " + std::to_string(count) + " " + what + " of " + std::to_string(sizeof(Record)) +
                    " bytes, only " + std::to_string(left_) + " bytes left");
    std::vector<Record> out((std::size_t) count);
    if (count > 0) take(out.data(), (std::size_t) count * sizeof(Record), what);
    return out;
  }

  // A sized block must be read to its last byte: anything left over means a count is wrong.
  void expect_end() const
  {
    if (left_ != 0)
      throw Damaged(std::to_string(left_) + " bytes left after its contents");
  }

  std::size_t left() const { return left_; }

 private:
  const char *at_;
  std::size_t left_;

  void take(void *to, std::size_t n, const char *what)
  {
    if (n > left_)
      throw Damaged(std::string("it ends inside ") + what + " (" + std::to_string(n) + " bytes needed, " +
                    std::to_string(left_) + " left)");
    std::memcpy(to, at_, n);
    at_ += n;
    if (left_ != UNKNOWN_SIZE) left_ -= n;
  }

};

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
