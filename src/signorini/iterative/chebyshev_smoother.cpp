#include "signorini/iterative/chebyshev_smoother.hpp"

#include "signorini/core/error.hpp"
#include "signorini/iterative/eigenvalue_estimate.hpp"
#include "signorini/iterative/jacobi_preconditioner.hpp"

namespace signorini {

ChebyshevSmoother::ChebyshevSmoother(PenalizedOperator& op, ChebyshevOptions options)
    : op_(op),
      options_(options),
      dinv_(op.backend(), op.size()),
      r_(op.backend(), op.size()),
      d_(op.backend(), op.size()),
      q_(op.backend(), op.size()) {
  if (options_.degree < 1) throw InputError("Chebyshev smoother: degree must be >= 1");
}

void ChebyshevSmoother::refresh() {
  op_.inverse_diagonal(dinv_);
  // lambda_max of D^{-1} H by Lanczos steps (eigenvalue_estimate.hpp) with the smoother's own
  // D^{-1}; the start and the work vectors are made on the first estimate only (levels estimated
  // elsewhere never need them), then reused: no allocation or upload per active set.
  if (!estimate_) {
    start_ = to_device(op_.backend(), eigenvalue_estimate_start(op_.size()));
    estimate_ = std::make_unique<Pcg>(op_.backend(), op_.size());
  }
  DiagonalPreconditioner jacobi(dinv_);
  lambda_max_ =
      estimate_largest_eigenvalue(op_, jacobi, start_, options_.lanczos_steps, *estimate_, r_);
}

void ChebyshevSmoother::refresh(double lambda_max) {
  op_.inverse_diagonal(dinv_);
  lambda_max_ = lambda_max;
}

void ChebyshevSmoother::smooth(const DeviceVector& b, DeviceVector& x, bool zero_initial_guess) {
  Backend& be = op_.backend();
  // Chebyshev iteration for D^{-1} H on [lo, hi] (Saad, Iterative Methods, Algorithm 12.1).
  const double hi = options_.upper_factor * lambda_max_;
  const double lo = options_.lower_fraction * lambda_max_;
  const double theta = 0.5 * (hi + lo);
  const double delta = 0.5 * (hi - lo);
  const double sigma = theta / delta;
  double rho = 1.0 / sigma;
  if (zero_initial_guess) {
    be.copy(b, r_);
    be.fill(x, 0.0);
  } else {
    op_.apply(x, r_);
    be.axpby(1.0, b, -1.0, r_);  // r = b - H x
  }
  be.chebyshev_update(0.0, 1.0 / theta, dinv_, r_, d_, x);  // d = D^{-1} r / theta; x += d
  for (int k = 1; k < options_.degree; ++k) {
    op_.apply(d_, q_);
    be.axpby(-1.0, q_, 1.0, r_);  // r = b - H x
    const double rho_new = 1.0 / (2.0 * sigma - rho);
    be.chebyshev_update(rho_new * rho, 2.0 * rho_new / delta, dinv_, r_, d_, x);
    rho = rho_new;
  }
}

}  // namespace signorini
