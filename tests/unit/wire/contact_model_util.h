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

// Scenes for the tests of the wire contact model (lib/wire/contact_model.h): open chains of
// nodes with ids 1..n, grains given by shape and pose.
#pragma once

#include "wire/contact_model.h"

#include <vector>

namespace nscd::wire::test {

inline SoftContactLaw frictionless(double k_n)
{
  SoftContactLaw law;
  law.k_n = k_n;
  return law;
}

// The elements of chains of n nodes with ids first..first+n-1 (node k to k+1).
inline std::vector<std::array<std::int64_t, 2>> chain_elements(int n, std::int64_t first = 1)
{
  std::vector<std::array<std::int64_t, 2>> out;
  for (int k = 0; k + 1 < n; ++k) out.push_back({first + k, first + k + 1});
  return out;
}

struct TestGrain {
  std::int64_t id;
  const Spheropolyhedron *shape;
  Pose pose;
  Vec3 velocity = Vec3::Zero();
};

// One open chain through `nodes` (ids 1..n, all owned, every element computed here) and
// the given grains.
inline ContactScene chain_scene(const std::vector<Vec3> &nodes, const std::vector<TestGrain> &grains)
{
  ContactScene scene;
  const int n = static_cast<int>(nodes.size());
  for (int k = 0; k < n; ++k) scene.node_id.push_back(k + 1);
  scene.node_boundaries.assign(n, 0u);
  for (int k = 0; k + 1 < n; ++k) scene.elements.push_back({k, k + 1, k + 1, k + 2, true});
  for (const TestGrain &g : grains) {
    GrainCopy copy;
    copy.id = g.id;
    copy.shape = g.shape;
    copy.pose = g.pose;
    copy.velocity = g.velocity;
    scene.grains.push_back(copy);
  }
  return scene;
}

}    // namespace nscd::wire::test
