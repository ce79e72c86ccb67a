#pragma once
// The generalised Hessian of method.md section 4 as an operator on a backend:
//   H = A + N^T diag(c) N,   c_j = r h_j on the active contact nodes, 0 elsewhere,
// i.e. (17)'s matrix A + r sum_{j active} h_j nu_j nu_j^T, kept as the fixed stiffness A and the
// fixed contact operator N; a change of the active set only changes the n_c numbers c. The same
// form describes every multigrid level (A_l = P^T A P, N_l = N P), so the Galerkin hierarchy
// never has to be rebuilt when the active set moves.

#include <memory>

#include "signorini/iterative/linear_operator.hpp"

namespace signorini {

/// How a solve should hold its stiffness A on the backend: a copy (on the CPU in node blocks,
/// whose products stream a third fewer bytes) where one takes under half the memory available
/// now, else A itself, multiplied in place (HostArrays::Share; A must outlive the operator).
[[nodiscard]] HostArrays stiffness_arrays(const SparseMatrix& A);

class PenalizedOperator final : public LinearOperator {
 public:
  /// A: n x n SPD (both triangles); N: n_c x n. Uploads A, N, N^T and (N.^2)^T. With
  /// HostArrays::Share the CPU backend multiplies by A in place (Backend::upload_transpose): A
  /// must then outlive this operator, unchanged.
  PenalizedOperator(Backend& backend, const SparseMatrix& A, const SparseMatrix& N,
                    HostArrays arrays = HostArrays::Copy);

  [[nodiscard]] Index size() const override { return n_; }
  [[nodiscard]] Index num_contact() const { return nc_; }
  /// y = A x + N^T (c .* (N x))
  void apply(const DeviceVector& x, DeviceVector& y) override;
  /// y += alpha N^T W N x: the contact terms alone (W = diag(c), or the block weights).
  void add_contact_terms(const DeviceVector& x, DeviceVector& y, double alpha);
  /// y = A x only (the energy and the residual A x - b need the stiffness alone).
  void apply_stiffness(const DeviceVector& x, DeviceVector& y);
  /// y = N x (n_c values) and y = N^T w (n values).
  void apply_contact(const DeviceVector& x, DeviceVector& y);
  void apply_contact_transpose(const DeviceVector& w, DeviceVector& y, double beta = 0.0);

  /// Replaces N by another matrix of the same shape (a coarse level's contact rows carried down
  /// by another fine prolongation, contact_prolongation.hpp); the weights stay.
  void set_contact_matrix(const SparseMatrix& N);
  /// Sets c (n_c values, host), and drops block weights.
  void set_weights(const Vector& c);
  /// Friction in 3D (docs/method.md, "Friction"): H = A + N^T W N with W block diagonal, the
  /// rows of N in groups of `block_size` (a node's normal and tangents), each block the node's
  /// r h_j D_j (symmetric). weights() becomes W's diagonal: the coarse levels of a multigrid
  /// take A_l + N_l^T diag(W) N_l, an approximation of H there (exact where the blocks are
  /// diagonal), while the products and the diagonal of this operator are exact.
  void set_block_weights(const SparseMatrix& W, Index block_size);
  /// Rows of N per block of W (1 without block weights).
  [[nodiscard]] Index block_size() const { return W_ ? block_size_ : 1; }
  /// diag(H) = diag(A) + (N.^2)^T c
  void diagonal(DeviceVector& out);
  /// diag(H)^{-1}: the Jacobi scaling of the preconditioner and of the smoother.
  void inverse_diagonal(DeviceVector& out);
  [[nodiscard]] Backend& backend() const { return backend_; }
  [[nodiscard]] const Vector& weights() const { return c_host_; }
  /// N^T on the host (column j is row j of N), whatever the backend.
  [[nodiscard]] const SparseMatrix& contact_transpose() const { return Nt_host_; }

 private:
  Backend& backend_;
  Index n_, nc_;
  std::unique_ptr<DeviceSparseMatrix> A_, N_, Nt_, N2t_, W_;
  DeviceVector diag_a_, c_, t_, t2_, diag_w_;
  Vector c_host_;
  SparseMatrix Nt_host_;  // N^T, for the diagonal of N^T W N and contact_transpose()
  Index block_size_ = 1;
};

}  // namespace signorini
