// Sonine (Laguerre) polynomials S2, S3 and the first-Sonine approximation of a2(ε) in the
// homogeneous cooling state, for d dimensions.
#pragma once

namespace molchaos::theory {

/// Second Sonine polynomial S2(x) = L^{(d/2-1)}_2(x) = x²/2 − (d+2)/2 · x + d(d+2)/8.
/// d = 2 gives the paper's Eq. (19), x²/2 − 2x + 1.
double sonine_s2(int dimension, double x);

/// Third Sonine polynomial S3(x) = L^{(d/2-1)}_3(x)
///   = −x³/6 + (d+4)/4 · x² − (d+2)(d+4)/8 · x + d(d+2)(d+4)/48.
double sonine_s3(int dimension, double x);

/// a2(ε) of the first Sonine approximation with the molecular-chaos (linearised) closure
/// (van Noije & Ernst 1998): 16(1−ε)(1−2ε²) / [9 + 24d − (41 − 8d)ε + 30ε²(1−ε)].
/// d = 2 gives the paper's Eq. (25). The same number follows from the quadrature of the
/// collision moments μ2, μ4 (collision_moments.hpp: a2_from_moments), which the tests compare.
double a2_first_sonine(int dimension, double restitution);

}  // namespace molchaos::theory
