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

/* The create_grains command (doc/create_grains.rst). The shapes, the random draws and the
   contact geometry are lib/'s; this file parses the deck, decides the placements from data
   every rank holds and creates each grain on the rank that owns its position. */

#include "create_grains.h"
#include "atom_vec_spheropolyhedron.h"
#include "nscd_args.h"
#include "nscd_arrays.h"
#include "nscd_boundary.h"
#include "nscd_boundary_fix.h"
#include "nscd_gather.h"
#include "nscd_new_atoms.h"
#include "nscd_wire_elements.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "modify.h"
#include "region.h"
#include "utils.h"

#include "geometry/contact.h"
#include "shape/random_draws.h"
#include "shape/shape_library.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

struct CreateGrains::Request {
  int type = 0;
  Region *region = nullptr;
  int shape_lo = 0, shape_hi = 0;
  double density = 0.0;
  bigint seed = 0;
  enum class Layout { lattice, random } layout = Layout::lattice;
  double spacing = 0.0;    // lattice
  bigint count = 0;        // random: grains wanted
  bigint tries = 0;        // random: candidate positions per grain wanted, at most
  double gap = 0.0;        // smallest surface distance to any other grain
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};    // the region's bounding box
};

struct CreateGrains::Placed {
  int shape;
  double x[3];
  double q[4];
};

struct CreateGrains::NearWire {
  nscd::wire::WirePieces pieces;
  double thickness = 0.0;    // the elements' radius: the wire's plus the gap
};

struct CreateGrains::Candidate {
  long index;    // 1, 2, ... in the order the sites are tried: keys the random draws
  Placed grain;
};

CreateGrains::CreateGrains(LAMMPS *lmp) :
    Command(lmp), request(std::make_unique<Request>()), avec(nullptr)
{}

CreateGrains::~CreateGrains() = default;

/* create_grains TYPE REGION-ID shape IMIN IMAX density RHO seed SEED
                 (lattice SPACING | random N TRIES) [gap G] */
void CreateGrains::command(int narg, char **arg)
{
  avec = AtomVecSpheropolyhedron::find(lmp, "create_grains");
  if (domain->box_exist == 0) error->all(FLERR, "create_grains: create the box first (create_box or read_data)");
  parse(narg, arg);
  Request &r = *request;
  r.region->prematch();

  std::vector<Placed> fixed = gather_grains_near_region();
  const std::vector<NSCDBoundary *> walls = walls_of_new_grains();
  const NearWire wire = wire_elements_near_region();
  std::vector<Candidate> accepted;
  std::vector<Placed> placed;
  bigint tried = 0, hit_wall = 0, hit_wire = 0, hit_old = 0, hit_new = 0, outside = 0;
  auto try_site = [&](const Candidate &c) {
    tried++;
    if (deepest_wall_overlap(c, walls) > -r.gap) return hit_wall++, void();
    if (touches_wire(c, wire)) return hit_wire++, void();
    if (deepest_overlap(c, fixed) > -r.gap) return hit_old++, void();
    if (deepest_overlap(c, placed) > -r.gap) return hit_new++, void();
    accepted.push_back(c);
    placed.push_back(c.grain);
  };
  if (r.layout == Request::Layout::lattice) {
    for (const Candidate &c : lattice_sites()) try_site(c);
  } else {
    const bigint most = r.count * r.tries;
    for (bigint k = 1; k <= most && (bigint) accepted.size() < r.count; k++) {
      double x[3];
      if (!random_site((long) k, x)) {
        outside++;
        continue;
      }
      try_site(draw((long) k, x));
    }
  }
  create(accepted);
  if (comm->me == 0) {
    std::string where = r.layout == Request::Layout::lattice
        ? fmt::format("{} lattice sites", tried)
        : fmt::format("{} random positions in the region ({} more fell outside it; {} wanted)", tried, outside, r.count);
    utils::logmesg(lmp, "create_grains: {} grains placed in region {} from {}; rejected: {} overlapping a wall, "
                   "{} overlapping a wire, {} overlapping grains already there, {} overlapping grains placed now "
                   "(gap {})\n", accepted.size(), r.region->id, where, hit_wall, hit_wire, hit_old, hit_new, r.gap);
  }
  if (r.layout == Request::Layout::random && (bigint) accepted.size() < r.count)
    error->warning(FLERR, "create_grains: placed {} of {} grains in {} tries (region too full); give more "
                   "tries, a larger region or fewer grains", accepted.size(), r.count, r.count * r.tries);
}

