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

/* fix nscd/wall: the wall's contacts with owned grains, via lib/geometry. */

#include "fix_nscd_wall.h"
#include "nscd_checks.h"
#include "nscd_args.h"

#include "atom.h"
#include "atom_vec_spheropolyhedron.h"
#include "nscd_arrays.h"
#include "nscd_boundary.h"
#include "nscd_contact.h"
#include "nscd_restart_blocks.h"
#include "comm.h"
#include "error.h"
#include "modify.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

namespace {
nscd::Vec3 read_vec3(LAMMPS *lmp, const char *what, char **arg)
{
  nscd::Vec3 v;
  for (int d = 0; d < 3; d++) v[d] = NSCD_NS::number(lmp, "fix nscd/wall", fmt::format("{} {}", what, "xyz"[d]), arg[d]);
  return v;
}

}    // namespace

/* The wall as fix nscd and fix wire see it. */
class FixNSCDWall::Wall final : public NSCDBoundary {
 public:
  explicit Wall(FixNSCDWall &owner) : fix(owner), tag(boundary_tag(owner.id)) {}

  void append_contacts(std::vector<nscd::Contact> &, double activation, double dt) override;
  void take_impulses(const nscd::Contact *, int, double dt) override;
  void advance(double dt) override { reference_point() += dt * velocity; }
  nscd::ContactPoint touch_sphere(const nscd::Vec3 &centre, double radius, double tau) const override;
  nscd::Vec3 surface_velocity() const override { return velocity; }
  double friction_coefficient() const override { return friction; }
  double deepest_overlap(const nscd::Spheropolyhedron &shape, const nscd::Pose &pose, double within) override;
  // The wall's contact with a grain (its kind's geometry), points up to the activation gap.
  nscd::ContactSet contact_with(const nscd::Spheropolyhedron &shape, const nscd::Pose &pose, double activation);

  bool inside(const nscd::Vec3 &x) const;
  nscd::Vec3 &reference_point() { return kind == Kind::plane ? plane.point : cylinder.axis_point; }

  FixNSCDWall &fix;
  enum class Kind { plane, cylinder } kind = Kind::plane;
  nscd::PlaneWall plane;
  nscd::CylinderWall cylinder;
  nscd::Vec3 velocity = nscd::Vec3::Zero();
  double friction = 0.0, restitution = 0.0;
  std::int64_t tag;                             // negative id in contact keys, from the fix ID
  nscd::Vec3 reaction = nscd::Vec3::Zero();    // force of the grains on the wall
  AtomVecSpheropolyhedron *avec = nullptr;
  nscd::ContactWorkspace workspace;
};

/* fix ID group nscd/wall plane PX PY PZ NX NY NZ [options]
   fix ID group nscd/wall cylinder CX CY CZ AX AY AZ R [options]
   options: friction MU, restitution E, velocity VX VY VZ */
FixNSCDWall::FixNSCDWall(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), wall(std::make_unique<Wall>(*this))
{
  vector_flag = 1;
  size_vector = 6;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;

  const char *usage = "expected plane or cylinder; see doc/fix_nscd_wall.rst, Syntax";
  if (narg < 4) error->all(FLERR, "Illegal fix nscd/wall command: {}", usage);
  int iarg;
  if (strcmp(arg[3], "plane") == 0) {
    if (narg < 10) error->all(FLERR, "Illegal fix nscd/wall plane command: {}", usage);
    wall->kind = Wall::Kind::plane;
    wall->plane.point = read_vec3(lmp, "plane point", &arg[4]);
    const nscd::Vec3 n = read_vec3(lmp, "plane normal", &arg[7]);
    if (!(n.norm() > 0.0)) error->all(FLERR, "fix nscd/wall: the plane normal (0 0 0) has no direction");
    wall->plane.normal = n.normalized();
    iarg = 10;
  } else if (strcmp(arg[3], "cylinder") == 0) {
    if (narg < 11) error->all(FLERR, "Illegal fix nscd/wall cylinder command: {}", usage);
    wall->kind = Wall::Kind::cylinder;
    nscd::CylinderWall &cylinder = wall->cylinder;
    cylinder.axis_point = read_vec3(lmp, "cylinder axis point", &arg[4]);
    const nscd::Vec3 a = read_vec3(lmp, "cylinder axis", &arg[7]);
    if (!(a.norm() > 0.0)) error->all(FLERR, "fix nscd/wall: the cylinder axis (0 0 0) has no direction");
    cylinder.axis_direction = a.normalized();
    cylinder.radius = NSCD_NS::number(lmp, "fix nscd/wall", "cylinder radius", arg[10]);
    if (!(cylinder.radius > 0.0))
      error->all(FLERR, "fix nscd/wall: cylinder radius {} must be positive", cylinder.radius);
    iarg = 11;
  } else {
    error->all(FLERR, "fix nscd/wall: unknown wall '{}' ({})", arg[3], usage);
  }
  while (iarg < narg) iarg = parse_option(narg, arg, iarg);
}

