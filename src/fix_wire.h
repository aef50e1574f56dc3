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

/* fix wire: integrates elastic wire nodes (atoms of shape 0 joined by bond_style wire and
   angle_style wire) with the Gear-5 predictor-corrector on a subcycle of n substeps per
   LAMMPS step (lib/wire/subcycle.h), with soft wire-wire, wire-grain and wire-boundary
   contacts (lib/wire/contact_model.h). The style is glue: it gathers the nodes, grains and
   boundaries, calls lib/wire, stores the nodes' new positions and velocities and hands out
   the forces, and does LAMMPS' communication, restart and output. The wire->grain forces and torques averaged over the substeps go to
   the grains' f and torque in post_force, so fix nscd takes them as external forces.
   See doc/fix_wire.rst. Only LAMMPS headers here: lib/ stays behind a pointer. */

#ifdef FIX_CLASS
// clang-format off
FixStyle(wire,FixWire);
// clang-format on
#else

#ifndef LMP_FIX_WIRE_H
#define LMP_FIX_WIRE_H

#include "fix.h"
#include "nscd_comm_count.h"
#include "nscd_copy_exchange.h"

#include <array>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace nscd {
namespace wire {
  struct StoredContact;
}    // namespace wire
}    // namespace nscd

namespace LAMMPS_NS {
namespace NSCD_NS {

// A wire element that broke (option strength): node IDs, tension, midpoint.
struct WireBreak {
  double id_a, id_b, tension, x, y, z;
};

}    // namespace NSCD_NS

class FixWire : public Fix {
 public:
  FixWire(class LAMMPS *, int, char **);
  ~FixWire() override;

  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  void post_run() override;
  void reset_dt() override;
  double compute_vector(int) override;
  double memory_usage() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;

  // compute wire/contacts: recording of contact points from the next step on, and the
  // points of the last step computed on this rank, CONTACT_COLUMNS numbers a row
  // (doc/compute_wire_contacts.rst).
  static constexpr int CONTACT_COLUMNS = 16;
  enum ContactColumn { ROW_NODE_1 = 0, ROW_OTHER = 2, ROW_KIND = 3, ROW_POINT = 4, ROW_NORMAL = 7, ROW_NORMAL_FORCE = 10,
                       ROW_TANGENTIAL_FORCE = 11 };
  static constexpr double ROW_WIRE_GRAIN = 1.0;    // ROW_KIND of a wire-grain contact
  void record_contacts();
  std::vector<double> contact_rows() const;

  // Friction memories this rank holds (kept with its atoms or in the contact model), and
  // how many of them belong to a contact this rank does not compute, i.e. whose first node
  // it does not own (none, by design; tests count them). Need an atom map.
  size_t wire_memories_held() const;
  size_t wire_memories_of_other_ranks() const;

  // This run's communication between ranks as this rank received it (nscd_comm_count.h,
  // doc/scaling.md "Counted"): the subcycle's node exchanges and the once-a-step ones; the
  // substeps run; the friction memories (and their doubles) packed with migrating atoms.
  enum CommKind { COMM_SUBSTEP, COMM_STEP, N_COMM_KINDS };
  const NSCD_NS::NSCDCommCount &comm_count() const { return comm_counts; }
  bigint substeps() const { return substeps_run; }
  double memories_migrated() const { return migrated[0]; }
  double memory_values_migrated() const { return migrated[1]; }

  // "radius" (create_wire's default), "k_n" (0: no contacts): pointers to doubles, dim 0.
  void *extract(const char *, int &) override;
  void pre_exchange() override;

 private:
  struct Lib;                   // lib/wire state (fix_wire_lib.h)
  std::unique_ptr<Lib> lib;

  // Gear state per atom: 18 scaled derivatives, then 1 if the state is initialised.
  static constexpr int GEAR_COLUMNS = 19;
  double **gear;
  double state_dt;              // the step the stored scaled derivatives refer to

  // options
  bool mu_s_given, mu_d_given;                    // a lone one sets both
  bool k_n_given;                                  // k_n 0 given, or the default
  double mu_ww_s, mu_ww_d;                         // wire-wire friction; < 0: not given
  struct GrainFriction {
    int lo, hi;                  // grain types
    double mu_s, mu_d;
  };
  std::vector<GrainFriction> grain_friction;    // option grain_friction, in the order given
  std::vector<int> grain_law_of_type;           // per atom type: the contact model's law
  bool contacts_recorded;                          // for compute wire/contacts
  double wire_radius, node_damping, contact_skin;
  int requested_substeps;        // 0: from dt_sp or chosen (auto or stable)
  bool fastest_stable;            // substeps stable: the stable step, not the accurate one
  bool springs_held;              // grain_springs held: wire-grain friction springs by the held poses
  double requested_dt_sp, safety, contacts_per_node;
  double inertia_scale;          // the nodes' inertia over their mass (option inertia)