void CreateGrains::parse(int narg, char **arg)
{
  Request &r = *request;
  const char *usage = "see doc/create_grains.rst, Syntax";
  if (narg < 2) error->all(FLERR, "Illegal create_grains command: {}", usage);
  r.type = (int) NSCD_NS::whole(lmp, "create_grains", "TYPE", arg[0], 1, INT_MAX);
  if (r.type > atom->ntypes)
    error->all(FLERR, "create_grains: atom type {} does not exist (the box has {} types)", r.type, atom->ntypes);
  r.region = domain->get_region_by_id(arg[1]);
  if (!r.region) error->all(FLERR, "create_grains: region '{}' does not exist; define it with 'region' first", arg[1]);
  if (!r.region->bboxflag)
    error->all(FLERR, "create_grains: region '{}' has no bounding box (an open or 'side out' region); give a "
               "closed region", arg[1]);
  r.lo[0] = r.region->extent_xlo, r.hi[0] = r.region->extent_xhi;
  r.lo[1] = r.region->extent_ylo, r.hi[1] = r.region->extent_yhi;
  r.lo[2] = r.region->extent_zlo, r.hi[2] = r.region->extent_zhi;

  bool have_shape = false, have_density = false, have_seed = false, have_layout = false;
  for (int iarg = 2; iarg < narg;) {
    const std::string key = arg[iarg];
    const int n = key == "shape" ? 2 : key == "random" ? 2 : 1;
    if (key != "shape" && key != "density" && key != "seed" && key != "lattice" && key != "random" && key != "gap")
      error->all(FLERR, "create_grains: unknown keyword '{}'; {}", key, usage);
    if (iarg + n >= narg) error->all(FLERR, "create_grains: keyword '{}' needs {} value(s); {}", key, n, usage);
    if (key == "shape") {
      r.shape_lo = (int) NSCD_NS::whole(lmp, "create_grains", "shape IMIN", arg[iarg + 1], INT_MIN, INT_MAX);
      r.shape_hi = (int) NSCD_NS::whole(lmp, "create_grains", "shape IMAX", arg[iarg + 2], INT_MIN, INT_MAX);
      have_shape = true;
    } else if (key == "density") {
      r.density = NSCD_NS::number(lmp, "create_grains", "density", arg[iarg + 1]);
      if (!(r.density > 0.0) || !std::isfinite(r.density))
        error->all(FLERR, "create_grains: density {} must be positive and finite", arg[iarg + 1]);
      have_density = true;
    } else if (key == "seed") {
      r.seed = NSCD_NS::whole(lmp, "create_grains", "seed", arg[iarg + 1]);
      if (r.seed <= 0) error->all(FLERR, "create_grains: seed {} must be a positive integer", r.seed);
      have_seed = true;
    } else if (key == "lattice") {
      r.layout = Request::Layout::lattice;
      r.spacing = NSCD_NS::number(lmp, "create_grains", "lattice SPACING", arg[iarg + 1]);
      if (!(r.spacing > 0.0) || !std::isfinite(r.spacing))
        error->all(FLERR, "create_grains: lattice spacing {} must be positive and finite", arg[iarg + 1]);
      have_layout = true;
    } else if (key == "random") {
      r.layout = Request::Layout::random;
      r.count = NSCD_NS::whole(lmp, "create_grains", "random N", arg[iarg + 1]);
      r.tries = NSCD_NS::whole(lmp, "create_grains", "random TRIES", arg[iarg + 2]);
      if (r.count < 1) error->all(FLERR, "create_grains: random N {} must be at least 1", r.count);
      if (r.tries < 1) error->all(FLERR, "create_grains: random TRIES {} must be at least 1", r.tries);
      if (r.count > LONG_MAX / r.tries) error->all(FLERR, "create_grains: random N x TRIES is too large");
      have_layout = true;
    } else if (key == "gap") {
      r.gap = NSCD_NS::number(lmp, "create_grains", "gap", arg[iarg + 1]);
      if (!(r.gap >= 0.0) || !std::isfinite(r.gap))
        error->all(FLERR, "create_grains: gap {} must be zero or positive", arg[iarg + 1]);
    }
    iarg += n + 1;
  }
  const int nshapes = avec->shapes().size();
  if (!have_shape) error->all(FLERR, "create_grains: give the shapes to draw from ('shape IMIN IMAX'); {}", usage);
  if (nshapes == 0)
    error->all(FLERR, "create_grains: the shape library is empty; load shapes first ('shapes random' or 'shapes read')");
  if (r.shape_lo < 1 || r.shape_hi > nshapes || r.shape_lo > r.shape_hi)
    error->all(FLERR, "create_grains: shape ids {}..{} must lie within the library's 1..{} with IMIN <= IMAX",
               r.shape_lo, r.shape_hi, nshapes);
  if (!have_density) error->all(FLERR, "create_grains: give the grains' density ('density RHO'); {}", usage);
  if (!have_seed) error->all(FLERR, "create_grains: give a random seed ('seed SEED'); {}", usage);
  if (!have_layout) error->all(FLERR, "create_grains: give the layout ('lattice SPACING' or 'random N TRIES'); {}", usage);
  for (int d = 0; d < 3; d++)
    if (r.lo[d] < domain->boxlo[d] || r.hi[d] > domain->boxhi[d])
      error->all(FLERR, "create_grains: region '{}' reaches outside the box in {} ({:.6g}..{:.6g}, box {:.6g}..{:.6g}); "
                 "use a region inside it",
                 arg[1], "xyz"[d], r.lo[d], r.hi[d], domain->boxlo[d], domain->boxhi[d]);
}

