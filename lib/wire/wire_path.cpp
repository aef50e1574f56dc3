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

#include "wire/wire_path.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <sstream>

namespace nscd::wire {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr int kMaxNodes = 100000000;    // far beyond any deck; stops a runaway walk

using Curve = std::function<Vec3(double)>;

std::string text(double x)
{
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}

// The parameter t in (from, to] where |at(t) - origin| first reaches `chord`, or a value
// above 1 if it never does before t = 1. The distance changes by at most the path length
// covered, so steps of `step` (a 64th of a chord's worth of path) cannot jump over the
// first crossing.
double next_node(const Curve &at, const Vec3 &origin, double from, double chord, double step)
{
  double lo = from, hi = from;
  for (;;) {
    if (hi >= 1.0) return 2.0;
    lo = hi;
    hi = std::min(1.0, hi + step);
    // (a path exactly k chords long ends on a node despite round-off in the sum)
    if ((at(hi) - origin).norm() >= chord * (1.0 - 1e-12)) break;
  }
  for (int iteration = 0; iteration < 200 && hi - lo > 1e-16 * std::max(1.0, hi); iteration++) {
    const double mid = 0.5 * (lo + hi);
    if ((at(mid) - origin).norm() < chord) lo = mid;
    else hi = mid;
  }
  return hi;
}

// Node parameters at equal chords from t = 0; stops after `max_nodes` nodes.
std::vector<double> walk(const Curve &at, double length, double chord, int max_nodes = kMaxNodes)
{
  const double step = std::max(chord / length / 64.0, 1e-9);
  std::vector<double> ts = {0.0};
  Vec3 here = at(0.0);
  while ((int) ts.size() < max_nodes) {
    const double t = next_node(at, here, ts.back(), chord, step);
    if (t > 1.0) break;
    ts.push_back(t);
    here = at(t);
  }
  return ts;
}

WireLayout layout_from(const Curve &at, const std::vector<double> &ts, double chord, bool closed)
{
  // a path that turns back within one element (found by fuzzing: tests/fuzz/regressions/polyline)
  if (ts.size() < 2)
    throw WirePathError("element length " + text(chord) + " is longer than the straight distance from the path's "
                        "start to any of its points: no second node fits; use shorter elements");
  WireLayout layout;
  for (double t : ts) layout.nodes.push_back(at(t));
  layout.closed = closed;
  layout.chord = chord;
  const int n = (int) layout.nodes.size();
  layout.topology = closed ? closed_ring_topology(n, chord) : open_chain_topology(n, chord);
  return layout;
}

// Open path cut at equal chords into exactly `nodes` nodes, the last on the path's end: the
// longest chord whose walk still places all nodes (a longer chord walks further), found by
// bisection; the last node then moves onto the end, by less than 1e-15 of a chord.
WireLayout open_nodes(const Curve &at, double length, int nodes)
{
  if (nodes < 2) throw WirePathError("nodes " + std::to_string(nodes) + ": a wire needs at least 2 nodes");
  auto fits = [&](double chord) { return (int) walk(at, length, chord, nodes).size() == nodes; };
  double lo = 0.0, hi = length / (nodes - 1);    // a chord is never longer than its arc
  if (fits(hi)) lo = hi;                         // a straight path
  while (hi - lo > 1e-15 * hi) {
    const double mid = 0.5 * (lo + hi);
    if (fits(mid)) lo = mid;
    else hi = mid;
  }
  std::vector<double> ts = walk(at, length, lo, nodes);
  ts.back() = 1.0;
  return layout_from(at, ts, lo, false);
}

void check_loop(const LoopPath &p)
{
  if (!(p.radius > 0.0) || !std::isfinite(p.radius))
    throw WirePathError("loop radius " + text(p.radius) + " must be positive and finite");
  if (!(p.axis.norm() > 0.0) || !p.axis.allFinite())
    throw WirePathError("the loop axis (0 0 0) has no direction");
  if (!p.centre.allFinite()) throw WirePathError("the loop centre is not finite");
  if (!(p.turns > 0.0) || !std::isfinite(p.turns))
    throw WirePathError("turns " + text(p.turns) + " must be positive");
  if (!(p.gap >= 0.0) || !(p.gap < kTwoPi * p.turns))
    throw WirePathError("gap " + text(p.gap * 360.0 / kTwoPi) + " degrees must be >= 0 and below the " +
                        text(360.0 * p.turns) + " degrees the turns sweep");
  if (!std::isfinite(p.pitch) || !std::isfinite(p.start))
    throw WirePathError("pitch and start must be finite");
  if (p.turns * kTwoPi - p.gap > kTwoPi * (1.0 + 1e-12) && p.pitch == 0.0)
    throw WirePathError("a flat loop of " + text(p.turns) + " turns lies on itself; give a pitch "
                        "(rise per turn) of at least the wire's diameter");
}

bool is_closed(const LoopPath &p)
{
  return p.pitch == 0.0 && p.gap == 0.0 && std::abs(p.turns - 1.0) < 1e-12;
}

double loop_length(const LoopPath &p)
{
  const double sweep = kTwoPi * p.turns - p.gap;
  const double rise = p.pitch * sweep / kTwoPi;
  return std::hypot(p.radius * sweep, rise);
}

Curve loop_curve(const LoopPath &p)
{
  return [p](double t) { return loop_point(p, t); };
}

double polyline_length(const PolylinePath &path)
{
  if (path.points.size() < 2) throw WirePathError("a polyline needs at least 2 points");
  double length = 0.0;
  for (size_t k = 0; k + 1 < path.points.size(); k++) {
    if (!path.points[k].allFinite() || !path.points[k + 1].allFinite())
      throw WirePathError("polyline point " + std::to_string(k + 1) + " is not finite");
    const double piece = (path.points[k + 1] - path.points[k]).norm();
    if (!(piece > 0.0))
      throw WirePathError("polyline points " + std::to_string(k + 1) + " and " + std::to_string(k + 2) +
                          " coincide; remove one");
    length += piece;
  }
  return length;
}

// The polyline by arc length: t in [0, 1] of the total.
Curve polyline_curve(const PolylinePath &path)
{
  std::vector<double> at_point = {0.0};
  for (size_t k = 0; k + 1 < path.points.size(); k++)
    at_point.push_back(at_point.back() + (path.points[k + 1] - path.points[k]).norm());
  const double total = at_point.back();
  for (double &s : at_point) s /= total;
  return [points = path.points, at_point](double t) {
    const size_t k = std::min<size_t>(std::upper_bound(at_point.begin(), at_point.end(), t) - at_point.begin(),
                                      at_point.size() - 1) - 1;
    const double piece = at_point[k + 1] - at_point[k];
    const double f = piece > 0.0 ? std::clamp((t - at_point[k]) / piece, 0.0, 1.0) : 0.0;
    return Vec3(points[k] + f * (points[k + 1] - points[k]));
  };
}

// The path preceded by the straight segment from `from` to its start, by arc length where
// the path is (loops and polylines are), with the joined length in `length`.
Curve continued(const Vec3 &from, const Curve &path, double path_length, double chord, double &length)
{
  if (!from.allFinite()) throw WirePathError("the wire's end to continue from is not finite");
  const Vec3 start = path(0.0);
  const double bridge = (start - from).norm();
  length = path_length;
  if (bridge <= 1e-9 * chord) return [from, path](double t) { return t <= 0.0 ? from : path(t); };
  length = bridge + path_length;
  const double split = bridge / length;
  return [from, start, path, split](double t) {
    if (t < split) return Vec3(from + (t / split) * (start - from));
    return path((t - split) / (1.0 - split));
  };
}

WireLayout lay_continued(const Vec3 &from, const Curve &path, double path_length, double chord)
{
  double length = 0.0;
  const Curve at = continued(from, path, path_length, chord, length);
  if (chord > length)
    throw WirePathError("element length " + text(chord) + " is longer than the path from the wire's end (" +
                        text(length) + ")");
  return layout_from(at, walk(at, length, chord), chord, false);
}

void check_chord(double chord)
{
  if (!(chord > 0.0) || !std::isfinite(chord))
    throw WirePathError("element length " + text(chord) + " must be positive and finite");
}

// A decimal number as decks write them: [+-] digits [. digits] [e [+-] digits], at least one
// digit before the exponent (no nan, inf, hexadecimal).
bool is_decimal(const std::string &word)
{
  size_t k = 0, digits = 0;
  auto run_of_digits = [&]() {
    size_t n = 0;
    while (k < word.size() && std::isdigit((unsigned char) word[k])) k++, n++;
    return n;
  };
  if (k < word.size() && (word[k] == '+' || word[k] == '-')) k++;
  digits += run_of_digits();
  if (k < word.size() && word[k] == '.') {
    k++;
    digits += run_of_digits();
  }
  if (digits == 0) return false;
  if (k < word.size() && (word[k] == 'e' || word[k] == 'E')) {
    k++;
    if (k < word.size() && (word[k] == '+' || word[k] == '-')) k++;
    if (run_of_digits() == 0) return false;
  }
  return k == word.size();
}

// The line as quoted in a message: at most 80 characters, control bytes as '?'.
std::string quoted_line(const std::string &line)
{
  std::string shown = line.substr(0, 80);
  for (char &c : shown)
    if ((unsigned char) c < 32 || c == 127) c = '?';
  return "'" + shown + (line.size() > 80 ? "...'" : "'");
}

}    // namespace

