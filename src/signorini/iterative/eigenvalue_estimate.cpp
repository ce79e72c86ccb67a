#include "signorini/iterative/eigenvalue_estimate.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>

#include "signorini/core/error.hpp"

namespace signorini {

Vector eigenvalue_estimate_start(Index n) {
  Vector start(n);
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  for (Index i = 0; i < n; ++i) start(i) = uni(rng);
  return start;
}

double estimate_largest_eigenvalue(LinearOperator& H, Preconditioner& M, const DeviceVector& start,
                                   int steps, Pcg& pcg, DeviceVector& x) {
  // CG on H x = start from x = 0, run for `steps` iterations whatever its residual (tolerance 0);
  // its coefficients alpha_j, beta_j give the Lanczos matrix of M^{-1} H:
  //   T_jj = 1/alpha_j + beta_{j-1}/alpha_{j-1},  T_{j,j+1} = sqrt(beta_j)/alpha_j.
  PcgOptions o;
  o.tolerance = 0.0;
  o.max_iterations = static_cast<int>(std::min<Index>(std::max(steps, 1), H.size()));
  o.zero_initial_guess = true;
  PcgCoefficients c;
  pcg.solve(H, M, start, x, o, &c);
  const auto k = static_cast<Index>(c.alpha.size());
  if (k == 0) throw NumericalError("eigenvalue estimate: the operator is not positive definite");
  Matrix T = Matrix::Zero(k, k);
  for (Index j = 0; j < k; ++j) {
    const auto uj = static_cast<std::size_t>(j);
    T(j, j) = 1.0 / c.alpha[uj] + (j > 0 ? c.beta[uj - 1] / c.alpha[uj - 1] : 0.0);
    if (j + 1 < k) T(j, j + 1) = T(j + 1, j) = std::sqrt(c.beta[uj]) / c.alpha[uj];
  }
  return Eigen::SelfAdjointEigenSolver<Matrix>(T, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
}

double estimate_largest_eigenvalue(LinearOperator& H, Preconditioner& M, const DeviceVector& start,
                                   int steps) {
  Backend& be = *start.backend();
  Pcg pcg(be, H.size());
  DeviceVector x(be, H.size());
  return estimate_largest_eigenvalue(H, M, start, steps, pcg, x);
}

}  // namespace signorini
