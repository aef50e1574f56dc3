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

// Cost of building shapes (hull + exact mass properties + body frame), with the error of
// the result beside it: the relative difference between the decomposition's volume and
// the Steiner formula V + A r + M r^2 + 4/3 pi r^3 computed from the same core.
#include "shape/mass_properties.h"
#include "shape/random_grain.h"
#include "shape/shape_library.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

using namespace nscd;

namespace {

std::vector<Vec3> ellipsoid_points(int count, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53 * 2 - 1; };
  std::vector<Vec3> points;
  while (static_cast<int>(points.size()) < count) {
    const Vec3 p(uniform(), uniform(), uniform());
    if (p.squaredNorm() > 1e-4 && p.squaredNorm() <= 1) points.push_back(p.normalized().cwiseProduct(Vec3(1, 0.8, 0.6)));
  }
  return points;
}

double steiner_relative_error(const Spheropolyhedron &s)
{
  double area = 0;
  for (const auto &f : s.faces) area += polygon_area(s.vertices, f);
  const double r = s.radius;
  const double core = polyhedron_moments(s.vertices, s.faces).volume;
  const double steiner = core + area * r + mean_curvature_integral(s.vertices, s.faces, s.edges, s.edge_faces) * r * r +
                         4.0 / 3.0 * 3.14159265358979323846 * r * r * r;
  return std::abs(s.volume - steiner) / steiner;
}

void BM_MakeSpheropolyhedron(benchmark::State &state)
{
  const auto points = ellipsoid_points(static_cast<int>(state.range(0)), 7);
  const double radius = state.range(1) / 100.0;
  Spheropolyhedron shape;
  for (auto _ : state) {
    shape = make_spheropolyhedron(points, radius);
    benchmark::DoNotOptimize(shape.vertices.data());    // (a double through DoNotOptimize gets garbled by GCC 12)
  }
  state.counters["vertices"] = static_cast<double>(shape.vertices.size());
  state.counters["volume_rel_err"] = steiner_relative_error(shape);
}
BENCHMARK(BM_MakeSpheropolyhedron)
    ->Args({8, 0})
    ->Args({24, 0})
    ->Args({24, 2})
    ->Args({100, 2})
    ->Args({1000, 2})
    ->Unit(benchmark::kMicrosecond);

void BM_LibrarySerializeRoundTrip(benchmark::State &state)
{
  ShapeLibrary library;
  RandomGrainParams params;
  params.radius = 0.02;
  add_random_grains(library, params, static_cast<int>(state.range(0)), 1);
  for (auto _ : state) {
    const auto again = ShapeLibrary::deserialize(library.serialize());
    benchmark::DoNotOptimize(again.max_bounding_radius() > 0);
  }
  state.counters["shapes"] = static_cast<double>(library.size());
}
BENCHMARK(BM_LibrarySerializeRoundTrip)->Arg(100)->Unit(benchmark::kMillisecond);

}    // namespace

BENCHMARK_MAIN();
