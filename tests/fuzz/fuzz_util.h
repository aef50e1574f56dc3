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

// Shared by the fuzz targets: a violated property aborts (libFuzzer keeps the input; the
// replay test fails).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace nscd_fuzz {

[[noreturn]] inline void violated(const std::string &what)
{
  std::fprintf(stderr, "property violated: %s\n", what.c_str());
  std::abort();
}

}    // namespace nscd_fuzz
