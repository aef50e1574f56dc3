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

// compute nscd/column against scenes with known answers, on 1, 2 and 4 ranks.
#include "lammps_fixture.h"

#include "compute.h"
#include "modify.h"

#include <cmath>
#include <fstream>
#include <string>

namespace {
const char *kCube = "shape cube\nradius 0\nvertices 8\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\nend\n";
}

class ColumnTest : public LammpsTest {
 protected:
  void SetUp() override
  {
    LammpsTest::SetUp();
    if (rank() == 0) std::ofstream(scratch("cube.shapes")) << kCube;
    MPI_Barrier(MPI_COMM_WORLD);
    commands({"units lj", "atom_style spheropolyhedron", "atom_modify map array", "boundary f f f",
              "shapes read " + scratch("cube.shapes"), "region box block -10 10 -10 10 -1 25",
              "create_box 1 box"});
  }
  double output(const std::string &id, int index)
  {
    LAMMPS_NS::Compute *c = lmp->modify->get_compute_by_id(id);
    c->compute_vector();
    return c->vector[index];
  }
};

// Height from the true surfaces: an aligned cube's top is its centre + 0.5, a cube turned
// 45 degrees about x reaches sqrt(1/2) above its centre; grains outside the radius count for
// the fraction's denominator and the overall top only.
TEST_F(ColumnTest, HeightAndRetainedFractionOfPlacedCubes)
{
  commands({"create_atoms 1 single 0 0 0.5", "create_atoms 1 single 0.2 0.1 3",
            "create_atoms 1 single 5 0 1", "shapes assign all shape 1 density 1",
            "set atom 2 quat 1 0 0 45", "run 0",
            "compute col all nscd/column 0 0 2 floor 0.6"});
  EXPECT_NEAR(output("col", 0), 3 + std::sqrt(0.5), 1e-12);    // height: the turned cube's edge
  EXPECT_NEAR(output("col", 1), 1.0 / 3.0, 1e-15);            // only atom 2 is in and above 0.6
  EXPECT_EQ(output("col", 2), 1.0);
  EXPECT_EQ(output("col", 3), 3.0);
  EXPECT_NEAR(output("col", 4), 3 + std::sqrt(0.5), 1e-12);    // highest of all
  run("compute narrow all nscd/column 5 0 0.5");    // only the cube at (5, 0, 1)
  EXPECT_NEAR(output("narrow", 0), 1.5, 1e-12);
  EXPECT_NEAR(output("narrow", 1), 1.0 / 3.0, 1e-15);    // no floor: every grain in the radius
}

// percentile P: the smallest top with P % of the column's tops at or below it (nearest rank)
TEST_F(ColumnTest, PercentileHeightIgnoresTheHighestGrains)
{
  for (int k = 1; k <= 10; k++) run("create_atoms 1 single " + num(0.3 * (k % 3)) + " 0 " + num(2.0 * k));
  commands({"shapes assign all shape 1 density 1", "run 0",
            "compute p50 all nscd/column 0 0 3 percentile 50", "compute p90 all nscd/column 0 0 3 percentile 90",
            "compute top all nscd/column 0 0 3"});
  ASSERT_EQ(lmp->atom->natoms, 10);
  EXPECT_NEAR(output("p50", 0), 10.5, 1e-12);    // tops 2.5, 4.5, ..., 20.5: the 5th
  EXPECT_NEAR(output("p90", 0), 18.5, 1e-12);    // the 9th
  EXPECT_NEAR(output("top", 0), 20.5, 1e-12);
}

TEST_F(ColumnTest, BadArgumentsAreNamed)
{
  EXPECT_NE(error_of("compute c all nscd/column 0 0 -1").find("radius -1"), std::string::npos);
  EXPECT_NE(error_of("compute c all nscd/column 0 0 1 percentile 0").find("percentile 0"), std::string::npos);
  EXPECT_NE(error_of("compute c all nscd/column 0 0 1 ceiling 3").find("ceiling"), std::string::npos);
}
