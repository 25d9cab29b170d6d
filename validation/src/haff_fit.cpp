// Haff's-law fit with gsl_multifit_nlinear (trust region, Levenberg–Marquardt).
#include "molchaos/validation/haff_fit.hpp"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <cmath>
#include <memory>

namespace molchaos::validation {
namespace {

struct FitData {
  std::vector<double> t, T;
};

// Relative residuals: T spans decades, so each point counts by its relative deviation.
int residual(const gsl_vector* x, void* data, gsl_vector* f) {
  const auto* d = static_cast<const FitData*>(data);
  const double T0 = gsl_vector_get(x, 0), tau0 = gsl_vector_get(x, 1);
  for (std::size_t i = 0; i < d->t.size(); ++i) {
    const double s = 1.0 + d->t[i] / tau0;
    gsl_vector_set(f, i, (T0 / (s * s) - d->T[i]) / d->T[i]);
  }
  return GSL_SUCCESS;
}

int jacobian(const gsl_vector* x, void* data, gsl_matrix* J) {
  const auto* d = static_cast<const FitData*>(data);
  const double T0 = gsl_vector_get(x, 0), tau0 = gsl_vector_get(x, 1);
  for (std::size_t i = 0; i < d->t.size(); ++i) {
    const double s = 1.0 + d->t[i] / tau0;
    gsl_matrix_set(J, i, 0, 1.0 / (s * s * d->T[i]));
    gsl_matrix_set(J, i, 1, 2.0 * T0 * d->t[i] / (tau0 * tau0 * s * s * s * d->T[i]));
  }
  return GSL_SUCCESS;
}

}  // namespace

HaffFit fit_haff(const std::vector<sim::Sample>& samples, double t_start, double t_stop) {
  HaffFit fit;
  fit.t_start = t_start;
  fit.t_stop = t_stop;
  FitData data;
  for (const auto& s : samples)
    if (s.t >= t_start && s.t <= t_stop && s.temperature > 0) {
      data.t.push_back(s.t);
      data.T.push_back(s.temperature);
    }
  fit.points = data.t.size();
  if (fit.points < 4) {
    fit.message = "fewer than 4 samples in the fit window [" + std::to_string(t_start) + ", " +
                  std::to_string(t_stop) + "]";
    return fit;
  }
  // Starting values from the straight line 1/√T = (1 + t/τ0)/√T0 through the window's ends.
  const double y0 = 1.0 / std::sqrt(data.T.front()), y1 = 1.0 / std::sqrt(data.T.back());
  const double slope = (y1 - y0) / (data.t.back() - data.t.front());
  const double intercept = y0 - slope * data.t.front();
  if (!(slope > 0 && intercept > 0)) {
    fit.message = "temperature does not decrease over the fit window";
    return fit;
  }
  double start[2] = {1.0 / (intercept * intercept), intercept / slope};

  gsl_set_error_handler_off();
  const std::size_t n = data.t.size(), p = 2;
  gsl_multifit_nlinear_fdf fdf;
  fdf.f = residual;
  fdf.df = jacobian;
  fdf.fvv = nullptr;
  fdf.n = n;
  fdf.p = p;
  fdf.params = &data;
  gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
  std::unique_ptr<gsl_multifit_nlinear_workspace, decltype(&gsl_multifit_nlinear_free)> w(
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, p),
      &gsl_multifit_nlinear_free);
  gsl_vector_view x0 = gsl_vector_view_array(start, p);
  gsl_multifit_nlinear_init(&x0.vector, &fdf, w.get());
  int info = 0;
  const int status =
      gsl_multifit_nlinear_driver(200, 1e-12, 1e-12, 1e-12, nullptr, nullptr, &info, w.get());
  if (status != GSL_SUCCESS) {
    fit.message = std::string("gsl_multifit_nlinear: ") + gsl_strerror(status);
    return fit;
  }
  gsl_matrix* J = gsl_multifit_nlinear_jac(w.get());
  std::unique_ptr<gsl_matrix, decltype(&gsl_matrix_free)> covar(gsl_matrix_alloc(p, p),
                                                                &gsl_matrix_free);
  gsl_multifit_nlinear_covar(J, 0.0, covar.get());
  const gsl_vector* f = gsl_multifit_nlinear_residual(w.get());
  double chi2 = 0.0;
  gsl_blas_ddot(f, f, &chi2);
  const double dof = static_cast<double>(n - p);
  const double scale = chi2 / dof;
  const gsl_vector* x = gsl_multifit_nlinear_position(w.get());
  fit.T0 = gsl_vector_get(x, 0);
  fit.tau0 = gsl_vector_get(x, 1);
  const double var_T0 = scale * gsl_matrix_get(covar.get(), 0, 0);
  const double var_tau = scale * gsl_matrix_get(covar.get(), 1, 1);
  const double cov = scale * gsl_matrix_get(covar.get(), 0, 1);
  fit.T0_error = std::sqrt(var_T0);
  fit.tau0_error = std::sqrt(var_tau);
  const double root_T0 = std::sqrt(fit.T0);
  fit.tau0_unit = root_T0 * fit.tau0;
  const double d_T0 = fit.tau0 / (2.0 * root_T0), d_tau = root_T0;
  fit.tau0_unit_error = std::sqrt(
      std::max(0.0, d_T0 * d_T0 * var_T0 + d_tau * d_tau * var_tau + 2 * d_T0 * d_tau * cov));
  fit.rms_relative_residual = std::sqrt(chi2 / static_cast<double>(n));
  fit.ok = std::isfinite(fit.tau0) && fit.tau0 > 0 && fit.T0 > 0;
  if (!fit.ok) fit.message = "fit did not converge to positive T0, tau0";
  return fit;
}

}  // namespace molchaos::validation
