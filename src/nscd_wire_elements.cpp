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

#include "nscd_wire_elements.h"
#include "atom_vec_spheropolyhedron.h"
#include "nscd_arrays.h"
#include "nscd_gather.h"

#include "atom.h"
#include "domain.h"
#include "fix.h"
#include "lammps.h"
#include "modify.h"

#include <algorithm>
#include <map>

namespace LAMMPS_NS {
namespace NSCD_NS {

WireElements gather_wire_elements(LAMMPS *lmp, const char *caller, const std::vector<std::array<tagint, 2>> &skip)
{
  struct Node {
    tagint tag;
    double x[3];
  };
  Atom *atom = lmp->atom;
  auto *avec = AtomVecSpheropolyhedron::find(lmp, caller);
  std::vector<Node> my_nodes;
  std::vector<std::array<tagint, 2>> my_bonds;
  for (int i = 0; i < atom->nlocal; i++) {
    if (avec->shape[i] != 0) continue;
    my_nodes.push_back({atom->tag[i], {atom->x[i][0], atom->x[i][1], atom->x[i][2]}});
    if (atom->num_bond)    // an atom style without bonds: points, no wire
      for (int m = 0; m < atom->num_bond[i]; m++) my_bonds.push_back({atom->tag[i], atom->bond_atom[i][m]});
  }
  std::map<tagint, nscd::Vec3> where;
  for (const Node &n : gather_records(my_nodes, lmp->world, true)) where[n.tag] = vec3(n.x);
  WireElements found;
  for (const auto &b : gather_records(my_bonds, lmp->world, true)) {
    const auto p = where.find(b[0]), q = where.find(b[1]);
    if (p == where.end() || q == where.end()) continue;    // a bond to a grain: not a wire element
    auto same = [&](const std::array<tagint, 2> &e) {
      return (e[0] == b[0] && e[1] == b[1]) || (e[0] == b[1] && e[1] == b[0]);
    };
    if (std::any_of(skip.begin(), skip.end(), same)) continue;
    double delta[3] = {q->second.x() - p->second.x(), q->second.y() - p->second.y(), q->second.z() - p->second.z()};
    lmp->domain->minimum_image(delta);
    const int first = (int) found.pieces.nodes.size();
    found.pieces.nodes.push_back(p->second);
    found.pieces.nodes.push_back(p->second + vec3(delta));
    found.pieces.elements.push_back({first, first + 1, 0.0});
    found.bonds.push_back(b);
  }
  return found;
}

double wire_radius_of_fix_wire(LAMMPS *lmp, double fallback)
{
  for (Fix *fix : lmp->modify->get_fix_by_style("^wire$")) {
    int dim = 0;
    if (auto *radius = static_cast<double *>(fix->extract("radius", dim))) return *radius;
  }
  return fallback;
}

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS
