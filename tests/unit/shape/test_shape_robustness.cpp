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

// Bad and extreme input to the shape library (doc/robustness.md): sizes at and beyond
// the documented limits, duplicate points and names, counts, densities, damaged text.
// Each case either works (checked against a closed form) or fails with a ShapeError
// that names the value.
#include "shape/grain_record.h"
#include "shape/random_grain.h"
#include "shape/shape_library.h"
#include "shape_test_util.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <filesystem>
#include <functional>
#include <sstream>

using namespace nscd;
using namespace nscd::test;

namespace {

std::vector<Vec3> scaled_unit_cube(double side)
{
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i) corners.push_back(side * Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  return corners;
}

std::string error_of(const std::function<void()> &action)
{
  try {
    action();
  } catch (const ShapeError &e) {
    return e.what();
  }
  return "no error";
}

std::string shape_error(const std::vector<Vec3> &points, double radius)
{
  return error_of([&] { make_spheropolyhedron(points, radius); });
}

std::string read_error(const std::string &text, ShapeLibrary &library)
{
  return error_of([&] {
    std::istringstream in(text);
    library.read(in, "test.shapes");
  });
}

std::string read_error(const std::string &text)
{
  ShapeLibrary library;
  return read_error(text, library);
}

std::string cube_file(const std::string &name, const std::string &side, const std::string &radius = "0")
{
  std::string text = "shape " + name + "\nradius " + radius + "\nvertices 8\n";
  for (int i = 0; i < 8; ++i) {
    text += std::string(i & 1 ? side : "0") + " " + ((i >> 1) & 1 ? side : "0") + " " + ((i >> 2) & 1 ? side : "0") + "\n";
  }
  return text + "end\n";
}

#define EXPECT_HAS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

}    // namespace

// Cube of side a: volume a^3, every principal moment a^5 / 6 per unit density; exact at
// both ends of the supported size range (hull and moments are computed in scaled units).
TEST(ShapeSizeLimits, CubesAtBothEndsOfTheRangeHaveExactMassProperties)
{
  for (double side : {1.5e-30, 1e-29, 1e-20, 1.0, 1e20, 5.7e29}) {
    const auto s = make_spheropolyhedron(scaled_unit_cube(side), 0.0);
    const double a3 = side * side * side;
    EXPECT_NEAR(s.volume, a3, 1e-13 * a3) << side;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.principal_inertia[k], a3 * side * side / 6, 1e-12 * a3 * side * side / 6) << side;
    EXPECT_NEAR(s.bounding_radius, std::sqrt(3.0) / 2 * side, 1e-13 * side) << side;
    EXPECT_EQ(s.faces.size(), 6u) << side;
  }
}

// A grain below 1e-30 (cubes of 1e-70 ... 1e-160 crashed or loaded with zero inertia, a
// 1e-90 tetrahedron broke the serialisation) is refused, naming its size.
TEST(ShapeSizeLimits, TinyShapesAreRefusedNamingTheSize)
{
  for (double side : {1e-31, 1e-70, 1e-80, 1e-85, 1e-100, 1e-160, 1e-300}) {
    const std::string message = shape_error(scaled_unit_cube(side), 0.0);
    EXPECT_HAS(message, "the grain size ");
    EXPECT_HAS(message, "is below the supported 1e-30; use a smaller length unit");
  }
  const std::vector<Vec3> tetrahedron{Vec3(0, 0, 0), Vec3(1e-90, 0, 0), Vec3(0, 1e-90, 0), Vec3(0, 0, 1e-90)};
  EXPECT_HAS(shape_error(tetrahedron, 0.0), "below the supported 1e-30");
  EXPECT_HAS(shape_error({Vec3(1, 2, 3)}, 1e-31), "the grain size 1e-31");
  // All points equal and radius 0: the old message, with the count.
  EXPECT_HAS(shape_error({Vec3(1, 2, 3), Vec3(1, 2, 3)}, 0.0), "all 2 points coincide; a single point with radius 0");
  // In a file the message carries the file and the shape's line.
  EXPECT_HAS(read_error(cube_file("tiny", "1e-100")), "test.shapes:1: shape 'tiny': the grain size ");
}

