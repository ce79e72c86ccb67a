#include "signorini/iterative/chebyshev_smoother.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>

#include "signorini/core/error.hpp"

namespace signorini {

namespace {

// A fixed start (seeded), so that runs are repeatable and the CPU and GPU agree.
Vector lanczos_start(Index n) {
  Vector start(n);
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  for (Index i = 0; i < n; ++i) start(i) = uni(rng);
  return start;
}

// The estimate with the caller's vectors: r holds the start on entry; r, z, p, q are overwritten.
double lanczos_lambda_max(PenalizedOperator& op, const DeviceVector& dinv, int steps,
                          DeviceVector& r, DeviceVector& z, DeviceVector& p, DeviceVector& q) {
  Backend& be = op.backend();
  steps = static_cast<int>(std::min<Index>(steps, op.size()));
  // CG on H x = r with x0 = 0 and Jacobi preconditioning; its coefficients give the Lanczos
  // tridiagonal matrix of D^{-1} H (Saad, Iterative Methods, section 6.7.3):
  //   T_jj = 1/alpha_j + beta_{j-1}/alpha_{j-1},  T_{j,j+1} = sqrt(beta_j)/alpha_j.
  std::vector<double> alphas, betas;
  be.multiply(dinv, r, z);
  be.copy(z, p);
  double rz = be.dot(r, z);
  for (int j = 0; j < steps && rz > 0.0; ++j) {
    op.apply(p, q);
    const double pq = be.dot(p, q);
    if (!(pq > 0.0)) break;
    const double alpha = rz / pq;
    alphas.push_back(alpha);
    be.axpby(-alpha, q, 1.0, r);
    be.multiply(dinv, r, z);
    const double rz_new = be.dot(r, z);
    const double beta = rz_new / rz;
    betas.push_back(beta);
    rz = rz_new;
    be.axpby(1.0, z, beta, p);
  }
  const auto k = static_cast<Index>(alphas.size());
  if (k == 0) throw NumericalError("eigenvalue estimate: the operator is not positive definite");
  Matrix T = Matrix::Zero(k, k);
  for (Index j = 0; j < k; ++j) {
    const auto uj = static_cast<std::size_t>(j);
    T(j, j) = 1.0 / alphas[uj] + (j > 0 ? betas[uj - 1] / alphas[uj - 1] : 0.0);
    if (j + 1 < k) T(j, j + 1) = T(j + 1, j) = std::sqrt(betas[uj]) / alphas[uj];
  }
  return Eigen::SelfAdjointEigenSolver<Matrix>(T, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
}

}  // namespace

double estimate_lambda_max(PenalizedOperator& op, const DeviceVector& dinv, int steps) {
  Backend& be = op.backend();
  const Index n = op.size();
  DeviceVector r = to_device(be, lanczos_start(n)), z(be, n), p(be, n), q(be, n);
  return lanczos_lambda_max(op, dinv, steps, r, z, p, q);
}

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
  // The start vector and one more work vector are made on the first estimate only (levels
  // estimated elsewhere never need them), then reused: no allocation or upload per active set.
  if (start_.size() == 0) {
    start_ = to_device(op_.backend(), lanczos_start(op_.size()));
    z_ = DeviceVector(op_.backend(), op_.size());
  }
  op_.backend().copy(start_, r_);
  lambda_max_ = lanczos_lambda_max(op_, dinv_, options_.lanczos_steps, r_, z_, d_, q_);
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
