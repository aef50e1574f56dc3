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

// lib/wire/wire_path: wire paths cut at equal chords, against closed forms.
#include "wire/wire_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace nscd;
using namespace nscd::wire;

namespace {
constexpr double kPi = 3.141592653589793;

void expect_vec_near(const Vec3 &a, const Vec3 &b, double tol, const std::string &what = "")
{
  EXPECT_LT((a - b).norm(), tol) << what << ": (" << a.transpose() << ") vs (" << b.transpose() << ")";
}

// Every element of the layout has the given straight length.
void expect_chords(const WireLayout &layout, double chord, double tol)
{
  for (const WireElement &e : layout.topology.elements)
    EXPECT_NEAR((layout.nodes[e.b] - layout.nodes[e.a]).norm(), chord, tol) << "element " << e.a;
}

// Angle step of a helix of radius R and pitch p whose chord is c, from
// c^2 = (2 R sin(d/2))^2 + (p d / 2 pi)^2, solved by bisection (the closed form).
double helix_step(double R, double p, double c)
{
  double lo = 0.0, hi = kPi;
  for (int k = 0; k < 200; k++) {
    const double d = 0.5 * (lo + hi);
    const double chord = std::hypot(2.0 * R * std::sin(0.5 * d), p * d / (2.0 * kPi));
    (chord < c ? lo : hi) = d;
  }
  return 0.5 * (lo + hi);
}
}    // namespace

TEST(WirePath, FlatLoopOfOneTurnClosesWithEqualArcs)
{
  LoopPath loop;
  loop.centre = Vec3(1, 2, 3);
  loop.radius = 2.0;
  const double chord = 0.25;
  const WireLayout w = lay_loop(loop, chord);
  const int n = (int) std::lround(2 * kPi * 2.0 / chord);    // 50
  ASSERT_EQ((int) w.nodes.size(), n);
  EXPECT_TRUE(w.closed);
  EXPECT_EQ(w.topology.elements.size(), (size_t) n);
  EXPECT_EQ(w.topology.joints.size(), (size_t) n);
  EXPECT_EQ(w.topology.elements.back().b, 0);    // the last element closes the ring
  EXPECT_NEAR(w.chord, 2 * 2.0 * std::sin(kPi / n), 1e-14);
  for (int k = 0; k < n; k++)
    expect_vec_near(w.nodes[k], Vec3(1 + 2 * std::cos(2 * kPi * k / n), 2 + 2 * std::sin(2 * kPi * k / n), 3), 1e-13);
  expect_chords(w, w.chord, 1e-13);
}

TEST(WirePath, OpenLoopHasExactChordsAndStopsWithinOneElementOfItsEnd)
{
  LoopPath loop;
  loop.radius = 1.5;
  loop.gap = 30 * kPi / 180;
  loop.start = 0.4;
  const double chord = 0.2;
  const WireLayout w = lay_loop(loop, chord);
  const double step = 2 * std::asin(chord / (2 * 1.5));
  const int n = (int) std::floor((2 * kPi - loop.gap) / step) + 1;
  ASSERT_EQ((int) w.nodes.size(), n);
  EXPECT_FALSE(w.closed);
  EXPECT_EQ(w.topology.elements.size(), (size_t) n - 1);
  EXPECT_EQ(w.topology.joints.size(), (size_t) n - 2);
  for (int k = 0; k < n; k++) {
    const double a = 0.4 + k * step;
    expect_vec_near(w.nodes[k], Vec3(1.5 * std::cos(a), 1.5 * std::sin(a), 0.0), 1e-12, "node " + std::to_string(k));
  }
  expect_chords(w, chord, 1e-12);
  EXPECT_DOUBLE_EQ(w.topology.elements.front().rest_length, chord);
}

