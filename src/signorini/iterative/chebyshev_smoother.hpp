#pragma once
// Chebyshev–Jacobi smoothing (docs/gpu.md): a fixed polynomial in D^{-1} H that damps the
// eigencomponents of D^{-1} H in [lower_fraction, upper_factor] * lambda_max, where lambda_max is
// estimated by a few Lanczos steps (eigenvalue_estimate.hpp, with the Jacobi scaling). It needs
// only products with H and vector updates, which suits a GPU, and being a fixed polynomial it
// keeps the multigrid V-cycle symmetric, as conjugate gradients require.

#include <memory>

#include "signorini/iterative/pcg.hpp"
#include "signorini/iterative/penalized_operator.hpp"

namespace signorini {

struct ChebyshevOptions {
  int degree = 2;               ///< products with H per smoothing sweep
  double lower_fraction = 0.1;  ///< smoothed interval [lower_fraction, upper_factor] lambda_max
  double upper_factor = 1.1;    ///< safety above the Lanczos estimate (a Ritz value, from below)
  int lanczos_steps = 12;
};

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
  // The estimate's start and work vectors (r_ is its x), made on the first refresh() (levels
  // estimated elsewhere never need them) and reused: no allocation per active set.
  DeviceVector start_;
  std::unique_ptr<Pcg> estimate_;
  double lambda_max_ = 0.0;
};

}  // namespace signorini
