#pragma once
// The largest eigenvalue of a preconditioned symmetric operator M^{-1} H by the Lanczos process:
// the one spectral estimate of the code. It sets the interval of Chebyshev smoothing, the damping
// of smoothed aggregation's prolongation smoother and the step of classical Uzawa. The Lanczos
// tridiagonal matrix is read from the coefficients of preconditioned conjugate gradients (Saad,
// Iterative Methods, section 6.7.3), so the Krylov loop is pcg.cpp's, not a copy of it.

#include "signorini/iterative/pcg.hpp"

namespace signorini {

/// A fixed pseudo-random start vector (seeded), so that estimates are repeatable and the CPU and
/// the GPU agree.
Vector eigenvalue_estimate_start(Index n);

/// The largest Ritz value of M^{-1} H after at most `steps` Lanczos steps from `start` (H and M
/// symmetric positive definite): from below the largest eigenvalue, and close to it after a few
/// steps, since the Lanczos process finds the ends of a spectrum first. `pcg` (of H's size) and
/// `x` provide the work vectors, so that repeated estimates allocate nothing. Fewer steps are taken
/// when the Krylov space is exhausted. Throws NumericalError when not one step can be taken (H or
/// M not positive definite on the start vector).
double estimate_largest_eigenvalue(LinearOperator& H, Preconditioner& M, const DeviceVector& start,
                                   int steps, Pcg& pcg, DeviceVector& x);

/// The same with its own work vectors.
double estimate_largest_eigenvalue(LinearOperator& H, Preconditioner& M, const DeviceVector& start,
                                   int steps);

}  // namespace signorini
