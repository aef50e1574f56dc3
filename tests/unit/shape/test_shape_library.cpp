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

// ShapeLibrary: text format (reading, every error path, write/read round trip) and the
// exact serialisation used in restart files.
#include "shape/random_grain.h"
#include "shape/shape_library.h"
#include "shape_test_util.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>

using namespace nscd;
using namespace nscd::test;

namespace {

const char *kTwoShapes = R"(# a 1 x 2 x 3 box and a ball
shape box123   # sharp box
radius 0
vertices 8
0 0 0
1 0 0
0 2 0
1 2 0

0 0 3
1 0 3
0 2 3
1 2 3
end

shape ball
radius 0.5
vertices 1
  7 8 9
end
)";

ShapeLibrary read_text(const std::string &text, const std::string &source = "test.shapes")
{
  std::istringstream in(text);
  ShapeLibrary library;
  library.read(in, source);
  return library;
}

std::string error_of(const std::string &text)
{
  try {
    read_text(text);
  } catch (const ShapeError &e) {
    return e.what();
  }
  return "no error";
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_bits(const Vec3 &a, const Vec3 &b)
{
  return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y()) && same_bits(a.z(), b.z());
}

void expect_identical(const Spheropolyhedron &a, const Spheropolyhedron &b)
{
  EXPECT_TRUE(same_bits(a.radius, b.radius));
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (size_t i = 0; i < a.vertices.size(); ++i) EXPECT_TRUE(same_bits(a.vertices[i], b.vertices[i]));
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.edge_faces, b.edge_faces);
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (size_t f = 0; f < a.faces.size(); ++f) {
    EXPECT_EQ(a.faces[f].vertices, b.faces[f].vertices);
    EXPECT_TRUE(same_bits(a.faces[f].normal, b.faces[f].normal));
    EXPECT_TRUE(same_bits(a.faces[f].offset, b.faces[f].offset));
  }
  EXPECT_TRUE(same_bits(a.volume, b.volume));
  EXPECT_TRUE(same_bits(a.principal_inertia, b.principal_inertia));
  EXPECT_TRUE(same_bits(a.bounding_radius, b.bounding_radius));
  EXPECT_TRUE(same_bits(a.input_centroid, b.input_centroid));
  EXPECT_TRUE(same_bits(a.input_rotation.coeffs().head<3>(), b.input_rotation.coeffs().head<3>()));
  EXPECT_TRUE(same_bits(a.input_rotation.w(), b.input_rotation.w()));
}

ShapeLibrary mixed_library()
{
  ShapeLibrary library = read_text(kTwoShapes);
  std::mt19937_64 rng(42);
  std::vector<Vec3> cloud;
  for (int i = 0; i < 24; ++i) cloud.push_back(random_in_ball(rng));
  library.add(make_spheropolyhedron(cloud, 0.05), "cloud");
  library.add(make_spheropolyhedron({Vec3(0, 0, 0), Vec3(1, 2, 3)}, 0.2));    // unnamed
  RandomGrainParams params;
  params.radius = 0.03;
  add_random_grains(library, params, 5, 7);
  return library;
}

}    // namespace

