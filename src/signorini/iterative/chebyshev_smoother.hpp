#pragma once
// Chebyshev–Jacobi smoothing (docs/gpu.md): a fixed polynomial in D^{-1} H that damps the
// eigencomponents of D^{-1} H in [lower_fraction, upper_factor] * lambda_max, where lambda_max is
// estimated by a few Lanczos steps (from the coefficients of Jacobi-preconditioned CG). It needs
// only products with H and vector updates, which suits a GPU, and being a fixed polynomial it
// keeps the multigrid V-cycle symmetric, as conjugate gradients require.

#include "signorini/iterative/penalized_operator.hpp"

namespace signorini {

struct ChebyshevOptions {
  int degree = 2;               ///< products with H per smoothing sweep
  double lower_fraction = 0.1;  ///< smoothed interval [lower_fraction, upper_factor] lambda_max
  double upper_factor = 1.1;    ///< safety above the Lanczos estimate (a Ritz value, from below)
  int lanczos_steps = 12;
};

/// Largest eigenvalue of D^{-1} H (D = diag H, dinv = D^{-1}) estimated by `steps` Lanczos steps
/// from a fixed pseudo-random start: the largest Ritz value, which is below the true one.
double estimate_lambda_max(PenalizedOperator& op, const DeviceVector& dinv, int steps);

class ChebyshevSmoother {
 public:
  /// Call refresh() before the first smooth().
  ChebyshevSmoother(PenalizedOperator& op, ChebyshevOptions options);
  /// Recomputes D^{-1} and lambda_max after the operator's weights changed.
  void refresh();
  /// The same with lambda_max estimated elsewhere (e.g. on the host for a small level).
  void refresh(double lambda_max);
  /// Improves x towards H x = b by one sweep of `degree` steps; x = 0 on entry if
  /// zero_initial_guess (which saves one product with H).
  void smooth(const DeviceVector& b, DeviceVector& x, bool zero_initial_guess);
  [[nodiscard]] double lambda_max() const { return lambda_max_; }

 private:
  PenalizedOperator& op_;
  ChebyshevOptions options_;
  DeviceVector dinv_, r_, d_, q_;
  DeviceVector start_, z_;  // Lanczos start and work vector, made on the first refresh()
  double lambda_max_ = 0.0;
};

}  // namespace signorini
