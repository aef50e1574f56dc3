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

/* create_wire: parses the command, lays the path out with lib/wire/wire_path, checks it
   against the box, the grains and the walls, then creates the nodes on the ranks that own
   their positions and the bonds and angles on the nodes that store them. */

#include "create_wire.h"
#include "nscd_args.h"

#include "angle.h"
#include "atom.h"
#include "atom_vec.h"
#include "atom_vec_spheropolyhedron.h"
#include "bond_wire.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "modify.h"
#include "nscd_arrays.h"
#include "nscd_boundary.h"
#include "nscd_boundary_fix.h"
#include "special.h"

#include "geometry/contact.h"
#include "shape/shape_library.h"
#include "nscd_gather.h"
#include "nscd_new_atoms.h"
#include "nscd_wire_elements.h"
#include "wire/wire_overlap.h"
#include "wire/wire_path.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

namespace {
constexpr double DEGREE = M_PI / 180.0;
constexpr double LENGTH_TOLERANCE = 1e-6;    // elements this close to the rest length are unstrained
}    // namespace

struct CreateWire::Request {
  enum class Shape { loop, polyline } shape = Shape::loop;
  std::string shape_name;
  nscd::wire::LoopPath loop;
  nscd::wire::PolylinePath polyline;
  int node_type = 0, bond_type = 0, angle_type = 0;
  int nodes = 0;                    // 0: as many as the rest length gives
  double mass = -1.0;
  tagint molecule = -1;             // -1: the next free molecule ID
  double radius = -1.0;             // -1: fix wire's
  double overlap = 0.1;             // allowed overlap with grains and walls, times the radius
  bool check_overlap = true;
  bool strained = false;            // elements may differ from the rest length
  bool drop = false;                // lowered until it touches what lies below
  double dropped = -1.0;            // how far it was (-1: not dropped)
  double rest_length = 0.0;         // of the bond type
  bool mol_given = false;

  // 'from ID|last': the wire continues from a free end, node 0 of the layout
  struct End {
    tagint tag = 0;                 // the end node (0: a new wire)
    tagint neighbour = 0;           // its one neighbour along the wire
    tagint second = 0;              // the neighbour's other neighbour (0: none)
    nscd::Vec3 x, x_neighbour, x_second;    // unwrapped
    int type = 0, bond_type = 0, angle_type = 0;
    tagint molecule = 0;
    double mass = 0.0;
    int bonds_stored = 0, angles_stored = 0, neighbour_angles_stored = 0;
    bool join_bond_on_end = true;   // newton_bond on: the join bond is stored on the end (else on the new node)
  } end;
  bool from_last = false;
  bool continues() const { return from_last || end.tag > 0; }
  // atom ID of layout node k (node 0 of a continued wire is its end)
  tagint tag(int k) const
  {
    if (!continues()) return first_tag + (tagint) k;
    return k == 0 ? end.tag : first_tag + (tagint) k - 1;
  }
  int first_new() const { return continues() ? 1 : 0; }

  nscd::wire::WireLayout layout;    // unwrapped node positions and topology
  std::vector<nscd::Vec3> in_box;   // the nodes remapped into a periodic box
  std::vector<imageint> images;
  tagint first_tag = 0;
};

void CreateWire::broadcast(std::string &text)
{
  bigint size = (bigint) text.size();
  MPI_Bcast(&size, 1, MPI_LMP_BIGINT, 0, world);
  if (size > INT_MAX) error->all(FLERR, "create_wire: the polyline file is too large ({} bytes)", size);
  text.resize((size_t) size);
  MPI_Bcast(&text[0], (int) size, MPI_CHAR, 0, world);
}

CreateWire::CreateWire(LAMMPS *lmp) : Command(lmp), request(std::make_unique<Request>()) {}

CreateWire::~CreateWire() = default;

/* create_wire TYPE loop X Y Z R | helix X Y Z R PITCH | line X1 Y1 Z1 X2 Y2 Z2 | polyline FILE
               bond BTYPE mass M [angle ATYPE] [turns N] [pitch P] [gap DEG] [start DEG]
               [axis AX AY AZ] [nodes N] [mol ID] [radius RW] [overlap TOL|ignore] [strained yes|no]
               [drop yes|no] [from ID|last] */