TEST(WirePath, DoubleLoopWithPitchFollowsTheHelixClosedForm)
{
  LoopPath loop;
  loop.radius = 3.0;
  loop.turns = 2.0;
  loop.pitch = 0.1;
  loop.gap = 10 * kPi / 180;
  loop.centre = Vec3(0, 0, 1);
  const double chord = 0.3;
  const WireLayout w = lay_loop(loop, chord);
  const double step = helix_step(3.0, 0.1, chord);
  const double sweep = 4 * kPi - loop.gap;
  ASSERT_EQ((int) w.nodes.size(), (int) std::floor(sweep / step) + 1);
  for (size_t k = 0; k < w.nodes.size(); k += 7) {
    const double a = k * step;
    expect_vec_near(w.nodes[k], Vec3(3 * std::cos(a), 3 * std::sin(a), 1 + 0.1 * a / (2 * kPi)), 1e-9);
  }
  expect_chords(w, chord, 1e-12);
  // the two turns lie 0.1 apart: no node of turn 2 sits on turn 1
  EXPECT_NEAR(w.nodes.back().z() - w.nodes.front().z(), 0.1 * sweep / (2 * kPi), 0.1 * step / (2 * kPi) + 1e-12);
}

TEST(WirePath, LoopAroundATiltedAxisStaysInItsPlane)
{
  std::mt19937 random(5);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 20; trial++) {
    LoopPath loop;
    loop.axis = Vec3(normal(random), normal(random), normal(random));
    loop.radius = 0.7;
    loop.gap = 0.5;
    const WireLayout w = lay_loop(loop, 0.1);
    const Vec3 a = loop.axis.normalized();
    for (const Vec3 &x : w.nodes) {
      EXPECT_NEAR(x.dot(a), 0.0, 1e-12);
      EXPECT_NEAR(x.norm(), 0.7, 1e-12);
    }
    Vec3 e1, e2;
    loop_frame(loop.axis, e1, e2);
    EXPECT_NEAR(e1.dot(e2), 0.0, 1e-14);
    EXPECT_NEAR(e1.cross(e2).dot(a), 1.0, 1e-14);    // right-handed about the axis
    expect_vec_near(w.nodes[0], 0.7 * e1, 1e-12);
  }
  Vec3 e1, e2;
  loop_frame(Vec3::UnitZ(), e1, e2);
  expect_vec_near(e1, Vec3::UnitX(), 1e-15);
  expect_vec_near(e2, Vec3::UnitY(), 1e-15);
}

TEST(WirePath, LineAndPolylineWalkTheirPieces)
{
  PolylinePath line{{Vec3(0, 0, 0), Vec3(2, 0, 0)}};
  WireLayout w = lay_polyline(line, 0.3);
  ASSERT_EQ(w.nodes.size(), 7u);    // 0 .. 1.8
  for (int k = 0; k < 7; k++) expect_vec_near(w.nodes[k], Vec3(0.3 * k, 0, 0), 1e-13);
  // a path of exactly 30 elements (0.2 x 30 = 6 up to round-off) ends on its last node
  w = lay_polyline(PolylinePath{{Vec3(-3, -3, 0.5), Vec3(3, -3, 0.5)}}, 0.2);
  ASSERT_EQ(w.nodes.size(), 31u);
  expect_vec_near(w.nodes.back(), Vec3(3, -3, 0.5), 1e-12);

  // around a right-angled corner: 0, 0.3, 0.6, 0.9 along x, then (1, sqrt(0.08)) on the
  // second leg, 0.3 straight from (0.9, 0, 0)
  PolylinePath corner{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)}};
  w = lay_polyline(corner, 0.3);
  expect_vec_near(w.nodes[3], Vec3(0.9, 0, 0), 1e-14);
  expect_vec_near(w.nodes[4], Vec3(1, std::sqrt(0.08), 0), 1e-12);
  expect_vec_near(w.nodes[5], Vec3(1, std::sqrt(0.08) + 0.3, 0), 1e-12);
  expect_chords(w, 0.3, 1e-12);
  EXPECT_LT((w.nodes.back() - Vec3(1, 1, 0)).norm(), 0.3);
}

