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

/* bond_style wire: LAMMPS glue around nscd::wire::axial_element_forces. */

#include "bond_wire.h"
#include "nscd_args.h"
#include "nscd_arrays.h"

#include "wire/elastic_forces.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neighbor.h"

#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

namespace {
// What bond_coeff and the restart reader both refuse ("" if the values are fine).
std::string problem_of(double stiffness, double rest)
{
  if (!(stiffness >= 0.0) || !std::isfinite(stiffness)) return fmt::format("k_elo = {} must be a finite force >= 0", stiffness);
  if (!(rest > 0.0) || !std::isfinite(rest)) return fmt::format("rest length r0 = {} must be > 0", rest);
  return "";
}
}    // namespace

BondWire::BondWire(LAMMPS *lmp) : Bond(lmp) {}

BondWire::~BondWire()
{
  if (allocated) memory->destroy(setflag);
}

void BondWire::allocate()
{
  allocated = 1;
  const int n = atom->nbondtypes;
  memory->create(setflag, n + 1, "bond:setflag");
  for (int i = 1; i <= n; i++) setflag[i] = 0;
  k_elo.assign(n + 1, 0.0);
  r0.assign(n + 1, 0.0);
  is_string.assign(n + 1, 0);
}

nscd::wire::AxialLaw BondWire::law(int type) const
{
  nscd::wire::AxialLaw law;
  law.k_elo = k_elo[type];
  law.resists_compression = !is_string[type];
  return law;
}

nscd::wire::AxialForces BondWire::element(int type, const double *a, const double *b) const
{
  try {
    return nscd::wire::axial_element_forces(law(type), r0[type], vec3(a), vec3(b));
  } catch (std::exception &e) {
    error->one(FLERR, "bond_style wire: bond of type {}: {}; two bonded wire nodes coincide "
               "(check the initial positions)", type, e.what());
  }
  return {};
}

void BondWire::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  double **x = atom->x, **f = atom->f;
  int **bondlist = neighbor->bondlist;
  const int nlocal = atom->nlocal, newton_bond = force->newton_bond;

  for (int n = 0; n < neighbor->nbondlist; n++) {
    const int i1 = bondlist[n][0], i2 = bondlist[n][1], type = bondlist[n][2];
    const nscd::wire::AxialForces e = element(type, x[i1], x[i2]);
    if (newton_bond || i1 < nlocal)
      for (int d = 0; d < 3; d++) f[i1][d] += e.on_a[d];
    if (newton_bond || i2 < nlocal)
      for (int d = 0; d < 3; d++) f[i2][d] += e.on_b[d];
    if (evflag) {
      const nscd::Vec3 del = vec3(x[i1]) - vec3(x[i2]);
      // LAMMPS' fbond: force on i1 = del * fbond (on_a is parallel to del)
      const double fbond = e.on_a.dot(del) / del.squaredNorm();
      ev_tally(i1, i2, nlocal, newton_bond, e.energy, fbond, del.x(), del.y(), del.z());
    }
  }
}

/* bond_coeff N k_elo r0 [string yes|no]   (string: default no = resists compression) */
void BondWire::coeff(int narg, char **arg)
{
  if (narg != 3 && narg != 5)
    error->all(FLERR, "bond_coeff for bond_style wire: expected 'bond_coeff N k_elo r0 "
               "[string yes|no]', got {} arguments", narg);
  if (!allocated) allocate();
  int ilo, ihi;
  utils::bounds(FLERR, arg[0], 1, atom->nbondtypes, ilo, ihi, error);
  const double stiffness = NSCD_NS::number(lmp, "bond_coeff wire", "k_elo", arg[1]);
  const double rest = NSCD_NS::number(lmp, "bond_coeff wire", "rest length r0", arg[2]);
  const std::string problem = problem_of(stiffness, rest);
  if (!problem.empty()) error->all(FLERR, "bond_coeff wire: {}", problem);
  bool string = false;
  if (narg == 5) {
    if (strcmp(arg[3], "string") != 0)
      error->all(FLERR, "bond_coeff wire: unknown keyword '{}' (expected 'string yes|no')", arg[3]);
    string = yes_or_no(lmp, "bond_coeff wire", "string", arg[4]);
  }
  for (int i = ilo; i <= ihi; i++) {
    k_elo[i] = stiffness;
    is_string[i] = string;
    r0[i] = rest;
    setflag[i] = 1;
  }
}

double BondWire::equilibrium_distance(int type)
{
  return r0[type];
}

void BondWire::write_restart(FILE *fp)
{
  const int n = atom->nbondtypes;
  for (int i = 1; i <= n; i++) {
    const double row[3] = {k_elo[i], r0[i], is_string[i] ? 1.0 : 0.0};
    fwrite(row, sizeof(double), 3, fp);
  }
}

void BondWire::read_restart(FILE *fp)
{
  allocate();
  const int n = atom->nbondtypes;
  std::vector<double> rows(3 * n);
  if (comm->me == 0) utils::sfread(FLERR, rows.data(), sizeof(double), 3 * n, fp, nullptr, error);
  MPI_Bcast(rows.data(), 3 * n, MPI_DOUBLE, 0, world);
  for (int i = 1; i <= n; i++) {
    const double *row = &rows[3 * (i - 1)];
    const std::string problem = problem_of(row[0], row[1]);
    if (!problem.empty() || (row[2] != 0.0 && row[2] != 1.0))
      error->all(FLERR, "bond_style wire: the restart file's coefficients of bond type {} are damaged ({}); write "
                 "it again, or use bond_coeff",
                 i, problem.empty() ? fmt::format("string flag {}", row[2]) : problem);
    k_elo[i] = rows[3 * (i - 1)];
    r0[i] = rows[3 * (i - 1) + 1];
    is_string[i] = rows[3 * (i - 1) + 2] != 0.0;
    setflag[i] = 1;
  }
}

void BondWire::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->nbondtypes; i++)
    fprintf(fp, "%d %.17g %.17g string %s\n", i, k_elo[i], r0[i], is_string[i] ? "yes" : "no");
}

/* Energy of a bond of length sqrt(rsq); fforce = force on i over the distance, as in compute(). */
double BondWire::single(int type, double rsq, int /*i*/, int /*j*/, double &fforce)
{
  const double r = std::sqrt(rsq);
  const double a[3] = {r, 0.0, 0.0}, b[3] = {0.0, 0.0, 0.0};
  const nscd::wire::AxialForces e = element(type, a, b);
  fforce = e.on_a.x() / r;
  return e.energy;
}
