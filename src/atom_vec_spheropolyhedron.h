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

/* atom_style spheropolyhedron: rigid convex spheropolyhedra (grains) as LAMMPS atoms.

   Per atom: shape id into the shape library (0 = a point, e.g. a wire node), orientation
   quaternion (body -> world, w x y z; LAMMPS' core per-atom `quat`, so `set quat`,
   `displace_atoms rotate` and `compute property/atom quatw ...` work on grains), angular
   velocity (world frame), torque, mass, principal moments of inertia (body frame) and the
   bounding radius used for neighbour lists and ghost cutoffs. The shape library lives in
   this object; it is stored in restart files as this style's arguments, so a restart is
   self-contained. See doc/atom_style_spheropolyhedron.rst.

   Only LAMMPS headers here: style_atom.h pulls this file into LAMMPS' core, which should
   not compile Eigen and lib/ (the library sits behind a pointer). */

#ifdef ATOM_CLASS
// clang-format off
AtomStyle(spheropolyhedron,AtomVecSpheropolyhedron);
// clang-format on
#else

#ifndef LMP_ATOM_VEC_SPHEROPOLYHEDRON_H
#define LMP_ATOM_VEC_SPHEROPOLYHEDRON_H

#include "atom_vec.h"

#include <memory>
#include <string>

namespace nscd {
class ShapeLibrary;
struct Spheropolyhedron;
struct Pose;
}    // namespace nscd

namespace LAMMPS_NS {

class AtomVecSpheropolyhedron : public AtomVec {
 public:
  AtomVecSpheropolyhedron(class LAMMPS *);
  ~AtomVecSpheropolyhedron() override;
  void process_args(int, char **) override;

  void grow_pointers() override;
  void create_atom_post(int) override;
  void data_atom_post(int) override;
  void unpack_restart_init(int) override;
  int property_atom(const std::string &) override;
  void pack_property_atom(int, double *, int, int) override;

  // The atom style instance of this run (also inside atom_style hybrid), or an error
  // naming the missing `atom_style spheropolyhedron` when there is none.
  static AtomVecSpheropolyhedron *find(class LAMMPS *, const char *caller);

  const nscd::ShapeLibrary &shapes() const;
  // Appends shapes and records the whole library in the atom style's arguments.
  void add_shapes(const nscd::ShapeLibrary &more);

  // Where grain i is: position and orientation as the geometry code wants them.
  nscd::Pose pose(int i) const;
  const nscd::Spheropolyhedron &shape_of(int i) const;

  // Gives atom i shape `shape_id` (0 = point) with the given mass; sets inertia and radius.
  void set_shape(int i, int shape_id, double mass);

  // This style's own per-atom arrays. Atom's registry points at these pointers; they live
  // in a block that outlives this object (see fields_storage()), because the generic
  // ~AtomVec of an enclosing atom_style hybrid frees the arrays through them after this
  // sub-style has been deleted.
  struct OwnFields {
    OwnFields() : shape(nullptr), inertia(nullptr) {}
    int *shape;
    double **inertia;
  };
  OwnFields &own;
  int *&shape;           // shape id, 1..N; 0 = point mass (no shape)
  double **&inertia;     // principal moments of inertia, body frame
  double **quat;         // orientation, body -> world, (w, x, y, z): atom->quat
  double *radius;       // bounding radius (centre of mass to farthest surface point)
  double *rmass;
  double **omega;       // angular velocity, world frame
  double **torque;

 private:
  std::unique_ptr<nscd::ShapeLibrary> library;

  static OwnFields &fields_storage();
  void point_peratom(const char *name, void *address, int datatype, int cols, int threadflag = 0);
  void record_library_in_style_args();
  void check_shape_id(int i) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
