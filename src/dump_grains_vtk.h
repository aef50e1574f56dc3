/* -*- c++ -*- ----------------------------------------------------------
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

/* dump grains/vtk: one legacy-VTK polydata file per snapshot with the true shape of every
   grain (polyhedral cores as polygons; spheres and spherocylinders as tessellated
   surfaces), for ParaView/VisIt. See doc/dump_grains_vtk.rst. */

#ifdef DUMP_CLASS
// clang-format off
DumpStyle(grains/vtk,DumpGrainsVTK);
// clang-format on
#else

#ifndef LMP_DUMP_GRAINS_VTK_H
#define LMP_DUMP_GRAINS_VTK_H

#include "dump.h"

#include <map>
#include <vector>

namespace LAMMPS_NS {

class DumpGrainsVTK : public Dump {
 public:
  DumpGrainsVTK(class LAMMPS *, int, char **);

 protected:
  void init_style() override;
  void write_header(bigint) override;
  void pack(tagint *) override;
  void write_data(int, double *) override;
  double memory_usage() override;

 private:
  struct Mesh {    // a shape's surface for display, body frame
    std::vector<double> points;                 // x y z ...
    std::vector<std::vector<int>> polygons;
  };
  class AtomVecSpheropolyhedron *avec;
  std::map<int, Mesh> meshes;          // by shape id, built on first use
  std::vector<double> snapshot;        // rows gathered on the writing rank
  bigint expected_rows;
  bigint timestep_of_snapshot;
  bool written;                        // this snapshot's file is complete

  const Mesh &mesh_of(int shape_id);
  void write_file();
};

}    // namespace LAMMPS_NS

#endif
#endif
