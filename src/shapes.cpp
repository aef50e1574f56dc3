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

/* The `shapes` command. Shape geometry and the generator live in lib/shape; this file
   parses the deck and moves shapes onto atoms. */

#include "shapes.h"
#include "nscd_checks.h"
#include "nscd_args.h"

#include "atom.h"
#include "atom_vec_spheropolyhedron.h"
#include "comm.h"
#include "error.h"
#include "group.h"
#include "utils.h"

#include "shape/random_draws.h"
#include "shape/random_grain.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

using namespace LAMMPS_NS;

using nscd::hashed_uniform;
using nscd::random_quaternion;

void Shapes::command(int narg, char **arg)
{
  if (narg < 1)
    error->all(FLERR, "Illegal shapes command: expected read, random, write, info or assign");
  avec = AtomVecSpheropolyhedron::find(lmp, "shapes");
  const std::string what = arg[0];
  if (what == "read") read(narg - 1, arg + 1);
  else if (what == "random") random(narg - 1, arg + 1);
  else if (what == "write") write(narg - 1, arg + 1);
  else if (what == "info") info(narg - 1, arg + 1);
  else if (what == "assign") assign(narg - 1, arg + 1);
  else
    error->all(FLERR, "Illegal shapes command: unknown keyword '{}' (expected read, random, "
               "write, info or assign)", what);
}

void Shapes::broadcast(std::string &text)
{
  bigint size = (bigint) text.size();
  MPI_Bcast(&size, 1, MPI_LMP_BIGINT, 0, world);
  if (size > INT_MAX)    // one MPI message, and the restart file stores it as one string
    error->all(FLERR, "shapes: the shape library is too large to send ({} "
               "bytes); use fewer or simpler shapes, or reuse shapes", size);
  const int n = (int) size;
  text.resize(n);
  MPI_Bcast(&text[0], n, MPI_CHAR, 0, world);
}

/* shapes read FILE */
void Shapes::read(int narg, char **arg)
{
  if (narg != 1) error->all(FLERR, "Illegal shapes read command: expected 'shapes read FILE'");
  // Rank 0 reads (the file may exist there only); every rank gets the same library.
  std::string text, problem;
  if (comm->me == 0) {
    try {
      nscd::ShapeLibrary parsed;
      parsed.read_file(arg[0]);
      nscd::ShapeLibrary all = avec->shapes();    // names must be new to the loaded library
      all.append(parsed);
      text = parsed.serialize();
    } catch (std::exception &e) {
      problem = e.what();
      if (problem.rfind(arg[0], 0) != 0) problem = std::string(arg[0]) + ": " + problem;
    }
  }
  broadcast(problem);
  if (!problem.empty()) error->all(FLERR, "shapes read: {}", problem);
  broadcast(text);
  const nscd::ShapeLibrary more = nscd::ShapeLibrary::deserialize(text);
  const int first = avec->shapes().size() + 1;
  avec->add_shapes(more);
  if (comm->me == 0)
    utils::logmesg(lmp, "shapes read: {} shape(s) from {}, ids {}..{}\n", more.size(), arg[0],
                   first, avec->shapes().size());
}

/* shapes random N seed S [vertices NMIN NMAX] [size DMIN DMAX] [axes B C] [radius R] */
void Shapes::random(int narg, char **arg)
{
  if (narg < 3 || strcmp(arg[1], "seed") != 0)
    error->all(FLERR, "Illegal shapes random command: expected "
               "'shapes random N seed SEED [keyword values ...]'");
  const bigint requested = NSCD_NS::whole(lmp, "shapes random", "count", arg[0]);
  const bigint seed = NSCD_NS::whole(lmp, "shapes random", "seed", arg[2]);
  const int room = nscd::ShapeLibrary::kMaxShapes - avec->shapes().size();
  if (requested < 1 || requested > room)
    error->all(FLERR, "shapes random: count {} must be between 1 and {} ({} shapes at most, {} loaded); reuse "
               "shapes ('shapes assign')",
               requested, room, nscd::ShapeLibrary::kMaxShapes, avec->shapes().size());
  const int count = (int) requested;
  nscd::RandomGrainParams params;
  for (int iarg = 3; iarg < narg;) {
    const std::string key = arg[iarg];
    auto need = [&](int n) {
      if (iarg + n >= narg) error->all(FLERR, "shapes random: keyword '{}' needs {} value(s)", key, n);
    };
    if (key == "vertices") {
      need(2);
      const bigint lo = NSCD_NS::whole(lmp, "shapes random", "vertices NMIN", arg[iarg + 1]);
      const bigint hi = NSCD_NS::whole(lmp, "shapes random", "vertices NMAX", arg[iarg + 2]);
      if (lo < 4 || hi < lo || hi > 10000)
        error->all(FLERR, "shapes random: vertices {} {} must satisfy 4 <= NMIN <= NMAX <= 10000",
                   lo, hi);
      params.min_vertices = (int) lo;
      params.max_vertices = (int) hi;
      iarg += 3;
    } else if (key == "size") {
      need(2);
      params.min_diameter = NSCD_NS::number(lmp, "shapes random", "size DMIN", arg[iarg + 1]);
      params.max_diameter = NSCD_NS::number(lmp, "shapes random", "size DMAX", arg[iarg + 2]);
      iarg += 3;
    } else if (key == "axes") {
      need(2);
      params.ratio_b = NSCD_NS::number(lmp, "shapes random", "axes B/A", arg[iarg + 1]);
      params.ratio_c = NSCD_NS::number(lmp, "shapes random", "axes C/A", arg[iarg + 2]);
      iarg += 3;
    } else if (key == "radius") {
      need(1);
      params.radius = NSCD_NS::number(lmp, "shapes random", "radius", arg[iarg + 1]);
      iarg += 2;
    } else {
      error->all(FLERR, "shapes random: unknown keyword '{}' (expected vertices, size, axes, "
                 "radius)", key);
    }
  }
  nscd::ShapeLibrary more;
  try {
    nscd::add_random_grains(more, params, count, (std::uint64_t) seed);
  } catch (std::exception &e) {
    error->all(FLERR, "shapes random: {}", e.what());
  }
  // Random grains are named after their seed: a taken name means a seed used before.
  if (more.size() > 0 && avec->shapes().find(more.name(1)) > 0)
    error->all(FLERR, "shapes random: seed {} was used before (its shape name '{}' is shape {} "
               "already); give another seed", seed, more.name(1), avec->shapes().find(more.name(1)));
  const int first = avec->shapes().size() + 1;
  avec->add_shapes(more);
  if (comm->me == 0)
    utils::logmesg(lmp, "shapes random: {} grain shape(s), ids {}..{}\n", count, first,
                   avec->shapes().size());
}