void CreateWire::command(int narg, char **arg)
{
  if (domain->box_exist == 0) error->all(FLERR, "create_wire: define the box first (create_box or read_data)");
  if (atom->molecular != Atom::MOLECULAR || !atom->avec->bonds_allow)
    error->all(FLERR, "create_wire needs an atom style with bonds, angles and molecule IDs, e.g. "
               "'atom_style hybrid spheropolyhedron angle'");
  AtomVecSpheropolyhedron::find(lmp, "create_wire");
  parse(narg, arg);
  if (request->continues()) find_end();
  check_types();
  if (request->continues()) check_room_at_end();
  lay_out();
  check_nodes_in_box();
  if (request->drop) drop_onto_what_is_below();
  if (request->check_overlap) {
    check_overlaps();
    check_wire_overlaps();
  }
  create_nodes();
  create_bonds_and_angles();
  Special special(lmp);
  special.build();

  const Request &r = *request;
  const size_t n = r.layout.nodes.size() - r.first_new();
  std::string end = r.layout.closed ? "closed ring" : "open";
  if (r.continues()) {
    end = fmt::format("continuing molecule {} from its end node ID {}", r.end.molecule, r.end.tag);
  } else if (r.shape == Request::Shape::loop && !r.layout.closed) {
    // equal chords on a loop or helix are equal angles: the gap left open is a little wider
    nscd::Vec3 e1, e2;
    nscd::wire::loop_frame(r.loop.axis, e1, e2);
    auto angle_of = [&](const nscd::Vec3 &x) {
      const nscd::Vec3 d = x - r.loop.centre;
      return std::atan2(d.dot(e2), d.dot(e1));
    };
    const double step = std::remainder(angle_of(r.layout.nodes[1]) - angle_of(r.layout.nodes[0]), 2.0 * M_PI);
    const double open = 2.0 * M_PI * r.loop.turns - (double) (n - 1) * std::abs(step);
    end = fmt::format("open, ends {:.4g} degrees apart", open / DEGREE);
  } else if (!r.layout.closed) {
    end = fmt::format("open, last node {:.4g} before the path's end",
                      (r.layout.nodes.back() - r.polyline.points.back()).norm());
  }
  if (r.dropped >= 0.0) end += fmt::format(", dropped {:.6g} onto what lies below", r.dropped);
  if (comm->me == 0)
    utils::logmesg(lmp, "create_wire: {} ({}): {} nodes (IDs {}..{}, molecule {}), {} elements of "
                   "length {:.10g}, {} joints\n", r.shape_name, end, n, r.first_tag,
                   r.first_tag + (tagint) n - 1, r.molecule, r.layout.topology.elements.size(),
                   r.layout.chord, r.angle_type ? r.layout.topology.joints.size() + (r.end.neighbour ? 1 : 0) : 0);
}