FixNSCDWall::~FixNSCDWall() = default;

NSCDBoundary &FixNSCDWall::boundary()
{
  return *wall;
}

int FixNSCDWall::parse_option(int narg, char **arg, int iarg)
{
  const std::string key = arg[iarg];
  if (key == "friction" && iarg + 1 < narg) {
    const double friction = NSCD_NS::number(lmp, "fix nscd/wall", key, arg[iarg + 1]);
    if (!(friction >= 0.0) || !std::isfinite(friction))
      error->all(FLERR, "fix nscd/wall: friction {} must be finite and >= 0", friction);
    wall->friction = friction;
    return iarg + 2;
  }
  if (key == "restitution" && iarg + 1 < narg) {
    const double restitution = NSCD_NS::number(lmp, "fix nscd/wall", key, arg[iarg + 1]);
    if (!(restitution >= 0.0 && restitution <= 1.0))
      error->all(FLERR, "fix nscd/wall: restitution {} must be in [0, 1]", restitution);
    wall->restitution = restitution;
    return iarg + 2;
  }
  if (key == "velocity" && iarg + 3 < narg) {
    wall->velocity = read_vec3(lmp, "velocity", &arg[iarg + 1]);
    return iarg + 4;
  }
  error->all(FLERR, "fix nscd/wall: unknown or incomplete keyword '{}' (expected friction MU, "
             "restitution E, velocity VX VY VZ)", key);
  return narg;
}

/* fix_modify ID velocity VX VY VZ | friction MU | restitution E */
int FixNSCDWall::setmask()
{
  return 0;    // fix nscd drives it; setup() is called for every fix all the same
}

int FixNSCDWall::modify_param(int narg, char **arg)
{
  const std::string key = arg[0];
  if (key != "velocity" && key != "friction" && key != "restitution") return 0;
  const int used = parse_option(narg, arg, 0);
  return used;
}

void FixNSCDWall::init()
{
  wall->avec = AtomVecSpheropolyhedron::find(lmp, "fix nscd/wall");
  if (modify->get_fix_by_style("^nscd$").empty())
    error->all(FLERR, "fix nscd/wall {} has no effect without fix nscd (which solves its "
               "contacts); define fix nscd as well", id);
}

/* A grain (or wire node) whose centre lies beyond the wall surface would be shot back
   across it in one step: that is a wrong wall (normal pointing out of the domain?) or a
   wrong atom. */
void FixNSCDWall::setup(int /*vflag*/)
{
  const tagint any_outside = NSCD_NS::lowest_tag_where(
      lmp, [&](int i) { return (atom->mask[i] & groupbit) && !wall->inside(vec3(atom->x[i])); });
  if (any_outside)
    error->all(FLERR, "fix nscd/wall {}: the centre of atom ID {} is outside the wall ({}); check its position and the normal's "
               "direction",
               id, any_outside, wall->kind == Wall::Kind::plane ? "behind the plane" : "outside the cylinder");
  warn_about_grains_in_the_wall();
}

/* A grain reaching into the wall by more than a fifth of its bounding radius at the start of
   a run (a cylinder narrower than the grains, grains placed into a wall) keeps that overlap:
   contacts stop it from growing but do not push it out. Warned about, naming the grain, the
   depth and, for a cylinder, its radius, as fix nscd warns about grains inside grains. */
void FixNSCDWall::warn_about_grains_in_the_wall()
{
  const GrainInBoundary grain = deepest_grain_in(lmp, *wall, *wall->avec, groupbit);
  if (!(grain.share > 0.2) || comm->me != 0) return;
  if (wall->kind == Wall::Kind::cylinder)
    error->warning(FLERR, "fix nscd/wall {}: grain ID {} reaches {:.4g} into the cylinder wall of radius {:.6g} at the "
                   "start{}", id, grain.id, grain.depth, wall->cylinder.radius,
                   wall->cylinder.radius < grain.bounding_radius ? " (narrower than the grain)" : "; place it inside");
  else
    error->warning(FLERR, "fix nscd/wall {}: grain ID {} reaches {:.4g} behind the plane wall "
                   "at the start; place it in front", id, grain.id, grain.depth);
}

