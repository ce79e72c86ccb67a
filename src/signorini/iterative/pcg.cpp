#include "signorini/iterative/pcg.hpp"

#include <cmath>

namespace signorini {

Pcg::Pcg(Backend& backend, Index n)
    : backend_(backend), r_(backend, n), z_(backend, n), p_(backend, n), q_(backend, n) {}

PcgResult Pcg::solve(LinearOperator& H, Preconditioner& M, const DeviceVector& b, DeviceVector& x,
                     const PcgOptions& options, PcgCoefficients* record) {
  Backend& be = backend_;
  PcgResult res;
  const double b_norm = norm(be, b);
  if (b_norm == 0.0) {  // H x = 0 has the solution 0
    be.fill(x, 0.0);
    be.fill(r_, 0.0);
    res.converged = true;
    return res;
  }
  if (options.zero_initial_guess) {
    be.fill(x, 0.0);
    be.copy(b, r_);
  } else if (options.initial_residual != nullptr) {
    be.copy(*options.initial_residual, r_);
  } else {
    H.apply(x, r_);
    be.axpby(1.0, b, -1.0, r_);  // r = b - H x
  }
  double r_norm = norm(be, r_);
  res.residual = r_norm / b_norm;
  if (res.residual <= options.tolerance) {
    res.converged = true;
    return res;
  }
  M.apply(r_, z_);
  be.copy(z_, p_);
  double rz = be.dot(r_, z_);
  for (int it = 1; it <= options.max_iterations; ++it) {
    H.apply(p_, q_);
    const double pq = be.dot(p_, q_);
    if (!(pq > 0.0) || !(rz > 0.0)) break;  // breakdown: H or M not positive definite
    const double alpha = rz / pq;
    if (record) record->alpha.push_back(alpha);
    be.axpby(alpha, p_, 1.0, x);
    be.axpby(-alpha, q_, 1.0, r_);
    r_norm = norm(be, r_);
    res.iterations = it;
    res.residual = r_norm / b_norm;
    if (res.residual <= options.tolerance) {
      res.converged = true;
      return res;
    }
    M.apply(r_, z_);
    const double rz_new = be.dot(r_, z_);
    if (record) record->beta.push_back(rz_new / rz);
    be.axpby(1.0, z_, rz_new / rz, p_);  // p = z + beta p
    rz = rz_new;
  }
  return res;
}

}  // namespace signorini
