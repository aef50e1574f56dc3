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

/* atom_style spheropolyhedron: LAMMPS glue around the shape library of lib/shape. */

#include "atom_vec_spheropolyhedron.h"

#include "atom.h"
#include "atom_vec_hybrid.h"
#include "error.h"
#include "memory.h"
#include "nscd_arrays.h"

#include "shape/grain_record.h"
#include "shape/shape_library.h"

#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

namespace {
const char *const STYLE_NAME = "spheropolyhedron";
const char *const LIBRARY_ARG = "library";    // followed by the serialised shape library
}    // namespace

AtomVecSpheropolyhedron::AtomVecSpheropolyhedron(LAMMPS *lmp) :
    AtomVec(lmp), own(fields_storage()), shape(own.shape), inertia(own.inertia), quat(nullptr),
    radius(nullptr), rmass(nullptr), omega(nullptr), torque(nullptr),
    library(std::make_unique<nscd::ShapeLibrary>())
{
  mass_type = PER_ATOM;
  molecular = Atom::ATOMIC;
  atom->rmass_flag = atom->radius_flag = atom->omega_flag = atom->torque_flag = 1;
  atom->quat_flag = 1;    // orientation in LAMMPS' own per-atom quat

  point_peratom("shape", &shape, Atom::INT, 0);
  point_peratom("inertia", &inertia, Atom::DOUBLE, 3);

  // Ghosts need shape and orientation for contact geometry, so quat goes every step;
  // the solver exchanges velocities itself, comm_vel is for `comm_modify vel yes`.
  fields_grow = {"shape", "quat", "inertia", "radius", "rmass", "omega", "torque"};
  fields_copy = {"shape", "quat", "inertia", "radius", "rmass", "omega"};
  fields_comm = {"quat"};
  fields_comm_vel = {"quat", "omega"};
  fields_reverse = {"torque"};
  fields_border = {"shape", "quat", "inertia", "radius", "rmass"};
  fields_border_vel = {"shape", "quat", "inertia", "radius", "rmass", "omega"};
  fields_exchange = {"shape", "quat", "inertia", "radius", "rmass", "omega"};
  fields_restart = {"shape", "quat", "inertia", "radius", "rmass", "omega"};
  fields_create = {"shape", "quat", "inertia", "radius", "rmass", "omega"};
  fields_data_atom = {"id", "type", "shape", "rmass", "x", "quat"};
  fields_data_vel = {"id", "v", "omega"};
}

AtomVecSpheropolyhedron::~AtomVecSpheropolyhedron() = default;

/* A new block per instance, kept until the program ends (a few bytes per atom_style
   command); ~AtomVec frees the arrays themselves. */
AtomVecSpheropolyhedron::OwnFields &AtomVecSpheropolyhedron::fields_storage()
{
  static std::vector<std::unique_ptr<OwnFields>> blocks;
  blocks.push_back(std::make_unique<OwnFields>());
  return *blocks.back();
}

/* Registers one of this style's own per-atom arrays with Atom. `atom_style` followed by
   `read_restart` constructs the style twice: the second instance re-points the entry. */
void AtomVecSpheropolyhedron::point_peratom(const char *name, void *address, int datatype,
                                            int cols, int threadflag)
{
  for (auto &entry : atom->peratom)
    if (entry.name == name) {
      entry.address = address;
      return;
    }
  atom->add_peratom(name, address, datatype, cols, threadflag);
}

/* Arguments: none, or `library <text>` as written by record_library_in_style_args() into
   restart files (and used by `replicate`). Users load shapes with the `shapes` command. */
void AtomVecSpheropolyhedron::process_args(int narg, char **arg)
{
  if (narg == 2 && strcmp(arg[0], LIBRARY_ARG) == 0) {
    try {
      *library = nscd::ShapeLibrary::deserialize(arg[1]);
    } catch (std::exception &e) {
      error->all(FLERR, "atom_style spheropolyhedron: the stored shape library "
                 "is unreadable ({}): a damaged or foreign restart file", e.what());
    }
  } else if (narg != 0) {
    error->all(FLERR, "Illegal atom_style spheropolyhedron command: it takes "
               "no arguments; load shapes with 'shapes read' or 'shapes random'");
  }
  setup_fields();
}

