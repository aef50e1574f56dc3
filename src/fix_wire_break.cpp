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

/* fix wire, option strength: elements whose tension reaches the strength break. A broken
   element leaves the bond topology (and the joints at its two nodes the angle topology) on
   every rank, so it is gone from the next step on, from restart and data files, and from
   fix wire's contacts; each break is logged (and written to the breaks file). See
   doc/fix_wire.rst, "Breaking". */

#include "fix_wire.h"

#include "atom.h"
#include "bond_wire.h"
#include "comm.h"
#include "error.h"
#include "neighbor.h"
#include "nscd_gather.h"
#include "special.h"
#include "update.h"

#include "shape/random_draws.h"
#include "wire/elastic_forces.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

namespace {
using Break = WireBreak;

bool same_element(tagint p, tagint q, const Break &b)
{
  return (p == (tagint) b.id_a && q == (tagint) b.id_b) || (p == (tagint) b.id_b && q == (tagint) b.id_a);
}

bool breaks_element(tagint p, tagint q, const std::vector<Break> &broken)
{
  return std::any_of(broken.begin(), broken.end(), [&](const Break &b) { return same_element(p, q, b); });
}
}    // namespace

/* One strength for all elements, or a Weibull distribution of scale `strength` and modulus
   `strength_spread` drawn per element from (seed, its nodes' IDs): the same on any rank count. */
double FixWire::element_strength(tagint a, tagint b) const
{
  if (!(strength_spread > 0.0)) return strength;
  const double u = nscd::hashed_uniform((std::uint64_t) strength_seed, (std::uint64_t) std::min(a, b),
                                        (std::uint64_t) std::max(a, b));
  return strength * std::pow(-std::log1p(-u), 1.0 / strength_spread);
}

/* At the start of a step (positions and ghosts current): each rank measures the tensions of
   the elements of its bond list (their largest, for output) and, with a strength, the breaks
   are shared and every rank removes them from its atoms' topology. */
void FixWire::check_element_tensions()
{
  std::vector<Break> mine;
  largest_tension = 0.0;
  for (int n = 0; bond && n < neighbor->nbondlist; n++) {
    const int *b = neighbor->bondlist[n];
    const double *xa = atom->x[b[0]], *xb = atom->x[b[1]];
    const double tension = bond->element(b[2], xa, xb).tension;
    largest_tension = std::max(largest_tension, tension);
    if (strength > 0.0 && tension >= element_strength(atom->tag[b[0]], atom->tag[b[1]]))
      mine.push_back({(double) atom->tag[b[0]], (double) atom->tag[b[1]], tension, 0.5 * (xa[0] + xb[0]),
                      0.5 * (xa[1] + xb[1]), 0.5 * (xa[2] + xb[2])});
  }
  largest_tension_in_run = std::max(largest_tension_in_run, largest_tension);
  if (!(strength > 0.0)) return;
  const std::vector<Break> broken = gather_records(mine, world, true);
  if (broken.empty()) return;
  remove_from_topology(broken);
  report_breaks(broken);
  next_reneighbor = update->ntimestep + 1;
  topology_changed = true;
}

template <class Remove>
static bigint remove_entries(int &count, Remove remove_k)
{
  bigint removed = 0;
  for (int m = 0; m < count;)
    if (remove_k(m)) count--, removed++;
    else m++;
  return removed;
}

/* Bonds of the broken elements and the angles whose two arms include one; each is stored with
   one atom (newton_bond on), so each rank removes those of its owned atoms. */
void FixWire::remove_from_topology(const std::vector<Break> &broken)
{
  bigint bonds = 0, angles = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    const tagint me = atom->tag[i];
    bonds += remove_entries(atom->num_bond[i], [&](int m) {
      if (!breaks_element(me, atom->bond_atom[i][m], broken)) return false;
      const int last = atom->num_bond[i] - 1;
      atom->bond_type[i][m] = atom->bond_type[i][last];
      atom->bond_atom[i][m] = atom->bond_atom[i][last];
      return true;
    });
    if (!atom->num_angle) continue;
    angles += remove_entries(atom->num_angle[i], [&](int m) {
      const tagint a = atom->angle_atom1[i][m], b = atom->angle_atom2[i][m], c = atom->angle_atom3[i][m];
      if (!breaks_element(a, b, broken) && !breaks_element(b, c, broken)) return false;
      const int last = atom->num_angle[i] - 1;
      atom->angle_type[i][m] = atom->angle_type[i][last];
      atom->angle_atom1[i][m] = atom->angle_atom1[i][last];
      atom->angle_atom2[i][m] = atom->angle_atom2[i][last];
      atom->angle_atom3[i][m] = atom->angle_atom3[i][last];
      return true;
    });
  }
  bigint removed[2] = {bonds, angles}, all[2];
  MPI_Allreduce(removed, all, 2, MPI_LMP_BIGINT, MPI_SUM, world);
  atom->nbonds -= all[0];
  atom->nangles -= all[1];
  specials_stale = true;
}

/* Before atoms change rank: the friction memories go with their atoms (fix_wire_io.cpp).
   The 1-2 and 1-3 neighbours of the nodes (LAMMPS' pair exclusions) follow the new topology.
   Rebuilt before the atoms are exchanged at the reneighbouring a break asks for: in the
   middle of a step the rebuild disturbed the ghost atoms' data (2 ranks lost atoms). */
void FixWire::pre_exchange()
{
  keep_memories_with_atoms();
  if (!specials_stale) return;
  Special special(lmp);
  special.build();
  specials_stale = false;
}

void FixWire::report_breaks(const std::vector<Break> &broken)
{
  elements_broken += (bigint) broken.size();
  diagnostics[BROKEN_DIAGNOSTIC] = (double) elements_broken;
  if (comm->me != 0) return;
  for (const Break &b : broken) {
    const auto line = fmt::format("{} {} {} {:.10g} {:.10g} {:.10g} {:.10g}", update->ntimestep, (tagint) b.id_a,
                                  (tagint) b.id_b, b.tension, b.x, b.y, b.z);
    utils::logmesg(lmp, "fix wire {}: step {}: the element of nodes ID {} and {} broke at tension {:.6g} "
                   "(its strength {:.6g}) at ({:.6g}, {:.6g}, {:.6g})\n", id, update->ntimestep, (tagint) b.id_a,
                   (tagint) b.id_b, b.tension, element_strength((tagint) b.id_a, (tagint) b.id_b), b.x, b.y, b.z);
    if (breaks_file) fprintf(breaks_file, "%s\n", line.c_str());
  }
  if (breaks_file) fflush(breaks_file);
}
