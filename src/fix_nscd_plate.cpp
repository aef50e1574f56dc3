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

/* fix nscd/plate: the plate's contacts with owned grains, its body in the contact problem,
   and its motion along z. */

#include "fix_nscd_plate.h"
#include "nscd_checks.h"
#include "nscd_args.h"

#include "atom.h"
#include "atom_vec_spheropolyhedron.h"
#include "comm.h"
#include "error.h"
#include "modify.h"
#include "nscd_arrays.h"
#include "nscd_boundary.h"
#include "nscd_contact.h"
#include "nscd_restart_blocks.h"
#include "update.h"

#include "shape/spheropolyhedron.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

namespace {
enum Output { Z, VZ, REACTION, LOAD, DISPLACEMENT, WINDOW_SINK, PEAK_FORCE, PEAK_DISPLACEMENT, FAILED, FAILURE_LOAD,
              NOUTPUTS };
}

/* The plate as fix nscd and fix wire see it: a body of the contact problem. */
class FixNSCDPlate::Plate final : public NSCDBoundary {
 public:
  explicit Plate(FixNSCDPlate &owner) : fix(owner), tag(boundary_tag(owner.id)) {}

  void append_contacts(std::vector<nscd::Contact> &, double activation, double dt) override;
  void take_impulses(const nscd::Contact *, int, double dt) override;
  void stop_if_sinking(const nscd::Contact *first, int count);
  void advance(double) override {}
  bool has_body() const override { return true; }
  nscd::SolverBody body(double dt) const override;
  void set_body_index(int index) override { body_index = index; }
  void take_body(const nscd::SolverBody &, double dt, double theta) override;
  nscd::ContactPoint touch_sphere(const nscd::Vec3 &centre, double radius, double tau) const override;
  nscd::Vec3 surface_velocity() const override { return nscd::Vec3(0.0, 0.0, vz); }
  double friction_coefficient() const override { return friction; }
  double deepest_overlap(const nscd::Spheropolyhedron &shape, const nscd::Pose &pose, double within) override;

  // Its underside at height h, facing the grains below.
  static nscd::PlaneWall face_at(double h) { return {nscd::Vec3(0.0, 0.0, h), nscd::Vec3(0.0, 0.0, -1.0)}; }
  double load() const { return load_start + load_rate * elapsed; }
  double force_on_plate() const { return reaction + wire_force_in(fix.update->ntimestep).z(); }
  double window_sink() const { return heights.empty() ? 0.0 : heights.front() - heights.back(); }
  void record_step();
  void fail_if_slumping();

  FixNSCDPlate &fix;
  double z = 0.0, vz = 0.0, z_start = 0.0;
  double mass = 0.0, gravity = 0.0;
  double load_start = 0.0, load_rate = 0.0;    // load F(t) = start + rate * elapsed time
  double elapsed = 0.0;
  double friction = 0.0, restitution = 0.0;
  double reaction = 0.0;                       // z force of the grains on the plate
  int body_index = -1;
  // failure criterion: the plate sinks more than fail_sink within fail_window steps
  int fail_window = 0;                         // 0: no criterion
  double fail_sink = 0.0;
  std::deque<double> heights;                  // z at the end of the last fail_window + 1 steps
  double peak_force = 0.0, peak_displacement = 0.0;
  bool failed = false;
  double failure_load = 0.0;
  std::int64_t tag;
  AtomVecSpheropolyhedron *avec = nullptr;
  nscd::ContactWorkspace workspace;
};

/* fix ID group nscd/plate Z mass M [load F0] [rate R] [gravity G] [friction MU]
   [restitution E] [fail_sink S fail_window N] : the plate's lower face is the plane z = Z, the grains are below it; the
   load F0 + R t pushes it down, as does its weight M G. */
