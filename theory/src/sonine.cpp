// Second and third Sonine polynomials and the first-Sonine a2(ε) in d dimensions.
#include "molchaos/theory/sonine.hpp"

#include "molchaos/theory/dimension.hpp"

namespace molchaos::theory {

double sonine_s2(int dimension, double x) {
  const double d = dimension;
  return 0.5 * x * x - 0.5 * (d + 2.0) * x + d * (d + 2.0) / 8.0;
}

double sonine_s3(int dimension, double x) {
  const double d = dimension;
  return -x * x * x / 6.0 + 0.25 * (d + 4.0) * x * x - 0.125 * (d + 2.0) * (d + 4.0) * x +
         d * (d + 2.0) * (d + 4.0) / 48.0;
}

double a2_first_sonine(int dimension, double restitution) {
  require_dimension(dimension);
  require_restitution(restitution);
  const double d = dimension;
  const double e = restitution;
  // + 0.0: at ε = 1 the product is (+0)(−1) = −0, and −0 + (+0) = +0 (IEEE 754): a2 of the
  // elastic gas is zero, not a negative zero in the output.
  return 16.0 * (1.0 - e) * (1.0 - 2.0 * e * e) /
             (9.0 + 24.0 * d - (41.0 - 8.0 * d) * e + 30.0 * e * e * (1.0 - e)) +
         0.0;
}

}  // namespace molchaos::theory
