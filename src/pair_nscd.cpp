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

/* pair_style nscd: narrow phase over LAMMPS' neighbour list, contact laws per type pair. */

#include "pair_nscd.h"
#include "nscd_args.h"

#include "atom.h"
#include "atom_vec_spheropolyhedron.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include "nscd_arrays.h"
#include "nscd_contact.h"
#include "nscd_restart_blocks.h"

#include "geometry/contact.h"
#include "math/capacity_bytes.h"
#include "shape/shape_library.h"
#include "solver/contact_problem.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

struct PairNSCD::Found {
  std::vector<nscd::Contact> contacts;
  nscd::ContactWorkspace workspace;
};

PairNSCD::PairNSCD(LAMMPS *lmp) :
    Pair(lmp), activation_given(-1.0), activation_fraction(0.1), activation(0.0), reach_given(-1.0),
    reach_fraction(0.5), reach(0.0), mu(nullptr), restitution_coeff(nullptr), avec(nullptr),
    found(std::make_unique<Found>())
{
  single_enable = 0;
  restartinfo = 1;
  no_virial_fdotr_compute = 1;    // no forces here: fix nscd carries the contact virial
  finitecutflag = 1;
}

PairNSCD::~PairNSCD()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(mu);
    memory->destroy(restitution_coeff);
  }
}

const std::vector<nscd::Contact> &PairNSCD::contacts() const
{
  return found->contacts;
}

void PairNSCD::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  memory->create(mu, n + 1, n + 1, "pair:mu");
  memory->create(restitution_coeff, n + 1, n + 1, "pair:restitution");
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) {
      setflag[i][j] = 0;
      mu[i][j] = restitution_coeff[i][j] = 0.0;
    }
}

/* pair_style nscd [activation D | activation/fraction F] [reach D | reach/fraction F]
   Each distance is given once, in one of its two forms: two values for one distance are
   refused rather than letting the later one win silently. */
void PairNSCD::settings(int narg, char **arg)
{
  activation_given = -1.0;
  activation_fraction = 0.1;
  reach_given = -1.0;
  reach_fraction = 0.5;
  std::string activation_as, reach_as;    // the keyword and value that gave each distance
  auto once = [&](std::string &given_as, const char *key, const char *value) {
    const std::string now = fmt::format("{} {}", key, value);
    if (!given_as.empty())
      error->all(FLERR, "pair_style nscd: '{}' and '{}' both set the {} distance; give it "
                 "once", given_as, now, strncmp(key, "activation", 10) == 0 ? "activation" : "reach");
    given_as = now;
  };
  for (int iarg = 0; iarg < narg; iarg += 2) {
    // (the text as given in the messages: older LAMMPS parse 1e400 as inf without a word)
    const std::string text = NSCD_NS::keyword_value(lmp, "pair_style nscd", narg, arg, iarg,
                                                    {"activation", "activation/fraction", "reach", "reach/fraction"});
    const double value = NSCD_NS::number(lmp, "pair_style nscd", arg[iarg], text);
    if (strcmp(arg[iarg], "activation") == 0) {
      once(activation_as, arg[iarg], arg[iarg + 1]);
      if (!(value >= 0.0) || !std::isfinite(value))
        error->all(FLERR, "pair_style nscd: activation {} must be finite and >= 0", arg[iarg + 1]);
      activation_given = value;
    } else if (strcmp(arg[iarg], "activation/fraction") == 0) {
      once(activation_as, arg[iarg], arg[iarg + 1]);
      if (!(value >= 0.0 && value <= NSCD_NS::MAX_ACTIVATION_FRACTION))
        error->all(FLERR, "pair_style nscd: activation/fraction {} must be in [0, {}]; for fast "
                   "grains lower the timestep", value, NSCD_NS::MAX_ACTIVATION_FRACTION);
      activation_given = -1.0;
      activation_fraction = value;
    } else if (strcmp(arg[iarg], "reach") == 0) {
      once(reach_as, arg[iarg], arg[iarg + 1]);
      if (!(value >= 0.0) || !std::isfinite(value))
        error->all(FLERR, "pair_style nscd: reach {} must be finite and >= 0", arg[iarg + 1]);
      reach_given = value;
    } else if (strcmp(arg[iarg], "reach/fraction") == 0) {
      once(reach_as, arg[iarg], arg[iarg + 1]);
      if (!(value >= 0.0 && value <= NSCD_NS::MAX_REACH_FRACTION))
        error->all(FLERR, "pair_style nscd: reach/fraction {} must be in [0, {}] (a multiple of the "
                   "smallest grain's bounding radius)", value, NSCD_NS::MAX_REACH_FRACTION);
      reach_given = -1.0;
      reach_fraction = value;
    }
  }
}

