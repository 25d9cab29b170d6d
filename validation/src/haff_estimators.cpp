// The four τ0 estimators of haff_estimators.hpp.
#include "molchaos/validation/haff_estimators.hpp"

#include <cmath>

#include "molchaos/validation/haff_fit.hpp"

namespace molchaos::validation {
namespace {

struct Window {
  std::vector<double> t, y;  ///< y = 1/√T
};

// ∫ dt/y over one interval with y = 1/√T linear in t (Haff's law).
double segment_integral(double dt, double y1, double y2) {
  const double dy = y2 - y1;
  // ln(y2/y1)/(y2 − y1) → 1/y1 as y2 → y1 (no collision between the samples).
  return std::fabs(dy) > 1e-9 * y1 ? dt * std::log(y2 / y1) / dy : dt * 2.0 / (y1 + y2);
}

double integral_of_root_temperature(const Window& w) {
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < w.t.size(); ++i)
    sum += segment_integral(w.t[i + 1] - w.t[i], w.y[i], w.y[i + 1]);
  return sum;
}

double line_slope(const Window& w) {
  const double n = static_cast<double>(w.t.size());
  double mt = 0.0, my = 0.0;
  for (std::size_t i = 0; i < w.t.size(); ++i) {
    mt += w.t[i] / n;
    my += w.y[i] / n;
  }
  double sty = 0.0, stt = 0.0;
  for (std::size_t i = 0; i < w.t.size(); ++i) {
    sty += (w.t[i] - mt) * (w.y[i] - my);
    stt += (w.t[i] - mt) * (w.t[i] - mt);
  }
  return sty / stt;
}

}  // namespace

double root_temperature_integral(double t1, double T1, double t2, double T2) {
  return segment_integral(t2 - t1, 1.0 / std::sqrt(T1), 1.0 / std::sqrt(T2));
}

std::string_view to_string(HaffEstimator e) {
  switch (e) {
    case HaffEstimator::least_squares: return "least_squares";
    case HaffEstimator::integrated: return "integrated";
    case HaffEstimator::secant: return "secant";
    case HaffEstimator::line: return "line";
  }
  return "?";
}

Tau0Estimate estimate_tau0(HaffEstimator e, const std::vector<sim::Sample>& samples,
                           double t_start, double t_stop) {
  Tau0Estimate r;
  if (e == HaffEstimator::least_squares) {
    const HaffFit f = fit_haff(samples, t_start, t_stop);
    r.ok = f.ok;
    r.message = f.message;
    r.tau0_unit = f.tau0_unit;
    return r;
  }
  Window w;
  for (const auto& s : samples)
    if (s.t >= t_start && s.t <= t_stop && s.temperature > 0) {
      w.t.push_back(s.t);
      w.y.push_back(1.0 / std::sqrt(s.temperature));
    }
  if (w.t.size() < 4) {
    r.message = "fewer than 4 samples in the fit window";
    return r;
  }
  if (!(w.y.back() > w.y.front())) {
    r.message = "temperature does not decrease over the fit window";
    return r;
  }
  // Each estimate is 1/slope of 1/√T against t in units of T0 = 1.
  switch (e) {
    case HaffEstimator::integrated:
      // ln(T_start/T_stop) = 2 ln(y_stop/y_start).
      r.tau0_unit = integral_of_root_temperature(w) / std::log(w.y.back() / w.y.front());
      break;
    case HaffEstimator::secant:
      r.tau0_unit = (w.t.back() - w.t.front()) / (w.y.back() - w.y.front());
      break;
    case HaffEstimator::line: r.tau0_unit = 1.0 / line_slope(w); break;
    case HaffEstimator::least_squares: break;  // handled above
  }
  r.ok = std::isfinite(r.tau0_unit) && r.tau0_unit > 0.0;
  if (!r.ok) r.message = "the " + std::string(to_string(e)) + " estimate of tau0 is not positive";
  return r;
}

}  // namespace molchaos::validation
