#include "wire/contact_weights.h"

#include <algorithm>

namespace nscd::wire {

double stretch_end_weight(double stretch, double ramp)
{
  if (!(ramp > 0.0)) return 1.0;
  return 0.5 + 0.5 * std::clamp(stretch / ramp, 0.0, 1.0);
}

}    // namespace nscd::wire