/* pair_coeff I J MU [restitution E] */
void PairNSCD::coeff(int narg, char **arg)
{
  if (narg != 3 && narg != 5)
    error->all(FLERR, "Illegal pair_coeff command for pair_style nscd: expected 'pair_coeff I J "
               "friction [restitution E]'");
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double friction_one = NSCD_NS::number(lmp, "pair_coeff nscd", "friction", arg[2]);
  if (!(friction_one >= 0.0) || !std::isfinite(friction_one))
    error->all(FLERR, "pair_coeff nscd: friction coefficient {} must be finite and >= 0", friction_one);
  double restitution_one = 0.0;
  if (narg == 5) {
    if (strcmp(arg[3], "restitution") != 0)
      error->all(FLERR, "pair_coeff nscd: unknown keyword '{}' (expected restitution)", arg[3]);
    restitution_one = NSCD_NS::number(lmp, "pair_coeff nscd", "restitution", arg[4]);
    if (!(restitution_one >= 0.0 && restitution_one <= 1.0))
      error->all(FLERR, "pair_coeff nscd: restitution {} must be in [0, 1]", restitution_one);
  }
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      mu[i][j] = friction_one;
      restitution_coeff[i][j] = restitution_one;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "pair_coeff nscd: no type pair in {} {}", arg[0], arg[1]);
}

void PairNSCD::init_style()
{
  avec = AtomVecSpheropolyhedron::find(lmp, "pair_style nscd");
  if (force->newton_pair == 0)
    error->all(FLERR, "pair_style nscd needs 'newton on' (each contact is then found by exactly "
               "one rank)");
  if (avec->shapes().empty())
    error->all(FLERR, "pair_style nscd: the shape library is empty; load shapes with "
               "'shapes read' or 'shapes random'");
  double smallest = avec->shapes().shape(1).bounding_radius;
  for (int id = 2; id <= avec->shapes().size(); id++)
    smallest = std::min(smallest, avec->shapes().shape(id).bounding_radius);
  activation = activation_given >= 0.0 ? activation_given : activation_fraction * smallest;
  reach = reach_given >= 0.0 ? reach_given : reach_fraction * smallest;
  const double largest = avec->shapes().max_bounding_radius();
  if (activation > 2.0 * largest)
    error->all(FLERR, "pair_style nscd: activation {} is larger than the largest grain "
               "({:.6g} across); use at most {:.6g}", activation, 2.0 * largest, 2.0 * largest);
  if (reach > 20.0 * largest)
    error->all(FLERR, "pair_style nscd: reach {} is more than 10 grains ({:.6g} across): lower the "
               "timestep instead", reach, 2.0 * largest);
  check_periodic_box_holds_grains();
  neighbor->add_request(this);
  // Contacts are found from the neighbour list every step: a stale list misses them.
  if ((neighbor->delay > 0 || neighbor->every > 1 || !neighbor->dist_check) && comm->me == 0)
    error->warning(FLERR, "pair_style nscd: neigh_modify every {} delay {} check {} can miss contacts; use 'every "
                   "1 delay 0 check yes'",
                   neighbor->every, neighbor->delay, neighbor->dist_check ? "yes" : "no");
}

/* A grain wider than a periodic box touches its own image: a rigid body cannot. The widths
   are those between opposite faces (also of a triclinic box). */
