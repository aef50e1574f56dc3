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

// Grain against a plane wall and against the inside of a cylindrical wall.
//
// Both distances are exact on the core's vertices: the height above a plane is linear and
// the distance from an axis is convex, so over a convex core both reach their extreme at
// a vertex. Every vertex closer than the activation distance is a contact point (a box
// face on a plane gives its 4 corners; they are distinct supports, and the solver copes
// with a force distribution that is not unique); only beyond ContactSet::kMaxPoints are
// they reduced, depth first (write_contact_set), so no penetrating vertex is dropped.
#include "geometry/contact.h"

#include "geometry/core_contact.h"
#include "geometry/feature_key.h"
#include "geometry/segment_closest.h"

#include <cmath>
#include <sstream>

namespace nscd {
namespace {

using namespace geometry_detail;

// The unit vector along v, or an error naming the wall's bad direction.
Vec3 unit_direction(const Vec3 &v, const char *what)
{
  const double n = v.norm();
  if (!std::isfinite(n) || n == 0.0) {
    std::ostringstream out;
    out << what << " (" << v.transpose() << ") is not a usable direction; give a finite, non-zero vector";
    throw ContactError(out.str());
  }
  return v / n;
}

void check_point(const Vec3 &p, const char *what)
{
  if (!p.allFinite()) {
    std::ostringstream out;
    out << what << " (" << p.transpose() << ") is not finite; give finite coordinates";
    throw ContactError(out.str());
  }
}

// Core vertices of the grain relative to its centre (the frame origin of the query).
void place_vertices(const Spheropolyhedron &shape, const Pose &pose, std::vector<Vec3> &vertices)
{
  const Mat3 rotation = pose.orientation.toRotationMatrix();
  vertices.resize(shape.vertices.size());
  for (size_t k = 0; k < shape.vertices.size(); ++k) vertices[k] = rotation * shape.vertices[k];
}

// A point at height `height` above a plane (offset `v` from the query's origin), dilated
// by `radius`: its gap and the contact position, midway between its surface and the plane.
struct Touch {
  Vec3 position;
  double gap;
};
Touch touch_plane(const Vec3 &v, double height, double radius, const Vec3 &normal)
{
  return {v - 0.5 * (height + radius) * normal, height - radius};
}

// A point at distance rho from a cylinder's axis (offset `v` from the query's origin, unit
// `outward` direction from the axis), dilated by `radius`, inside a cylinder of radius R.
Touch touch_cylinder(const Vec3 &v, double rho, const Vec3 &outward, double radius, double R)
{
  return {v + 0.5 * (R - rho + radius) * outward, R - rho - radius};
}

// The unit direction from the axis to a point at radial offset `radial` (length rho). A
// point on the axis itself is equally far from the whole wall: any radial direction will
// do; take a fixed one so the answer is deterministic.
Vec3 outward_from_axis(const Vec3 &radial, double rho, const Vec3 &axis)
{
  return rho > 0.0 ? Vec3(radial / rho) : any_perpendicular(axis);
}

Vec3 checked_cylinder_axis(const CylinderWall &wall)
{
  check_point(wall.axis_point, "cylinder wall axis point");
  const Vec3 axis = unit_direction(wall.axis_direction, "cylinder wall axis direction");
  if (!std::isfinite(wall.radius) || wall.radius <= 0.0) {
    std::ostringstream out;
    out << "cylinder wall radius " << wall.radius << " is invalid; give a finite radius > 0";
    throw ContactError(out.str());
  }
  return axis;
}

}    // namespace

ContactSet contact_grain_plane(const Spheropolyhedron &shape, const Pose &pose,
                               const PlaneWall &wall, double activation, ContactWorkspace &ws)
{
  check_activation(activation);
  check_point(wall.point, "plane wall point");
  const Vec3 normal = unit_direction(wall.normal, "plane wall normal");
  ContactSet out;
  const double centre_height = normal.dot(pose.position - wall.point);
  if (centre_height - shape.bounding_radius > activation) return out;

  place_vertices(shape, pose, ws.vertices_i);
  ws.candidates.clear();
  for (size_t k = 0; k < ws.vertices_i.size(); ++k) {
    const Vec3 &v = ws.vertices_i[k];
    const Touch t = touch_plane(v, centre_height + normal.dot(v), shape.radius, normal);
    if (!(t.gap <= activation)) continue;
    ws.candidates.push_back({t.position, v, t.gap, make_key(vertex_feature(static_cast<int>(k)), wall_feature()), normal});
  }
  write_contact_set(ws, normal, pose.position, shape.bounding_radius, out);
  return out;
}

ContactSet contact_grain_cylinder(const Spheropolyhedron &shape, const Pose &pose,
                                  const CylinderWall &wall, double activation,
                                  ContactWorkspace &ws)
{
  check_activation(activation);
  const Vec3 axis = checked_cylinder_axis(wall);
  ContactSet out;
  const Vec3 centre_offset = pose.position - wall.axis_point;
  const Vec3 centre_radial = centre_offset - axis.dot(centre_offset) * axis;
  if (wall.radius - centre_radial.norm() - shape.bounding_radius > activation) return out;

  place_vertices(shape, pose, ws.vertices_i);
  ws.candidates.clear();
  Vec3 deepest_outward = Vec3::Zero();
  double deepest_gap = 0.0;
  for (size_t k = 0; k < ws.vertices_i.size(); ++k) {
    const Vec3 &v = ws.vertices_i[k];
    const Vec3 radial = centre_radial + v - axis.dot(v) * axis;    // from the axis to the vertex
    const double rho = radial.norm();
    const Vec3 outward = outward_from_axis(radial, rho, axis);
    const Touch t = touch_cylinder(v, rho, outward, shape.radius, wall.radius);
    if (!(t.gap <= activation)) continue;
    ws.candidates.push_back({t.position, v, t.gap, make_key(vertex_feature(static_cast<int>(k)), wall_feature()), -outward});
    if (ws.candidates.size() == 1 || t.gap < deepest_gap) {
      deepest_gap = t.gap;
      deepest_outward = outward;
    }
  }
  // Reduce (if needed) in the plane tangent at the deepest point, then give each point its own
  // normal (the wall is curved): from the wall towards the axis.
  write_contact_set(ws, -deepest_outward, pose.position, shape.bounding_radius, out);
  for (int k = 0; k < out.count; ++k) {
    const Vec3 offset = out.points[k].point - wall.axis_point;
    const Vec3 radial = offset - axis.dot(offset) * axis;
    out.points[k].normal = -outward_from_axis(radial, radial.norm(), axis);
  }
  return out;
}

ContactPoint contact_sphere_plane(const Vec3 &centre, double radius, const PlaneWall &wall)
{
  check_point(wall.point, "plane wall point");
  const Vec3 normal = unit_direction(wall.normal, "plane wall normal");
  const Touch t = touch_plane(Vec3::Zero(), normal.dot(centre - wall.point), radius, normal);
  return {centre + t.position, normal, t.gap, make_key(vertex_feature(0), wall_feature())};
}

ContactPoint contact_sphere_cylinder(const Vec3 &centre, double radius, const CylinderWall &wall)
{
  const Vec3 axis = checked_cylinder_axis(wall);
  const Vec3 offset = centre - wall.axis_point;
  const Vec3 radial = offset - axis.dot(offset) * axis;
  const double rho = radial.norm();
  const Vec3 outward = outward_from_axis(radial, rho, axis);
  const Touch t = touch_cylinder(Vec3::Zero(), rho, outward, radius, wall.radius);
  return {centre + t.position, -outward, t.gap, make_key(vertex_feature(0), wall_feature())};
}

}    // namespace nscd