/* shapes write FILE : rank 0 writes the library (body frame) in the text format. */
void Shapes::write(int narg, char **arg)
{
  if (narg != 1) error->all(FLERR, "Illegal shapes write command: expected 'shapes write FILE'");
  if (avec->shapes().empty())
    error->all(FLERR, "shapes write: the shape library is empty; load shapes first with "
               "'shapes read' or 'shapes random'");
  if (comm->me != 0) return;
  std::ofstream out(arg[0]);
  if (!out) error->one(FLERR, "shapes write: cannot open file {} for writing", arg[0]);
  avec->shapes().write(out);
  if (!out) error->one(FLERR, "shapes write: writing {} failed", arg[0]);
}

/* shapes info : one line per shape in the log. */
void Shapes::info(int narg, char ** /*arg*/)
{
  if (narg != 0) error->all(FLERR, "Illegal shapes info command: it takes no arguments");
  if (comm->me != 0) return;
  const nscd::ShapeLibrary &lib = avec->shapes();
  std::string text = fmt::format("shapes info: {} shape(s)\n  id vertices faces radius "
                                 "volume bounding_radius name\n", lib.size());
  for (int id = 1; id <= lib.size(); id++) {
    const nscd::Spheropolyhedron &s = lib.shape(id);
    text += fmt::format("  {} {} {} {:.6g} {:.6g} {:.6g} {}\n", id, s.vertices.size(),
                        s.faces.size(), s.radius, s.volume, s.bounding_radius, lib.name(id));
  }
  text += fmt::format("  largest bounding radius {:.6g} (grain centres closer than twice this may overlap)\n",
                      lib.max_bounding_radius());
  utils::logmesg(lmp, text);
}

/* Every shape id in lo..hi must give finite, normal mass and moments with the given density
   or mass (density 1e400 is inf, 1e-320 denormal): checked on all ranks before any atom
   changes, with the value named. */
void Shapes::check_mass_properties(int lo, int hi, double density, double mass)
{
  if (!(density > 0.0) && !(mass > 0.0)) return;
  for (int id = lo; id <= hi; id++) {
    try {
      const nscd::Spheropolyhedron &shape = avec->shapes().shape(id);
      if (density > 0.0) nscd::grain_inertia_from_density(shape, density);
      else nscd::grain_inertia_from_mass(shape, mass);
    } catch (std::exception &e) {
      error->all(FLERR, "shapes assign: shape {}: {}", id, e.what());    // e.what() names the density or mass
    }
  }
}

/* shapes assign GROUP [shape I | shape random IMIN IMAX SEED] [density RHO | mass M]
                       [orient random SEED | orient quat W X Y Z] */