TEST(ShapeLibrary, ReadsShapesWithIdsNamesAndMassProperties)
{
  const auto library = read_text(kTwoShapes);
  ASSERT_EQ(library.size(), 2);
  EXPECT_EQ(library.name(1), "box123");
  EXPECT_EQ(library.name(2), "ball");
  EXPECT_EQ(library.find("ball"), 2);
  EXPECT_EQ(library.find("nothing"), 0);
  EXPECT_NEAR(library.shape(1).volume, 6.0, 1e-14);
  EXPECT_NEAR(library.shape(1).principal_inertia[0], 6.0 * (1 + 4) / 12, 1e-13);    // about the long side
  EXPECT_NEAR(library.shape(2).volume, 4.0 / 3.0 * kPi / 8, 1e-15);
  EXPECT_NEAR((library.shape(2).input_centroid - Vec3(7, 8, 9)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(library.max_bounding_radius(), std::sqrt(14.0) / 2, 1e-14);
}

TEST(ShapeLibrary, ReadingAppendsAndIdsContinue)
{
  auto library = read_text(kTwoShapes);
  std::istringstream more("shape extra\nradius 0.1\nvertices 2\n0 0 0\n1 0 0\nend\n");
  library.read(more, "more.shapes");
  ASSERT_EQ(library.size(), 3);
  EXPECT_TRUE(library.shape(3).is_spherocylinder());
  // A failed read appends nothing.
  std::istringstream bad("shape late\nradius 0.1\nvertices 1\n0 0 0\nend\nshape broken\n");
  EXPECT_THROW(library.read(bad, "bad.shapes"), ShapeError);
  EXPECT_EQ(library.size(), 3);
}

TEST(ShapeLibrary, IdOutOfRangeIsAnError)
{
  const auto library = read_text(kTwoShapes);
  for (int id : {0, 3, -1}) {
    try {
      library.shape(id);
      ADD_FAILURE() << "id " << id << " accepted";
    } catch (const ShapeError &e) {
      EXPECT_NE(std::string(e.what()).find("shape id " + std::to_string(id) + " is not in the library (ids 1..2)"),
                std::string::npos);
    }
  }
}

TEST(ShapeLibrary, WriteThenReadGivesTheSameShapes)
{
  const auto library = mixed_library();
  std::stringstream text;
  library.write(text);
  ShapeLibrary again;
  again.read(text, "written");
  ASSERT_EQ(again.size(), library.size());
  for (int id = 1; id <= library.size(); ++id) {
    const auto &a = library.shape(id), &b = again.shape(id);
    EXPECT_EQ(again.name(id), library.name(id));
    const double size = a.bounding_radius;
    EXPECT_EQ(a.radius, b.radius);
    ASSERT_EQ(a.vertices.size(), b.vertices.size()) << "id " << id;
    for (size_t i = 0; i < a.vertices.size(); ++i) EXPECT_LT((a.vertices[i] - b.vertices[i]).norm(), 1e-12 * size);
    ASSERT_EQ(a.faces.size(), b.faces.size());
    for (size_t f = 0; f < a.faces.size(); ++f) EXPECT_EQ(a.faces[f].vertices, b.faces[f].vertices);
    EXPECT_EQ(a.edges, b.edges);
    EXPECT_NEAR(a.volume, b.volume, 1e-12 * a.volume);
    EXPECT_LT((a.principal_inertia - b.principal_inertia).norm(), 1e-12 * a.principal_inertia.norm());
    EXPECT_NEAR(a.bounding_radius, b.bounding_radius, 1e-12 * size);
  }
}

TEST(ShapeLibrary, SerialisationIsExact)
{
  auto library = mixed_library();
  // Commas (the serialisation's separator) and bytes above 127 (UTF-8) in a name.
  library.add(make_spheropolyhedron({Vec3(1, 1, 1)}, 0.3), "commas,in,a;n\xc3\xa4me");
  const std::string text = library.serialize();
  for (char c : text) EXPECT_TRUE(c > ' ' && c < 127) << "character " << int(c);
  const auto again = ShapeLibrary::deserialize(text);
  ASSERT_EQ(again.size(), library.size());
  for (int id = 1; id <= library.size(); ++id) {
    EXPECT_EQ(again.name(id), library.name(id));
    expect_identical(again.shape(id), library.shape(id));
  }
  EXPECT_EQ(again.serialize(), text);
  EXPECT_EQ(ShapeLibrary::deserialize(ShapeLibrary().serialize()).size(), 0);
}

TEST(ShapeLibrary, DamagedSerialisationIsRejected)
{
  const std::string text = mixed_library().serialize();
  auto rejects = [](const std::string &damaged, const std::string &why) {
    try {
      ShapeLibrary::deserialize(damaged);
    } catch (const ShapeError &e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted damaged text (" << why << ")";
  };
  rejects(text.substr(0, text.size() / 2), "ends too early");
  rejects("other-format," + text, "does not start with");
  rejects(text + "0,", "text after the last shape");
  // The counts of the next two must fit the text's length (else "ends too early"): padded.
  const std::string padding(300, '0');
  rejects("nscd-shapes-1,1,,0000000000000000,1,00000000000000zz," + padding, "not a 16-digit hexadecimal number");
  // A face that refers to vertex 5 of a 4-vertex shape.
  rejects("nscd-shapes-1,1,,0000000000000000,4,"
          "0000000000000000,0000000000000000,0000000000000000,"
          "0000000000000000,0000000000000000,0000000000000000,"
          "0000000000000000,0000000000000000,0000000000000000,"
          "0000000000000000,0000000000000000,0000000000000000,"
          "1,3,0,1,5," + padding,
          "out of range");
}

TEST(ShapeLibrary, ReadFileReportsUnreadablePath)
{
  ShapeLibrary library;
  try {
    library.read_file("/nonexistent/dir/lib.shapes");
    ADD_FAILURE();
  } catch (const ShapeError &e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/lib.shapes: cannot open"), std::string::npos);
  }
}

// Every error names the source, the line, the problem and the way out.
struct BadFile {
  const char *name;    // test name suffix
  const char *text;
  const char *expected;    // "<source>:<line>: ..." prefix and a key phrase
};

class ShapeLibraryErrors : public ::testing::TestWithParam<BadFile> {};

TEST_P(ShapeLibraryErrors, NameSourceLineAndProblem)
{
  const std::string message = error_of(GetParam().text);
  EXPECT_NE(message.find(GetParam().expected), std::string::npos) << "message: " << message;
}

INSTANTIATE_TEST_SUITE_P(
    AllErrors, ShapeLibraryErrors,
    ::testing::Values(
        BadFile{"EmptyFile", "", "test.shapes:1: no shape found (empty library)"},
        BadFile{"CommentsOnly", "# only a comment\n\n", "test.shapes:2: no shape found"},
        BadFile{"UnknownKeyword", "shape a\nradius 0.1\nfoo 3\n", "test.shapes:3: unknown keyword 'foo'"},
        BadFile{"KeywordOutsideBlock", "radius 0.1\n", "test.shapes:1: 'radius' outside a shape block"},
        BadFile{"MissingRadius", "shape a\nvertices 1\n0 0 0\nend\n", "test.shapes:4: shape 'a' has no radius; add 'radius R'"},
        BadFile{"MissingVertices", "shape a\nradius 1\nend\n", "test.shapes:3: shape 'a' has no vertices"},
        BadFile{"TooFewVertices", "shape a\nradius 1\nvertices 3\n0 0 0\n1 0 0\nend\n",
                "test.shapes:6: shape 'a' declares 3 vertices but 'end' came after 2"},
        BadFile{"TooManyVertices", "shape a\nradius 1\nvertices 1\n0 0 0\n1 0 0\nend\n",
                "test.shapes:5: shape 'a' has more vertex lines than the 1 declared"},
        BadFile{"VertexBeforeCount", "shape a\nradius 1\n0 0 0\n", "test.shapes:3: a vertex line before 'vertices N'"},
        BadFile{"WrongFieldCount", "shape a\nradius 1\nvertices 1\n0 0\nend\n", "test.shapes:4: a vertex line needs 3 coordinates"},
        BadFile{"NonNumericField", "shape a\nradius 1\nvertices 1\n0 0x 0\nend\n", "test.shapes:4: coordinate '0x' is not a number"},
        BadFile{"NonNumericRadius", "shape a\nradius abc\n", "test.shapes:2: radius 'abc' is not a number"},
        BadFile{"NaN", "shape a\nradius 1\nvertices 1\n0 nan 0\nend\n", "test.shapes:4: coordinate 'nan' is not finite"},
        BadFile{"Inf", "shape a\nradius 1\nvertices 1\n0 0 inf\nend\n", "test.shapes:4: coordinate 'inf' is not finite"},
        BadFile{"RadiusOverflow", "shape a\nradius 1e999\n", "test.shapes:2: radius '1e999' is not finite"},
        BadFile{"NegativeRadius", "shape a\nradius -0.5\n", "test.shapes:2: radius -0.5 is negative; give a rounding radius >= 0"},
        BadFile{"ExtraValue", "shape a\nradius 1 2\n", "test.shapes:2: 'radius' takes 1 value(s), found 2"},
        BadFile{"NonNumericCount", "shape a\nradius 1\nvertices two\n", "test.shapes:3: vertex count 'two' is not a whole number"},
        BadFile{"ZeroCount", "shape a\nradius 1\nvertices 0\n", "test.shapes:3: vertex count '0'"},
        BadFile{"FlatPoints", "# flat\nshape sq\nradius 0.1\nvertices 4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\nend\n",
                "test.shapes:2: shape 'sq': 4 coplanar points form a flat point set"},
        BadFile{"PointWithoutRadius", "shape p\nradius 0\nvertices 1\n0 0 0\nend\n", "test.shapes:1: shape 'p': a single point with radius 0"},
        BadFile{"UnterminatedBlock", "shape a\nradius 1\nvertices 1\n0 0 0\n", "test.shapes:1: shape 'a' is not terminated; add a line 'end'"},
        BadFile{"NestedBlock", "shape a\nradius 1\nvertices 1\n0 0 0\nshape b\n", "test.shapes:5: 'shape' inside shape 'a' (line 1)"},
        BadFile{"EndWithoutShape", "end\n", "test.shapes:1: 'end' without 'shape'"},
        BadFile{"NameWithSpace", "shape a b\n", "test.shapes:1: a shape name is one word"},
        BadFile{"DuplicateName", "shape a\nradius 1\nvertices 1\n0 0 0\nend\nshape a\n", "test.shapes:6: shape name 'a' is already used"},
        BadFile{"SecondRadius", "shape a\nradius 1\nradius 2\n", "test.shapes:3: second 'radius'"}),
    [](const ::testing::TestParamInfo<BadFile> &info) { return std::string(info.param.name); });

TEST(ShapeLibrary, ExampleOfTheFormatPageReads)
{
  // The format page shows this file (literalinclude), so the example read here is the one shown.
  std::ifstream file(NSCD_FORMAT_EXAMPLE);
  ASSERT_TRUE(file) << NSCD_FORMAT_EXAMPLE;
  std::stringstream all;
  all << file.rdbuf();
  const std::string example = all.str();
  const auto library = read_text(example, "doc example");
  ASSERT_EQ(library.size(), 4);
  EXPECT_NEAR(library.shape(1).volume, 6.0, 1e-14);
  EXPECT_EQ(library.shape(2).vertices.size(), 5u);    // the interior point is dropped
  EXPECT_TRUE(library.shape(3).is_sphere());
  EXPECT_TRUE(library.shape(4).is_spherocylinder());
}
