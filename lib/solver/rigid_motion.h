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

// Rigid-body kinematics around the contact solver: world-frame inverse inertia, the
// gyroscopic torque that goes into the free velocity, and the theta-method pose update.
#pragma once

#include "math/types.h"

namespace nscd {

// Inverse inertia tensor in the world frame, R diag(1/I_k) R^T, from the principal moments
// (body frame) and the body-to-world rotation. A moment of +infinity gives a zero row
// (rotation locked about that axis). Throws std::invalid_argument for a moment <= 0 or NaN.
Mat3 world_inverse_inertia(const Vec3 &principal_moments, const Quat &orientation);

// Gyroscopic torque -w x (I w) in the world frame (I from principal moments and orientation).
// Moreau-Jean treats it explicitly: it is added to the external torque of the free velocity.
Vec3 gyroscopic_torque(const Vec3 &principal_moments, const Quat &orientation, const Vec3 &w);

// Theta-method pose update: x += dt ((1-theta) v_old + theta v_new) and the orientation is
// turned by the exact rotation of the theta-weighted angular velocity over dt (exponential
// map, so the quaternion stays a unit quaternion up to round-off; it is renormalised).
void advance_pose(Pose &pose, const Vec3 &v_old, const Vec3 &w_old, const Vec3 &v_new,
                  const Vec3 &w_new, double dt, double theta);

}    // namespace nscd