void CreateWire::parse(int narg, char **arg)
{
  Request &r = *request;
  const char *usage = "see doc/create_wire.rst, Syntax";
  if (narg < 3) error->all(FLERR, "Illegal create_wire command: {}", usage);
  r.node_type = (int) NSCD_NS::whole(lmp, "create_wire", "atom type", arg[0], INT_MIN, INT_MAX);
  if (r.node_type < 1 || r.node_type > atom->ntypes)
    error->all(FLERR, "create_wire: atom type {} is not between 1 and {}", r.node_type, atom->ntypes);
  r.shape_name = arg[1];
  // a number of the path (named by its place in the usage) or of a keyword (named by it)
  auto number = [&](int i, const std::string &what = "") {
    return NSCD_NS::number(lmp, "create_wire " + r.shape_name, what.empty() ? arg[i - 1] : what, arg[i]);
  };
  auto point = [&](int i, const std::string &what) {
    return nscd::Vec3(number(i, what + " x"), number(i + 1, what + " y"), number(i + 2, what + " z"));
  };
  int iarg;
  if (r.shape_name == "loop" || r.shape_name == "helix") {
    const int args = r.shape_name == "loop" ? 4 : 5;
    if (narg < 2 + args) error->all(FLERR, "Illegal create_wire {} command: {}", r.shape_name, usage);
    r.loop.centre = point(2, "centre");
    r.loop.radius = number(5, "radius R");
    if (r.shape_name == "helix") r.loop.pitch = number(6, "pitch");
    iarg = 2 + args;
  } else if (r.shape_name == "line") {
    if (narg < 8) error->all(FLERR, "Illegal create_wire line command: {}", usage);
    r.shape = Request::Shape::polyline;
    r.polyline.points = {point(2, "start"), point(5, "end")};
    iarg = 8;
  } else if (r.shape_name == "polyline") {
    r.shape = Request::Shape::polyline;
    std::string text, problem;
    if (comm->me == 0) {
      std::ifstream in(arg[2]);
      if (!in) problem = fmt::format("cannot open the polyline file {}", arg[2]);
      std::stringstream all;
      all << in.rdbuf();
      text = all.str();
    }
    broadcast(problem);
    if (!problem.empty()) error->all(FLERR, "create_wire: {}", problem);
    broadcast(text);
    try {
      r.polyline = nscd::wire::read_polyline(text, arg[2]);
    } catch (std::exception &e) {
      error->all(FLERR, "create_wire: {}", e.what());
    }
    iarg = 3;
  } else {
    error->all(FLERR, "create_wire: unknown path '{}' ({})", r.shape_name, usage);
  }

  while (iarg < narg) {
    const std::string key = arg[iarg];
    auto need = [&](int n) {
      if (iarg + n >= narg) error->all(FLERR, "create_wire: keyword '{}' needs {} value(s)", key, n);
    };
    const bool loop_keyword = key == "turns" || key == "pitch" || key == "gap" || key == "start" || key == "axis";
    if (loop_keyword && r.shape != Request::Shape::loop)
      error->all(FLERR, "create_wire: '{}' applies to a loop or helix, not a {}", key, r.shape_name);
    if (key == "bond") {
      need(1);
      r.bond_type = (int) NSCD_NS::whole(lmp, "create_wire", key, arg[iarg + 1], INT_MIN, INT_MAX);
      iarg += 2;
    } else if (key == "angle") {
      need(1);
      r.angle_type = (int) NSCD_NS::whole(lmp, "create_wire", key, arg[iarg + 1], INT_MIN, INT_MAX);
      iarg += 2;
    } else if (key == "mass") {
      need(1);
      r.mass = number(iarg + 1);
      if (!(r.mass > 0.0) || !std::isfinite(r.mass))
        error->all(FLERR, "create_wire: node mass {} must be positive and finite", arg[iarg + 1]);
      iarg += 2;
    } else if (key == "turns") {
      need(1);
      r.loop.turns = number(iarg + 1);
      iarg += 2;
    } else if (key == "pitch") {
      need(1);
      r.loop.pitch = number(iarg + 1);
      iarg += 2;
    } else if (key == "gap") {
      need(1);
      r.loop.gap = number(iarg + 1) * DEGREE;
      iarg += 2;
    } else if (key == "start") {
      need(1);
      r.loop.start = number(iarg + 1) * DEGREE;
      iarg += 2;
    } else if (key == "axis") {
      need(3);
      r.loop.axis = point(iarg + 1, "axis");
      iarg += 4;
    } else if (key == "nodes") {
      need(1);
      const bigint n = NSCD_NS::whole(lmp, "create_wire", key, arg[iarg + 1]);
      if (n < 2 || n > 100000000)
        error->all(FLERR, "create_wire: nodes {} must be between 2 and 100000000", n);
      r.nodes = (int) n;
      iarg += 2;
    } else if (key == "mol") {
      need(1);
      r.molecule = (tagint) NSCD_NS::whole(lmp, "create_wire", key, arg[iarg + 1], 1, MAXTAGINT);
      r.mol_given = true;
      iarg += 2;
    } else if (key == "from") {
      need(1);
      if (strcmp(arg[iarg + 1], "last") == 0) r.from_last = true;
      else r.end.tag = (tagint) NSCD_NS::whole(lmp, "create_wire", key, arg[iarg + 1], 1, MAXTAGINT);
      iarg += 2;
    } else if (key == "radius") {
      need(1);
      r.radius = number(iarg + 1);
      if (!(r.radius > 0.0) || !std::isfinite(r.radius))
        error->all(FLERR, "create_wire: radius {} must be positive and finite", arg[iarg + 1]);
      iarg += 2;
    } else if (key == "overlap") {
      need(1);
      r.check_overlap = strcmp(arg[iarg + 1], "ignore") != 0;
      if (r.check_overlap) {
        r.overlap = number(iarg + 1);
        if (!(r.overlap >= 0.0))
          error->all(FLERR, "create_wire: overlap {} must be >= 0 (a fraction of the wire radius) "
                     "or 'ignore'", arg[iarg + 1]);
      }
      iarg += 2;
    } else if (key == "strained") {
      need(1);
      r.strained = utils::logical(FLERR, arg[iarg + 1], false, lmp) != 0;
      iarg += 2;
    } else if (key == "drop") {
      need(1);
      r.drop = utils::logical(FLERR, arg[iarg + 1], false, lmp) != 0;
      iarg += 2;
    } else {
      error->all(FLERR, "create_wire: unknown keyword '{}'; the "
                 "keywords are listed in doc/create_wire.rst, Syntax", key);
    }
  }
  if (r.continues()) {
    if (r.drop)
      error->all(FLERR, "create_wire: 'drop' cannot be combined with 'from' (a continued wire starts at its "
                 "end); remove one");
    if (r.nodes > 0)
      error->all(FLERR, "create_wire: 'nodes' cannot be combined with "
                 "'from'; drop 'nodes' (doc/create_wire.rst, Errors)");
    return;    // the types, molecule and mass default to the wire's (find_end)
  }
  if (r.bond_type == 0) error->all(FLERR, "create_wire: give the bond type of the elements ('bond BTYPE')");
  if (r.mass < 0.0) error->all(FLERR, "create_wire: give the node mass ('mass M')");
}

/* 'from ID|last': the wire nodes, their bonds and angles from every rank (a setup command),
   the end checked to be a free end (a wire node with exactly one element), and the wire's
   node type, bond and angle types, molecule ID and node mass there, which the new part takes
   (given values must agree). */
