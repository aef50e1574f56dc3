/* fix nscd/wall: a plane or the inside of a cylinder as a boundary of infinite mass in
   fix nscd's contact problem; may move with a prescribed velocity and be removed (unfix).
   See doc/fix_nscd_wall.md. */

#ifdef FIX_CLASS
// clang-format off
FixStyle(nscd/wall,FixNSCDWall);
// clang-format on
#else

#ifndef LMP_FIX_NSCD_WALL_H
#define LMP_FIX_NSCD_WALL_H

#include "fix.h"
#include "nscd_boundary.h"

#include "geometry/contact.h"

namespace LAMMPS_NS {

class FixNSCDWall : public Fix, public NSCDBoundary {
 public:
  FixNSCDWall(class LAMMPS *, int, char **);

  int setmask() override;
  void init() override;
  void setup(int) override;
  int modify_param(int, char **) override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  void append_contacts(std::vector<nscd::Contact> &, double activation) override;
  void take_impulses(const nscd::Contact *, int, double dt) override;
  void advance(double dt) override;
  nscd::ContactPoint touch_sphere(const nscd::Vec3 &centre, double radius, double tau) const override;
  nscd::Vec3 surface_velocity() const override { return velocity; }
  double friction_coefficient() const override { return friction; }

 private:
  enum class Kind { plane, cylinder } kind;
  nscd::PlaneWall plane;
  nscd::CylinderWall cylinder;
  nscd::Vec3 velocity = nscd::Vec3::Zero();
  double friction = 0.0, restitution = 0.0;
  std::int64_t wall_tag;          // negative id in contact keys, from the fix ID
  nscd::Vec3 reaction = nscd::Vec3::Zero();    // force of the grains on the wall
  class AtomVecSpheropolyhedron *avec = nullptr;
  nscd::ContactWorkspace workspace;

  nscd::Vec3 &reference_point() { return kind == Kind::plane ? plane.point : cylinder.axis_point; }
  int parse_option(int narg, char **arg, int iarg);
  bool inside(const nscd::Vec3 &x) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
