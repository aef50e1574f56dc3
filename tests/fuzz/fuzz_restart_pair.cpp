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

// Fuzz target: pair_style nscd's part of a restart file (src/nscd_restart_blocks.h): its
// settings, then the coefficients of every type pair. The first input byte sets the number
// of atom types (1 to 4), the rest is the file from the settings on. Any input may be
// refused with NSCD_NS::Damaged; anything else is a bug: a crash, a read outside the
// input, another exception, or accepted values that pair_style / pair_coeff would refuse or
// that do not write back to the bytes read.
#include "fuzz_util.h"
#include "nscd_restart_blocks.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS::NSCD_NS;
using nscd_fuzz::violated;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  if (size < 1) return 0;
  const int ntypes = 1 + data[0] % 4;
  const std::vector<char> bytes(data + 1, data + size);    // exactly the rest, on the heap
  BlockReader in(bytes.empty() ? reinterpret_cast<const char *>(data) : bytes.data(), bytes.size());
  std::string written;
  try {
    const PairSettings s = read_pair_settings(in);
    if (s.activation_given != -1.0 && !(s.activation_given >= 0.0 && std::isfinite(s.activation_given)))
      violated("accepted activation is neither -1 nor a finite distance");
    if (!(s.activation_fraction >= 0.0 && s.activation_fraction <= MAX_ACTIVATION_FRACTION))
      violated("accepted activation fraction out of range");
    if (!(s.reach_fraction >= 0.0 && s.reach_fraction <= MAX_REACH_FRACTION)) violated("accepted reach fraction out of range");
    written = pair_settings_bytes(s);
    for (int i = 1; i <= ntypes; i++)
      for (int j = i; j <= ntypes; j++) {
        const PairCoefficient c = read_pair_coefficient(in);
        if (c.set != 0 && c.set != 1) violated("accepted a flag other than 0 or 1");
        if (c.set && (!(c.friction >= 0.0) || !std::isfinite(c.friction) || !(c.restitution >= 0.0 && c.restitution <= 1.0)))
          violated("accepted coefficients pair_coeff refuses");
        written += pair_coefficient_bytes(c);
      }
  } catch (const Damaged &) {
    return 0;    // refused with a message: fine
  }
  if (written.size() > bytes.size() || std::memcmp(written.data(), bytes.data(), written.size()) != 0)
    violated("accepted settings do not write back to the bytes read");
  return 0;
}