FixNSCDPlate::FixNSCDPlate(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), plate(std::make_unique<Plate>(*this))
{
  vector_flag = 1;
  size_vector = NOUTPUTS;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  Plate &p = *plate;
  if (narg < 6 || strcmp(arg[4], "mass") != 0)
    error->all(FLERR, "Illegal fix nscd/plate command: expected 'fix "
               "ID group nscd/plate Z mass M [keyword value ...]'");
  p.z = p.z_start = NSCD_NS::number(lmp, "fix nscd/plate", "height Z", arg[3]);
  if (!std::isfinite(p.z)) error->all(FLERR, "fix nscd/plate: the height {} must be finite", arg[3]);
  p.mass = NSCD_NS::number(lmp, "fix nscd/plate", "mass", arg[5]);
  if (!(p.mass > 0.0) || !std::isfinite(p.mass))
    error->all(FLERR, "fix nscd/plate: mass {} must be positive and finite", p.mass);
  if (p.mass < nscd::kMinBodyMass || p.mass > nscd::kMaxBodyMass)
    error->all(FLERR, "fix nscd/plate: mass {} is outside the {} to {} the solver supports; "
               "change the mass unit", p.mass, nscd::kMinBodyMass, nscd::kMaxBodyMass);
  for (int iarg = 6; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    const std::string text = NSCD_NS::keyword_value(
        lmp, "fix nscd/plate", narg, arg, iarg,
        {"load", "rate", "gravity", "friction", "restitution", "fail_sink", "fail_window"});
    const double value = NSCD_NS::number(lmp, "fix nscd/plate", key, text);
    if (!std::isfinite(value))
      error->all(FLERR, "fix nscd/plate: {} {} must be a finite number", key, arg[iarg + 1]);
    if (key == "fail_window") {
      if (!(value >= 1.0 && value <= 1e7 && value == std::floor(value)))
        error->all(FLERR, "fix nscd/plate: fail_window {} must be a whole number of steps from 1 to 1e7",
                   arg[iarg + 1]);
      p.fail_window = (int) value;
    } else if (key == "fail_sink") {
      if (!(value > 0.0))
        error->all(FLERR, "fix nscd/plate: fail_sink {} must be a positive distance", arg[iarg + 1]);
      p.fail_sink = value;
    } else if (key == "load") p.load_start = value;
    else if (key == "rate") p.load_rate = value;
    else if (key == "gravity") p.gravity = value;
    else if (key == "friction") p.friction = value;
    else if (key == "restitution") p.restitution = value;
  }
  if ((p.fail_window > 0) != (p.fail_sink > 0.0))
    error->all(FLERR, "fix nscd/plate: fail_sink and fail_window go together; give both or neither");
  if (!(p.friction >= 0.0) || !std::isfinite(p.friction))
    error->all(FLERR, "fix nscd/plate: friction {} must be finite and >= 0", p.friction);
  if (!(p.restitution >= 0.0 && p.restitution <= 1.0))
    error->all(FLERR, "fix nscd/plate: restitution {} must be in [0, 1]", p.restitution);
}

FixNSCDPlate::~FixNSCDPlate() = default;

NSCDBoundary &FixNSCDPlate::boundary()
{
  return *plate;
}

int FixNSCDPlate::setmask()
{
  return 0;    // driven by fix nscd
}

void FixNSCDPlate::init()
{
  plate->avec = AtomVecSpheropolyhedron::find(lmp, "fix nscd/plate");
  if (modify->get_fix_by_style("^nscd$").empty())
    error->all(FLERR, "fix nscd/plate {} needs fix nscd (which solves its contacts)", id);
}

void FixNSCDPlate::setup(int /*vflag*/)
{
  const double z = plate->z;
  const tagint any_above =
      NSCD_NS::lowest_tag_where(lmp, [&](int i) { return (atom->mask[i] & groupbit) && atom->x[i][2] >= z; });
  if (any_above)
    error->all(FLERR, "fix nscd/plate {}: atom ID {} is above the plate (z = {}); put the plate "
               "above all grains and wire nodes of its group", id, any_above, z);
  // A grain whose centre is below the plate can still reach into it (a grain leaning on a
  // column's side, higher than the column's top): the first step would find the plate that
  // deep and stop as a plate sinking under its load does; say what is wrong instead.
  const GrainInBoundary grain = deepest_grain_in(lmp, *plate, *plate->avec, groupbit);
  if (grain.share > 0.2)
    error->all(FLERR, "fix nscd/plate {}: grain ID {} reaches {:.4g} into the plate at z = {}; "
               "put it above the grains' tops", id, grain.id, grain.depth, z);
}

