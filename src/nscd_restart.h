/* Global restart blocks of this package's fixes carry a format version.

   A block is: the size in bytes of what follows (int, LAMMPS' convention), the header
   {kMagic, version} (two ints), then the fix's own payload. Blocks written before versions
   existed (before LAMMPS 4 Feb 2025 became the default) have no header; their payload is
   that of version 1. Their first four bytes are a record count or part of a double, which
   cannot be kMagic followed by a version this code knows (2^-64 for a double), so they
   are recognised as version 0. */

#ifndef LMP_NSCD_RESTART_H
#define LMP_NSCD_RESTART_H

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace LAMMPS_NS {
namespace nscd_restart {

constexpr std::int32_t kMagic = 0x4e534344;    // "NSCD"
constexpr int kHeaderBytes = 2 * sizeof(std::int32_t);
constexpr std::int32_t kNewestKnown = 1000;    // versions above are not ours: no header

// Writes the block's size (header and payload) and the header; the payload follows.
inline void write_header(FILE *fp, std::int32_t version, int payload_bytes)
{
  const int size = kHeaderBytes + payload_bytes;
  const std::int32_t header[2] = {kMagic, version};
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(header, sizeof(std::int32_t), 2, fp);
}

// The format version of the block that LAMMPS hands to Fix::restart() (after its size),
// 0 for a block without a header; `buf` is moved past the header, onto the payload.
inline int read_version(const char *&buf)
{
  std::int32_t header[2];
  std::memcpy(header, buf, sizeof(header));
  if (header[0] != kMagic || header[1] < 1 || header[1] > kNewestKnown) return 0;
  buf += kHeaderBytes;
  return header[1];
}

}    // namespace nscd_restart
}    // namespace LAMMPS_NS

#endif
