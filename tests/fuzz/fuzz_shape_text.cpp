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

// Fuzz target: the shape-library text parser (ShapeLibrary::read).
// Any input may be refused with a ShapeError; anything else is a bug: a crash, another
// exception, a sanitizer report, or an accepted library that breaks one of these
// properties: its serialisation reads back to the same text, and its written text file
// reads back to as many shapes with the same names.
#include "shape/shape_library.h"

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

void check_round_trips(const nscd::ShapeLibrary &library)
{
  const std::string serial = library.serialize();
  nscd::ShapeLibrary restored;
  try {
    restored = nscd::ShapeLibrary::deserialize(serial);
  } catch (const nscd::ShapeError &e) {
    violated(std::string("deserialize(serialize()) failed: ") + e.what());
  }
  if (restored.serialize() != serial) violated("deserialize(serialize()) is not the same library");

  std::stringstream written;
  library.write(written);
  nscd::ShapeLibrary reread;
  try {
    reread.read(written, "written");
  } catch (const nscd::ShapeError &e) {
    violated(std::string("reading the written library failed: ") + e.what());
  }
  if (reread.size() != library.size()) violated("the written library reads back to another number of shapes");
  for (int id = 1; id <= library.size(); ++id) {
    if (reread.name(id) != library.name(id)) violated("the written library reads back with other names");
  }
}

}    // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char *>(data), size));
  nscd::ShapeLibrary library;
  try {
    library.read(in, "fuzz.shapes");
  } catch (const nscd::ShapeError &) {
    return 0;    // refused with a message: fine
  }
  check_round_trips(library);
  return 0;
}
