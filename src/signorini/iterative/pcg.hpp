#pragma once
// Preconditioned conjugate gradients on a backend (Hestenes–Stiefel with the preconditioned
// residual; Saad, Iterative Methods, Algorithm 9.1). Stops when ||b - H x||_2 <= tolerance
// ||b||_2, measured on the recursively updated residual; per iteration three dot products come
// back to the host, nothing else.

#include <vector>

#include "signorini/iterative/linear_operator.hpp"

namespace signorini {

struct PcgOptions {
  double tolerance = 1e-13;  ///< relative to ||b||_2 (the paper's CG tolerance)
  int max_iterations = 10000;
  /// Start from x = 0 whatever x holds (saves the product H x of the first residual).
  bool zero_initial_guess = false;
  /// b - H x for the x given, where the caller has it at less than a product with H (a Newton
  /// step of GNM knows A x); null: computed here.
  const DeviceVector* initial_residual = nullptr;
};

/// The step lengths alpha_j and the ratios beta_j = (r_{j+1}, z_{j+1}) / (r_j, z_j) of a run, in
/// order: the Lanczos coefficients of M^{-1} H (eigenvalue_estimate.hpp).
struct PcgCoefficients {
  std::vector<double> alpha, beta;
};

struct PcgResult {
  int iterations = 0;
  double residual = 0.0;  ///< ||r|| / ||b|| reached
  bool converged = false;
};

class Pcg {
 public:
  Pcg(Backend& backend, Index n);
  /// Solves H x = b; x holds the initial guess on entry. With `record`, the coefficients of
  /// every step are appended to it.
  PcgResult solve(LinearOperator& H, Preconditioner& M, const DeviceVector& b, DeviceVector& x,
                  const PcgOptions& options, PcgCoefficients* record = nullptr);
  /// b - H x at the end of the last solve: the recursively updated residual (equal to the true
  /// one up to rounding), so that H x = b - residual() costs no product with H.
  [[nodiscard]] const DeviceVector& residual() const { return r_; }

 private:
  Backend& backend_;
  DeviceVector r_, z_, p_, q_;
};

}  // namespace signorini