void AtomVecSpheropolyhedron::grow_pointers()
{
  quat = atom->quat;
  radius = atom->radius;
  rmass = atom->rmass;
  omega = atom->omega;
  torque = atom->torque;
}

void AtomVecSpheropolyhedron::create_atom_post(int i)
{
  quat[i][0] = 1.0;
  set_shape(i, 0, 1.0);
}

/* An Atoms line's shape id, mass and orientation, checked (lib/shape/grain_record.h); the
   quaternion is normalised, inertia and radius come from the shape. */
void AtomVecSpheropolyhedron::data_atom_post(int i)
{
  nscd::CheckedGrain grain;
  try {
    grain = nscd::check_grain_record(*library, {shape[i], rmass[i], {quat[i][0], quat[i][1], quat[i][2], quat[i][3]}},
                                     nscd::QuaternionLength::any);
  } catch (std::exception &e) {
    error->one(FLERR, "Atoms section: atom ID {}: {}", atom->tag[i], e.what());
  }
  for (int k = 0; k < 4; k++) quat[i][k] = grain.quat[k];
  set_shape(i, shape[i], rmass[i]);
  omega[i][0] = omega[i][1] = omega[i][2] = 0.0;
  torque[i][0] = torque[i][1] = torque[i][2] = 0.0;
}

/* An atom just read from a restart file: its shape id, mass and orientation as a data file's
   must be, its stored inertia, radius and angular velocity finite. A damaged file is
   refused here rather than indexing the library with a wrong id later. */
void AtomVecSpheropolyhedron::unpack_restart_init(int i)
{
  try {
    nscd::check_grain_record(*library, {shape[i], rmass[i], {quat[i][0], quat[i][1], quat[i][2], quat[i][3]}},
                             nscd::QuaternionLength::unit);
  } catch (std::exception &e) {
    error->one(FLERR, "read_restart: atom ID {}: {}; the restart file is damaged", atom->tag[i], e.what());
  }
  const double stored[7] = {inertia[i][0], inertia[i][1], inertia[i][2], radius[i], omega[i][0], omega[i][1], omega[i][2]};
  const char *names[7] = {"inertia", "inertia", "inertia", "radius", "angular velocity", "angular velocity",
                          "angular velocity"};
  for (int k = 0; k < 7; k++)
    if (!std::isfinite(stored[k]) || (k < 4 && stored[k] < 0.0))
      error->one(FLERR, "read_restart: atom ID {} has {} {}; the restart file is damaged", atom->tag[i], names[k],
                 stored[k]);
}

void AtomVecSpheropolyhedron::check_shape_id(int i) const
{
  if (shape[i] < 0 || shape[i] > library->size())
    error->one(FLERR, "Atom ID {} has shape id {}, but the library holds {} shape(s); use 'shapes "
               "read' before read_data, or 0 for a point", atom->tag[i], shape[i], library->size());
}

void AtomVecSpheropolyhedron::set_shape(int i, int shape_id, double mass)
{
  shape[i] = shape_id;
  check_shape_id(i);
  rmass[i] = mass;
  if (shape_id == 0) {
    inertia[i][0] = inertia[i][1] = inertia[i][2] = 0.0;
    radius[i] = 0.0;
    return;
  }
  const nscd::Spheropolyhedron &s = library->shape(shape_id);
  nscd::GrainInertia grain;
  try {
    grain = nscd::grain_inertia_from_mass(s, mass);
  } catch (std::exception &e) {
    error->one(FLERR, "atom ID {} with shape {}: {}", atom->tag[i], shape_id, e.what());
  }
  for (int k = 0; k < 3; k++) inertia[i][k] = grain.inertia[k];
  radius[i] = s.bounding_radius;
}

