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

#include "shape/body_export.h"

#include <cmath>
#include <ostream>
#include <string>

namespace nscd {

namespace {

// BODY accepts triangles and quads only; a larger (convex, planar) face becomes a fan of
// triangles around its first vertex, which keeps the outward orientation.
void add_body_faces(const Face &face, std::vector<std::array<int, 4>> &faces)
{
  const std::vector<int> &v = face.vertices;
  if (v.size() == 3 || v.size() == 4) {
    faces.push_back({v[0], v[1], v[2], v.size() == 4 ? v[3] : -1});
    return;
  }
  for (size_t k = 1; k + 1 < v.size(); ++k) faces.push_back({v[0], v[k], v[k + 1], -1});
}

}    // namespace

int BodyEntry::value_count() const
{
  return 6 + 3 * static_cast<int>(vertices.size()) + 2 * static_cast<int>(edges.size()) +
         4 * static_cast<int>(faces.size()) + 1;
}

BodyEntry body_entry(const Spheropolyhedron &shape, const Quat &orientation, double mass)
{
  if (!std::isfinite(mass) || mass <= 0)
    throw ShapeError("BODY export: mass " + std::to_string(mass) + " is not a finite positive number; give the grain's mass");
  BodyEntry entry;
  const Mat3 rotation = orientation.normalized().toRotationMatrix();
  for (const Vec3 &v : shape.vertices) entry.vertices.push_back(rotation * v);
  if (shape.is_polyhedron()) {
    entry.edges = shape.edges;
    for (const Face &face : shape.faces) add_body_faces(face, entry.faces);
  }
  const Vec3 principal = shape.principal_inertia * (mass / shape.volume);
  entry.inertia = rotation * principal.asDiagonal() * rotation.transpose();
  entry.diameter = 2.0 * shape.radius;
  return entry;
}

void write_body_entry(std::ostream &out, long long atom_id, const BodyEntry &entry)
{
  // LAMMPS' read_data takes at most 32 lines per body (MAXBODY) of at most 255 characters
  // (MAXLINE 256): 3 vertices (9 numbers of <= 24 characters), 10 edges or 8 faces per line
  // keep a grain of up to 60 vertices within both limits.
  const auto precision = out.precision(17);
  const Mat3 &I = entry.inertia;
  out << atom_id << " 3 " << entry.value_count() << '\n'
      << entry.vertices.size() << ' ' << entry.edges.size() << ' ' << entry.faces.size() << '\n'
      << I(0, 0) << ' ' << I(1, 1) << ' ' << I(2, 2) << ' ' << I(0, 1) << ' ' << I(0, 2) << ' ' << I(1, 2) << '\n';
  auto end_of_item = [&out](size_t k, size_t count, size_t per_line) {
    out << ((k + 1) % per_line == 0 || k + 1 == count ? '\n' : ' ');
  };
  for (size_t k = 0; k < entry.vertices.size(); ++k) {
    const Vec3 &v = entry.vertices[k];
    out << v.x() << ' ' << v.y() << ' ' << v.z();
    end_of_item(k, entry.vertices.size(), 3);
  }
  for (size_t k = 0; k < entry.edges.size(); ++k) {
    out << entry.edges[k][0] << ' ' << entry.edges[k][1];
    end_of_item(k, entry.edges.size(), 10);
  }
  for (size_t k = 0; k < entry.faces.size(); ++k) {
    const auto &f = entry.faces[k];
    out << f[0] << ' ' << f[1] << ' ' << f[2] << ' ' << f[3];
    end_of_item(k, entry.faces.size(), 8);
  }
  out << entry.diameter << '\n';
  out.precision(precision);
}

}    // namespace nscd