// Coordinates or radius beyond 1e30 (sides 1e150 / 1e200 and a vertex at 1e300 gave qhull
// or "single point" messages; radius 1e300 gave an infinite volume) are refused by value.
TEST(ShapeSizeLimits, HugeCoordinatesAndRadiiAreRefusedNamingTheValue)
{
  for (const char *side : {"1e31", "1e150", "1e200"}) {
    EXPECT_HAS(read_error(cube_file("big", side)), "is beyond +-1e+30: centre the shape or use a larger unit");
  }
  auto cube = scaled_unit_cube(1.0);
  cube[3] = Vec3(0, 1e300, 0);
  EXPECT_HAS(shape_error(cube, 0.0), "point 4 (0, 1e+300, 0) is beyond +-1e+30");
  EXPECT_HAS(read_error(cube_file("r", "1", "1e300")), "rounding radius 1e+300 is above the supported 1e+30");
  EXPECT_HAS(shape_error({Vec3::Zero()}, 2e30), "rounding radius 2e+30 is above the supported 1e+30");
  // At the limit itself a sphere is fine and finite.
  const auto ball = make_spheropolyhedron({Vec3::Zero()}, 1e30);
  EXPECT_NEAR(ball.volume, 4.0 / 3.0 * kPi * 1e90, 1e-14 * ball.volume);
  EXPECT_TRUE(std::isfinite(ball.principal_inertia.sum()));
}

// Needles: the smallest principal moment is resolved only to ~1e-16 of the largest, so
// a rod (or polyhedron) thinner than 1e-6 x its length is refused (a rod of radius
// 1e-9 got an axial moment of 0; 1e-300 gives no volume at all). Just above the limit
// the axial moment matches the closed form pi r^4 L / 2 + 8/15 pi r^5.
TEST(ShapeSizeLimits, NeedlesThinnerThanOneE6AreRefused)
{
  for (double r : {1e-300, 1e-9, 0.9e-6}) {
    EXPECT_HAS(shape_error({Vec3(-1, 0, 0), Vec3(1, 0, 0)}, r), "collinear points is below 1e-06 x their size 1");
  }
  const Vec3 direction = Vec3(1, 2, -3).normalized();    // not along an axis: rotation mixes moments
  const double r = 2e-6, length = 2.0;
  const auto rod = make_spheropolyhedron({-direction, direction}, r);
  const double axial = kPi * std::pow(r, 4) * length / 2 + 8.0 / 15.0 * kPi * std::pow(r, 5);
  EXPECT_NEAR(rod.principal_inertia[0], axial, 1e-3 * axial);
  // A polyhedral needle: a 2 x t x t box.
  const auto needle = [](double t) { return box_corners(2.0, t, t); };
  EXPECT_HAS(shape_error(needle(1e-7), 0.0), "the shape is a needle: its principal moments of inertia");
  const auto box = make_spheropolyhedron(needle(4e-6), 0.0);
  const double t = 4e-6, mass = 2 * t * t;
  EXPECT_NEAR(box.principal_inertia[0], mass * (t * t + t * t) / 12, 1e-3 * mass * t * t / 6);
}

// The same shape built at two scales s differs by s^3 in volume and s^5 in inertia.
TEST(ShapeSizeLimits, MassPropertiesScaleWithTheShape)
{
  std::mt19937_64 rng(11);
  std::vector<Vec3> points(30);
  for (auto &p : points) p = random_in_ball(rng) + Vec3(0.3, -2, 5);
  const auto unit = make_spheropolyhedron(points, 0.1);
  for (double scale : {3e-28, 1.7e-9, 6.1e13, 2e28}) {
    std::vector<Vec3> scaled(points.size());
    for (size_t i = 0; i < points.size(); ++i) scaled[i] = scale * points[i];
    const auto s = make_spheropolyhedron(scaled, 0.1 * scale);
    EXPECT_NEAR(s.volume / unit.volume, std::pow(scale, 3), 1e-12 * std::pow(scale, 3));
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(s.principal_inertia[k] / unit.principal_inertia[k], std::pow(scale, 5), 1e-11 * std::pow(scale, 5));
    }
    EXPECT_EQ(s.vertices.size(), unit.vertices.size());
  }
}

