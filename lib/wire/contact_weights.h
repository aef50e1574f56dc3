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

// How much of a soft contact each point found by a wire element carries.
//
// Each element is its own spherocylinder and each element-body pair its own contact (the
// paper's model), so near a node two elements can both touch a body, each with its own
// point: a contact there is up to twice as stiff as along an element, but the force stays
// continuous as the body slides past the node. An element lying on a face touches it along
// a stretch, reported as the stretch's two ends; their weights keep the force continuous
// as the stretch grows from a point (tests/unit/wire/test_contact_weights.cpp).
#pragma once

namespace nscd::wire {

// Weight of each of the two ends of a touching stretch `stretch` long: from 1/2 (as the
// stretch shrinks to a point, the two ends become one point of weight 1) up to 1 once the
// stretch is `ramp` long. With ramp = the activation distance of the contact query, a far
// end whose gap grows leaves the query only once the stretch is at least that long (along
// an element the gap changes by at most the distance travelled), so the other end's
// weight is then 1 already, as for a single point.
double stretch_end_weight(double stretch, double ramp);

}    // namespace nscd::wire