PolylinePath read_polyline(const std::string &text, const std::string &source_name)
{
  PolylinePath path;
  std::istringstream lines(text);
  std::string line;
  for (long number = 1; std::getline(lines, line); number++) {
    const std::string place = source_name + ":" + std::to_string(number) + ": ";
    std::istringstream words(line.substr(0, line.find('#')));
    std::vector<std::string> values;
    for (std::string word; words >> word;) values.push_back(word);
    if (values.empty()) continue;    // blank or comment
    if (values.size() != 3)
      throw WirePathError(place + "expected three numbers 'x y z', got " + std::to_string(values.size()) +
                          " word(s): " + quoted_line(line));
    Vec3 point;
    for (int d = 0; d < 3; d++) {
      const std::string &word = values[d];
      if (!is_decimal(word))
        throw WirePathError(place + "'" + word.substr(0, 40) + "' is not a number such as 1.5 or -2e-3: " +
                            quoted_line(line));
      point[d] = std::strtod(word.c_str(), nullptr);
      if (!std::isfinite(point[d]))
        throw WirePathError(place + word.substr(0, 40) + " is beyond the range of doubles (1.8e308): " +
                            quoted_line(line));
    }
    path.points.push_back(point);
  }
  return path;
}

void loop_frame(const Vec3 &axis, Vec3 &e1, Vec3 &e2)
{
  const Vec3 a = axis.normalized();
  // the world axis least aligned with `axis` (x first on ties: z axis -> e1 = x)
  int least = 0;
  for (int d = 1; d < 3; d++)
    if (std::abs(a[d]) < std::abs(a[least]) - 1e-15) least = d;
  const Vec3 seed = Vec3::Unit(least);
  e1 = (seed - seed.dot(a) * a).normalized();
  e2 = a.cross(e1);
}