// De-duplication (now on a hash grid) keeps today's rule: a point within 1e-10 x the
// grain size of an earlier kept point is dropped, one just beyond it is kept.
TEST(ShapeDeduplication, ToleranceIsOneE10OfTheGrainSize)
{
  const double radius = 0.1;    // the grain size L of two nearly equal points
  const double tolerance = 1e-10 * radius;
  EXPECT_TRUE(make_spheropolyhedron({Vec3(0.3, 0.3, 0.3), Vec3(0.3 + 0.9 * tolerance, 0.3, 0.3)}, radius).is_sphere());
  EXPECT_TRUE(make_spheropolyhedron({Vec3(0.3, 0.3, 0.3), Vec3(0.3 + 1.5 * tolerance, 0.3, 0.3)}, radius)
                  .is_spherocylinder());
}

// Near-duplicates of every point, in random directions (so across grid-cell borders),
// change nothing: the result equals the shape of the clean points.
TEST(ShapeDeduplication, NearDuplicatesInAnyDirectionAreDropped)
{
  std::mt19937_64 rng(5);
  std::vector<Vec3> clean(2000);
  for (auto &p : clean) p = random_in_ball(rng);
  std::vector<Vec3> noisy;
  for (const auto &p : clean) {
    noisy.push_back(p);
    for (int copy = 0; copy < 3; ++copy) noisy.push_back(p + 0.4e-10 * random_in_ball(rng));
  }
  const auto a = make_spheropolyhedron(clean, 0.0), b = make_spheropolyhedron(noisy, 0.0);
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  EXPECT_EQ(a.faces.size(), b.faces.size());
  EXPECT_NEAR(a.volume, b.volume, 1e-9 * a.volume);
}

// 10^5 points (the old pairwise de-duplication took 15 s) make a hull whose volume
// approaches the ball's; the cost is in doc/robustness.md.
TEST(ShapeDeduplication, HundredThousandPointsMakeOneShape)
{
  std::mt19937_64 rng(3);
  std::vector<Vec3> points(100000);
  for (auto &p : points) p = random_in_ball(rng);
  const auto s = make_spheropolyhedron(points, 0.0);
  const double ball = 4.0 / 3.0 * kPi;
  EXPECT_LT(s.volume, ball);
  EXPECT_GT(s.volume, 0.98 * ball);    // the hull of 1e5 points in a ball misses ~1.5 % of it
}

TEST(ShapeNames, ASecondFileWithATakenNameIsRefusedAndAddsNothing)
{
  ShapeLibrary library;
  std::istringstream first(cube_file("cube", "1"));
  library.read(first, "first.shapes");
  const std::string text = cube_file("other", "2") + cube_file("cube", "3");
  EXPECT_HAS(read_error(text, library), "test.shapes:13: shape name 'cube' is already used by shape id 1");
  EXPECT_EQ(library.size(), 1);
  // The same through append (e.g. shapes read after read_restart): nothing appended.
  ShapeLibrary restarted = ShapeLibrary::deserialize(library.serialize());
  ShapeLibrary more;
  std::istringstream again(cube_file("cube", "2"));
  more.read(again, "again.shapes");
  EXPECT_HAS(error_of([&] { restarted.append(more); }), "shape name 'cube' is already used by shape id 1; rename");
  EXPECT_EQ(restarted.size(), 1);
  // Unnamed shapes can repeat.
  ShapeLibrary unnamed;
  unnamed.add(make_spheropolyhedron({Vec3::Zero()}, 1.0));
  unnamed.append(unnamed);
  EXPECT_EQ(unnamed.size(), 2);
}

TEST(ShapeNames, AddRefusesTakenAndMultiWordNames)
{
  ShapeLibrary library;
  const auto ball = make_spheropolyhedron({Vec3::Zero()}, 1.0);
  EXPECT_EQ(library.add(ball, "a"), 1);
  EXPECT_EQ(library.add(ball, "b"), 2);
  EXPECT_HAS(error_of([&] { library.add(ball, "a"); }), "shape name 'a' is already used by shape id 1");
  EXPECT_HAS(error_of([&] { library.add(ball, "two words"); }), "is not one word");
  EXPECT_HAS(error_of([&] { library.add(ball, "hash#tag"); }), "is not one word");
  // A control byte is shown escaped, so that the message is not cut at a NUL.
  EXPECT_HAS(error_of([&] { library.add(ball, std::string("a\0b", 3)); }), "shape name 'a\\x00b' is not one word");
  EXPECT_EQ(library.size(), 2);
  EXPECT_EQ(library.find("b"), 2);
  EXPECT_EQ(library.find("c"), 0);
}

