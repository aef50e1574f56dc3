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

/* Conversions between LAMMPS' per-atom arrays (double[3], double[4]) and the Eigen types of
   lib/, shared by every style of the package; a .cpp names them with
   `using namespace NSCD_NS;`, the namespace of the package's helpers. */

#ifndef LMP_NSCD_ARRAYS_H
#define LMP_NSCD_ARRAYS_H

#include "math/types.h"

namespace LAMMPS_NS {
namespace NSCD_NS {

inline nscd::Vec3 vec3(const double *a)
{
  return nscd::Vec3(a[0], a[1], a[2]);
}

inline nscd::Quat quat_of(const double *q)
{
  return nscd::Quat(q[0], q[1], q[2], q[3]);    // (w, x, y, z)
}

inline void store(const nscd::Vec3 &v, double *a)
{
  a[0] = v.x();
  a[1] = v.y();
  a[2] = v.z();
}

inline void add_to(double *a, const nscd::Vec3 &v)
{
  a[0] += v.x();
  a[1] += v.y();
  a[2] += v.z();
}

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