/* The grains already there that a new grain in the region could touch, from every rank (a
   setup command, run once per layer). Points (wire nodes, shape 0) are left out. */
std::vector<CreateGrains::Placed> CreateGrains::gather_grains_near_region() const
{
  const Request &r = *request;
  const double reach = 2.0 * avec->shapes().max_bounding_radius() + r.gap;
  std::vector<Placed> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    if (avec->shape[i] == 0) continue;
    const double *x = atom->x[i];
    bool near = true;
    for (int d = 0; d < 3; d++) near = near && x[d] >= r.lo[d] - reach && x[d] <= r.hi[d] + reach;
    if (!near) continue;
    Placed p{avec->shape[i], {x[0], x[1], x[2]}, {avec->quat[i][0], avec->quat[i][1], avec->quat[i][2], avec->quat[i][3]}};
    mine.push_back(p);
  }
  return gather_records(mine, world, true);
}

/* The wire elements a new grain in the region could touch, from every rank, each as thick as
   the wire plus the gap (fix wire's radius; 0 before fix wire is defined: the wire's axis),
   so that an overlap of the thickened element is a surface distance below the gap. */
CreateGrains::NearWire CreateGrains::wire_elements_near_region() const
{
  const Request &r = *request;
  const WireElements all = gather_wire_elements(lmp, "create_grains");
  NearWire nearby;
  nearby.thickness = wire_radius_of_fix_wire(lmp, 0.0) + r.gap;
  const double reach = avec->shapes().max_bounding_radius() + nearby.thickness;
  auto near = [&](const nscd::Vec3 &p, const nscd::Vec3 &q) {
    for (int d = 0; d < 3; d++)
      if (std::max(p[d], q[d]) < r.lo[d] - reach || std::min(p[d], q[d]) > r.hi[d] + reach) return false;
    return true;
  };
  for (const nscd::wire::WireElement &e : all.pieces.elements) {
    const nscd::Vec3 &p = all.pieces.nodes[e.a], &q = all.pieces.nodes[e.b];
    if (!near(p, q)) continue;
    const int first = (int) nearby.pieces.nodes.size();
    nearby.pieces.nodes.push_back(p);
    nearby.pieces.nodes.push_back(q);
    nearby.pieces.elements.push_back({first, first + 1, 0.0});
  }
  return nearby;
}