  class BondWire *bond;
  class AngleWire *angle;
  class AtomVecSpheropolyhedron *avec;
  double stable_dt_sp;

  // Index of each local atom (owned and ghost) among the wire nodes (-1: a grain), the
  // nodes' and the grains' atoms; rebuilt with LAMMPS' neighbour lists.
  std::vector<int> node_of_atom, atom_of_node, atom_of_grain;
  int owned_nodes;
  bool grains_anywhere;            // on some rank, owned or ghost: the grain exchanges are collective
  bigint indexed_at;            // neighbour build the indices belong to
  // Where the friction memories are: with the atoms that compute their contacts (after a
  // restart, or filed before atoms move: pre_exchange, the end of a run, write_restart) or
  // in the contact model (while the atoms stay on their ranks).
  bool memories_with_atoms;

  // Global wire topology, the same on every rank: (lower tag, higher tag) of each element.
  std::vector<std::array<tagint, 2>> elements;
  double longest_element;

  enum class Comm { node_state, node_position, node_force, grain_velocity, grain_force, node_origin } comm_mode;
  bool counting_comm;                        // the subcycle's communication: counted
  NSCD_NS::NSCDCommCount comm_counts;
  std::array<double, 2> migrated;            // memories packed with migrating atoms, their doubles
  std::vector<double> grain_force_buffer;    // 6 per local atom
  // The subcycle's exchange of node copies on several ranks (one rank: LAMMPS' comm, which
  // only copies within the rank there): planned after each neighbour build from each ghost
  // node's origin (shift of its image; owner rank, owner's node index, 0), 6 per local atom.
  NSCD_NS::NSCDCopyExchange node_copies;
  std::vector<double> origin_buffer;
  bool direct_exchange() const;
  void plan_copy_exchange();

  std::array<double, 16> diagnostics;
  static constexpr int BROKEN_DIAGNOSTIC = 13;    // elements broken so far (option strength)
  // The largest element tension at this step's start and over every step since the fix was
  // defined, on this rank (compute_vector takes the maximum over the ranks).
  static constexpr int TENSION_DIAGNOSTIC = 14, RUN_TENSION_DIAGNOSTIC = 15;
  double largest_tension, largest_tension_in_run;

  // option strength (fix_wire_break.cpp)
  double strength;                  // tension at which an element breaks; 0: never
  double strength_spread;           // Weibull modulus of the elements' strengths; 0: all equal
  double strength_seed;             // their seed (option seed)
  double element_strength(tagint a, tagint b) const;
  FILE *breaks_file;                // option breaks: one line per break (rank 0)
  bool breaks_given;                // on every rank (the file is open on rank 0 only)
  bigint elements_broken;
  bool topology_changed;            // elements broke: gather the topology after the next build
  bool specials_stale;              // elements broke: rebuild the special lists (pre_exchange)
  void check_element_tensions();
  void remove_from_topology(const std::vector<NSCD_NS::WireBreak> &broken);
  void report_breaks(const std::vector<NSCD_NS::WireBreak> &broken);
  bool warned_fast_motion;

  // fix wire's own timing of the run (printed after it): seconds, node-substeps, doubles sent
  enum Timing { T_TOTAL, T_CPU, T_CONTACTS, T_ELASTIC, T_INTEGRATION, T_COMM, T_COMM_STEP, T_NODE_SUBSTEPS,
                T_SENT, T_SENT_ALL_ATOMS, N_TIMING };
  std::array<double, N_TIMING> timing;
  bigint substeps_run;
  int rebuilds_at_start;

  void parse_option(int narg, char **arg, int &iarg);
  void parse_grain_friction(int narg, char **arg, int &iarg);
  void check_partners();
  void find_boundaries();
  void check_contacts_possible();
  void warn_about_elements_inside_grains();
  void warn_about_strained_elements();
  void plan_substeps();
  void refuse_absurd_substeps(int needed);
  std::string requested_substeps_text() const;
  void make_contact_model();
  void gather_elements();
  void rescale_states(double new_dt);

  void index_atoms();
  void load_nodes();
  void store_nodes();
  void update_scene(bool reindexed);
  int element_partner(int i, tagint tag) const;
  void keep_memories_with_atoms();
  void take_memories_from_atoms();
  void file_with_owned_nodes(const std::vector<nscd::wire::StoredContact> &memories);
  bool owned_here(tagint tag) const;
  void check_motion_within_skin();
  void hand_forces();
  void communicate(Comm mode, bool reverse, bool counted = false);
  void exchange_copies(bool reverse);
  std::string communication_report() const;
  int comm_fields(int i, double *field[2]);
};

}    // namespace LAMMPS_NS

#endif
#endif