// 10^5 one-vertex shapes (the old name lookup was linear per shape: 8 s); every name is
// then found at its id.
TEST(ShapeNames, HundredThousandNamedShapesAreFoundByName)
{
  std::string text;
  for (int k = 0; k < 100000; ++k) text += "shape s" + std::to_string(k) + "\nradius 0.5\nvertices 1\n0 0 0\nend\n";
  ShapeLibrary library;
  std::istringstream in(text);
  library.read(in, "many.shapes");
  ASSERT_EQ(library.size(), 100000);
  for (int k = 0; k < 100000; k += 997) EXPECT_EQ(library.find("s" + std::to_string(k)), k + 1);
}

TEST(ShapeNames, RandomGrainsWithAUsedSeedAreRefused)
{
  ShapeLibrary library;
  RandomGrainParams params;
  add_random_grains(library, params, 2, 7);
  EXPECT_HAS(error_of([&] { add_random_grains(library, params, 3, 7); }),
             "shape name 'grain_7_1' is already used by shape id 1 (seed 7 was used before); give another seed");
  EXPECT_EQ(library.size(), 2);
  add_random_grains(library, params, 1, 8);
  EXPECT_EQ(library.size(), 3);
}

TEST(ShapeCounts, LibraryAndRandomCountsAreBounded)
{
  ShapeLibrary library;
  RandomGrainParams params;
  EXPECT_HAS(error_of([&] { add_random_grains(library, params, 100000000, 1); }),
             "count 100000000 is more than the library can take (100000 shapes at most, 0 loaded)");
  const auto ball = make_spheropolyhedron({Vec3::Zero()}, 1.0);
  for (int k = 0; k < ShapeLibrary::kMaxShapes; ++k) library.add(ball);
  EXPECT_HAS(error_of([&] { library.add(ball); }), "would hold 100001 shapes, more than 100000");
  EXPECT_HAS(error_of([&] { add_random_grains(library, params, 1, 1); }), "count 1 is more than the library can take");
  ShapeLibrary one;
  one.add(ball);
  EXPECT_HAS(error_of([&] { library.append(one); }), "would hold 100001 shapes");
  EXPECT_EQ(library.size(), ShapeLibrary::kMaxShapes);
}

// `size 1e300 1e300` made NaN points; tiny diameters make grains below the size limit.
TEST(ShapeCounts, RandomGrainDiametersOutsideTheRangeAreRefused)
{
  RandomGrainParams params;
  params.min_diameter = params.max_diameter = 1e300;
  EXPECT_HAS(error_of([&] { validate(params); }), "max diameter 1e+300 is not a number up to the supported 1e+29");
  params.min_diameter = params.max_diameter = 1e-300;
  EXPECT_HAS(error_of([&] { validate(params); }), "min diameter 1e-300 is below the supported 1e-29");
  params.min_diameter = 1.0;
  params.max_diameter = NAN;
  EXPECT_HAS(error_of([&] { validate(params); }), "max diameter nan is not a number");
  // At the ends of the range the grains are finite with the drawn volume.
  for (double d : {1e-29, 1e29}) {
    params.min_diameter = params.max_diameter = d;
    const auto grain = random_grain(params, 3, 0);
    EXPECT_NEAR(grain.volume, kPi / 6 * d * d * d, 1e-10 * grain.volume);
    EXPECT_TRUE(grain.principal_inertia.allFinite());
  }
}