/* Whether the candidate comes within the gap of a wire element, from the wire-grain contact
   geometry fix wire uses (lib/wire/wire_overlap.h). */
bool CreateGrains::touches_wire(const Candidate &c, const NearWire &wire) const
{
  if (wire.pieces.elements.empty()) return false;
  nscd::Pose pose;
  pose.position = vec3(c.grain.x);
  pose.orientation = quat_of(c.grain.q);
  const std::vector<nscd::wire::PlacedGrain> grain{{&avec->shapes().shape(c.grain.shape), pose}};
  try {
    return nscd::wire::deepest_overlap_with_grains(wire.pieces, wire.thickness, grain, {}).b >= 0;
  } catch (std::exception &e) {
    error->one(FLERR, "create_grains: the wire overlap test of site {} failed: {}", c.index, e.what());
  }
  return false;
}

/* The example's layout: a simple cubic lattice of the given spacing plus its body centres,
   in x and y at multiples of the spacing from the origin, in z from the region's bottom;
   the sites inside the region, ordered by height, then y, then x. */
std::vector<CreateGrains::Candidate> CreateGrains::lattice_sites() const
{
  const Request &r = *request;
  const double a = r.spacing;
  std::vector<Candidate> sites;
  long index = 0;
  const long nz = (long) std::floor((r.hi[2] - r.lo[2]) / a * 2.0 + 1e-9);
  for (long kz = 0; kz <= nz; kz++) {
    const double shift = (kz % 2) * 0.5;    // even half-planes: the cubic lattice; odd: its body centres
    const double z = r.lo[2] + 0.5 * kz * a;
    for (long j = (long) std::ceil(r.lo[1] / a - shift); (j + shift) * a <= r.hi[1]; j++)
      for (long i = (long) std::ceil(r.lo[0] / a - shift); (i + shift) * a <= r.hi[0]; i++) {
        const double x[3] = {(i + shift) * a, (j + shift) * a, z};
        if (!r.region->match(x[0], x[1], x[2])) continue;
        sites.push_back(draw(++index, x));
      }
  }
  return sites;
}

/* Shape (uniform over IMIN..IMAX) and orientation (uniform rotation) of site `index`, keyed by
   (seed, index) as `shapes assign` keys them by (seed, atom ID). */
CreateGrains::Candidate CreateGrains::draw(long index, const double x[3]) const
{
  const Request &r = *request;
  Candidate c;
  c.index = index;
  const auto seed = (std::uint64_t) r.seed, item = (std::uint64_t) index;
  const int span = r.shape_hi - r.shape_lo + 1;
  c.grain.shape = r.shape_lo + std::min(span - 1, (int) (span * nscd::hashed_uniform(seed, item, 0)));
  nscd::random_quaternion(nscd::hashed_uniform(seed, item, 1), nscd::hashed_uniform(seed, item, 2),
                          nscd::hashed_uniform(seed, item, 3), c.grain.q);
  for (int d = 0; d < 3; d++) c.grain.x[d] = x[d];
  return c;
}

/* Position `index` of the random layout: uniform in the region's bounding box; false when
   it falls outside the region. */
bool CreateGrains::random_site(long index, double x[3]) const
{
  const Request &r = *request;
  for (int d = 0; d < 3; d++)
    x[d] = r.lo[d] + (r.hi[d] - r.lo[d]) * nscd::hashed_uniform((std::uint64_t) r.seed, (std::uint64_t) index, 4 + d);
  return r.region->match(x[0], x[1], x[2]) != 0;
}

/* The deepest overlap of the candidate with any of the grains (negative: the smallest gap
   between their surfaces; -infinity when none is within reach), from the contact geometry
   pair nscd uses. */
