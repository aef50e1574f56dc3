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

/* dump grains/vtk: gathers (id, type, shape, position, orientation, velocity) per grain and
   writes the grains' surfaces in world coordinates as VTK polydata. */

#include "dump_grains_vtk.h"

#include "atom.h"
#include "atom_vec_spheropolyhedron.h"
#include "comm.h"
#include "error.h"
#include "update.h"

#include "math/capacity_bytes.h"
#include "shape/shape_library.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

namespace {
enum Column { ID, TYPE, SHAPE, X, Y, Z, QW, QX, QY, QZ, VX, VY, VZ, NCOLUMNS };

// Directions on the unit sphere (icosahedron vertices plus edge midpoints, 42 in all):
// enough to show spheres and spherocylinder caps as round.
std::vector<nscd::Vec3> make_sphere_directions()
{
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<nscd::Vec3> ico;
  for (double a : {-1.0, 1.0})
    for (double b : {-g, g}) {
      ico.emplace_back(0, a, b);
      ico.emplace_back(a, b, 0);
      ico.emplace_back(b, 0, a);
    }
  const double edge = 2.0;
  std::vector<nscd::Vec3> dirs;
  for (auto &p : ico) dirs.push_back(p.normalized());
  for (size_t i = 0; i < ico.size(); i++)
    for (size_t j = i + 1; j < ico.size(); j++)
      if (std::abs((ico[i] - ico[j]).norm() - edge) < 1e-9) dirs.push_back((ico[i] + ico[j]).normalized());
  return dirs;
}
}    // namespace

DumpGrainsVTK::DumpGrainsVTK(LAMMPS *lmp, int narg, char **arg) :
    Dump(lmp, narg, arg), avec(nullptr), expected_rows(0), timestep_of_snapshot(0), written(false)
{
  if (narg != 5)
    error->all(FLERR, "Illegal dump grains/vtk command: expected 'dump ID group grains/vtk N "
               "file.*.vtk'");
  if (!multifile)
    error->all(FLERR, "dump grains/vtk: file name '{}' needs a '*' (one VTK file per snapshot, "
               "e.g. grains.*.vtk)", filename);
  if (binary || compressed)
    error->all(FLERR, "dump grains/vtk writes plain-text VTK: drop the .bin/.gz file ending");
  size_one = NCOLUMNS;
  sort_flag = 1;
  sortcol = 0;    // by atom ID, so files are deterministic whatever the rank count
}

void DumpGrainsVTK::init_style()
{
  avec = AtomVecSpheropolyhedron::find(lmp, "dump grains/vtk");
  if (multiproc)
    error->all(FLERR, "dump grains/vtk writes one file per snapshot from rank 0: remove "
               "dump_modify nfile/fileper");
  if (!write_header_flag)
    error->all(FLERR, "dump grains/vtk needs its header (point and polygon counts): remove "
               "dump_modify header no");
}

void DumpGrainsVTK::write_header(bigint nrows)
{
  expected_rows = nrows;
  timestep_of_snapshot = update->ntimestep;
  snapshot.clear();
  written = false;
}

void DumpGrainsVTK::pack(tagint *ids)
{
  int m = 0, n = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double row[NCOLUMNS] = {(double) atom->tag[i], (double) atom->type[i],
                                  (double) avec->shape[i], atom->x[i][0], atom->x[i][1],
                                  atom->x[i][2], avec->quat[i][0], avec->quat[i][1],
                                  avec->quat[i][2], avec->quat[i][3], atom->v[i][0],
                                  atom->v[i][1], atom->v[i][2]};
    for (double value : row) buf[m++] = value;
    if (ids) ids[n++] = atom->tag[i];
  }
}

void DumpGrainsVTK::write_data(int nrows, double *rows)
{
  // Called once per rank's chunk (even empty ones): write when the last row has arrived.
  snapshot.insert(snapshot.end(), rows, rows + (size_t) nrows * NCOLUMNS);
  if (!written && (bigint) (snapshot.size() / NCOLUMNS) == expected_rows) {
    write_file();
    written = true;
  }
}

/* Polyhedral cores are drawn as their faces; shapes with no faces (spheres, spherocylinders)
   as the hull of their dilated vertices, sampled by sphere_directions(). A point (shape 0,
   e.g. a wire node) gets no surface. */
