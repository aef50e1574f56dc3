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

/* compute nscd/crush/atom: the largest contact force on each grain against a grain-crushing
   strength (doc/compute_nscd_crush_atom.rst). */

#include "compute_nscd_crush_atom.h"

#include "atom.h"
#include "atom_vec_spheropolyhedron.h"
#include "error.h"
#include "fix_nscd.h"
#include "fix_wire.h"
#include "nscd_args.h"

#include "nscd_contact_pairs.h"
#include "shape/spheropolyhedron.h"

#include <cmath>
#include <map>
#include <string>
#include <utility>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

namespace {
enum Column { FORCE, DIAMETER, TENSILE_STRESS, CRUSH_INDEX, NCOLUMNS };
}    // namespace

/* compute ID group nscd/crush/atom S0 [size D0 weibull M] [boundaries yes|no] [wire yes|no] */
ComputeNSCDCrushAtom::ComputeNSCDCrushAtom(LAMMPS *lmp, int narg, char **arg) :
    ComputeNSCDGrainSums(lmp, narg, arg, NCOLUMNS, "nscd/crush/atom", Combine::largest), strength(0.0),
    reference_size(0.0), weibull(0.0)
{
  parse(narg, arg);
}

void ComputeNSCDCrushAtom::parse(int narg, char **arg)
{
  const std::string where = "compute nscd/crush/atom";
  const char *usage = "see doc/compute_nscd_crush_atom.rst, Syntax";
  if (narg < 4) error->all(FLERR, "{}: the strength S0 is missing; {}", where, usage);
  strength = NSCD_NS::number(lmp, where, "strength", arg[3]);
  if (!(strength > 0.0)) error->all(FLERR, "{}: strength {} must be > 0 (a stress, force/area); {}", where, arg[3], usage);
  for (int iarg = 4; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (iarg + 1 >= narg) error->all(FLERR, "{}: keyword '{}' needs a value; {}", where, key, usage);
    const std::string value = arg[iarg + 1];
    if (parse_contact_keyword(key, value)) {
    } else if (key == "size" || key == "weibull") {
      const double v = NSCD_NS::number(lmp, where, key, value);
      if (!(v > 0.0)) error->all(FLERR, "{}: {} {} must be > 0; {}", where, key, value, usage);
      (key == "size" ? reference_size : weibull) = v;
    } else {
      error->all(FLERR, "{}: unknown keyword or value '{} {}'; {}", where, key, value, usage);
    }
  }
  if ((reference_size > 0.0) != (weibull > 0.0))
    error->all(FLERR, "{}: the size effect needs both 'size D0' and 'weibull M'; "
               "give both or neither (doc/compute_nscd_crush_atom.rst, Errors)", where);
}

void ComputeNSCDCrushAtom::compute_peratom()
{
  start_sums();
  add_grain_contacts();
  if (wire) add_wire_contacts();
  finish_sums();
  finish_owned();
}

void ComputeNSCDCrushAtom::add_largest(double tag, double force)
{
  const double row[NCOLUMNS] = {force, 0.0, 0.0, 0.0};
  add((std::int64_t) tag, row);
}

/* A contact's force is its pair's: the normal forces of all its points (a face on a face
   presses with the whole patch). */
void ComputeNSCDCrushAtom::add_grain_contacts()
{
  const auto pairs = group_contact_pairs(fix->contacts(), fix->timestep(),
                                         [this](size_t k) { return fix->boundary_of(k); });
  for (const ContactPair &p : pairs) {
    if (p.boundary != 0 && !with_boundaries) continue;
    add_largest((double) p.tag_i, p.normal_force);
    if (p.boundary == 0) add_largest((double) p.tag_j, p.normal_force);
  }
}

/* A wire element's contact with a grain: the normal forces of its points (two for an element
   lying on a face), summed per element and grain. */
void ComputeNSCDCrushAtom::add_wire_contacts()
{
  const std::vector<double> rows = wire->contact_rows();
  const size_t cols = FixWire::CONTACT_COLUMNS;
  std::map<std::pair<double, double>, double> per_element;
  for (size_t r = 0; r + cols <= rows.size(); r += cols)
    if (rows[r + FixWire::ROW_KIND] == FixWire::ROW_WIRE_GRAIN)
      per_element[{rows[r + FixWire::ROW_NODE_1], rows[r + FixWire::ROW_OTHER]}] += rows[r + FixWire::ROW_NORMAL_FORCE];
  for (const auto &[key, force] : per_element) add_largest(key.second, force);
}

/* Diameter, characteristic tensile stress F / d^2 and its ratio to the strength at that size,
   sigma_f(d) = S0 (d / D0)^(-3/m) (or S0); atoms outside the group and wire nodes get zeros. */
void ComputeNSCDCrushAtom::finish_owned()
{
  auto *avec = AtomVecSpheropolyhedron::find(lmp, "compute nscd/crush/atom");
  for (int i = 0; i < atom->nlocal; i++) {
    double *row = array_atom[i];
    if (!(atom->mask[i] & groupbit) || avec->shape[i] == 0) {
      for (int k = 0; k < NCOLUMNS; k++) row[k] = 0.0;
      continue;
    }
    const double d = std::cbrt(6.0 * avec->shape_of(i).volume / M_PI);
    const double grain_strength = weibull > 0.0 ? strength * std::pow(d / reference_size, -3.0 / weibull) : strength;
    row[DIAMETER] = d;
    row[TENSILE_STRESS] = row[FORCE] / (d * d);
    row[CRUSH_INDEX] = row[TENSILE_STRESS] / grain_strength;
  }
}