// density 1e400 (inf) and 1e-320 (a denormal mass) led to garbage later.
TEST(GrainInertia, DensityAndMassMustGiveFiniteNormalValues)
{
  const auto cube = make_spheropolyhedron(scaled_unit_cube(2.0), 0.0);
  const auto grain = grain_inertia_from_density(cube, 3.0);
  EXPECT_DOUBLE_EQ(grain.mass, 24.0);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(grain.inertia[k], 24.0 * 4.0 / 6.0, 1e-12 * 16);
  const auto same = grain_inertia_from_mass(cube, 24.0);
  EXPECT_LT((same.inertia - grain.inertia).norm(), 1e-12 * grain.inertia.norm());
  EXPECT_HAS(error_of([&] { grain_inertia_from_density(cube, HUGE_VAL); }), "density inf is invalid; give a finite density > 0");
  EXPECT_HAS(error_of([&] { grain_inertia_from_density(cube, -1.0); }), "density -1 is invalid");
  EXPECT_HAS(error_of([&] { grain_inertia_from_density(cube, 1e-320); }), "gives a grain of mass");
  EXPECT_HAS(error_of([&] { grain_inertia_from_density(cube, 1e308); }), "not all finite positive numbers");
  EXPECT_HAS(error_of([&] { grain_inertia_from_mass(cube, NAN); }), "mass nan is invalid");
  EXPECT_HAS(error_of([&] { grain_inertia_from_mass(cube, 1e-310); }), "gives a grain of mass");
  // normal numbers, but beyond what the solver can square (before: 1000 unconverged sweeps a step)
  EXPECT_HAS(error_of([&] { grain_inertia_from_mass(cube, 1e-300); }), "mass 1e-300 gives a grain of mass 1e-300, outside the solver's 1e-100 to 1e+100");
  EXPECT_HAS(error_of([&] { grain_inertia_from_density(cube, 1e101); }), "outside the solver's 1e-100 to 1e+100");
  EXPECT_NO_THROW(grain_inertia_from_mass(cube, 1e-100));
  EXPECT_NO_THROW(grain_inertia_from_mass(cube, 1e100));
}

TEST(ShapeFiles, DirectoryEmptyLibraryAndControlBytesGetClearMessages)
{
  const std::string directory = std::filesystem::temp_directory_path().string();
  ShapeLibrary library;
  EXPECT_HAS(error_of([&] { library.read_file(directory); }), directory + ": is a directory, not a shape library file");
  std::ostringstream out;
  EXPECT_HAS(error_of([&] { library.write(out); }), "the shape library is empty, so there is nothing to write");
  EXPECT_TRUE(out.str().empty());
  // A NUL byte used to cut the message (and "0\0x" read as 0); now the byte is named.
  const std::string with_nul = std::string("shape a\nradius 0") + '\0' + "5\nvertices 1\n0 0 0\nend\n";
  EXPECT_HAS(read_error(with_nul), "test.shapes:2: column 9 holds the control byte 0x00; a shape library is plain text");
  EXPECT_HAS(read_error("shape a\x01\n"), "test.shapes:1: column 8 holds the control byte 0x01");
  // Tab, CR (Windows line ends), vertical tab and form feed are white space.
  ShapeLibrary crlf;
  EXPECT_EQ(read_error("shape a\r\nradius\t0.5\r\nvertices 1\v\n0 0 0\f\nend\r\n", crlf), "no error");
  // A very long token is cut in the message.
  const std::string long_word(5000, 'x');
  const std::string message = read_error(long_word + "\n");
  EXPECT_HAS(message, "...' (5000 characters)");
  EXPECT_LT(message.size(), 300u);
  // Underflow in a coordinate is no error (it is ~0); overflow is.
  ShapeLibrary tiny;
  EXPECT_EQ(read_error("shape a\nradius 0.5\nvertices 2\n0 0 1e-320\n1 0 0\nend\n", tiny), "no error");
  EXPECT_HAS(read_error("shape a\nradius 0.5\nvertices 1\n0 0 1e400\nend\n"), "coordinate '1e400' is not finite");
}

