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

/* fix nscd: time integration of rigid spheropolyhedra by Non-Smooth Contact Dynamics
   (Moreau-Jean theta-method, nonlinear Gauss-Seidel with the Signorini condition and exact
   Coulomb friction). Contacts come from pair_style nscd and from boundary fixes
   (fix nscd/wall); the solver is lib/solver. See doc/fix_nscd.rst. */

#ifdef FIX_CLASS
// clang-format off
FixStyle(nscd,FixNSCD);
// clang-format on
#else

#ifndef LMP_FIX_NSCD_H
#define LMP_FIX_NSCD_H

#include "fix.h"
#include "nscd_comm_count.h"
#include "nscd_copy_exchange.h"

#include <memory>
#include <string>
#include <vector>

namespace nscd {
struct Contact;
struct ImpulseRecord;
}    // namespace nscd

namespace LAMMPS_NS {
namespace NSCD_NS {
class NSCDBoundary;
}    // namespace NSCD_NS

class FixNSCD : public Fix {
 public:
  FixNSCD(class LAMMPS *, int, char **);
  ~FixNSCD() override;

  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  void final_integrate() override;
  void post_run() override;
  void pre_exchange() override;
  int modify_param(int, char **) override;
  double compute_vector(int) override;
  double memory_usage() override;

  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;

  void write_restart(FILE *) override;
  void restart(char *) override;

  // The warm-start impulses travel with their atoms (per-atom arrays, doc/fix_nscd.rst).
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

  // Warm-start records this rank holds (kept with its atoms or in the solver's cache), and
  // how many of them concern no atom this rank owns (none, by design; tests count them).
  size_t warm_start_records_held() const;
  size_t warm_start_records_of_other_ranks() const;

  // This run's communication between ranks as this rank received it (nscd_comm_count.h,
  // doc/scaling.md "Counted"): the exchanges after the sweeps, the ghosts' state at the
  // step's start, the rest of the step (motion, shares, virial), the warm-start records
  // handed to ghosts' owners; and the sweep exchanges and solver reductions done.
  enum CommKind { COMM_SWEEP, COMM_GHOST_STATE, COMM_STEP, COMM_RECORDS, N_COMM_KINDS };
  const NSCD_NS::NSCDCommCount &comm_count() const { return comm_counts; }
  bigint sweep_exchanges() const { return exchanges_run; }
  // Plans of the sweep exchange made this run (several ranks: one per neighbour build).
  bigint exchange_plans() const { return plans_run; }
  bigint solver_reductions() const { return reductions_run; }

  // The contacts of the last solve (grain-grain first, then boundaries), with impulses.
  const std::vector<nscd::Contact> &contacts() const;
  double timestep() const { return dt; }
  // 0 for a grain-grain contact, else k for the k-th boundary fix (in definition order).
  int boundary_of(size_t contact) const;

 private:
  // The contact problem, its solver's options and report, and the warm-start impulses,
  // behind a pointer: style_fix.h pulls this header into LAMMPS' core, which need not
  // compile lib/ and Eigen (fix_nscd.cpp).
  struct Solver;
  std::unique_ptr<Solver> solver;
  bool set_option(const std::string &key, const char *value);
  void check_options();

  int exchange_every;           // sweeps between ghost velocity exchanges
  int warn_every;               // steps between repeated "unconverged" warnings
  double interpenetration_warning;          // warn past this fraction of the smallest rounding radius
  double smallest_rounding;                 // over the group's rounded grains (0: none)
  double warned_depth;                      // interpenetration of this run's last such warning
  double dt;
  bigint problem_step;          // write_problem: the step whose contact problem is written,
  std::string problem_file;     //   to this file (.RANK appended on several ranks)

  class PairNSCD *pair;
  class AtomVecSpheropolyhedron *avec;
  std::vector<NSCD_NS::NSCDBoundary *> boundaries;
  std::vector<Fix *> boundary_fixes;       // the fix of each boundary
  size_t pair_count;                 // problem.contacts: pair_count grain pairs, then each
  std::vector<int> boundary_counts;  // boundary's in turn (as of the last solve)
  std::vector<int> global_bodies;    // bodies that every rank holds (boundaries' own)
  std::vector<int> split_owned;      // owned bodies whose contacts lie on several copies (share > 1)
  std::vector<Fix *> global_body_fixes;  // their fixes

  // Where the warm-start impulses are: with the atoms (after a restart, or filed before atoms
  // move: pre_exchange, end of a run, write_restart) or in the solver's cache (between list
  // rebuilds). solved_since_filing: the cache holds a solve the atoms do not have yet.
  bool impulses_with_atoms;
  bool solved_since_filing;
  double records_sent;          // records packed for ghosts' owners and migrating atoms, this run,
  double values_sent;           //   and the doubles sent with them (counts, places)
  double records_migrated, values_migrated;                // of these, with migrating atoms
  double records_received;          // ghosts' records received from other ranks' ghosts
  NSCD_NS::NSCDCommCount comm_counts;
  bigint exchanges_run, reductions_run;

  enum class Exchange { state, motion, share, correction, velocity, virial, records, origin } exchange_mode;

  // The sweeps' exchange on several ranks: straight between the ranks owning and holding copies
  // of grains (nscd_copy_exchange.h), planned after each neighbour build.
  NSCD_NS::NSCDCopyExchange grain_copies;
  std::vector<int> copy_atoms;           // the atom index of each copy in the plan
  std::vector<double> origin_buffer;     // per atom: its owner's rank and index there
  bigint copies_planned_at;              // neighbor->lastcall of the plan (-1: none)
  bigint plans_run;

  // diagnostics of the last step (and the solver's report)
  bigint unconverged_steps, last_warning_step, last_speed_warning_step;
  double max_step_travel;          // largest 2 (|v| + |w| R) dt over the group, last step
  double kinetic_translational, kinetic_rotational;
  double warm_start_dt;          // timestep of the stored warm-start impulses

  void find_partners();
  void check_no_other_integrator();
  void check_no_bonds_on_grains();
  void warn_if_grains_overlap();
  void stop_on_non_finite_problem();
  void check_grains_are_consistent();
  void check_no_points_in_group();
  void check_overlap_speed();
  void build_bodies();
  void gather_contacts();
  void count_shares();
  void warm_start_contacts();
  void keep_impulses_with_atoms();
  void hand_ghost_records_to_owners();
  static constexpr int RECORDS_PER_GHOST = 4;    // per ghost and round of hand_ghost_records_to_owners
  // Values per ghost that a round may send: its place, count and records (plus one per message).
  static int ghost_records_slot();
  void keep_record_with(int atom_index, const nscd::ImpulseRecord &record);
  void take_impulses_from_atoms();
  void keep_restored_records(const std::vector<nscd::ImpulseRecord> &records);
  void check_no_migration_before_this_fix();
  bool owned_here(tagint tag) const;
  void prepare_problem();
  void write_problem();
  void solve();
  void count_run_statistics();
  CommKind comm_kind() const;
  bool in_sweep_exchange(int i) const;
  std::string communication_report();
  void exchange_velocities();
  bool direct_exchange() const;
  void plan_grain_copies();
  void exchange_copies(Exchange mode);
  void move_grains();
  void hand_back_forces();
  void tally_virial(int i, int j, const double *point, const double *force);
  void warn_if_unconverged();
  void warn_if_contacts_can_be_missed();
  void find_smallest_rounding();
  void warn_if_interpenetrating();
  void measure_kinetic_energy();
};

}    // namespace LAMMPS_NS

#endif
#endif
