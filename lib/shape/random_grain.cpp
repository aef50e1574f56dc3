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

#include "shape/random_grain.h"

#include "shape/mass_properties.h"

#include <cmath>
#include <random>
#include <sstream>

namespace nscd {
namespace {

constexpr double kPi = 3.14159265358979323846;
// A draw whose inertia-equivalent ellipsoid is thinner than this fraction of the smallest
// semi-axis it was drawn on is a sliver (likely with few points) and is drawn again.
constexpr double kMinThicknessFraction = 0.25;
constexpr int kMaxDraws = 1000;
// Diameters allowed: grains then stay inside the shape size limits (1e-30 .. 1e30).
constexpr double kMinDiameter = 1e-29;
constexpr double kMaxDiameter = 1e29;

// Mixes (seed, index) into a well-spread engine seed (SplitMix64 finaliser).
std::uint64_t mix(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Uniform in [0, 1) from the top 53 bits of the raw output: the same on every platform,
// unlike std::uniform_real_distribution.
double uniform01(std::mt19937_64 &rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

double uniform(std::mt19937_64 &rng, double lo, double hi) { return lo + (hi - lo) * uniform01(rng); }

int uniform_int(std::mt19937_64 &rng, int lo, int hi)
{
  const int value = lo + static_cast<int>(uniform01(rng) * (hi - lo + 1.0));
  return std::min(value, hi);
}

// Uniform direction by rejection from the cube (square root only, no trigonometry).
Vec3 random_direction(std::mt19937_64 &rng)
{
  for (;;) {
    const Vec3 p(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    const double norm2 = p.squaredNorm();
    if (norm2 > 1e-4 && norm2 <= 1.0) return p / std::sqrt(norm2);
  }
}

void check(bool ok, const std::string &problem)
{
  if (!ok) throw ShapeError("random grains: " + problem);
}

std::string str(double v)
{
  std::ostringstream out;
  out.precision(10);
  out << v;
  return out.str();
}

// Semi-axes of the solid ellipsoid with the same volume-normalised principal moments.
double thinnest_equivalent_semi_axis(const Spheropolyhedron &s)
{
  const Vec3 &I = s.principal_inertia;
  const double sum = I.sum();
  double thinnest = HUGE_VAL;
  for (int k = 0; k < 3; ++k) thinnest = std::min(thinnest, 2.5 * (sum - 2 * I[k]) / s.volume);
  return std::sqrt(std::max(thinnest, 0.0));
}

// Sharp core on an ellipsoid with semi-axes (1, b, c); slivers are drawn again.
Spheropolyhedron random_core(std::mt19937_64 &rng, int count, double b, double c)
{
  for (int draw = 0; draw < kMaxDraws; ++draw) {
    std::vector<Vec3> points(count);
    for (auto &p : points) p = random_direction(rng).cwiseProduct(Vec3(1.0, b, c));
    try {
      Spheropolyhedron core = make_spheropolyhedron(points, 0.0);
      if (thinnest_equivalent_semi_axis(core) >= kMinThicknessFraction * std::min(b, c)) return core;
    } catch (const ShapeError &) {
      // A flat draw (coplanar points): draw again.
    }
  }
  throw ShapeError("random grains: no non-degenerate grain in " + std::to_string(kMaxDraws) +
                   " draws; use more vertices or less extreme axis ratios");
}

// Scale s at which the core dilated by r has volume `target`: the root of the Steiner
// polynomial V s^3 + A r s^2 + M r^2 s + 4/3 pi r^3 = target (increasing and convex in s,
// so Newton from the r = 0 root, which lies above it, converges monotonically).
double scale_for_volume(const Spheropolyhedron &core, double r, double target)
{
  double area = 0.0;
  for (const auto &f : core.faces) area += polygon_area(core.vertices, f);
  const double curvature = mean_curvature_integral(core.vertices, core.faces, core.edges, core.edge_faces);
  const double ball = 4.0 / 3.0 * kPi * r * r * r;
  double s = std::cbrt(target / core.volume);
  for (int iter = 0; iter < 100; ++iter) {
    const double f = ((core.volume * s + area * r) * s + curvature * r * r) * s + ball - target;
    const double slope = (3 * core.volume * s + 2 * area * r) * s + curvature * r * r;
    const double step = f / slope;
    s -= step;
    if (std::abs(step) <= 1e-15 * s) break;
  }
  return s;
}

std::string random_grain_name(std::uint64_t seed, int k)
{
  return "grain_" + std::to_string(seed) + "_" + std::to_string(k);
}

}    // namespace

void validate(const RandomGrainParams &p)
{
  check(p.min_vertices >= 4, "min vertices " + std::to_string(p.min_vertices) + " is below 4; a solid needs at least 4");
  check(p.max_vertices >= p.min_vertices, "max vertices " + std::to_string(p.max_vertices) + " is below min vertices " +
                                              std::to_string(p.min_vertices) + "; give NMIN <= NMAX");
  check(p.max_vertices <= 10000, "max vertices " + std::to_string(p.max_vertices) + " is above 10000; use fewer");
  check(std::isfinite(p.min_diameter) && p.min_diameter > 0,
        "min diameter " + str(p.min_diameter) + " is not a positive number; give DMIN > 0");
  check(p.min_diameter >= kMinDiameter, "min diameter " + str(p.min_diameter) + " is below the supported " +
                                            str(kMinDiameter) + "; use a smaller length unit");
  check(!(p.max_diameter < p.min_diameter),
        "max diameter " + str(p.max_diameter) + " is below min diameter " + str(p.min_diameter) + "; give DMIN <= DMAX");
  check(std::isfinite(p.max_diameter) && p.max_diameter <= kMaxDiameter,
        "max diameter " + str(p.max_diameter) + " is not a number up to the supported " + str(kMaxDiameter) +
            "; use a larger length unit");
  check(p.ratio_b > 0 && p.ratio_b <= 1, "axis ratio b/a " + str(p.ratio_b) + " is outside (0, 1]; give 0 < b/a <= 1");
  check(p.ratio_c > 0 && p.ratio_c <= 1, "axis ratio c/a " + str(p.ratio_c) + " is outside (0, 1]; give 0 < c/a <= 1");
  check(p.ratio_spread >= 0 && p.ratio_spread < 1,
        "axis ratio spread " + str(p.ratio_spread) + " is outside [0, 1); give 0 <= spread < 1");
  check(std::isfinite(p.radius) && p.radius >= 0, "rounding radius " + str(p.radius) + " is invalid; give r >= 0");
  check(p.radius < 0.5 * p.min_diameter, "rounding radius " + str(p.radius) +
                                             " leaves no room for a core in a grain of diameter " +
                                             str(p.min_diameter) + "; give r < DMIN / 2");
}

Spheropolyhedron random_grain(const RandomGrainParams &params, std::uint64_t seed, int index)
{
  validate(params);
  std::mt19937_64 rng(mix(seed ^ mix(static_cast<std::uint64_t>(index))));
  const int count = uniform_int(rng, params.min_vertices, params.max_vertices);
  const double diameter = uniform(rng, params.min_diameter, params.max_diameter);
  auto spread_ratio = [&](double ratio) {
    return std::min(1.0, ratio * uniform(rng, 1 - params.ratio_spread, 1 + params.ratio_spread));
  };
  const double b = spread_ratio(params.ratio_b);
  const double c = spread_ratio(params.ratio_c);
  const Spheropolyhedron core = random_core(rng, count, b, c);
  const double target = kPi / 6 * diameter * diameter * diameter;
  const double s = scale_for_volume(core, params.radius, target);
  std::vector<Vec3> scaled(core.vertices.size());
  for (size_t i = 0; i < scaled.size(); ++i) scaled[i] = s * core.vertices[i];
  return make_spheropolyhedron(scaled, params.radius);
}

int add_random_grains(ShapeLibrary &library, const RandomGrainParams &params, int count, std::uint64_t seed)
{
  validate(params);
  check(count >= 1, "count " + std::to_string(count) + " must be at least 1");
  const int room = ShapeLibrary::kMaxShapes - library.size();
  check(count <= room, "count " + std::to_string(count) + " is more than the library can take (" +
                           std::to_string(ShapeLibrary::kMaxShapes) + " shapes at most, " +
                           std::to_string(library.size()) + " loaded); make fewer grains and give each "
                           "shape to many of them");
  // Checked before the (slow) generation. Names repeat only with a seed used before.
  for (int k = 1; k <= count; ++k) {
    const int taken = library.find(random_grain_name(seed, k));
    check(taken == 0, "shape name '" + random_grain_name(seed, k) + "' is already used by shape id " +
                          std::to_string(taken) + " (seed " + std::to_string(seed) +
                          " was used before); give another seed");
  }
  ShapeLibrary grains;
  for (int k = 0; k < count; ++k) grains.add(random_grain(params, seed, k), random_grain_name(seed, k + 1));
  const int first = library.size() + 1;
  library.append(grains);
  return first;
}

}    // namespace nscd
