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
  set_contact_matrix(N);
  diag_a_ = to_device(backend, Vector(A.diagonal()));
  c_host_ = Vector::Zero(nc_);
  c_ = DeviceVector(backend, nc_);
  t_ = DeviceVector(backend, nc_);
}

void PenalizedOperator::apply(const DeviceVector& x, DeviceVector& y) {
  backend_.spmv(*A_, x, y);
  add_contact_terms(x, y, 1.0);
}

void PenalizedOperator::add_contact_terms(const DeviceVector& x, DeviceVector& y, double alpha) {
  if (nc_ == 0) return;
  backend_.spmv(*N_, x, t_);
  if (W_) {
    backend_.spmv(*W_, t_, t2_);
    backend_.spmv(*Nt_, t2_, y, alpha, 1.0);
    return;
  }
  backend_.multiply(c_, t_, t_);
  backend_.spmv(*Nt_, t_, y, alpha, 1.0);
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

void PenalizedOperator::set_contact_matrix(const SparseMatrix& N) {
  if (N.rows() != nc_ || N.cols() != n_)
    throw NumericalError("penalized operator: contact rows of the wrong size");
  N_ = backend_.upload(N);
  Nt_host_ = N.transpose();
  Nt_ = backend_.upload(Nt_host_);
  N2t_ = backend_.upload(SparseMatrix(Nt_host_.cwiseAbs2()));
}

void PenalizedOperator::set_weights(const Vector& c) {
  if (c.size() != nc_) throw NumericalError("penalized operator: wrong number of weights");
  c_host_ = c;
  upload_into(c, c_);
  W_.reset();
}

void PenalizedOperator::set_block_weights(const SparseMatrix& W, Index block_size) {
  if (W.rows() != nc_ || W.cols() != nc_ || block_size < 1 || nc_ % block_size != 0)
    throw NumericalError("penalized operator: block weights of the wrong size");
  c_host_ = W.diagonal();
  upload_into(c_host_, c_);
  // diag(N^T W N)_k = sum_j (N^T W)_kj N_jk: the row sums of (N^T W) .* N^T.
  const SparseMatrix NtW = Nt_host_ * W;
  const Vector diag = SparseMatrix(NtW.cwiseProduct(Nt_host_)) * Vector::Ones(nc_);
  W_ = backend_.upload(W);
  diag_w_ = to_device(backend_, diag);
  if (t2_.size() != nc_) t2_ = DeviceVector(backend_, nc_);
  block_size_ = block_size;
}

void PenalizedOperator::diagonal(DeviceVector& out) {
  backend_.copy(diag_a_, out);
  if (nc_ == 0) return;
  if (W_) {
    backend_.axpby(1.0, diag_w_, 1.0, out);
    return;
  }
  backend_.spmv(*N2t_, c_, out, 1.0, 1.0);
}

void PenalizedOperator::inverse_diagonal(DeviceVector& out) {
  diagonal(out);
  backend_.reciprocal(out, out);
}

}  // namespace signorini