void CreateWire::find_end()
{
  Request &r = *request;
  Request::End &end = r.end;
  auto *avec = AtomVecSpheropolyhedron::find(lmp, "create_wire");
  struct NodeRecord {
    tagint tag, molecule;
    int type, grain, bonds, angles;
    double x[3], mass;
  };
  struct BondRecord {
    tagint a, b;
    int type;
  };
  struct AngleRecord {
    tagint a, b, c;
    int type;
  };
  std::vector<NodeRecord> my_nodes;
  std::vector<BondRecord> my_bonds;
  std::vector<AngleRecord> my_angles;
  for (int i = 0; i < atom->nlocal; i++) {
    const bool grain = avec->shape[i] != 0;
    if (grain && atom->tag[i] != end.tag) continue;
    NodeRecord n{atom->tag[i], atom->molecule[i], atom->type[i], grain ? 1 : 0, atom->num_bond[i],
                 atom->num_angle ? atom->num_angle[i] : 0, {0.0, 0.0, 0.0}, avec->rmass[i]};
    domain->unmap(atom->x[i], atom->image[i], n.x);
    my_nodes.push_back(n);
    if (grain) continue;
    for (int m = 0; m < atom->num_bond[i]; m++)
      my_bonds.push_back({atom->tag[i], atom->bond_atom[i][m], atom->bond_type[i][m]});
    for (int m = 0; atom->num_angle && m < atom->num_angle[i]; m++)
      my_angles.push_back({atom->angle_atom1[i][m], atom->angle_atom2[i][m], atom->angle_atom3[i][m],
                           atom->angle_type[i][m]});
  }
  std::map<tagint, NodeRecord> nodes;
  for (const NodeRecord &n : gather_records(my_nodes, world, true)) nodes[n.tag] = n;
  std::map<tagint, std::map<tagint, int>> partners;    // node -> neighbour -> bond type
  for (const BondRecord &b : gather_records(my_bonds, world, true)) {
    if (!nodes.count(b.a) || !nodes.count(b.b) || nodes[b.b].grain) continue;
    partners[b.a][b.b] = b.type;
    partners[b.b][b.a] = b.type;
  }
  const std::vector<AngleRecord> angles = gather_records(my_angles, world, true);
  auto free_ends_of = [&](tagint molecule) {
    std::vector<tagint> ends;
    for (const auto &[tag, n] : nodes)
      if (!n.grain && n.molecule == molecule && partners[tag].size() == 1) ends.push_back(tag);
    return ends;
  };

  const std::string what = r.from_last ? "from last" : fmt::format("from {}", end.tag);
  if (r.from_last) {
    for (const auto &[tag, n] : nodes)
      if (!n.grain && partners[tag].size() == 1) end.tag = tag;    // the largest ID
    if (end.tag == 0)
      error->all(FLERR, "create_wire from last: no wire has a free end (a node with one element) to continue");
  }
  const auto found = nodes.find(end.tag);
  if (found == nodes.end())
    error->all(FLERR, "create_wire {}: no atom has ID {}; give the ID of a wire's free end", what, end.tag);
  const NodeRecord &e = found->second;
  if (e.grain)
    error->all(FLERR, "create_wire {}: atom ID {} is a grain, not a wire node; give the ID of a wire's free end",
               what, end.tag);
  const size_t elements = partners[end.tag].size();
  if (elements != 1) {
    const std::vector<tagint> ends = free_ends_of(e.molecule);
    std::string listed;
    for (tagint t : ends) listed += fmt::format("{}{}", listed.empty() ? "" : " ", t);
    std::string hint = ends.empty() ? fmt::format("its wire (molecule {}) has no free end: a closed ring", e.molecule)
                                    : fmt::format("the free ends of molecule {}: ID(s) {}", e.molecule, listed);
    error->all(FLERR, "create_wire {}: node ID {} is not a free end of a wire: it joins {} elements ({}); start from a node of one "
               "element; {}",
               what, end.tag, elements, elements == 0 ? "a lone node" : "an inner node, or a node of a ring", hint);
  }
  end.neighbour = partners[end.tag].begin()->first;
  end.bond_type = partners[end.tag].begin()->second;
  for (const auto &[tag, type] : partners[end.neighbour])
    if (tag != end.tag) end.second = tag;
  end.x = vec3(e.x);
  end.x_neighbour = vec3(nodes[end.neighbour].x);
  if (end.second) end.x_second = vec3(nodes[end.second].x);
  end.type = e.type;
  end.molecule = e.molecule;
  end.mass = e.mass;
  end.bonds_stored = e.bonds;
  end.angles_stored = e.angles;
  end.neighbour_angles_stored = nodes[end.neighbour].angles;
  // the wire's bending type: the joint at the neighbour, else any joint of the molecule
  for (const AngleRecord &a : angles)
    if (a.b == end.neighbour || (!end.angle_type && nodes.count(a.b) && nodes[a.b].molecule == end.molecule))
      end.angle_type = a.type;

  auto agree = [&](const char *name, long long given, long long wire, const char *keyword) {
    if (given != wire)
      error->all(FLERR, "create_wire {}: {} {} differs from the wire's {} at node ID {}; give {} or drop "
                 "'{}' (doc/create_wire.rst, Errors)", what, name, given, wire, end.tag, wire, keyword);
  };
  agree("atom type", r.node_type, end.type, "TYPE");
  if (r.bond_type) agree("bond type", r.bond_type, end.bond_type, "bond");
  r.bond_type = end.bond_type;
  if (r.angle_type && end.angle_type) agree("angle type", r.angle_type, end.angle_type, "angle");
  if (end.angle_type) r.angle_type = end.angle_type;
  if (r.mol_given) agree("molecule", r.molecule, end.molecule, "mol");
  r.molecule = end.molecule;
  if (r.mass < 0.0) r.mass = end.mass;
}

/* The end node stores the join bond (newton_bond on: if it has room, else the first new node
   does) and the joint at the end; with newton_bond off every atom of a bond or angle stores
   it. Room is checked before anything is created. */
void CreateWire::check_room_at_end()
{
  Request &r = *request;
  Request::End &end = r.end;
  const int bonds = atom->bond_per_atom, angles = atom->angle_per_atom;
  auto short_of = [&](const char *what, tagint tag, int stored, int per_atom, const char *keyword) {
    error->all(FLERR, "create_wire from {}: node ID {} stores {} {}(s), room for {}; the join needs one "
               "more: create the box with '{} {}'", end.tag, tag, stored, what, per_atom, keyword, stored + 1);
  };
  if (force->newton_bond) {
    end.join_bond_on_end = end.bonds_stored < bonds;
    if (!end.join_bond_on_end && bonds < 2) short_of("bond", end.tag, end.bonds_stored, bonds, "extra/bond/per/atom");
  } else if (end.bonds_stored >= bonds) {
    short_of("bond", end.tag, end.bonds_stored, bonds, "extra/bond/per/atom");
  }
  if (!r.angle_type) return;
  if (end.angles_stored >= angles) short_of("angle", end.tag, end.angles_stored, angles, "extra/angle/per/atom");
  if (!force->newton_bond && end.neighbour_angles_stored >= angles)
    short_of("angle", end.neighbour, end.neighbour_angles_stored, angles, "extra/angle/per/atom");
}

