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

/* compute nscd/stress/atom: the Love-Weber stress of each grain from its contact forces. */

#include "compute_nscd_stress_atom.h"

#include "atom.h"
#include "atom_vec_spheropolyhedron.h"
#include "domain.h"
#include "error.h"
#include "fix_nscd.h"
#include "fix_wire.h"

#include "shape/spheropolyhedron.h"
#include "solver/contact_problem.h"

#include <string>

using namespace LAMMPS_NS;

namespace {
enum Column { XX, YY, ZZ, XY, XZ, YZ, NCOLUMNS };
}    // namespace

/* compute ID group nscd/stress/atom [boundaries yes|no] [wire yes|no] [volume grain|none] */
ComputeNSCDStressAtom::ComputeNSCDStressAtom(LAMMPS *lmp, int narg, char **arg) :
    ComputeNSCDGrainSums(lmp, narg, arg, NCOLUMNS, "nscd/stress/atom"), per_volume(true)
{
  const char *usage = "see doc/compute_nscd_stress_atom.rst, Syntax";
  for (int iarg = 3; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (iarg + 1 >= narg)
      error->all(FLERR, "compute nscd/stress/atom: keyword '{}' needs a value; {}", key, usage);
    const std::string value = arg[iarg + 1];
    if (parse_contact_keyword(key, value)) {
    } else if (key == "volume" && (value == "grain" || value == "none")) {
      per_volume = value == "grain";
    } else {
      error->all(FLERR, "compute nscd/stress/atom: unknown keyword or value '{} {}'; {}", key, value, usage);
    }
  }
}

void ComputeNSCDStressAtom::compute_peratom()
{
  start_sums();
  add_grain_contacts();
  if (wire) add_wire_contacts();
  finish_sums();
  finish_owned();
}

/* The force on a grain at a point adds sym(f (x) r), r from the grain's centre (nearest
   periodic image: the grain found by ID may be another image than the one that touched). */
void ComputeNSCDStressAtom::add_force(double tag, const double *f, const double *point)
{
  const int i = atom->map((tagint) tag);
  double r[3] = {0.0, 0.0, 0.0};
  if (i >= 0) {
    for (int k = 0; k < 3; k++) r[k] = point[k] - atom->x[i][k];
    domain->minimum_image(r);
  }
  const double row[NCOLUMNS] = {f[0] * r[0], f[1] * r[1], f[2] * r[2], 0.5 * (f[0] * r[1] + f[1] * r[0]),
                                0.5 * (f[0] * r[2] + f[2] * r[0]), 0.5 * (f[1] * r[2] + f[2] * r[1])};
  add((std::int64_t) tag, row);
}

/* Each contact point of the last solve: its force on i, and the opposite on j (a grain). */
void ComputeNSCDStressAtom::add_grain_contacts()
{
  const std::vector<nscd::Contact> &contacts = fix->contacts();
  const double dt = fix->timestep();
  for (size_t k = 0; k < contacts.size(); k++) {
    const nscd::Contact &c = contacts[k];
    const bool boundary = fix->boundary_of(k) != 0;
    if (boundary && !with_boundaries) continue;
    const nscd::Vec3 force = c.impulse / dt;
    const double on_i[3] = {force.x(), force.y(), force.z()}, on_j[3] = {-on_i[0], -on_i[1], -on_i[2]};
    const double point[3] = {c.point.x(), c.point.y(), c.point.z()};
    add_force((double) c.key.tag_i, on_i, point);
    if (!boundary) add_force((double) c.key.tag_j, on_j, point);
  }
}

/* fix wire's rows give the force on the wire (fn n + f_t, the step's mean): the grain
   receives the opposite. */
void ComputeNSCDStressAtom::add_wire_contacts()
{
  const std::vector<double> rows = wire->contact_rows();
  const size_t cols = FixWire::CONTACT_COLUMNS;
  for (size_t r = 0; r + cols <= rows.size(); r += cols) {
    const double *row = &rows[r];
    if (row[FixWire::ROW_KIND] != FixWire::ROW_WIRE_GRAIN) continue;
    double on_grain[3];
    for (int k = 0; k < 3; k++) on_grain[k] = -(row[FixWire::ROW_NORMAL_FORCE] * row[FixWire::ROW_NORMAL + k] +
                     row[FixWire::ROW_TANGENTIAL_FORCE + k]);
    add_force(row[FixWire::ROW_OTHER], on_grain, row + FixWire::ROW_POINT);
  }
}

/* Sums over the grain's volume (volume grain); atoms outside the group, and wire nodes
   (points, no volume), get zeros. */
void ComputeNSCDStressAtom::finish_owned()
{
  auto *avec = AtomVecSpheropolyhedron::find(lmp, "compute nscd/stress/atom");
  for (int i = 0; i < atom->nlocal; i++) {
    double *row = array_atom[i];
    const bool grain = (atom->mask[i] & groupbit) && avec->shape[i] != 0;
    const double scale = !grain ? 0.0 : per_volume ? 1.0 / avec->shape_of(i).volume : 1.0;
    for (int k = 0; k < NCOLUMNS; k++) row[k] *= scale;
  }
}
