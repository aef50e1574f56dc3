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

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace nscd;

TEST(RigidMotion, WorldInverseInertiaInvertsTheRotatedTensor)
{
  const Vec3 moments(1.0, 2.0, 5.0);
  const Quat q = Quat(Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -1.0).normalized()));
  const Mat3 R = q.toRotationMatrix();
  const Mat3 inertia = R * moments.asDiagonal() * R.transpose();
  EXPECT_LT((world_inverse_inertia(moments, q) * inertia - Mat3::Identity()).norm(), 1e-14);
}

TEST(RigidMotion, InfiniteMomentLocksRotationAndBadMomentThrows)
{
  const double inf = std::numeric_limits<double>::infinity();
  const Mat3 locked = world_inverse_inertia(Vec3(inf, inf, inf), Quat::Identity());
  EXPECT_EQ(locked, Mat3::Zero());
  EXPECT_THROW(world_inverse_inertia(Vec3(1.0, 0.0, 1.0), Quat::Identity()),
               std::invalid_argument);
}

TEST(RigidMotion, GyroscopicTorqueIsZeroForSpheresAndPrincipalSpins)
{
  const Quat q = Quat(Eigen::AngleAxisd(0.3, Vec3::UnitX()));
  EXPECT_LT(gyroscopic_torque(Vec3(2.0, 2.0, 2.0), q, Vec3(1.0, -2.0, 3.0)).norm(), 1e-14);
  EXPECT_LT(gyroscopic_torque(Vec3(1.0, 2.0, 3.0), q, q * Vec3(0.0, 4.0, 0.0)).norm(), 1e-14);
  // Off-axis spin of an asymmetric body: -w x (I w), worked out in the body frame.
  const Vec3 w_body(1.0, 1.0, 0.0);
  const Vec3 expected_body = -w_body.cross(Vec3(1.0, 2.0, 0.0));    // = (0, 0, -1)
  EXPECT_LT((gyroscopic_torque(Vec3(1.0, 2.0, 3.0), q, q * w_body) - q * expected_body).norm(),
            1e-14);
}

TEST(RigidMotion, AdvancePoseUsesTheThetaWeightedVelocities)
{
  Pose pose;
  const double dt = 0.1, theta = 0.5;
  advance_pose(pose, Vec3(1.0, 0.0, 0.0), Vec3(0.0, 0.0, 1.0), Vec3(3.0, 0.0, 0.0),
               Vec3(0.0, 0.0, 3.0), dt, theta);
  EXPECT_NEAR(pose.position.x(), 0.2, 1e-15);
  // Turned by 2 rad/s * 0.1 s = 0.2 rad about z.
  const Vec3 x_axis = pose.orientation * Vec3::UnitX();
  EXPECT_NEAR(std::atan2(x_axis.y(), x_axis.x()), 0.2, 1e-15);
  EXPECT_NEAR(pose.orientation.norm(), 1.0, 1e-15);
}