/* The types must exist with bond_style wire coefficients: the bond type's rest length is the
   element length. The nodes store one bond and one angle each. */
void CreateWire::check_types()
{
  Request &r = *request;
  if (r.bond_type < 1 || r.bond_type > atom->nbondtypes)
    error->all(FLERR, "create_wire: bond type {} is not between 1 and {} (create_box ... bond/types N)",
               r.bond_type, atom->nbondtypes);
  auto *bond = dynamic_cast<BondWire *>(force->bond);
  if (!bond)
    error->all(FLERR, "create_wire needs bond_style wire (its rest length sets the element length); "
               "bond_style is '{}'", force->bond_style ? force->bond_style : "none");
  if (!bond->setflag || !bond->setflag[r.bond_type])
    error->all(FLERR, "create_wire: bond type {} has no coefficients yet; give 'bond_coeff {} K_ELO "
               "REST_LENGTH' first", r.bond_type, r.bond_type);
  r.rest_length = bond->rest_length(r.bond_type);
  if (r.angle_type != 0) {
    if (!atom->avec->angles_allow)
      error->all(FLERR, "create_wire: angle {} needs an atom style with angles (e.g. 'atom_style "
                 "hybrid spheropolyhedron angle')", r.angle_type);
    if (r.angle_type < 1 || r.angle_type > atom->nangletypes)
      error->all(FLERR, "create_wire: angle type {} is not between 1 and {} (create_box ... "
                 "angle/types N)", r.angle_type, atom->nangletypes);
    if (!force->angle || !force->angle->setflag || !force->angle->setflag[r.angle_type])
      error->all(FLERR, "create_wire: angle type {} has no coefficients yet; give angle_style wire "
                 "and 'angle_coeff {} K_ROT' first", r.angle_type, r.angle_type);
  }
  if (atom->bond_per_atom < 1 || (r.angle_type && atom->angle_per_atom < 1))
    error->all(FLERR, "create_wire: each node stores a bond and an angle; create "
               "the box with 'extra/bond/per/atom 1 extra/angle/per/atom 1'");
  if (r.radius < 0.0) {
    r.radius = wire_radius_of_fix_wire(lmp, -1.0);
    if (r.radius < 0.0)
      error->all(FLERR, "create_wire: give the wire radius ('radius RW') or define fix wire first");
  }
  if (r.rest_length < 2.0 * r.radius)
    error->all(FLERR, "create_wire: element length {} (rest length of bond type {}) is below the "
               "wire's diameter {}; use longer elements", r.rest_length, r.bond_type, 2.0 * r.radius);
}

void CreateWire::lay_out()
{
  Request &r = *request;
  try {
    const bool loop = r.shape == Request::Shape::loop;
    if (r.continues())
      r.layout = loop ? lay_loop_from(r.end.x, r.loop, r.rest_length) : lay_polyline_from(r.end.x, r.polyline, r.rest_length);
    else if (r.nodes > 0) r.layout = loop ? lay_loop_nodes(r.loop, r.nodes) : lay_polyline_nodes(r.polyline, r.nodes);
    else r.layout = loop ? lay_loop(r.loop, r.rest_length) : lay_polyline(r.polyline, r.rest_length);
  } catch (std::exception &e) {
    error->all(FLERR, "create_wire {}: {}", r.shape_name, e.what());
  }
  const double strain = r.layout.chord / r.rest_length - 1.0;
  if (std::abs(strain) > LENGTH_TOLERANCE && !r.strained)
    error->all(FLERR, "create_wire {}: elements {:.10g} long, rest length {:.10g} (strain {:.3g}); "
               "see doc/create_wire.rst, Errors", r.shape_name, r.layout.chord, r.rest_length, strain);
  for (nscd::wire::WireElement &e : r.layout.topology.elements) e.rest_length = r.rest_length;
}

/* Nodes in non-periodic directions must lie in the box; periodic ones are wrapped into it
   (their image flags keep the wire whole). */
void CreateWire::check_nodes_in_box()
{
  Request &r = *request;
  const size_t n = r.layout.nodes.size();
  r.in_box.resize(n);
  r.images.resize(n);
  for (size_t k = 0; k < n; k++) {
    double x[3];
    store(r.layout.nodes[k], x);
    imageint image = ((imageint) IMGMAX << IMG2BITS) | ((imageint) IMGMAX << IMGBITS) | IMGMAX;
    domain->remap(x, image);
    double lamda[3], *coord = x;
    if (domain->triclinic) {
      domain->x2lamda(x, lamda);
      coord = lamda;
    }
    const double *lo = domain->triclinic ? domain->boxlo_lamda : domain->boxlo;
    const double *hi = domain->triclinic ? domain->boxhi_lamda : domain->boxhi;
    for (int d = 0; d < 3; d++)
      if (!domain->periodicity[d] && !(coord[d] >= lo[d] && coord[d] < hi[d]))
        error->all(FLERR, "create_wire {}: node {} at ({:.6g}, {:.6g}, {:.6g}) is outside the box in {}; move the path or enlarge "
                   "the box",
                   r.shape_name, k + 1, r.layout.nodes[k].x(), r.layout.nodes[k].y(), r.layout.nodes[k].z(), "xyz"[d]);
    r.in_box[k] = vec3(x);
    r.images[k] = image;
  }
}