double FixNSCDWall::Wall::deepest_overlap(const nscd::Spheropolyhedron &shape, const nscd::Pose &pose, double within)
{
  return contact_with(shape, pose, within).deepest_overlap();
}

nscd::ContactSet FixNSCDWall::Wall::contact_with(const nscd::Spheropolyhedron &shape, const nscd::Pose &pose,
                                                double activation)
{
  return kind == Kind::plane ? nscd::contact_grain_plane(shape, pose, plane, activation, workspace)
                             : nscd::contact_grain_cylinder(shape, pose, cylinder, activation, workspace);
}

bool FixNSCDWall::Wall::inside(const nscd::Vec3 &x) const
{
  if (kind == Kind::plane) return (x - plane.point).dot(plane.normal) > 0.0;
  const nscd::Vec3 d = x - cylinder.axis_point;
  return (d - d.dot(cylinder.axis_direction) * cylinder.axis_direction).norm() < cylinder.radius;
}

void FixNSCDWall::Wall::append_contacts(std::vector<nscd::Contact> &contacts, double base, double dt)
{
  const ContactLaw law{friction, restitution};
  Atom *atom = fix.atom;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & fix.groupbit) || avec->shape[i] == 0) continue;
    const double closing = closing_speed_on_boundary(vec3(atom->v[i]), vec3(avec->omega[i]), avec->radius[i], velocity);
    const double activation = speculative_activation(base, closing, dt);
    nscd::ContactSet set;
    try {
      set = contact_with(avec->shape_of(i), avec->pose(i), activation);
    } catch (std::exception &e) {
      fix.error->one(FLERR, "fix nscd/wall {}: contact with grain ID {} failed: {}", fix.id,
                     atom->tag[i], e.what());
    }
    for (const nscd::ContactPoint &p : set) {
      nscd::Contact c = make_contact(p, i, nscd::kEnvironment, atom->tag[i], tag, law);
      c.wall_velocity = velocity;
      contacts.push_back(c);
    }
  }
}

void FixNSCDWall::Wall::take_impulses(const nscd::Contact *first, int count, double dt)
{
  nscd::Vec3 mine = nscd::Vec3::Zero();
  for (int k = 0; k < count; k++) mine -= first[k].impulse;    // impulse on the grain: minus on the wall
  mine /= dt;
  MPI_Allreduce(mine.data(), reaction.data(), 3, MPI_DOUBLE, MPI_SUM, fix.world);
}

nscd::ContactPoint FixNSCDWall::Wall::touch_sphere(const nscd::Vec3 &centre, double radius, double tau) const
{
  if (kind == Kind::plane) {
    nscd::PlaneWall moved = plane;
    moved.point += tau * velocity;
    return nscd::contact_sphere_plane(centre, radius, moved);
  }
  nscd::CylinderWall moved = cylinder;
  moved.axis_point += tau * velocity;
  return nscd::contact_sphere_cylinder(centre, radius, moved);
}

double FixNSCDWall::compute_vector(int n)
{
  if (n < 3) return wall->reaction[n] + wall->wire_force_in(update->ntimestep)[n];    // grains + wire
  return wall->reference_point()[n - 3];
}

/* Restart: the wall's kind and current reference point (it may have moved); the deck that
   defines the wall again after read_restart keeps its own settings (velocity, friction). */
void FixNSCDWall::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  NSCD_NS::WallBlock block;
  block.cylinder = wall->kind == Wall::Kind::cylinder;
  const nscd::Vec3 &p = wall->reference_point();
  block.point = {p.x(), p.y(), p.z()};
  NSCD_NS::write_block(fp, NSCD_NS::wall_block(block));
}

void FixNSCDWall::restart(char *bytes)
{
  const NSCD_NS::WallBlock block = NSCD_NS::read_restart_block(
      lmp, this, NSCD_NS::read_wall_block, bytes, "doc/fix_nscd_wall.rst");
  if (block.cylinder != (wall->kind == Wall::Kind::cylinder)) {
    if (comm->me == 0)
      error->warning(FLERR, "fix nscd/wall {}: the restart file holds a {} wall of this ID; "
                     "its position is not used", id, block.cylinder ? "cylinder" : "plane");
    return;
  }
  wall->reference_point() = nscd::Vec3(block.point[0], block.point[1], block.point[2]);
}

// The wall's state and its contact queries' scratch buffers.
double FixNSCDWall::memory_usage()
{
  return (double) sizeof(Wall) + (double) wall->workspace.memory_bytes();
}
