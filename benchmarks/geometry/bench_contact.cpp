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

// Pairs per second of the narrow phase for typical random grains (hull of 12-24 random
// points on an ellipsoid, fixed seed), in the poses a simulation hands it:
//   touching       dilated surfaces overlapping or apart by up to 1% of the size
//   near           apart by 1-5% of the size (inside a 5% activation distance)
//   core_overlap   the polyhedral cores themselves overlap (separating-axis path)
//   separated      bounding spheres apart (rejected first)
// and the fast paths (spheres), a box resting on a box (4-point patch) and grains on a
// plane (random poses, and resting on a face with many vertices in the activation band).
#include "geometry/contact.h"
#include "shape/spheropolyhedron.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>
#include <vector>

namespace {

using namespace nscd;

constexpr double kActivation = 0.05;    // grains have size ~1
constexpr int kPairs = 256;

struct Pair {
  const Spheropolyhedron *a, *b;
  Pose pa, pb;
};

Spheropolyhedron random_grain(std::mt19937_64 &rng)
{
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_int_distribution<int> count(12, 24);
  std::vector<Vec3> cloud;
  const int n = count(rng);
  for (int k = 0; k < n; ++k) {
    const Vec3 p = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    cloud.emplace_back(1.0 * p.x(), 0.8 * p.y(), 0.6 * p.z());
  }
  return make_spheropolyhedron(cloud, 0.03);
}

Quat random_rotation(std::mt19937_64 &rng)
{
  std::normal_distribution<double> normal(0.0, 1.0);
  return Quat(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
}

// Smallest gap of the pair (large activation so that it is always reported).
double pair_gap(const Pair &p, ContactWorkspace &ws)
{
  const ContactSet set = contact_grains(*p.a, p.pa, *p.b, p.pb, 100.0, ws);
  double g = 1e300;
  for (const auto &c : set) g = std::min(g, c.gap);
  return g;
}

// Pairs whose gap is uniform in [gap_lo, gap_hi]: j slid along a random direction.
std::vector<Pair> make_pairs(const std::vector<Spheropolyhedron> &grains, double gap_lo, double gap_hi, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<size_t> pick(0, grains.size() - 1);
  ContactWorkspace ws;
  std::vector<Pair> pairs;
  while (pairs.size() < kPairs) {
    Pair p{&grains[pick(rng)], &grains[pick(rng)], {}, {}};
    p.pa.orientation = random_rotation(rng);
    p.pb.orientation = random_rotation(rng);
    const Vec3 dir = Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5).normalized();
    const double target = gap_lo + (gap_hi - gap_lo) * unit(rng);
    double lo = 0.0, hi = p.a->bounding_radius + p.b->bounding_radius + 1.0;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      p.pb.position = mid * dir;
      (pair_gap(p, ws) < target ? lo : hi) = mid;
    }
    p.pb.position = hi * dir;
    pairs.push_back(p);
  }
  return pairs;
}

const std::vector<Spheropolyhedron> &grains()
{
  static const std::vector<Spheropolyhedron> g = [] {
    std::mt19937_64 rng(12345);
    std::vector<Spheropolyhedron> out;
    for (int k = 0; k < 32; ++k) out.push_back(random_grain(rng));
    return out;
  }();
  return g;
}