/* The periodic translations of the box that can bring one part of the new wire onto
   another, onto a wire already there or onto a grain: every lattice vector up to the new wire's extent
   (in box lengths, plus one) in each periodic direction. */
static std::vector<nscd::Vec3> periodic_shifts(const Domain *domain, const std::vector<nscd::Vec3> &nodes)
{
  const nscd::Vec3 edges[3] = {nscd::Vec3(domain->xprd, 0.0, 0.0), nscd::Vec3(domain->xy, domain->yprd, 0.0),
                               nscd::Vec3(domain->xz, domain->yz, domain->zprd)};
  int reach[3] = {0, 0, 0};
  for (int d = 0; d < 3; d++) {
    if (!domain->periodicity[d]) continue;
    double farthest = 0.0;
    for (const nscd::Vec3 &x : nodes) farthest = std::max(farthest, std::abs(x[d] - 0.5 * (domain->boxlo[d] + domain->boxhi[d])));
    reach[d] = (int) std::ceil(farthest / domain->prd[d]) + 1;
  }
  std::vector<nscd::Vec3> shifts;
  for (int i = -reach[0]; i <= reach[0]; i++)
    for (int j = -reach[1]; j <= reach[1]; j++)
      for (int k = -reach[2]; k <= reach[2]; k++)
        if (i || j || k) shifts.push_back(i * edges[0] + j * edges[1] + k * edges[2]);
  return shifts;
}

/* This rank's grains where they stand, for the overlap checks (and their atom IDs). */
static std::vector<nscd::wire::PlacedGrain> local_grains(LAMMPS *lmp, std::vector<tagint> *tags = nullptr)
{
  auto *avec = AtomVecSpheropolyhedron::find(lmp, "create_wire");
  std::vector<nscd::wire::PlacedGrain> grains;
  for (int i = 0; i < lmp->atom->nlocal; i++) {
    if (avec->shape[i] == 0) continue;
    grains.push_back({&avec->shape_of(i), avec->pose(i)});
    if (tags) tags->push_back(lmp->atom->tag[i]);
  }
  return grains;
}

/* The walls and plates (fix nscd/wall, fix nscd/plate) a wire must not start in. */
static std::vector<NSCDBoundaryFix *> boundary_fixes(Modify *modify)
{
  std::vector<NSCDBoundaryFix *> found;
  for (Fix *fix : modify->get_fix_list())
    if (auto *boundary_fix = dynamic_cast<NSCDBoundaryFix *>(fix)) found.push_back(boundary_fix);
  return found;
}

/* The wire must not start inside grains or walls: each rank tests its own grains (and their
   periodic images) against the elements near them, every rank the walls against the node
   spheres; the deepest overlap beyond the tolerance stops the command, named. */
void CreateWire::check_overlaps()
{
  Request &r = *request;
  const double allowed = r.overlap * r.radius;
  std::vector<tagint> grain_tags;
  const std::vector<nscd::wire::PlacedGrain> grains = local_grains(lmp, &grain_tags);
  const nscd::wire::ElementOverlap o = nscd::wire::deepest_overlap_with_grains(
      {r.layout.nodes, r.layout.topology.elements}, r.radius, grains, periodic_shifts(domain, r.layout.nodes));
  double worst[2] = {o.b >= 0 ? o.depth : -1.0, o.b >= 0 ? (double) grain_tags[o.b] : 0.0};    // depth, grain ID
  double deepest[2];
  MPI_Allreduce(worst, deepest, 1, MPI_2DOUBLE_PRECISION, MPI_MAXLOC, world);
  if (deepest[0] > allowed)
    error->all(FLERR, "create_wire {}: the wire overlaps grain ID {} by {:.4g} (allowed: {:.4g}); see "
               "doc/create_wire.rst, Errors", r.shape_name, (tagint) deepest[1], deepest[0], allowed);

  for (NSCDBoundaryFix *boundary_fix : boundary_fixes(modify))
    for (size_t k = r.first_new(); k < r.in_box.size(); k++) {
      const nscd::ContactPoint p = boundary_fix->boundary().touch_sphere(r.in_box[k], r.radius, 0.0);
      if (-p.gap > allowed)
        error->all(FLERR, "create_wire {}: node {} overlaps the wall or plate of fix {} by {:.4g} (allowed: "
                   "{:.4g}); doc/create_wire.rst, Errors", r.shape_name, k + 1, dynamic_cast<Fix *>(boundary_fix)->id, -p.gap, allowed);
    }
}

/* The new wire must not lie on itself (turns of a helix closer than its diameter, a loop
   reaching its own periodic image) nor on a wire already there: elements as
   spherocylinders of the wire radius, the pairs the contact model would see
   (lib/wire/wire_overlap.h), overlapping by more than the tolerance stop the command. The
   existing wires' elements are gathered on every rank (a setup command). */