Vec3 loop_point(const LoopPath &p, double t)
{
  Vec3 e1, e2;
  loop_frame(p.axis, e1, e2);
  const double sweep = kTwoPi * p.turns - p.gap;
  const double angle = p.start + sweep * t;
  return p.centre + p.radius * (std::cos(angle) * e1 + std::sin(angle) * e2) +
      p.axis.normalized() * (p.pitch * sweep * t / kTwoPi);
}

WireTopology closed_ring_topology(int num_nodes, double rest_length)
{
  WireTopology topology;
  for (int k = 0; k < num_nodes; k++) {
    topology.elements.push_back({k, (k + 1) % num_nodes, rest_length});
    topology.joints.push_back({(k + num_nodes - 1) % num_nodes, k, (k + 1) % num_nodes});
  }
  return topology;
}

WireLayout lay_loop(const LoopPath &path, double chord)
{
  check_loop(path);
  check_chord(chord);
  if (!(chord < 2.0 * path.radius))
    throw WirePathError("element length " + text(chord) + " does not fit a loop of radius " +
                        text(path.radius) + " (it must be below the diameter)");
  const Curve at = loop_curve(path);
  const double length = loop_length(path);
  if (is_closed(path)) {
    const int n = std::max(3, (int) std::lround(length / chord));
    return lay_loop_nodes(path, n);
  }
  if (chord > length) throw WirePathError("element length " + text(chord) + " is longer than the path (" + text(length) + ")");
  return layout_from(at, walk(at, length, chord), chord, false);
}

WireLayout lay_loop_nodes(const LoopPath &path, int nodes)
{
  check_loop(path);
  const Curve at = loop_curve(path);
  if (is_closed(path)) {
    if (nodes < 3) throw WirePathError("a closed loop needs at least 3 nodes, not " + std::to_string(nodes));
    std::vector<double> ts(nodes);
    for (int k = 0; k < nodes; k++) ts[k] = (double) k / nodes;
    return layout_from(at, ts, (at(ts[1]) - at(0.0)).norm(), true);
  }
  return open_nodes(at, loop_length(path), nodes);
}

WireLayout lay_polyline(const PolylinePath &path, double chord)
{
  const double length = polyline_length(path);
  check_chord(chord);
  if (chord > length) throw WirePathError("element length " + text(chord) + " is longer than the path (" + text(length) + ")");
  const Curve at = polyline_curve(path);
  return layout_from(at, walk(at, length, chord), chord, false);
}

WireLayout lay_polyline_nodes(const PolylinePath &path, int nodes)
{
  const double length = polyline_length(path);
  return open_nodes(polyline_curve(path), length, nodes);
}

WireLayout lay_loop_from(const Vec3 &from, const LoopPath &path, double chord)
{
  check_loop(path);
  check_chord(chord);
  if (is_closed(path))
    throw WirePathError("a closed ring (one flat turn without a gap) cannot continue a wire: leave a gap or give a "
                        "pitch");
  if (!(chord < 2.0 * path.radius))
    throw WirePathError("element length " + text(chord) + " does not fit a loop of radius " +
                        text(path.radius) + " (it must be below the diameter)");
  return lay_continued(from, loop_curve(path), loop_length(path), chord);
}

WireLayout lay_polyline_from(const Vec3 &from, const PolylinePath &path, double chord)
{
  const double length = polyline_length(path);
  check_chord(chord);
  return lay_continued(from, polyline_curve(path), length, chord);
}

}    // namespace nscd::wire