void FixNSCDPlate::Plate::append_contacts(std::vector<nscd::Contact> &contacts, double base, double dt)
{
  const nscd::PlaneWall face = face_at(z);
  const ContactLaw law{friction, restitution};
  Atom *atom = fix.atom;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & fix.groupbit) || avec->shape[i] == 0) continue;
    const double closing = closing_speed_on_boundary(vec3(atom->v[i]), vec3(avec->omega[i]), avec->radius[i],
                                                     nscd::Vec3(0.0, 0.0, vz));
    const double activation = speculative_activation(base, closing, dt);
    nscd::ContactSet set;
    try {
      set = nscd::contact_grain_plane(avec->shape_of(i), avec->pose(i), face, activation, workspace);
    } catch (std::exception &e) {
      fix.error->one(FLERR, "fix nscd/plate {}: contact with grain ID {} failed: {}", fix.id,
                     atom->tag[i], e.what());
    }
    for (const nscd::ContactPoint &p : set)
      contacts.push_back(make_contact(p, i, body_index, atom->tag[i], tag, law));
  }
}

/* The plate moves along z only and does not turn: its inverse mass acts on z alone and its
   inverse inertia is zero. The load of a step is the one at its end (implicit, as the
   contact forces), so that after the step f_ID[4] is the load the grains carried. */
nscd::SolverBody FixNSCDPlate::Plate::body(double dt) const
{
  nscd::SolverBody b;
  b.position = nscd::Vec3(0.0, 0.0, z);
  b.velocity = nscd::Vec3(0.0, 0.0, vz);
  b.inv_mass = 1.0 / mass;
  b.inv_mass_axes = nscd::Vec3(0.0, 0.0, 1.0);
  const double load_at_end = load() + load_rate * dt;
  const double wire = wire_force_in(fix.update->ntimestep).z();    // the wire pushing up on it
  b.external_impulse = nscd::Vec3(0.0, 0.0, dt * (wire - load_at_end - mass * gravity));
  return b;
}

double FixNSCDPlate::Plate::deepest_overlap(const nscd::Spheropolyhedron &shape, const nscd::Pose &pose, double within)
{
  return nscd::contact_grain_plane(shape, pose, face_at(z), within, workspace).deepest_overlap();
}

nscd::ContactPoint FixNSCDPlate::Plate::touch_sphere(const nscd::Vec3 &centre, double radius, double tau) const
{
  const nscd::PlaneWall face = face_at(z + tau * vz);
  return nscd::contact_sphere_plane(centre, radius, face);
}

void FixNSCDPlate::Plate::take_body(const nscd::SolverBody &solved, double dt, double theta)
{
  const double v_new = solved.velocity.z();
  z += dt * ((1.0 - theta) * vz + theta * v_new);
  vz = v_new;
  elapsed += dt;
  record_step();
}

/* The failure criterion sees every step: the sink over a sliding window of steps, not the
   plate's state at the few moments a deck looks (a slump that starts and stops between two
   looks leaves the plate at rest and only a little lower). */
void FixNSCDPlate::Plate::record_step()
{
  if (fail_window <= 0) return;
  heights.push_back(z);
  while ((int) heights.size() > fail_window + 1) heights.pop_front();
  fail_if_slumping();
}

