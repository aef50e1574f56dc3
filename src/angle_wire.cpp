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

/* angle_style wire: LAMMPS glue around nscd::wire::bending_node_forces. */

#include "angle_wire.h"
#include "nscd_args.h"
#include "nscd_arrays.h"

#include "wire/elastic_forces.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "math_const.h"
#include "memory.h"
#include "neighbor.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

AngleWire::AngleWire(LAMMPS *lmp) : Angle(lmp) {}

AngleWire::~AngleWire()
{
  if (allocated) memory->destroy(setflag);
}

void AngleWire::allocate()
{
  allocated = 1;
  const int n = atom->nangletypes;
  memory->create(setflag, n + 1, "angle:setflag");
  for (int i = 1; i <= n; i++) setflag[i] = 0;
  stiffness.assign(n + 1, 0.0);
  rest.assign(n + 1, 0.0);
}

nscd::wire::BendingForces AngleWire::joint(int type, const double *a, const double *b,
                                           const double *c) const
{
  try {
    return nscd::wire::bending_node_forces(stiffness[type], vec3(a), vec3(b), vec3(c), rest[type]);
  } catch (std::exception &e) {
    error->one(FLERR, "angle_style wire: angle of type {}: {}; two wire nodes of a joint "
               "coincide (check the initial positions)", type, e.what());
  }
  return {};
}

void AngleWire::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  double **x = atom->x, **f = atom->f;
  int **anglelist = neighbor->anglelist;
  const int nlocal = atom->nlocal, newton_bond = force->newton_bond;

  for (int n = 0; n < neighbor->nanglelist; n++) {
    const int i1 = anglelist[n][0], i2 = anglelist[n][1], i3 = anglelist[n][2];
    const int type = anglelist[n][3];
    const nscd::wire::BendingForces e = joint(type, x[i1], x[i2], x[i3]);
    const int node[3] = {i1, i2, i3};
    const nscd::Vec3 *force[3] = {&e.on_a, &e.on_b, &e.on_c};
    for (int k = 0; k < 3; k++)
      if (newton_bond || node[k] < nlocal)
        for (int d = 0; d < 3; d++) f[node[k]][d] += (*force[k])[d];
    if (evflag) {
      const nscd::Vec3 d1 = vec3(x[i1]) - vec3(x[i2]), d2 = vec3(x[i3]) - vec3(x[i2]);
      double f1[3] = {e.on_a.x(), e.on_a.y(), e.on_a.z()};
      double f3[3] = {e.on_c.x(), e.on_c.y(), e.on_c.z()};
      ev_tally(i1, i2, i3, nlocal, newton_bond, e.energy, f1, f3, d1.x(), d1.y(), d1.z(),
               d2.x(), d2.y(), d2.z());
    }
  }
}

/* angle_coeff N k_rot [theta0]: theta0 in degrees as LAMMPS' other angle styles (180: a
   straight wire at rest); kept as the turn at rest nu0 = pi - theta0 in radians. */
void AngleWire::coeff(int narg, char **arg)
{
  if (narg != 2 && narg != 3)
    error->all(FLERR, "angle_coeff for angle_style wire: expected 'angle_coeff N k_rot [theta0]', got {} "
               "arguments", narg);
  if (!allocated) allocate();
  int ilo, ihi;
  utils::bounds(FLERR, arg[0], 1, atom->nangletypes, ilo, ihi, error);
  const double k = NSCD_NS::number(lmp, "angle_coeff wire", "k_rot", arg[1]);
  if (!(k >= 0.0) || !std::isfinite(k))
    error->all(FLERR, "angle_coeff wire: k_rot = {} must be a finite moment >= 0 (k_rot = EI / l)", k);
  const double theta0 = narg == 3 ? NSCD_NS::number(lmp, "angle_coeff wire", "theta0", arg[2]) : 180.0;
  if (!(theta0 > 0.0 && theta0 <= 180.0))
    error->all(FLERR, "angle_coeff wire: theta0 = {} must be in (0, 180] degrees (180: straight); "
               "see doc/angle_style_wire.rst, Errors", theta0);
  for (int i = ilo; i <= ihi; i++) {
    stiffness[i] = k;
    rest[i] = (180.0 - theta0) * MathConst::MY_PI / 180.0;
    setflag[i] = 1;
  }
}

double AngleWire::equilibrium_angle(int type)
{
  return MathConst::MY_PI - rest[type];
}

/* The coefficients behind a marker a stiffness cannot have (k_rot >= 0), then the rest turns:
   files written before the rest turn existed hold k_rot alone and are read as straight. */
static constexpr double RESTART_WITH_REST_TURN = -2.0;

void AngleWire::write_restart(FILE *fp)
{
  const int n = atom->nangletypes;
  if (n == 0) return;
  fwrite(&RESTART_WITH_REST_TURN, sizeof(double), 1, fp);
  fwrite(&stiffness[1], sizeof(double), n, fp);
  fwrite(&rest[1], sizeof(double), n, fp);
}

void AngleWire::read_restart(FILE *fp)
{
  allocate();
  const int n = atom->nangletypes;
  if (n == 0) return;
  if (comm->me == 0) {
    double first;
    utils::sfread(FLERR, &first, sizeof(double), 1, fp, nullptr, error);
    if (first == RESTART_WITH_REST_TURN) {
      utils::sfread(FLERR, &stiffness[1], sizeof(double), n, fp, nullptr, error);
      utils::sfread(FLERR, &rest[1], sizeof(double), n, fp, nullptr, error);
    } else {
      stiffness[1] = first;
      if (n > 1) utils::sfread(FLERR, &stiffness[2], sizeof(double), n - 1, fp, nullptr, error);
    }
  }
  MPI_Bcast(&stiffness[1], n, MPI_DOUBLE, 0, world);
  MPI_Bcast(&rest[1], n, MPI_DOUBLE, 0, world);
  for (int i = 1; i <= n; i++) {
    if (!(stiffness[i] >= 0.0) || !std::isfinite(stiffness[i]))
      error->all(FLERR, "angle_style wire: the restart file's k_rot = {} of angle type "
                 "{} is damaged; write it again, or use angle_coeff", stiffness[i], i);
    if (!(rest[i] >= 0.0 && rest[i] < MathConst::MY_PI))
      error->all(FLERR, "angle_style wire: the restart file's rest turn {} of angle type {} "
                 "is damaged; write it again, or use angle_coeff", rest[i], i);
    setflag[i] = 1;
  }
}

void AngleWire::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->nangletypes; i++)
    fprintf(fp, "%d %.17g %.17g\n", i, stiffness[i], 180.0 - rest[i] * 180.0 / MathConst::MY_PI);
}

double AngleWire::single(int type, int i1, int i2, int i3)
{
  // the images of the outer nodes closest to the middle one, as compute angle/local uses
  double **x = atom->x;
  double a[3], c[3];
  domain->closest_image(x[i2], x[i1], a);
  domain->closest_image(x[i2], x[i3], c);
  return joint(type, a, x[i2], c).energy;
}