TEST(WirePath, GivenNodeCountSpansTheWholePathAtEqualChords)
{
  PolylinePath line{{Vec3(0, 0, 0), Vec3(0, 0, 1)}};
  WireLayout w = lay_polyline_nodes(line, 11);
  ASSERT_EQ(w.nodes.size(), 11u);
  EXPECT_NEAR(w.chord, 0.1, 1e-14);
  expect_vec_near(w.nodes.back(), Vec3(0, 0, 1), 1e-15);
  expect_chords(w, 0.1, 1e-13);

  LoopPath loop;
  loop.radius = 1.0;
  loop.turns = 2.0;
  loop.pitch = 0.05;
  loop.gap = 20 * kPi / 180;
  w = lay_loop_nodes(loop, 120);
  ASSERT_EQ(w.nodes.size(), 120u);
  expect_vec_near(w.nodes.back(), loop_point(loop, 1.0), 1e-12);
  expect_chords(w, w.chord, 1e-12);
  const double step = (4 * kPi - loop.gap) / 119;    // equal chords on a helix: equal angles
  EXPECT_NEAR(w.chord, std::hypot(2 * std::sin(step / 2), 0.05 * step / (2 * kPi)), 1e-12);

  loop.turns = 1.0;
  loop.pitch = 0.0;
  loop.gap = 0.0;
  w = lay_loop_nodes(loop, 8);
  EXPECT_TRUE(w.closed);
  EXPECT_NEAR(w.chord, 2 * std::sin(kPi / 8), 1e-14);
}

TEST(WirePath, ImpossiblePathsAreRefusedNamingTheValue)
{
  auto message = [](auto &&call) {
    try {
      call();
    } catch (WirePathError &e) {
      return std::string(e.what());
    }
    return std::string();
  };
  LoopPath loop;
  loop.radius = 0.5;
  EXPECT_NE(message([&] { lay_loop(loop, 1.2); }).find("1.2"), std::string::npos);
  EXPECT_NE(message([&] { lay_loop(loop, 0.0); }).find("element length 0"), std::string::npos);
  loop.radius = -1;
  EXPECT_NE(message([&] { lay_loop(loop, 0.1); }).find("radius -1"), std::string::npos);
  loop.radius = 1;
  loop.turns = 2;
  EXPECT_NE(message([&] { lay_loop(loop, 0.1); }).find("pitch"), std::string::npos);
  loop.turns = 1;
  loop.gap = 7.0;
  EXPECT_NE(message([&] { lay_loop(loop, 0.1); }).find("gap"), std::string::npos);
  PolylinePath twice{{Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0)}};
  EXPECT_NE(message([&] { lay_polyline(twice, 0.1); }).find("coincide"), std::string::npos);
  PolylinePath shortline{{Vec3(0, 0, 0), Vec3(0.05, 0, 0)}};
  EXPECT_NE(message([&] { lay_polyline(shortline, 0.1); }).find("longer than the path"), std::string::npos);
  EXPECT_NE(message([&] { lay_polyline_nodes(shortline, 1); }).find("at least 2"), std::string::npos);
}

// A polyline file's lines are points, blank lines or comments; anything else stops the read
// naming the line (before: a line whose first number could not be read, such as nan, inf,
// 1e400 or a header, was skipped as a comment and the wire took another path).
TEST(WirePath, PolylineFileLinesThatAreNotPointsAreRefusedByLine)
{
  const PolylinePath path = read_polyline("# x y z\n0 0 1\n\n  1 0 1   # corner\n1 1 1\n-2.5e-1 .5 +3.\n", "p.txt");
  ASSERT_EQ(path.points.size(), 4u);
  expect_vec_near(path.points[1], Vec3(1, 0, 1), 1e-300);
  expect_vec_near(path.points[3], Vec3(-0.25, 0.5, 3.0), 1e-300);
  auto problem = [](const std::string &text) {
    try {
      read_polyline(text, "p.txt");
    } catch (const WirePathError &e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::pair<const char *, const char *> cases[] = {
      {"0 0 1\nnan 0 1\n1 1 1\n", "p.txt:2: 'nan' is not a number"},
      {"0 0 1\ninf 0 1\n", "p.txt:2: 'inf' is not a number"},
      {"0 0 1\n1e400 0 1\n", "p.txt:2: 1e400 is beyond the range"},
      {"x y z\n0 0 1\n1 0 1\n", "p.txt:1: 'x' is not a number"},
      {"0 0 1\n1 0\n", "p.txt:2: expected three numbers 'x y z', got 2 word(s)"},
      {"0 0 1\n1 0 1 4\n", "got 4 word(s)"},
      {"0 0 1\n0x10 0 1\n", "'0x10' is not a number"},
      {"0 0 1\n1.0.0 0 1\n", "'1.0.0' is not a number"},
      {"0 0 1\n1e 0 1\n", "'1e' is not a number"},
      {"0 0 1\n1,5 0 1\n", "'1,5' is not a number"},
  };
  for (const auto &c : cases) EXPECT_NE(problem(c.first).find(c.second), std::string::npos) << c.first << " -> " << problem(c.first);
}

// A path that turns back within one element has no point a chord away from its start: a
// WirePathError (before: std::invalid_argument from the chain topology, "a chain needs at
// least 2 nodes"; found by fuzzing, tests/fuzz/regressions/polyline).
TEST(WirePath, PathTurningBackWithinOneElementIsRefused)
{
  PolylinePath path;
  path.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.1, 0, 0.1)};    // 1.906 long, never > 1 from its start
  try {
    lay_polyline(path, 1.5);
    FAIL() << "no error";
  } catch (const WirePathError &e) {
    EXPECT_NE(std::string(e.what()).find("no second node fits"), std::string::npos) << e.what();
  }
  EXPECT_EQ(lay_polyline(path, 0.9).nodes.size(), 2u);    // (0.9, 0, 0): the rest lies within 0.81 of it
}