void Shapes::assign(int narg, char **arg)
{
  if (narg < 2)
    error->all(FLERR, "Illegal shapes assign command: expected 'shapes assign GROUP keyword "
               "values ...'");
  if (atom->natoms == 0 && comm->me == 0)
    error->warning(FLERR, "shapes assign: there are no atoms yet (create them first)");
  const int igroup = group->find(arg[0]);
  if (igroup < 0) error->all(FLERR, "shapes assign: unknown group '{}'", arg[0]);
  const int groupbit = group->bitmask[igroup];
  const int nshapes = avec->shapes().size();

  enum { KEEP, FIXED, RANDOM } shape_mode = KEEP, orient_mode = KEEP;
  int shape_lo = 0, shape_hi = 0;
  bigint shape_seed = 0, orient_seed = 0;
  double density = -1.0, mass = -1.0, fixed_quat[4] = {1.0, 0.0, 0.0, 0.0};

  for (int iarg = 1; iarg < narg;) {
    const std::string key = arg[iarg];
    auto need = [&](int n) {
      if (iarg + n >= narg) error->all(FLERR, "shapes assign: keyword '{}' needs {} value(s)", key, n);
    };
    if (key == "shape" && iarg + 1 < narg && strcmp(arg[iarg + 1], "random") == 0) {
      need(4);
      shape_mode = RANDOM;
      shape_lo = (int) NSCD_NS::whole(lmp, "shapes assign", "shape random IMIN", arg[iarg + 2], INT_MIN, INT_MAX);
      shape_hi = (int) NSCD_NS::whole(lmp, "shapes assign", "shape random IMAX", arg[iarg + 3], INT_MIN, INT_MAX);
      shape_seed = NSCD_NS::whole(lmp, "shapes assign", "shape random SEED", arg[iarg + 4]);
      if (shape_lo > shape_hi)
        error->all(FLERR, "shapes assign: shape random {} {}: IMIN must not exceed IMAX",
                   shape_lo, shape_hi);
      iarg += 5;
    } else if (key == "shape") {
      need(1);
      shape_mode = FIXED;
      shape_lo = shape_hi = (int) NSCD_NS::whole(lmp, "shapes assign", "shape", arg[iarg + 1], INT_MIN, INT_MAX);
      iarg += 2;
    } else if (key == "density") {
      need(1);
      density = NSCD_NS::number(lmp, "shapes assign", "density", arg[iarg + 1]);
      if (!(density > 0.0)) error->all(FLERR, "shapes assign: density {} must be positive", density);
      iarg += 2;
    } else if (key == "mass") {
      need(1);
      mass = NSCD_NS::number(lmp, "shapes assign", "mass", arg[iarg + 1]);
      if (!(mass > 0.0)) error->all(FLERR, "shapes assign: mass {} must be positive", mass);
      iarg += 2;
    } else if (key == "orient" && iarg + 1 < narg && strcmp(arg[iarg + 1], "random") == 0) {
      need(2);
      orient_mode = RANDOM;
      orient_seed = NSCD_NS::whole(lmp, "shapes assign", "orient random SEED", arg[iarg + 2]);
      iarg += 3;
    } else if (key == "orient" && iarg + 1 < narg && strcmp(arg[iarg + 1], "quat") == 0) {
      need(5);
      orient_mode = FIXED;
      double norm = 0.0;
      for (int k = 0; k < 4; k++) {
        fixed_quat[k] = NSCD_NS::number(lmp, "shapes assign", "orient quat", arg[iarg + 2 + k]);
        norm += fixed_quat[k] * fixed_quat[k];
      }
      if (!(norm > 1e-20)) error->all(FLERR, "shapes assign: orient quat has zero length");
      for (double &c : fixed_quat) c /= std::sqrt(norm);
      iarg += 6;
    } else {
      error->all(FLERR, "shapes assign: unknown keyword '{}' (expected shape, density, mass, "
                 "orient)", key);
    }
  }
  if (shape_mode != KEEP && (shape_lo < 0 || shape_hi > nshapes || shape_lo > shape_hi))
    error->all(FLERR, "shapes assign: shape ids {}..{} are outside the library's 0..{}; load "
               "shapes with 'shapes read' or 'shapes random'", shape_lo, shape_hi, nshapes);
  if (density > 0.0 && mass > 0.0)
    error->all(FLERR, "shapes assign: give density or mass, not both");
  check_mass_properties(shape_mode == KEEP ? 1 : std::max(shape_lo, 1),
                        shape_mode == KEEP ? nshapes : shape_hi, density, mass);

  int *mask = atom->mask;
  tagint *tag = atom->tag;
  auto shape_of = [&](int i) {
    if (shape_mode == FIXED) return shape_lo;
    if (shape_mode == RANDOM)
      return shape_lo + (int) ((shape_hi - shape_lo + 1) * hashed_uniform(shape_seed, tag[i], 0));
    return avec->shape[i];
  };
  if (density > 0.0) {    // a point has no volume: check on all ranks before changing anything
    const tagint any_point =
        NSCD_NS::lowest_tag_where(lmp, [&](int i) { return (mask[i] & groupbit) && shape_of(i) == 0; });
    if (any_point)
      error->all(FLERR, "shapes assign: atom ID {} is a point (shape 0) and has no volume; "
                 "give its 'mass' instead of a density", any_point);
  }
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const int id = shape_of(i);
    double m = avec->rmass[i];
    if (mass > 0.0) m = mass;
    if (density > 0.0) m = density * avec->shapes().shape(id).volume;
    avec->set_shape(i, id, m);
    if (orient_mode == FIXED)
      for (int k = 0; k < 4; k++) avec->quat[i][k] = fixed_quat[k];
    if (orient_mode == RANDOM)
      random_quaternion(hashed_uniform(orient_seed, tag[i], 1), hashed_uniform(orient_seed, tag[i], 2),
                        hashed_uniform(orient_seed, tag[i], 3), avec->quat[i]);
  }
}
