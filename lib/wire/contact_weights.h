// How much of a soft contact each point found by one wire element carries.
//
// The wire's surface is the union of its elements' spherocylinders. An element lying on a
// face touches it along a stretch, reported as the stretch's two ends; near a node, the
// elements meeting there can find the same contact. Weighting the points as below keeps the
// summed force continuous as a contact slides along the wire, past a node, onto or off a
// face, and as an element tilts (tests/unit/wire/test_contact_weights.cpp).
#pragma once

#include "math/types.h"

namespace nscd::wire {

// Weight of each of the two ends of a touching stretch `stretch` long: from 1/2 (as the
// stretch shrinks to a point, the two ends become one point of weight 1) up to 1 once the
// stretch is `ramp` long. With ramp = the activation distance of the contact query, a far
// end leaves the query only once the stretch is at least that long (along an element the
// gap changes by at most the distance travelled), so the other end's weight is then 1
// already, as for a single point.
double stretch_end_weight(double stretch, double ramp);

// Weight of a contact point on the sphere of a wire node, found by one element meeting
// there. `normal`: unit contact normal, from the other body towards the wire; `others`:
// unit directions from the node along the other elements there that can touch that body.
// An element whose direction points into the other body (direction . normal < 0) comes
// closer to it inside itself and carries the contact there: the node's point counts 0.
// Otherwise the node is the closest point of every element there, each finds the same
// point and each counts 1 / (1 + count), so the node's sphere is pushed once.
double node_point_weight(const Vec3 &normal, const Vec3 *others, int count);

}    // namespace nscd::wire