// Continuing a wire from its end: node 0 is the end itself, then a straight bridge to the
// path's start (none when they coincide), then the path, all at the same chord.
TEST(WirePath, ContinuedPathStartsAtTheWiresEnd)
{
  // the end on the line's start: the line's own nodes, the end first
  WireLayout w = lay_polyline_from(Vec3(0, 0, 0), PolylinePath{{Vec3(0, 0, 0), Vec3(1, 0, 0)}}, 0.2);
  ASSERT_EQ(w.nodes.size(), 6u);
  for (int k = 0; k < 6; k++) expect_vec_near(w.nodes[k], Vec3(0.2 * k, 0, 0), 1e-12);
  EXPECT_EQ(w.topology.elements.size(), 5u);
  EXPECT_EQ(w.topology.joints.size(), 4u);
  // a bridge of 0.5 up to a line along x: 0, 0.2, 0.4 up, then the corner is cut at chord 0.2
  w = lay_polyline_from(Vec3(0, 0, 0), PolylinePath{{Vec3(0, 0, 0.5), Vec3(1, 0, 0.5)}}, 0.2);
  EXPECT_EQ(w.nodes[0], Vec3(0, 0, 0));
  expect_vec_near(w.nodes[2], Vec3(0, 0, 0.4), 1e-12);
  expect_vec_near(w.nodes[3], Vec3(std::sqrt(0.04 - 0.01), 0, 0.5), 1e-12);
  expect_chords(w, 0.2, 1e-12);
  // a helix continued from the point one chord before its start, on its tangent line's side:
  // the join is one element, then the helix's own nodes
  LoopPath helix;
  helix.radius = 2.0;
  helix.turns = 1.5;
  helix.pitch = 0.3;
  const WireLayout alone = lay_loop(helix, 0.2);
  w = lay_loop_from(Vec3(2.0, -0.2, 0.0), helix, 0.2);
  ASSERT_EQ(w.nodes.size(), alone.nodes.size() + 1);
  for (size_t k = 0; k < alone.nodes.size(); k++) expect_vec_near(w.nodes[k + 1], alone.nodes[k], 1e-9);
  expect_chords(w, 0.2, 1e-12);
}

TEST(WirePath, ContinuingWithAClosedRingOrTooShortAPathIsRefused)
{
  LoopPath ring;
  ring.radius = 1.0;
  EXPECT_THROW(lay_loop_from(Vec3(1, 0, 0.5), ring, 0.2), WirePathError);
  EXPECT_THROW(lay_polyline_from(Vec3(0, 0, 0), PolylinePath{{Vec3(0, 0, 0), Vec3(0.1, 0, 0)}}, 0.2),
               WirePathError);
  EXPECT_THROW(lay_polyline_from(Vec3(0, 0, NAN), PolylinePath{{Vec3(0, 0, 0), Vec3(1, 0, 0)}}, 0.2),
               WirePathError);
}
