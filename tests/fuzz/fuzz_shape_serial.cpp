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

// Fuzz target: the reader of serialised shape libraries (ShapeLibrary::deserialize, as
// used for restart files). Any input may be refused with a ShapeError; anything else is a
// bug: a crash, another exception, a sanitizer report, or an accepted text that does not
// serialise back to itself or gives a library whose accessors misbehave.
#include "shape/shape_library.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace {

[[noreturn]] void violated(const std::string &what)
{
  std::fprintf(stderr, "property violated: %s\n", what.c_str());
  std::abort();
}

}    // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char *>(data), size);
  nscd::ShapeLibrary library;
  try {
    library = nscd::ShapeLibrary::deserialize(text);
  } catch (const nscd::ShapeError &) {
    return 0;    // refused with a message: fine
  }
  if (library.serialize() != text) violated("serialize(deserialize(text)) differs from the text");
  if (!std::isfinite(library.max_bounding_radius())) violated("bounding radius is not finite");
  for (int id = 1; id <= library.size(); ++id) {
    const auto &shape = library.shape(id);
    if (!(shape.volume > 0.0) || !shape.principal_inertia.allFinite()) violated("mass properties are not usable");
    if (!library.name(id).empty() && library.find(library.name(id)) != id) violated("find(name) is not the id");
  }
  if (!library.empty()) {
    std::ostringstream written;
    library.write(written);
  }
  return 0;
}