void PairNSCD::check_periodic_box_holds_grains()
{
  double mine = 0.0, widest = 0.0;
  for (int i = 0; i < atom->nlocal; i++) mine = std::max(mine, avec->radius[i]);
  MPI_Allreduce(&mine, &widest, 1, MPI_DOUBLE, MPI_MAX, world);
  const double a[3] = {domain->xprd, 0.0, 0.0}, b[3] = {domain->xy, domain->yprd, 0.0},
               c[3] = {domain->xz, domain->yz, domain->zprd};
  const double *edges[3] = {a, b, c};
  const double volume = domain->xprd * domain->yprd * domain->zprd;
  const char *names = "xyz";
  for (int d = 0; d < 3; d++) {
    if (!domain->periodicity[d]) continue;
    const double *u = edges[(d + 1) % 3], *w = edges[(d + 2) % 3];
    const double cross[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double width = volume / std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
    if (width < 2.0 * widest + activation)
      error->all(FLERR, "pair_style nscd: the periodic box is {:.6g} wide in {}, a grain up to "
                 "{:.6g} across; see doc/pair_nscd.rst, Errors", width, names[d], 2.0 * widest);
  }
}

double PairNSCD::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR, "pair_style nscd: no pair_coeff for types {} {} (every type pair needs "
               "a friction coefficient)", i, j);
  mu[j][i] = mu[i][j];
  restitution_coeff[j][i] = restitution_coeff[i][j];
  // Grains of any shape may carry any type: the neighbour cutoff covers the largest pair,
  // and the speculative activation up to `reach` beyond the smallest.
  return 2.0 * avec->shapes().max_bounding_radius() + activation + reach;
}

/* Grain-grain contacts of this step, over the half neighbour list (newton on: each pair
   once on exactly one rank). Points (shape 0, wire nodes) are left to the wire styles. */
void PairNSCD::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  found->contacts.clear();
  const int inum = list->inum;
  for (int ii = 0; ii < inum; ii++) {
    const int i = list->ilist[ii];
    if (avec->shape[i] == 0) continue;
    const int *jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (avec->shape[j] == 0) continue;
      add_grain_contacts(i, j);
    }
  }
}

void PairNSCD::add_grain_contacts(int i, int j)
{
  // Which points of a touching patch the geometry reports, and their feature keys, depend on
  // which grain comes first. In the order of IDs a pair gets the same points whichever rank
  // and whichever neighbour-list order finds it, so its warm start is found again.
  if (atom->tag[j] < atom->tag[i]) std::swap(i, j);
  double **x = atom->x;
  const nscd::Spheropolyhedron &shape_i = avec->shape_of(i), &shape_j = avec->shape_of(j);
  const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
  // Speculative activation from the pair's closing speed, within the reach that the
  // neighbour cutoff covers (fix nscd warns when that is not enough).
  const double closing = (vec3(atom->v[i]) - vec3(atom->v[j])).norm() +
      vec3(avec->omega[i]).norm() * shape_i.bounding_radius + vec3(avec->omega[j]).norm() * shape_j.bounding_radius;
  const double pair_activation = std::min(speculative_activation(activation, closing, update->dt),
                                          activation + reach);
  // The points a turning grain brings down (vertices over faces, edges across face borders)
  // only where they can close within this step: a pair at rest gets only its touching ones.
  const double turning_reach = std::min(speculative_activation(0.0, closing, update->dt), pair_activation);
  // The shapes' own bounding radii, not the per-atom radius a `set diameter` could change.
  const double centres = shape_i.bounding_radius + shape_j.bounding_radius + pair_activation;
  if (dx * dx + dy * dy + dz * dz >= centres * centres) return;
  nscd::ContactSet set;
  try {
    set = nscd::contact_grains(shape_i, avec->pose(i), shape_j, avec->pose(j), pair_activation,
                               found->workspace, turning_reach);
  } catch (std::exception &e) {
    error->one(FLERR, "pair_style nscd: contact of atoms {} and {} failed: {}", atom->tag[i],
               atom->tag[j], e.what());
  }
  const ContactLaw law{mu[atom->type[i]][atom->type[j]], restitution_coeff[atom->type[i]][atom->type[j]]};
  for (const nscd::ContactPoint &p : set)
    found->contacts.push_back(make_contact(p, i, j, atom->tag[i], atom->tag[j], law));
}

/* For `neighbor multi`: grains of bounding radii ri and rj interact within ri + rj plus the
   activation distance. */
double PairNSCD::radii2cut(double ri, double rj)
{
  return ri + rj + activation + reach;
}

/* Restart (format: nscd_restart_blocks.h): the settings, then friction and restitution of
   every type pair that has them. */
void PairNSCD::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      const std::string bytes = NSCD_NS::pair_coefficient_bytes({setflag[i][j], mu[i][j], restitution_coeff[i][j]});
      fwrite(bytes.data(), 1, bytes.size(), fp);
    }
}

