#include "orchestrator/export/equivalent_diameters.hpp"

#include <cmath>

namespace aerobreak {

double volume_equivalent_diameter(double primaries) { return std::cbrt(primaries); }

double mobility_equivalent_diameter(double primaries) {
  return std::pow(primaries / kProjectedAreaPrefactor, 1.0 / (2.0 * kProjectedAreaExponent));
}

}  // namespace aerobreak
