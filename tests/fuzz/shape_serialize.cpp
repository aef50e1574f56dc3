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

// Prints the serialised form (ShapeLibrary::serialize) of a shape library file: makes the
// seed corpus of the deserialize fuzz target from text libraries (tools/fuzz.sh).
#include "shape/shape_library.h"

#include <cstdio>

int main(int argc, char **argv)
{
  if (argc != 2) {
    std::fprintf(stderr, "usage: shape_serialize FILE.shapes\n");
    return 2;
  }
  try {
    nscd::ShapeLibrary library;
    library.read_file(argv[1]);
    std::fputs(library.serialize().c_str(), stdout);
  } catch (const nscd::ShapeError &e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
