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

// Linear-algebra vocabulary of the physics core: Eigen types under short names.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace nscd {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

// Where a rigid body is: centre of mass and the rotation from body to world frame.
struct Pose {
  Vec3 position = Vec3::Zero();
  Quat orientation = Quat::Identity();

  Vec3 to_world(const Vec3 &body_point) const { return position + orientation * body_point; }
  Vec3 to_body(const Vec3 &world_point) const
  {
    return orientation.conjugate() * (world_point - position);
  }
};

}    // namespace nscd