void FixNSCDPlate::Plate::fail_if_slumping()
{
  if (failed || !(window_sink() > fail_sink)) return;
  failed = true;
  failure_load = load();
  if (fix.comm->me == 0)
    utils::logmesg(fix.lmp, "fix nscd/plate {}: failure at step {}: the plate sank {:.4g} within the last {} "
                   "steps (fail_sink {:.4g}) under a load of {:.6g}; peak force so far {:.6g} at displacement "
                   "{:.4g}\n", fix.id, fix.update->ntimestep, window_sink(), (int) heights.size() - 1, fail_sink,
                   failure_load, peak_force, peak_displacement);
}

void FixNSCDPlate::Plate::take_impulses(const nscd::Contact *first, int count, double dt)
{
  double mine = 0.0;
  for (int k = 0; k < count; k++) mine -= first[k].impulse.z();    // on the plate
  mine /= dt;
  MPI_Allreduce(&mine, &reaction, 1, MPI_DOUBLE, MPI_SUM, fix.world);
  if (force_on_plate() > peak_force) {    // the peak of the load-displacement curve
    peak_force = force_on_plate();
    peak_displacement = z - z_start;
  }
  stop_if_sinking(first, count);
}

/* Under a load far beyond what the scene can take in a step (a huge 'rate'), the plate
   sinks into the grains: its load drives it past its contacts within one step (they are
   activated from its velocity at the start of the step), and the solver's relative
   tolerance leaves impulse errors that let it sink step after step, without an unconverged
   step. The run stops when the plate's deepest contact at the start of a step goes past a
   fifth of the grain's bounding radius (the depth at which fix nscd warns about grains
   inside grains): from there on the scene is not the one asked for (at 1e12 the plate went
   through the grains and the run ended in "Lost atoms"). */
void FixNSCDPlate::Plate::stop_if_sinking(const nscd::Contact *first, int count)
{
  double mine = 0.0;    // depth / bounding radius
  for (int k = 0; k < count; k++)
    mine = std::max(mine, -first[k].gap / avec->radius[first[k].body_i]);
  double worst = 0.0;
  MPI_Allreduce(&mine, &worst, 1, MPI_DOUBLE, MPI_MAX, fix.world);
  if (!(worst > 0.2)) return;
  fix.error->all(FLERR, "fix nscd/plate {}: step {}: the plate is {:.3g} of a grain's bounding radius deep; "
                 "lower the load {:.6g} or rate {:.6g}", fix.id, fix.update->ntimestep, worst, load_start, load_rate);
}

double FixNSCDPlate::compute_vector(int n)
{
  const Plate &p = *plate;
  switch (n) {
    case Z: return p.z;
    case VZ: return p.vz;
    case REACTION: return p.force_on_plate();    // grains + wire
    case LOAD: return p.load();
    case DISPLACEMENT: return p.z - p.z_start;
    case WINDOW_SINK: return p.window_sink();
    case PEAK_FORCE: return p.peak_force;
    case PEAK_DISPLACEMENT: return p.peak_displacement;
    case FAILED: return p.failed ? 1.0 : 0.0;
    case FAILURE_LOAD: return p.failure_load;
  }
  return 0.0;
}

/* Restart: position, velocity and the time the load has grown for. */
void FixNSCDPlate::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  NSCD_NS::PlateBlock block;
  block.z = plate->z;
  block.vz = plate->vz;
  block.elapsed = plate->elapsed;
  block.z_start = plate->z_start;
  NSCD_NS::write_block(fp, NSCD_NS::plate_block(block));
}

void FixNSCDPlate::restart(char *bytes)
{
  const NSCD_NS::PlateBlock block = NSCD_NS::read_restart_block(
      lmp, this, NSCD_NS::read_plate_block, bytes, "doc/fix_nscd_plate.rst");
  plate->z = block.z;
  plate->vz = block.vz;
  plate->elapsed = block.elapsed;
  plate->z_start = block.z_start;
}

// The plate's state and its contact queries' scratch buffers.
double FixNSCDPlate::memory_usage()
{
  return (double) sizeof(Plate) + (double) plate->workspace.memory_bytes();
}
