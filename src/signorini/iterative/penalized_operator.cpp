#include "signorini/iterative/penalized_operator.hpp"

#include "signorini/core/error.hpp"
#include "signorini/core/peak_memory.hpp"

namespace signorini {

HostArrays stiffness_arrays(const SparseMatrix& A) {
  const double copy_bytes = 12.0 * static_cast<double>(A.nonZeros());  // at most, as CSR
  return copy_bytes <= 0.5 * available_memory_bytes() ? HostArrays::Copy : HostArrays::Share;
}

PenalizedOperator::PenalizedOperator(Backend& backend, const SparseMatrix& A, const SparseMatrix& N,
                                     HostArrays arrays)
    : backend_(backend), n_(A.rows()), nc_(N.rows()) {
  if (A.cols() != n_ || N.cols() != n_)
    throw NumericalError("penalized operator: sizes of A and N do not match");
  A_ = backend.upload_symmetric(A, arrays);
  N_ = backend.upload(N);
  const SparseMatrix Nt = N.transpose();
  Nt_ = backend.upload(Nt);
  N2t_ = backend.upload(SparseMatrix(Nt.cwiseAbs2()));
  diag_a_ = to_device(backend, Vector(A.diagonal()));
  c_host_ = Vector::Zero(nc_);
  c_ = DeviceVector(backend, nc_);
  t_ = DeviceVector(backend, nc_);
}

void PenalizedOperator::apply(const DeviceVector& x, DeviceVector& y) {
  backend_.spmv(*A_, x, y);
  if (nc_ == 0) return;
  backend_.spmv(*N_, x, t_);
  backend_.multiply(c_, t_, t_);
  backend_.spmv(*Nt_, t_, y, 1.0, 1.0);
}

void PenalizedOperator::apply_stiffness(const DeviceVector& x, DeviceVector& y) {
  backend_.spmv(*A_, x, y);
}

void PenalizedOperator::apply_contact(const DeviceVector& x, DeviceVector& y) {
  backend_.spmv(*N_, x, y);
}

void PenalizedOperator::apply_contact_transpose(const DeviceVector& w, DeviceVector& y,
                                                double beta) {
  backend_.spmv(*Nt_, w, y, 1.0, beta);
}

void PenalizedOperator::set_weights(const Vector& c) {
  if (c.size() != nc_) throw NumericalError("penalized operator: wrong number of weights");
  c_host_ = c;
  upload_into(c, c_);
}

void PenalizedOperator::diagonal(DeviceVector& out) {
  backend_.copy(diag_a_, out);
  if (nc_ > 0) backend_.spmv(*N2t_, c_, out, 1.0, 1.0);
}

void PenalizedOperator::inverse_diagonal(DeviceVector& out) {
  diagonal(out);
  backend_.reciprocal(out, out);
}

}  // namespace signorini