namespace {
// The pair's part of a restart file, read by rank 0 as nscd_restart_blocks.h's readers expect:
// the end of the file is a damaged block, not LAMMPS' generic "unexpected end of file".
class RestartFile {
 public:
  explicit RestartFile(FILE *fp) : fp_(fp) {}
  std::int32_t version()
  {
    std::int32_t mark[2];
    take(mark, sizeof(mark), "its mark and format number");
    return NSCD_NS::version_of_mark(mark);
  }
  template <class T> T value(const char *what)
  {
    T x;
    take(&x, sizeof(T), what);
    return x;
  }

 private:
  FILE *fp_;
  void take(void *to, std::size_t n, const char *what)
  {
    if (fread(to, 1, n, fp_) != n)
      throw NSCD_NS::Damaged(std::string("the file ends inside ") + what + ": it is cut short");
  }
};
}    // namespace

/* Rank 0 reads, every rank gets the values or the problem (then all stop alike). */
void PairNSCD::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int n = atom->ntypes;
  std::vector<NSCD_NS::PairCoefficient> all;
  std::string problem;
  if (comm->me == 0) {
    RestartFile in(fp);
    for (int i = 1; i <= n && problem.empty(); i++)
      for (int j = i; j <= n && problem.empty(); j++) try {
          all.push_back(NSCD_NS::read_pair_coefficient(in));
        } catch (NSCD_NS::Damaged &e) {
          problem = fmt::format("type pair {} {}: {}", i, j, e.what());
        }
  }
  stop_if_damaged(problem);
  all.resize((size_t) n * (n + 1) / 2);
  MPI_Bcast(all.data(), (int) (all.size() * sizeof(all[0])), MPI_BYTE, 0, world);
  for (int i = 1, k = 0; i <= n; i++)
    for (int j = i; j <= n; j++, k++) {
      setflag[i][j] = all[k].set;
      mu[i][j] = all[k].friction;
      restitution_coeff[i][j] = all[k].restitution;
    }
}

void PairNSCD::write_restart_settings(FILE *fp)
{
  const std::string bytes = NSCD_NS::pair_settings_bytes({activation_given, activation_fraction, reach_given,
                                                         reach_fraction});
  fwrite(bytes.data(), 1, bytes.size(), fp);
}

void PairNSCD::read_restart_settings(FILE *fp)
{
  NSCD_NS::PairSettings s;
  std::string problem;
  if (comm->me == 0) {
    RestartFile in(fp);
    try {
      s = NSCD_NS::read_pair_settings(in);
    } catch (NSCD_NS::Damaged &e) {
      problem = e.what();
    }
  }
  stop_if_damaged(problem);
  MPI_Bcast(&s, sizeof(s), MPI_BYTE, 0, world);
  activation_given = s.activation_given;
  activation_fraction = s.activation_fraction;
  reach_given = s.reach_given;
  reach_fraction = s.reach_fraction;
}

/* A problem found by rank 0 stops every rank with its text. */
void PairNSCD::stop_if_damaged(std::string problem)
{
  int size = (int) problem.size();
  MPI_Bcast(&size, 1, MPI_INT, 0, world);
  if (size == 0) return;
  problem.resize(size);
  MPI_Bcast(&problem[0], size, MPI_CHAR, 0, world);
  error->all(FLERR, "pair_style nscd: restart file's settings refused: {}; start from a data file "
             "(doc/pair_nscd.rst, Errors)", problem);
}

/* The contacts of the last compute() (at capacity) and the per type-pair laws, besides what
   Pair counts itself (per-atom energy and virial). The geometry's scratch space is sized by
   the largest pair of shapes, not by the atoms, and is left out. */
double PairNSCD::memory_usage()
{
  const int n = atom->ntypes + 1;
  double bytes = Pair::memory_usage() + (double) nscd::capacity_bytes(found->contacts) +
                 (double) found->workspace.memory_bytes();
  if (allocated) bytes += 2.0 * n * n * sizeof(double) + (double) n * n * (sizeof(int) + sizeof(double));
  return bytes;
}

void *PairNSCD::extract(const char *name, int &dim)
{
  dim = 2;
  if (strcmp(name, "mu") == 0) return (void *) mu;
  return nullptr;
}