void AtomVecSpheropolyhedron::add_shapes(const nscd::ShapeLibrary &more)
{
  try {    // every rank holds the same library: all fail alike
    library->append(more);
  } catch (std::exception &e) {
    error->all(FLERR, "{}", e.what());
  }
  record_library_in_style_args();
}

/* The restart file stores the atom style's arguments; putting the library there makes
   restarts (and `replicate`) carry their shapes. Inside `atom_style hybrid` the hybrid's
   own argument list is the one written, so our slice of it is replaced. */
void AtomVecSpheropolyhedron::record_library_in_style_args()
{
  const std::string text = library->serialize();
  AtomVec *top = atom->avec;
  std::vector<std::string> args;
  if (top == this) {
    args = {LIBRARY_ARG, text};
  } else {
    auto hybrid = dynamic_cast<AtomVecHybrid *>(top);
    if (!hybrid) error->all(FLERR, "atom_style spheropolyhedron: unexpected owning atom style");
    auto is_keyword = [hybrid](const char *word) {
      for (int k = 0; k < hybrid->nstyles; k++)
        if (strcmp(word, hybrid->keywords[k]) == 0) return true;
      return false;
    };
    for (int a = 0; a < top->nargcopy; a++) {
      args.emplace_back(top->argcopy[a]);
      if (strcmp(top->argcopy[a], STYLE_NAME) != 0) continue;
      while (a + 1 < top->nargcopy && !is_keyword(top->argcopy[a + 1])) a++;
      args.emplace_back(LIBRARY_ARG);
      args.push_back(text);
    }
  }
  std::vector<char *> argv;
  for (auto &s : args) argv.push_back(&s[0]);
  for (int a = 0; a < top->nargcopy; a++) delete[] top->argcopy[a];
  delete[] top->argcopy;
  top->nargcopy = 0;
  top->argcopy = nullptr;
  top->store_args((int) argv.size(), argv.data());
}

AtomVecSpheropolyhedron *AtomVecSpheropolyhedron::find(LAMMPS *lmp, const char *caller)
{
  AtomVec *avec = lmp->atom->atom_style ? lmp->atom->style_match(STYLE_NAME) : nullptr;
  if (!avec)
    lmp->error->all(FLERR, "{} needs atom_style spheropolyhedron (alone or inside atom_style "
                    "hybrid); define it before this command", caller);
  return static_cast<AtomVecSpheropolyhedron *>(avec);
}

const nscd::ShapeLibrary &AtomVecSpheropolyhedron::shapes() const
{
  return *library;
}

const nscd::Spheropolyhedron &AtomVecSpheropolyhedron::shape_of(int i) const
{
  return library->shape(shape[i]);
}

nscd::Pose AtomVecSpheropolyhedron::pose(int i) const
{
  nscd::Pose p;
  p.position = vec3(atom->x[i]);
  p.orientation = quat_of(quat[i]);
  return p;
}

/* Per-atom values for compute property/atom and dump custom: shape, qw qx qy qz,
   inertia1 inertia2 inertia3 (names distinct from the ellipsoid/body ones). */
namespace {
const char *const PROPERTIES[] = {"shape", "qw", "qx", "qy", "qz", "inertia1", "inertia2", "inertia3"};
}

int AtomVecSpheropolyhedron::property_atom(const std::string &name)
{
  for (int k = 0; k < 8; k++)
    if (name == PROPERTIES[k]) return k;
  return -1;
}

void AtomVecSpheropolyhedron::pack_property_atom(int index, double *buf, int nvalues, int groupbit)
{
  for (int i = 0, n = 0; i < atom->nlocal; i++, n += nvalues) {
    if (!(atom->mask[i] & groupbit)) {
      buf[n] = 0.0;
      continue;
    }
    if (index == 0) buf[n] = shape[i];
    else if (index <= 4) buf[n] = quat[i][index - 1];
    else buf[n] = inertia[i][index - 5];
  }
}
