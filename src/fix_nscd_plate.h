/* fix nscd/plate: a horizontal loading plate above the grains: a rigid body with its own
   mass that moves only along z (no rotation), pushed down by a load that grows linearly in
   time (or stays constant). Takes part in fix nscd's contact problem. See
   doc/fix_nscd_plate.md. */

#ifdef FIX_CLASS
// clang-format off
FixStyle(nscd/plate,FixNSCDPlate);
// clang-format on
#else

#ifndef LMP_FIX_NSCD_PLATE_H
#define LMP_FIX_NSCD_PLATE_H

#include "fix.h"
#include "nscd_boundary.h"

#include "geometry/contact.h"

namespace LAMMPS_NS {

class FixNSCDPlate : public Fix, public NSCDBoundary {
 public:
  FixNSCDPlate(class LAMMPS *, int, char **);

  int setmask() override;
  void init() override;
  void setup(int) override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  void append_contacts(std::vector<nscd::Contact> &, double activation) override;
  void take_impulses(const nscd::Contact *, int, double dt) override;
  void advance(double) override {}
  bool has_body() const override { return true; }
  nscd::SolverBody body(double dt) const override;
  void set_body_index(int index) override { body_index = index; }
  void take_body(const nscd::SolverBody &, double dt, double theta) override;
  nscd::ContactPoint touch_sphere(const nscd::Vec3 &centre, double radius, double tau) const override;
  nscd::Vec3 surface_velocity() const override { return nscd::Vec3(0.0, 0.0, vz); }
  double friction_coefficient() const override { return friction; }

 private:
  double z = 0.0, vz = 0.0, z_start = 0.0;
  double mass = 0.0, gravity = 0.0;
  double load_start = 0.0, load_rate = 0.0;    // load F(t) = start + rate * elapsed time
  double elapsed = 0.0;
  double friction = 0.0, restitution = 0.0;
  double reaction = 0.0;                       // z force of the grains on the plate
  int body_index = -1;
  std::int64_t plate_tag;
  class AtomVecSpheropolyhedron *avec = nullptr;
  nscd::ContactWorkspace workspace;

  double load() const { return load_start + load_rate * elapsed; }
};

}    // namespace LAMMPS_NS

#endif
#endif