void CreateWire::check_wire_overlaps()
{
  namespace wire = nscd::wire;
  const Request &r = *request;
  const double allowed = r.overlap * r.radius;
  const std::vector<nscd::Vec3> shifts = periodic_shifts(domain, r.layout.nodes);
  const wire::WirePieces mine{r.layout.nodes, r.layout.topology.elements};
  // a continued wire: its last two elements join the new part's own check, where the pairs
  // joined through the end are exempt as the contact model exempts them
  wire::WirePieces joined = mine;
  std::vector<std::array<tagint, 2>> end_elements;
  const int n = (int) r.layout.nodes.size();
  if (r.continues()) {
    joined.nodes.push_back(r.end.x_neighbour);
    joined.elements.push_back({n, 0, r.rest_length});
    end_elements.push_back({r.end.neighbour, r.end.tag});
    if (r.end.second) {
      joined.nodes.push_back(r.end.x_second);
      joined.elements.push_back({n + 1, n, r.rest_length});
      end_elements.push_back({r.end.second, r.end.neighbour});
    }
  }
  auto node_name = [&](int k) {
    if (k < n && k >= r.first_new()) return fmt::format("{}", k + 1 - r.first_new());
    return fmt::format("ID {}", k == 0 ? r.end.tag : k == n ? r.end.neighbour : r.end.second);
  };
  const wire::ElementOverlap self = wire::deepest_overlap_within(joined, r.radius, shifts);
  if (self.depth > allowed) {
    const auto &ea = joined.elements[self.a], &eb = joined.elements[self.b];
    // the cause where it is known (doc/create_wire.rst, Errors, has the rest)
    std::string why = fmt::format(" (allowed {:.4g}); lay it elsewhere or raise 'overlap'", allowed);
    if (self.shift.squaredNorm() > 0.0)
      why = ": it reaches its periodic image; shrink it or enlarge the box";
    else if (r.shape == Request::Shape::loop && r.loop.turns > 1.0 && std::abs(r.loop.pitch) < 2.0 * r.radius)
      why = fmt::format(": the pitch {:.6g} is below the wire's diameter {:.6g}; raise it", r.loop.pitch,
                        2.0 * r.radius);
    error->all(FLERR, "create_wire {}: overlaps itself by {:.4g} at elements {}-{}, {}-{}{}", r.shape_name,
               self.depth, node_name(ea.a), node_name(ea.b), node_name(eb.a), node_name(eb.b), why);
  }

  const WireElements existing = gather_wire_elements(lmp, "create_wire", end_elements);
  const wire::ElementOverlap other = wire::deepest_overlap_between(mine, existing.pieces, r.radius, shifts);
  if (other.depth > allowed)
    error->all(FLERR, "create_wire {}: overlaps the wire element between atoms ID {} and {} by {:.4g}; see "
               "doc/create_wire.rst, Errors", r.shape_name, existing.bonds[other.b][0], existing.bonds[other.b][1], other.depth);
}

/* 'drop yes': the wire as laid out is lowered straight down (-z) until it touches a grain, a
   wall or plate, or a wire already there: laid on the surface below it, as a string laid
   on gravel, instead of falling onto it. Each candidate drop is checked as the overlap
   checks do (every rank its grains, every rank the walls, the other wires gathered once),
   the deepest overlap reduced over the ranks; the scan steps by the wire's radius (nothing
   it can meet is thinner than the wire's diameter), then bisects to 1e-6 of the radius. */
void CreateWire::drop_onto_what_is_below()
{
  Request &r = *request;
  const std::vector<nscd::wire::PlacedGrain> grains = local_grains(lmp);
  const std::vector<NSCDBoundaryFix *> boundaries = boundary_fixes(modify);
  const WireElements existing = gather_wire_elements(lmp, "create_wire");
  // down to the box's floor (a periodic box: one box height); the periodic images to check
  // are those the wire can reach anywhere along the way
  double lowest = r.layout.nodes[0].z();
  for (const nscd::Vec3 &x : r.layout.nodes) lowest = std::min(lowest, x.z());
  const double max_drop = domain->zperiodic ? domain->zprd : std::max(0.0, lowest - r.radius - domain->boxlo[2]);
  std::vector<nscd::Vec3> swept = r.layout.nodes;
  for (const nscd::Vec3 &x : r.layout.nodes) swept.push_back(x - max_drop * nscd::Vec3::UnitZ());
  const std::vector<nscd::Vec3> shifts = periodic_shifts(domain, swept);
  nscd::wire::WirePieces lowered{r.layout.nodes, r.layout.topology.elements};

  auto depth = [&](double drop) {
    for (size_t k = 0; k < lowered.nodes.size(); k++) lowered.nodes[k] = r.layout.nodes[k] - drop * nscd::Vec3::UnitZ();
    double deepest = -1.0;
    const nscd::wire::ElementOverlap on_grain = nscd::wire::deepest_overlap_with_grains(lowered, r.radius, grains, shifts);
    if (on_grain.b >= 0) deepest = std::max(deepest, on_grain.depth);
    const nscd::wire::ElementOverlap on_wire =
        nscd::wire::deepest_overlap_between(lowered, existing.pieces, r.radius, shifts);
    if (on_wire.b >= 0) deepest = std::max(deepest, on_wire.depth);
    for (NSCDBoundaryFix *boundary_fix : boundaries)
      for (size_t k = 0; k < r.in_box.size(); k++) {
        const nscd::Vec3 x = r.in_box[k] - drop * nscd::Vec3::UnitZ();
        deepest = std::max(deepest, -boundary_fix->boundary().touch_sphere(x, r.radius, 0.0).gap);
      }
    double everywhere;
    MPI_Allreduce(&deepest, &everywhere, 1, MPI_DOUBLE, MPI_MAX, world);
    return everywhere;
  };

  const nscd::wire::Drop drop = nscd::wire::first_touch_drop(depth, max_drop, r.radius, 1e-6 * r.radius);
  if (!drop.touched)
    error->all(FLERR, "create_wire {}: 'drop yes': nothing below the wire within {:.4g} (the box's floor); lay it "
               "above a grain, wall or wire", r.shape_name, max_drop);
  for (nscd::Vec3 &x : r.layout.nodes) x.z() -= drop.distance;
  r.dropped = drop.distance;
  check_nodes_in_box();
}

