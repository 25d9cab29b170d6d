// Argument checks shared by the theory functions; messages name the parameter and its range.
#include "molchaos/theory/dimension.hpp"

#include <cmath>
#include <sstream>

namespace molchaos::theory {

void require_in_range(const std::string& name, double x, double lo, double hi, bool hi_open) {
  const bool ok = std::isfinite(x) && x > lo && (hi_open ? x < hi : x <= hi);
  if (!ok) {
    std::ostringstream msg;
    msg << name << ": value " << exact_text(x) << " is outside the allowed range ("
        << exact_text(lo) << ", " << exact_text(hi) << (hi_open ? ")" : "]");
    throw std::invalid_argument(msg.str());
  }
}

void require_restitution(double restitution) {
  require_in_range("restitution", restitution, 0.0, 1.0, false);
}

void require_density(int dimension, double density) {
  require_in_range("density", density, 0.0, close_packing_density(dimension), true);
}

}  // namespace molchaos::theory
