#pragma once
// What the Krylov and multigrid algorithms see of a matrix and of a preconditioner: y = A x and
// z = M^{-1} r on vectors of one backend (backend/backend.hpp).

#include "signorini/backend/backend.hpp"

namespace signorini {

class LinearOperator {
 public:
  virtual ~LinearOperator() = default;
  [[nodiscard]] virtual Index size() const = 0;
  /// y = A x (x and y distinct)
  virtual void apply(const DeviceVector& x, DeviceVector& y) = 0;
};

class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  /// z = M^{-1} r (r and z distinct). M must be symmetric positive definite for CG.
  virtual void apply(const DeviceVector& r, DeviceVector& z) = 0;
  /// Follows a change of the operator it preconditions (new weights of H: a new active set).
  virtual void refresh() = 0;
};

/// z = r: no preconditioning.
class IdentityPreconditioner final : public Preconditioner {
 public:
  void apply(const DeviceVector& r, DeviceVector& z) override { r.backend()->copy(r, z); }
  void refresh() override {}
};

/// y = A x for a symmetric matrix held on the host, on vectors of a host backend, without a copy
/// of A (it must outlive this object). Rows in parallel: column i of A is its row i.
class SymmetricMatrixOperator final : public LinearOperator {
 public:
  explicit SymmetricMatrixOperator(const SparseMatrix& A) : A_(A) {}
  [[nodiscard]] Index size() const override { return A_.rows(); }
  void apply(const DeviceVector& x, DeviceVector& y) override;

 private:
  const SparseMatrix& A_;
};

}  // namespace signorini