void run_pairs(benchmark::State &state, const std::vector<Pair> &pairs)
{
  ContactWorkspace ws;
  size_t k = 0;
  long points = 0;
  for (auto _ : state) {
    const Pair &p = pairs[k];
    const ContactSet set = contact_grains(*p.a, p.pa, *p.b, p.pb, kActivation, ws);
    benchmark::DoNotOptimize(set);
    points += set.count;
    k = (k + 1) % pairs.size();
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["points_per_pair"] = static_cast<double>(points) / state.iterations();
}

void BM_GrainsTouching(benchmark::State &state)
{
  static const auto pairs = make_pairs(grains(), -0.01, 0.01, 1);
  run_pairs(state, pairs);
}
void BM_GrainsNearTouching(benchmark::State &state)
{
  static const auto pairs = make_pairs(grains(), 0.01, 0.05, 2);
  run_pairs(state, pairs);
}
void BM_GrainsCoreOverlap(benchmark::State &state)
{
  // Gap below -(r_i + r_j) = -0.06: the cores intersect.
  static const auto pairs = make_pairs(grains(), -0.10, -0.07, 3);
  run_pairs(state, pairs);
}
void BM_GrainsSeparated(benchmark::State &state)
{
  static const std::vector<Pair> pairs = [] {
    std::vector<Pair> out;
    std::mt19937_64 rng(4);
    for (int k = 0; k < kPairs; ++k) {
      Pair p{&grains()[k % 32], &grains()[(k * 7) % 32], {}, {}};
      p.pb.position = Vec3(2.5, 0.1 * k / kPairs, 0);
      p.pb.orientation = random_rotation(rng);
      out.push_back(p);
    }
    return out;
  }();
  run_pairs(state, pairs);
}

void BM_SpheresTouching(benchmark::State &state)
{
  static const Spheropolyhedron ball = make_spheropolyhedron({Vec3::Zero()}, 0.5);
  std::vector<Pair> pairs;
  for (int k = 0; k < kPairs; ++k) {
    Pair p{&ball, &ball, {}, {}};
    p.pb.position = Vec3(1.0 + 0.0001 * k, 0.0, 0.0);
    pairs.push_back(p);
  }
  run_pairs(state, pairs);
}

void BM_BoxOnBox(benchmark::State &state)
{
  std::vector<Vec3> corners;
  for (int s = 0; s < 8; ++s) corners.emplace_back(s & 1 ? 0.5 : -0.5, s & 2 ? 0.5 : -0.5, s & 4 ? 0.5 : -0.5);
  static const Spheropolyhedron box = make_spheropolyhedron(corners, 0.02);
  std::vector<Pair> pairs;
  for (int k = 0; k < kPairs; ++k) {
    Pair p{&box, &box, {}, {}};
    p.pb.position = Vec3(0.3 * k / kPairs, 0.1, 1.04 - 0.001);
    pairs.push_back(p);
  }
  run_pairs(state, pairs);
}

void BM_GrainOnPlane(benchmark::State &state)
{
  ContactWorkspace ws;
  const PlaneWall floor{Vec3::Zero(), Vec3::UnitZ()};
  std::mt19937_64 rng(5);
  std::vector<Pose> poses;
  for (int k = 0; k < kPairs; ++k) {
    Pose p;
    p.orientation = random_rotation(rng);
    p.position = Vec3(0, 0, 0.5);
    poses.push_back(p);
  }
  size_t k = 0;
  for (auto _ : state) {
    const ContactSet set = contact_grain_plane(grains()[k % 32], poses[k], floor, kActivation, ws);
    benchmark::DoNotOptimize(set);
    k = (k + 1) % poses.size();
  }
  state.SetItemsProcessed(state.iterations());
}

// A grain resting on a plane, the case of a settled pile: one of its faces turned down,
// tilted by up to 0.03 rad, its lowest vertex 0.005 into the wall; activation 0.1, so
// several vertices (often more than ContactSet::kMaxPoints) are in the activation band.
void BM_GrainRestingOnPlane(benchmark::State &state)
{
  ContactWorkspace ws;
  const PlaneWall floor{Vec3::Zero(), Vec3::UnitZ()};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Pose> poses;
  for (int k = 0; k < kPairs; ++k) {
    const Spheropolyhedron &g = grains()[k % 32];
    const Vec3 &down = g.faces[static_cast<size_t>(unit(rng) * g.faces.size()) % g.faces.size()].normal;
    const Vec3 axis = Vec3(unit(rng) - 0.5, unit(rng) - 0.5, 0.0).normalized();
    Pose p;
    p.orientation = Quat(Eigen::AngleAxisd(0.03 * unit(rng), axis)) * Quat::FromTwoVectors(down, -Vec3::UnitZ());
    double lowest = 1e300;
    for (const Vec3 &v : g.vertices) lowest = std::min(lowest, (p.orientation * v).z());
    p.position = Vec3(0, 0, -lowest + g.radius - 0.005);
    poses.push_back(p);
  }
  size_t k = 0;
  long points = 0;
  for (auto _ : state) {
    const ContactSet set = contact_grain_plane(grains()[k % 32], poses[k], floor, 0.1, ws);
    benchmark::DoNotOptimize(set);
    points += set.count;
    k = (k + 1) % poses.size();
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["points_per_pair"] = static_cast<double>(points) / state.iterations();
}

void BM_SegmentGrain(benchmark::State &state)
{
  ContactWorkspace ws;
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Segment> segments;
  for (int k = 0; k < kPairs; ++k) {
    const Vec3 mid = 0.65 * Vec3(unit(rng), unit(rng), unit(rng)).normalized();
    const Vec3 dir = Vec3(unit(rng), unit(rng), unit(rng)).normalized();
    segments.push_back({mid - 0.1 * dir, mid + 0.1 * dir, 0.01});
  }
  size_t k = 0;
  Pose pose;
  for (auto _ : state) {
    const auto c = contact_segment_grain(segments[k], grains()[k % 32], pose, kActivation, ws);
    benchmark::DoNotOptimize(c);
    k = (k + 1) % segments.size();
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_GrainsTouching);
BENCHMARK(BM_GrainsNearTouching);
BENCHMARK(BM_GrainsCoreOverlap);
BENCHMARK(BM_GrainsSeparated);
BENCHMARK(BM_SpheresTouching);
BENCHMARK(BM_BoxOnBox);
BENCHMARK(BM_GrainOnPlane);
BENCHMARK(BM_GrainRestingOnPlane);
BENCHMARK(BM_SegmentGrain);

}    // namespace

BENCHMARK_MAIN();