/* Each rank creates the nodes whose positions lie in its sub-domain, with consecutive new
   atom IDs and the molecule ID. */
void CreateWire::create_nodes()
{
  Request &r = *request;
  auto *avec = AtomVecSpheropolyhedron::find(lmp, "create_wire");
  tagint mine = 0, mol = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    mine = std::max(mine, atom->tag[i]);
    if (atom->molecule) mol = std::max(mol, atom->molecule[i]);
  }
  tagint max_tag, max_mol;
  MPI_Allreduce(&mine, &max_tag, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  MPI_Allreduce(&mol, &max_mol, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  r.first_tag = max_tag + 1;
  if (r.molecule < 0) r.molecule = max_mol + 1;

  const bigint natoms_before = atom->natoms;
  const int nlocal_before = atom->nlocal;
  drop_ghosts_for_new_atoms(lmp);
  for (size_t k = r.first_new(); k < r.in_box.size(); k++) {
    double x[3];
    store(r.in_box[k], x);
    if (!in_my_subdomain(domain, x)) continue;
    atom->avec->create_atom(r.node_type, x);
    const int i = atom->nlocal - 1;
    atom->tag[i] = r.tag((int) k);
    atom->molecule[i] = r.molecule;
    atom->image[i] = r.images[k];
    avec->set_shape(i, 0, r.mass);
  }
  finish_new_atoms(lmp, natoms_before, nlocal_before, (bigint) r.in_box.size() - r.first_new(),
                   fmt::format("nodes of create_wire {} found no rank (on the box's upper faces?); move the path "
                               "inside the box", r.shape_name));
}

/* A bond is stored on its first node, an angle on its middle node (and with newton_bond off
   also on the others), as create_bonds does. A continued wire's join bond is stored on its end
   if that has room, else on the first new node (check_room_at_end); the joint at the end
   (neighbour, end, first new node) is one more angle. */
void CreateWire::create_bonds_and_angles()
{
  const Request &r = *request;
  auto local_tag = [&](tagint tag) {
    const int i = atom->map(tag);
    return i >= 0 && i < atom->nlocal ? i : -1;
  };
  auto local = [&](int node) { return local_tag(r.tag(node)); };
  auto add_bond = [&](int i, int other) {
    if (i < 0) return;
    if (atom->num_bond[i] == atom->bond_per_atom)
      error->one(FLERR, "create_wire: node ID {} has no room for another bond; create the box with "
                 "more 'extra/bond/per/atom'", atom->tag[i]);
    atom->bond_type[i][atom->num_bond[i]] = r.bond_type;
    atom->bond_atom[i][atom->num_bond[i]++] = r.tag(other);
  };
  for (const auto &e : r.layout.topology.elements) {
    const bool join = r.continues() && e.a == 0;
    if (join && force->newton_bond && !r.end.join_bond_on_end) {
      add_bond(local(e.b), e.a);
      continue;
    }
    add_bond(local(e.a), e.b);
    if (!force->newton_bond) add_bond(local(e.b), e.a);
  }
  atom->nbonds += (bigint) r.layout.topology.elements.size();
  if (!r.angle_type) return;

  auto add_angle = [&](int i, const std::array<tagint, 3> &j) {
    if (i < 0) return;
    if (atom->num_angle[i] == atom->angle_per_atom)
      error->one(FLERR, "create_wire: node ID {} has no room for another angle; create the box with "
                 "more 'extra/angle/per/atom'", atom->tag[i]);
    const int m = atom->num_angle[i]++;
    atom->angle_type[i][m] = r.angle_type;
    atom->angle_atom1[i][m] = j[0];
    atom->angle_atom2[i][m] = j[1];
    atom->angle_atom3[i][m] = j[2];
  };
  std::vector<std::array<tagint, 3>> joints;
  if (r.continues()) joints.push_back({r.end.neighbour, r.end.tag, r.tag(1)});
  for (const auto &j : r.layout.topology.joints) joints.push_back({r.tag(j.a), r.tag(j.b), r.tag(j.c)});
  for (const auto &j : joints) {
    add_angle(local_tag(j[1]), j);
    if (!force->newton_bond) {
      add_angle(local_tag(j[0]), j);
      add_angle(local_tag(j[2]), j);
    }
  }
  atom->nangles += (bigint) joints.size();
}
