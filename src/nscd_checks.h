/* -*- c++ -*- ----------------------------------------------------------
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

/* Checks that every style of the package makes the same way, written once: the lowest ID
   of the atoms that break a rule (the same on every rank, so the error is raised on all
   ranks alike and names one atom whatever the number of ranks), one instance of a fix, and
   the refusal of a damaged restart block. For the .cpp files of this package (not style
   headers: LAMMPS compiles those into its core). */

#ifndef LMP_NSCD_CHECKS_H
#define LMP_NSCD_CHECKS_H

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "lammps.h"
#include "lmptype.h"
#include "modify.h"

#include "nscd_restart.h"

#include <mpi.h>

#include <algorithm>

namespace LAMMPS_NS {
namespace NSCD_NS {

// The lowest of the ranks' `mine` (an atom ID, or MAXTAGINT for none). Collective.
inline tagint lowest_tag_of_all(MPI_Comm world, tagint mine)
{
  tagint all = MAXTAGINT;
  MPI_Allreduce(&mine, &all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  return all;
}

// The lowest ID of the owned atoms i for which bad(i) holds, over all ranks; 0 if there is
// none (atom IDs start at 1), so that `if (tagint id = lowest_tag_where(...)) error->all(...)`.
// Collective: every rank must call it.
template <class Bad> tagint lowest_tag_where(LAMMPS *lmp, Bad bad)
{
  Atom *atom = lmp->atom;
  tagint mine = MAXTAGINT;
  for (int i = 0; i < atom->nlocal; i++)
    if (bad(i)) mine = std::min(mine, atom->tag[i]);
  const tagint all = lowest_tag_of_all(lmp->world, mine);
  return all == MAXTAGINT ? 0 : all;
}

// Stops if another fix of the class Style than `fix` is defined; `why_one` says why one is
// enough ("one solver handles all grains and boundaries").
template <class Style> void refuse_second_instance(LAMMPS *lmp, const Fix *fix, const char *why_one)
{
  for (const Fix *other : lmp->modify->get_fix_list())
    if (other != fix && dynamic_cast<const Style *>(other))
      lmp->error->all(FLERR, "fix {}: only one fix {} may be defined ({} and {}); {}", fix->style, fix->style,
                      other->id, fix->id, why_one);
}

// Stops if a fix that moves atoms between ranks in its pre_exchange (fix balance, ...) is
// defined before `fix`, which hands `what` (contact state kept with the atoms) to the atoms
// in its own pre_exchange, by where they were at the last step: atoms that left before it
// would lose theirs.
inline void refuse_migration_before(LAMMPS *lmp, const Fix *fix, const char *what)
{
  for (const Fix *other : lmp->modify->get_fix_list()) {
    if (other == fix) return;
    if (other->pre_exchange_migrate)
      lmp->error->all(FLERR, "fix {} {} must be defined before fix {} {}, which moves atoms before fix {} hands "
                      "them {}; define it after",
                      fix->style, fix->id, other->style, other->id, fix->style, what);
  }
}

// read(bytes, size) from nscd_restart_blocks.h on the block LAMMPS hands Fix::restart(), or
// an error naming the fix and what is wrong with the block if it is damaged; the way out
// (another fix ID starts without the stored state, or a newer build) is explained under
// Errors of the fix's page `page` ("doc/fix_nscd.rst").
template <class Read>
auto read_restart_block(LAMMPS *lmp, const Fix *fix, Read read, const char *bytes, const char *page)
    -> decltype(read(bytes, UNKNOWN_SIZE))
{
  try {
    return read(bytes, UNKNOWN_SIZE);
  } catch (Damaged &e) {
    lmp->error->all(FLERR, "fix {} {}: restart block refused: {} ({}, Errors)", fix->style, fix->id, e.what(), page);
  }
  return {};    // not reached: error->all does not return
}

// Warns (on rank 0) that the block holding `what` is in an older format whose length this
// build cannot check, so it is not read; `instead` says what the run does without it, `page`
// the fix's page whose Errors section explains it ("doc/fix_nscd.rst").
inline void warn_format_not_read(LAMMPS *lmp, const Fix *fix, const char *what, int format, const char *instead,
                                 const char *page)
{
  if (lmp->comm->me == 0)
    lmp->error->warning(FLERR, "fix {} {}: restart file's {} in old format {} not read: {} ({}, Errors)", fix->style,
                        fix->id, what, format, instead, page);
}

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
