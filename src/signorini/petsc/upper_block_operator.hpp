#pragma once
// One rank's A and Newton matrix H = A + (the contact nodes' blocks) as PETSc shells on the
// serial tool's copy of A in upper node blocks (backend/node_block_matrix.hpp): half the bytes
// of PETSc's node blocks, and each off-diagonal block used twice per product, as B and B^T. On
// one rank with the multigrid's levels kept (docs/distributed.md, "The one-rank products"),
// instead of A and H in PETSc's node blocks (two full copies of A) and their threaded products:
// at a million hex8 unknowns the fine products took a third of the process's samples there.
// H's contact terms are a few small dense blocks, one per contact node with a weight, applied
// beside A's product.

#include <petscmat.h>

#include <memory>
#include <vector>

#include "signorini/backend/node_block_matrix.hpp"
#include "signorini/core/types.hpp"

namespace signorini::petsc {

class UpperBlockOperator {
 public:
  /// From A (symmetric, n x n, both triangles stored, on the PETSc numbering of one rank), or
  /// nothing where A is not in whole node blocks (NodeBlockMatrix::from_symmetric_csr).
  static std::unique_ptr<UpperBlockOperator> make(const SparseMatrix& A, MPI_Comm comm);
  UpperBlockOperator(NodeBlockMatrix upper, Vector diagonal, MPI_Comm comm);
  UpperBlockOperator(const UpperBlockOperator&) = delete;
  UpperBlockOperator& operator=(const UpperBlockOperator&) = delete;
  ~UpperBlockOperator();

  /// The shells of A and of H (MatMult, MatMultAdd, MatGetDiagonal), alive with this object.
  [[nodiscard]] Mat stiffness() const { return A_; }
  [[nodiscard]] Mat newton() const { return H_; }

  /// H's contact terms from here on: for each block b, the k_b x k_b values (row-major) at the
  /// unknowns dofs[b]; H's state is raised, so that a KSP given it sets its preconditioner up
  /// again.
  void set_contact_blocks(std::vector<std::vector<PetscInt>> dofs,
                          std::vector<std::vector<double>> values);

  /// y = A x (+ the contact terms where `newton`), or w = y + the same.
  void multiply(Vec x, Vec y, Vec w, bool add, bool newton) const;
  void diagonal(Vec d, bool newton) const;

 private:
  NodeBlockMatrix upper_;
  Vector diagonal_;  // A's
  MPI_Comm comm_;
  std::vector<std::vector<PetscInt>> dofs_;
  std::vector<std::vector<double>> values_;
  Mat A_ = nullptr, H_ = nullptr;
};

}  // namespace signorini::petsc
