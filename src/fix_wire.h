/* fix wire: integrates elastic wire nodes (atoms of shape 0 joined by bond_style wire and
   angle_style wire) with the Gear-5 predictor-corrector on a subcycle of n substeps per
   LAMMPS step (lib/wire/subcycle.h), with soft wire-wire and wire-grain contacts
   (lib/wire/soft_contact.h, lib/geometry). The wire->grain forces and torques averaged over
   the substeps are added to the grains' f and torque in post_force, so fix nscd takes them
   as external forces. Runs on any number of MPI ranks: each contact is computed on the rank
   owning the first node of its lower element (see find_candidates). See doc/fix_wire.md. */

#ifdef FIX_CLASS
// clang-format off
FixStyle(wire,FixWire);
// clang-format on
#else

#ifndef LMP_FIX_WIRE_H
#define LMP_FIX_WIRE_H

#include "fix.h"

#include "geometry/contact.h"
#include "geometry/point_grid.h"
#include "wire/soft_contact.h"
#include "wire/stability.h"
#include "wire/subcycle.h"

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace LAMMPS_NS {

class FixWire : public Fix {
 public:
  FixWire(class LAMMPS *, int, char **);
  ~FixWire() override;

  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
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

  double substep() const { return plan.dt_sp; }
  int substeps() const { return plan.substeps; }

  // Identity of a contact, stable across steps and restarts: the two node tags of
  // element A (ascending), then element B's two node tags, or (grain tag, slot of the
  // point: see kSlots); a node on a wall or the plate: (node tag, 0, boundary key < 0, 0).
  using ContactKey = std::array<tagint, 4>;

 private:
  // Gear state per atom: 18 scaled derivatives, then 1 if the state is initialised.
  static constexpr int kGearColumns = nscd::wire::Gear5State::kNumDoubles + 1;
  double **gear = nullptr;
  double state_dt = 0.0;    // the step the stored scaled derivatives refer to

  // options
  nscd::wire::SoftContactLaw law;
  bool mu_s_given = false, mu_d_given = false;    // a lone one sets both
  double wire_radius = 0.0;
  double node_damping = 0.0;
  int requested_substeps = 0;    // 0: from dt_sp or from the stability limit
  double requested_dt_sp = 0.0;
  double safety = 0.5;
  double contacts_per_node = 2.0;

  class BondWire *bond = nullptr;
  class AngleWire *angle = nullptr;
  class AtomVecSpheropolyhedron *avec = nullptr;

  nscd::wire::SubcyclePlan plan;
  double stable_dt_sp = 0.0;
  std::array<double, 6> corrector{};

  // per step
  nscd::wire::WireNodeSet nodes;
  std::vector<int> node_atom;              // node k -> local atom index
  std::vector<nscd::Vec3> step_start;      // per node: position at the start of the step
  std::vector<nscd::Vec3> external_force;  // per node: atom f minus the wire's own elastic force
  std::vector<double> fbuf;                // per local atom: 3 (node forces) or 6 (grain f, torque)
  std::vector<double> vbuf;                // per local atom: node velocity (3)
  std::vector<nscd::wire::GrainMotion> motion;    // per local grain
  nscd::wire::GrainForceAccumulator grain_forces;
  nscd::ContactWorkspace workspace;
  enum class Comm { node_state, grain_velocity, node_force, grain_force } comm_mode = Comm::node_state;

  // Wire topology, the same on every rank: the elements as (lower tag, higher tag), sorted.
  // Gathered at setup from the bond lists of all ranks.
  std::vector<std::array<tagint, 2>> elements;
  double longest_element = 0.0;    // rest or current, the longer, at setup

  // One copy of an element on this rank: nodes a (first node, or an image of it) and b
  // (the image of the second node closest to a).
  struct ElementImage {
    int a, b;
    int element;    // index in `elements`
    nscd::Vec3 centre;
    double half;    // half length
  };
  std::vector<ElementImage> images;
  nscd::PointGrid image_grid, grain_grid;
  std::vector<int> grain_atom;    // grain_grid point -> local atom index

  // The walls and the loading plate (fixes with NSCDBoundary) the wire can touch.
  struct BoundaryLink {
    class NSCDBoundary *boundary;
    int groupbit;                         // the nodes it touches: those of its fix group
    tagint key;                           // < 0, from the fix ID: for contact keys
    nscd::wire::SoftContactLaw law;       // fix wire's, with the boundary's friction
  };
  std::vector<BoundaryLink> boundaries;

  // Friction histories of one pair: a wire-grain pair has a slot per point it can touch
  // with (its start sphere, its end sphere, two points inside), other pairs one point.
  static constexpr int kSlots = 4;
  struct Candidate {
    enum class Kind : std::uint8_t { wire_wire, wire_grain, wire_boundary } kind;
    int a1, a2;    // element A's nodes (local indices), or (node, -1) on a boundary
    int b1, b2;    // element B's nodes, (grain, -1), or (index in boundaries, -1)
    ContactKey key;    // of the pair; histories are kept under history_key()
    std::array<nscd::wire::TangentialHistory, kSlots> history;
  };
  static int slots_of(const Candidate &c) { return c.kind == Candidate::Kind::wire_grain ? kSlots : 1; }
  static ContactKey history_key(const Candidate &c, int slot);
  std::vector<Candidate> candidates;
  std::map<ContactKey, nscd::wire::TangentialHistory> histories;    // between steps
  bigint histories_placed_at = -1;    // neighbor build after which histories were handed over
  bool histories_on_every_rank = false;    // just read from a restart file

  // diagnostics of the last substep; see compute_vector()
  std::array<double, 13> diagnostics{};
  bool warned_fast_motion = false;    // this run

  void parse_option(int narg, char **arg, int &iarg);
  void check_partners();
  bool acts_on_nodes(const Fix *other) const;
  void plan_substeps();
  nscd::wire::WireStiffness stiffness() const;
  void check_ghost_cutoff();
  void check_motion_within_skin();
  void rescale_states(double new_dt);

  void load_nodes();
  void store_nodes();
  void measure_external_forces();
  void gather_elements();
  bool joined(tagint p, tagint q) const;
  void hand_over_histories();
  void share_grain_velocities();
  void find_candidates();
  void locate_element_images();
  void find_wire_grain_candidates(std::vector<Candidate> &found);
  void find_wire_wire_candidates(std::vector<Candidate> &found);
  void find_boundaries();
  void find_wire_boundary_candidates(std::vector<Candidate> &found);
  void sum_diagnostics_over_ranks();
  void substep_forces(const nscd::wire::SubstepInfo &info, const std::vector<nscd::Vec3> &x,
                      const std::vector<nscd::Vec3> &v, std::vector<nscd::Vec3> &f);
  void share_node_state();
  double add_elastic_forces(double *energy_axial, double *energy_bending);
  void add_contact_forces(double tau, double dt);
  bool wire_grain_force(Candidate &c, double tau, double dt, double &energy);
  bool wire_wire_force(Candidate &c, double dt, double &energy);
  bool wire_boundary_force(Candidate &c, double tau, double dt, double &energy);
  void hand_forces_to_boundaries();
  void sum_ghost_forces(int columns);
  void hand_forces_to_grains();
  void keep_histories();
};

}    // namespace LAMMPS_NS

#endif
#endif