// deserialize() accepts exactly what serialize() writes, and no impossible shape.
TEST(ShapeSerialisation, NonCanonicalOrImpossibleTextIsDamaged)
{
  ShapeLibrary library;
  library.add(make_spheropolyhedron(scaled_unit_cube(1.0), 0.1), "cube");
  library.add(make_spheropolyhedron({Vec3::Zero()}, 0.75), "ball");
  const std::string text = library.serialize();
  auto damaged = [](const std::string &t) {
    return error_of([&] { ShapeLibrary::deserialize(t); });
  };
  auto replaced = [&](const std::string &from, const std::string &to) {
    std::string t = text;
    const auto at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return t.replace(at, from.size(), to);
  };
  EXPECT_HAS(damaged(replaced(",2,", ",+2,")), "'+2' is not a count or an index");
  EXPECT_HAS(damaged(replaced(",2,", ",02,")), "'02' is not a count or an index");
  // The ball's radius 0.75 = 3fe8000000000000: upper case, a NaN, a negative value.
  EXPECT_HAS(damaged(replaced("3fe8000000000000", "3FE8000000000000")), "is not a 16-digit hexadecimal number");
  EXPECT_HAS(damaged(replaced("3fe8000000000000", "7ff8000000000000")), "a shape has a bad radius");
  EXPECT_HAS(damaged(replaced("3fe8000000000000", "bfe8000000000000")), "a shape has a bad radius");
  // A count far beyond the text's length fails at once, before any allocation.
  EXPECT_HAS(damaged("nscd-shapes-1,1,00,0000000000000000,999999," + std::string(400, '0')),
             "it ends too early: count 999999");
  EXPECT_HAS(damaged("nscd-shapes-1,99999,"), "it ends too early");
  // Two shapes with the same name.
  EXPECT_HAS(damaged(replaced("62616c6c", "63756265")), "shape name 'cube' is already used by shape id 1");
  // A NaN volume: the cube's volume is the first real after its edge list... found by
  // rewriting the serialisation of a library whose shape has a NaN volume.
  ShapeLibrary bad;
  auto ball = make_spheropolyhedron({Vec3::Zero()}, 0.5);
  ball.volume = NAN;
  bad.add(ball);
  EXPECT_HAS(damaged(bad.serialize()), "has a volume, inertia or bounding radius that is not a finite positive number");
  ball.volume = 1.0;
  ball.input_rotation = Quat(2, 0, 0, 0);
  ShapeLibrary unnormalised;
  unnormalised.add(ball);
  EXPECT_HAS(damaged(unnormalised.serialize()), "rotation that is not a unit quaternion");
  // The good text round-trips exactly.
  EXPECT_EQ(ShapeLibrary::deserialize(text).serialize(), text);
}

// The atom style's data-file and restart readers check each grain with check_grain_record:
// every impossible value is refused naming it; a fine one gives the normalised orientation
// and the moments of the shape at that mass (cube of side 1, mass 6: I = m a^2 / 6 = 1).
TEST(GrainRecords, ImpossibleShapeIdsMassesAndOrientationsAreRefused)
{
  ShapeLibrary library;
  std::istringstream text("shape cube\nradius 0\nvertices 8\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\nend\n");
  library.read(text, "cube");
  auto problem = [&](const GrainRecord &r, QuaternionLength length = QuaternionLength::any) {
    return error_of([&]() { check_grain_record(library, r, length); });
  };
  EXPECT_NE(problem({2, 1.0, {1, 0, 0, 0}}).find("shape id 2 is outside 0..1"), std::string::npos);
  EXPECT_NE(problem({-1, 1.0, {1, 0, 0, 0}}).find("shape id -1"), std::string::npos);
  EXPECT_NE(problem({1, 0.0, {1, 0, 0, 0}}).find("mass 0 must be"), std::string::npos);
  EXPECT_NE(problem({1, NAN, {1, 0, 0, 0}}).find("mass nan"), std::string::npos);
  EXPECT_NE(problem({0, -1.0, {1, 0, 0, 0}}).find("mass -1"), std::string::npos);    // points too
  EXPECT_NE(problem({1, 1e-320, {1, 0, 0, 0}}).find("not all finite positive"), std::string::npos);    // moments
  EXPECT_NE(problem({1, 1.0, {0, 0, 0, 0}}).find("no usable length"), std::string::npos);
  EXPECT_NE(problem({1, 1.0, {1e300, 1e300, 0, 0}}).find("no usable length"), std::string::npos);
  EXPECT_NE(problem({1, 1.0, {NAN, 0, 0, 0}}).find("nan"), std::string::npos);
  EXPECT_NE(problem({1, 1.0, {2, 0, 0, 0}}, QuaternionLength::unit).find("has length 2, not 1"), std::string::npos);

  const CheckedGrain grain = check_grain_record(library, {1, 6.0, {2, 0, 0, 0}}, QuaternionLength::any);
  EXPECT_EQ(grain.quat[0], 1.0);
  for (int k = 0; k < 3; k++) EXPECT_NEAR(grain.inertia[k], 1.0, 1e-12);
  EXPECT_NEAR(grain.bounding_radius, std::sqrt(0.75), 1e-12);
  const CheckedGrain point = check_grain_record(library, {0, 0.5, {1, 0, 0, 0}}, QuaternionLength::unit);
  EXPECT_EQ(point.inertia.norm(), 0.0);
}