double CreateGrains::deepest_overlap(const Candidate &c, const std::vector<Placed> &grains) const
{
  const Request &r = *request;
  const nscd::Spheropolyhedron &shape = avec->shapes().shape(c.grain.shape);
  nscd::Pose pose;
  pose.position = vec3(c.grain.x);
  pose.orientation = quat_of(c.grain.q);
  static thread_local nscd::ContactWorkspace workspace;
  double deepest = -std::numeric_limits<double>::infinity();
  for (const Placed &g : grains) {
    const nscd::Spheropolyhedron &other = avec->shapes().shape(g.shape);
    const double reach = shape.bounding_radius + other.bounding_radius + r.gap;
    const nscd::Vec3 d = vec3(g.x) - pose.position;
    if (d.squaredNorm() >= reach * reach) continue;
    nscd::Pose other_pose;
    other_pose.position = vec3(g.x);
    other_pose.orientation = quat_of(g.q);
    try {
      const nscd::ContactSet set = nscd::contact_grains(shape, pose, other, other_pose, r.gap, workspace, 0.0);
      deepest = std::max(deepest, set.deepest_overlap());
    } catch (std::exception &e) {
      error->one(FLERR, "create_grains: the overlap test of site {} failed: {}", c.index, e.what());
    }
  }
  return deepest;
}

/* The walls and plates (fix nscd/wall, fix nscd/plate) of group all: the only ones a grain
   belongs to when it is created. A grain placed into one would keep that overlap (contacts
   stop it from growing, they do not push it out). */
std::vector<NSCDBoundary *> CreateGrains::walls_of_new_grains() const
{
  std::vector<NSCDBoundary *> walls;
  for (Fix *fix : modify->get_fix_list()) {
    auto *boundary_fix = dynamic_cast<NSCDBoundaryFix *>(fix);
    if (boundary_fix && fix->igroup == 0) walls.push_back(&boundary_fix->boundary());
  }
  return walls;
}

/* The candidate's deepest overlap with any of the walls (negative: the smallest gap within
   the gap allowed; -infinity when none is that near), from the walls' own contact geometry. */
double CreateGrains::deepest_wall_overlap(const Candidate &c, const std::vector<NSCDBoundary *> &walls) const
{
  const nscd::Spheropolyhedron &shape = avec->shapes().shape(c.grain.shape);
  nscd::Pose pose;
  pose.position = vec3(c.grain.x);
  pose.orientation = quat_of(c.grain.q);
  double deepest = -std::numeric_limits<double>::infinity();
  for (NSCDBoundary *wall : walls) {
    try {
      deepest = std::max(deepest, wall->deepest_overlap(shape, pose, request->gap));
    } catch (std::exception &e) {
      error->one(FLERR, "create_grains: the wall overlap test of site {} failed: {}", c.index, e.what());
    }
  }
  return deepest;
}

/* Each rank creates the accepted grains whose centres lie in its sub-domain; IDs follow the
   largest ID there, in the order the sites were tried, so they are the same on any rank count. */
void CreateGrains::create(const std::vector<Candidate> &accepted)
{
  const Request &r = *request;
  tagint mine = 0, max_tag = 0;
  for (int i = 0; i < atom->nlocal; i++) mine = std::max(mine, atom->tag[i]);
  MPI_Allreduce(&mine, &max_tag, 1, MPI_LMP_TAGINT, MPI_MAX, world);

  const bigint natoms_before = atom->natoms;
  const int nlocal_before = atom->nlocal;
  drop_ghosts_for_new_atoms(lmp);
  for (size_t k = 0; k < accepted.size(); k++) {
    const Placed &g = accepted[k].grain;
    if (!in_my_subdomain(domain, g.x)) continue;
    atom->avec->create_atom(r.type, const_cast<double *>(g.x));
    const int i = atom->nlocal - 1;
    atom->tag[i] = max_tag + 1 + (tagint) k;
    avec->set_shape(i, g.shape, r.density * avec->shapes().shape(g.shape).volume);
    for (int d = 0; d < 4; d++) avec->quat[i][d] = g.q[d];
  }
  finish_new_atoms(lmp, natoms_before, nlocal_before, (bigint) accepted.size(),
                   "new grains found no rank (on the box's upper faces?); keep the region inside the box");
}
