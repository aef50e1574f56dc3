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

#include "solver/rigid_motion.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace nscd {

Mat3 world_inverse_inertia(const Vec3 &principal_moments, const Quat &orientation)
{
  Vec3 inverse_moments;
  for (int k = 0; k < 3; ++k) {
    const double moment = principal_moments[k];
    if (!(moment > 0.0))
      throw std::invalid_argument("principal moment of inertia " + std::to_string(k) + " is " +
                                  std::to_string(moment) +
                                  ": it must be > 0 (use +infinity to lock that rotation)");
    inverse_moments[k] = std::isinf(moment) ? 0.0 : 1.0 / moment;
  }
  const Mat3 rotation = orientation.normalized().toRotationMatrix();
  return rotation * inverse_moments.asDiagonal() * rotation.transpose();
}

Vec3 gyroscopic_torque(const Vec3 &principal_moments, const Quat &orientation, const Vec3 &w)
{
  // Work in the body frame where the inertia tensor is diagonal; a locked (infinite) axis
  // carries no angular velocity, so its (inf * 0) term is dropped rather than made NaN.
  const Quat q = orientation.normalized();
  const Vec3 w_body = q.conjugate() * w;
  Vec3 momentum_body;
  for (int k = 0; k < 3; ++k)
    momentum_body[k] = std::isinf(principal_moments[k]) ? 0.0 : principal_moments[k] * w_body[k];
  return q * (-w_body.cross(momentum_body));
}

void advance_pose(Pose &pose, const Vec3 &v_old, const Vec3 &w_old, const Vec3 &v_new,
                  const Vec3 &w_new, double dt, double theta)
{
  pose.position += dt * ((1.0 - theta) * v_old + theta * v_new);
  const Vec3 w = (1.0 - theta) * w_old + theta * w_new;
  const double angle = w.norm() * dt;
  if (angle > 0.0) {
    const Quat turn(Eigen::AngleAxisd(angle, w / w.norm()));
    pose.orientation = (turn * pose.orientation).normalized();
  }
}

}    // namespace nscd
