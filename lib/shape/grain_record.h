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

// A grain as a data file's Atoms line or a restart file gives it (shape id, mass,
// orientation), checked against the shape library before the atom style takes it: the
// checks of the atom style's data-file and restart readers, in one place and without
// LAMMPS (tests/fuzz/fuzz_grain_record.cpp feeds it arbitrary values).
#pragma once

#include "math/types.h"
#include "shape/shape_library.h"

#include <array>

namespace nscd {

struct GrainRecord {
  int shape = 0;                                     // 0: a point (wire node), else 1..library size
  double mass = 0.0;
  std::array<double, 4> quat{1.0, 0.0, 0.0, 0.0};    // w x y z
};

// A data file may give any non-zero quaternion (it is normalised); a restart file holds
// unit quaternions (off by more than 1e-6: damaged).
enum class QuaternionLength { any, unit };

struct CheckedGrain {
  std::array<double, 4> quat{1.0, 0.0, 0.0, 0.0};    // normalised
  Vec3 inertia = Vec3::Zero();                       // principal moments from shape and mass
  double bounding_radius = 0.0;
};

// Throws ShapeError naming the bad value and the way out: a shape id outside 0..size(), a
// mass that is not finite and > 0 (or that gives no finite normal moments), a quaternion
// of zero, infinite or NaN length (or, with `unit`, not of length 1).
CheckedGrain check_grain_record(const ShapeLibrary &library, const GrainRecord &record, QuaternionLength length);

}    // namespace nscd