const DumpGrainsVTK::Mesh &DumpGrainsVTK::mesh_of(int shape_id)
{
  auto found = meshes.find(shape_id);
  if (found != meshes.end()) return found->second;
  Mesh &mesh = meshes[shape_id];
  if (shape_id == 0) return mesh;
  const nscd::Spheropolyhedron &shape = avec->shapes().shape(shape_id);
  const nscd::Spheropolyhedron *surface = &shape;
  nscd::Spheropolyhedron rounded;
  if (!shape.is_polyhedron()) {
    static const std::vector<nscd::Vec3> directions = make_sphere_directions();
    std::vector<nscd::Vec3> points;
    for (const nscd::Vec3 &v : shape.vertices)
      for (const nscd::Vec3 &d : directions) points.push_back(v + shape.radius * d);
    try {
      rounded = nscd::make_spheropolyhedron(points, 0.0);
    } catch (std::exception &e) {    // e.g. a needle near the thinnest shape allowed
      error->warning(FLERR, "dump grains/vtk: shape {} gets no surface mesh ({})", shape_id, e.what());
      return mesh;
    }
    for (nscd::Vec3 &v : rounded.vertices) v = rounded.input_rotation * v + rounded.input_centroid;
    surface = &rounded;
  }
  for (const nscd::Vec3 &v : surface->vertices) mesh.points.insert(mesh.points.end(), {v.x(), v.y(), v.z()});
  for (const nscd::Face &f : surface->faces) mesh.polygons.push_back(f.vertices);
  return mesh;
}

void DumpGrainsVTK::write_file()
{
  const bigint nrows = (bigint) (snapshot.size() / NCOLUMNS);
  bigint npoints = 0, npolygons = 0, nindices = 0;
  for (bigint r = 0; r < nrows; r++) {
    const Mesh &mesh = mesh_of((int) snapshot[r * NCOLUMNS + SHAPE]);
    npoints += mesh.points.size() / 3;
    npolygons += mesh.polygons.size();
    for (auto &p : mesh.polygons) nindices += p.size() + 1;
  }
  fmt::print(fp, "# vtk DataFile Version 3.0\nLAMMPS grains, timestep {}\nASCII\n"
             "DATASET POLYDATA\nPOINTS {} double\n", timestep_of_snapshot, npoints);
  for (bigint r = 0; r < nrows; r++) {
    const double *row = &snapshot[r * NCOLUMNS];
    const nscd::Quat q(row[QW], row[QX], row[QY], row[QZ]);
    const nscd::Vec3 centre(row[X], row[Y], row[Z]);
    const Mesh &mesh = mesh_of((int) row[SHAPE]);
    for (size_t k = 0; k < mesh.points.size(); k += 3) {
      const nscd::Vec3 p = centre + q * nscd::Vec3(mesh.points[k], mesh.points[k + 1], mesh.points[k + 2]);
      fmt::print(fp, "{:.9g} {:.9g} {:.9g}\n", p.x(), p.y(), p.z());
    }
  }
  fmt::print(fp, "POLYGONS {} {}\n", npolygons, nindices);
  bigint offset = 0;
  for (bigint r = 0; r < nrows; r++) {
    const Mesh &mesh = mesh_of((int) snapshot[r * NCOLUMNS + SHAPE]);
    for (auto &polygon : mesh.polygons) {
      fmt::print(fp, "{}", polygon.size());
      for (int v : polygon) fmt::print(fp, " {}", offset + v);
      fmt::print(fp, "\n");
    }
    offset += mesh.points.size() / 3;
  }
  // One value per polygon: the grain it belongs to, so ParaView can colour by grain.
  fmt::print(fp, "CELL_DATA {}\n", npolygons);
  auto write_cell_column = [&](const char *name, int column) {
    fmt::print(fp, "SCALARS {} int 1\nLOOKUP_TABLE default\n", name);
    for (bigint r = 0; r < nrows; r++) {
      const double *row = &snapshot[r * NCOLUMNS];
      const size_t n = mesh_of((int) row[SHAPE]).polygons.size();
      for (size_t k = 0; k < n; k++) fmt::print(fp, "{}\n", (long long) row[column]);
    }
  };
  write_cell_column("id", ID);
  write_cell_column("type", TYPE);
  write_cell_column("shape", SHAPE);
  fmt::print(fp, "VECTORS velocity double\n");
  for (bigint r = 0; r < nrows; r++) {
    const double *row = &snapshot[r * NCOLUMNS];
    const size_t n = mesh_of((int) row[SHAPE]).polygons.size();
    for (size_t k = 0; k < n; k++) fmt::print(fp, "{:.9g} {:.9g} {:.9g}\n", row[VX], row[VY], row[VZ]);
  }
  snapshot.clear();
}

// LAMMPS' buffers, the gathered rows and the display meshes of the shapes seen.
double DumpGrainsVTK::memory_usage()
{
  double bytes = Dump::memory_usage() + (double) nscd::capacity_bytes(snapshot);
  for (const auto &m : meshes) {
    bytes += (double) (sizeof(m) + nscd::capacity_bytes(m.second.points) + nscd::capacity_bytes(m.second.polygons));
    for (const auto &polygon : m.second.polygons) bytes += (double) nscd::capacity_bytes(polygon);
  }
  return bytes;
}
