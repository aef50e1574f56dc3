#include "wire/contact_weights.h"

#include <algorithm>

namespace nscd::wire {

double stretch_end_weight(double stretch, double ramp)
{
  if (!(ramp > 0.0)) return 1.0;
  return 0.5 + 0.5 * std::clamp(stretch / ramp, 0.0, 1.0);
}

double node_point_weight(const Vec3 &normal, const Vec3 *others, int count)
{
  // Round-off of unit vectors: a direction along the contact plane counts as along it.
  constexpr double kAlong = 1e-12;
  for (int k = 0; k < count; ++k)
    if (others[k].dot(normal) < -kAlong) return 0.0;
  return 1.0 / (1 + count);
}

}    // namespace nscd::wire
