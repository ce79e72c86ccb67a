#pragma once
// A PETSc matrix's product on the process's OpenMP threads (docs/distributed.md, "Threads per
// rank"): PETSc's own MatMult runs on one thread, so a rank given several cores
// (PetscEngine::share_the_cores) left all but one idle in the CG's products, the smoothers' and
// the multigrid's transfers, most of a solve's time. Wrapped as a MATSHELL whose MatMult and
// MatMultAdd split the rank's rows among the threads: the rank's own columns first, while the
// neighbours' values arrive (one VecScatter), then the others. The diagonal (the smoothers'
// Jacobi) comes from the matrix itself. Node blocks (SeqBAIJ, MPIBAIJ) and scalar rows (SeqAIJ,
// MPIAIJ), square or not; rows of 1, 2 and 3 (the project's node blocks) have their own loops,
// other block sizes a generic one.
//
// The wrapped matrix keeps its nonzero pattern: its values may change (MatCopy with
// SAME_NONZERO_PATTERN, MatSetValues into existing entries, MatAXPY with a subset pattern),
// after which refresh() is called, so that a KSP that takes the shell as its operator sets its
// preconditioner up again.

#include <petscmat.h>

namespace signorini::petsc {

class ThreadedProduct {
 public:
  /// Wraps M, which must outlive this object.
  explicit ThreadedProduct(Mat M);
  ~ThreadedProduct();
  ThreadedProduct(const ThreadedProduct&) = delete;
  ThreadedProduct& operator=(const ThreadedProduct&) = delete;

  /// The shell, with M's sizes: MatMult, MatMultAdd and MatGetDiagonal.
  [[nodiscard]] Mat shell() const { return shell_; }
  /// The wrapped matrix.
  [[nodiscard]] Mat matrix() const { return M_; }
  /// After M's values changed: the shell's state raised (the arrays are taken at each product).
  void refresh();

  /// y = M x, or y += M x, on the process's OpenMP threads (the shell's products).
  void multiply(Vec x, Vec y, bool add) const;

  /// Whether wrapping M pays: a matrix of a type above, and more than one OpenMP thread in the
  /// process.
  [[nodiscard]] static bool worthwhile(Mat M);

 private:
  struct Part {  // one sequential matrix: the rank's own columns, or the neighbours'
    Mat M = nullptr;
    PetscInt rows = 0;  // block rows (rows of scalars for AIJ)
    const PetscInt* ia = nullptr;
    const PetscInt* ja = nullptr;
    const PetscScalar* values = nullptr;  // blocks column-major, bs * bs each
  };
  void take_arrays(Part& part) const;
  void release_arrays(Part& part) const;
  void multiply_part(const Part& part, const PetscScalar* x, PetscScalar* y, bool add) const;

  Mat M_ = nullptr;
  Mat shell_ = nullptr;
  bool blocks_ = false;  // BAIJ, else AIJ
  PetscInt bs_ = 1;      // the loops' block size: 1 for AIJ
  Part own_, others_;
  VecScatter scatter_ = nullptr;  // the neighbours' values, in the order of others_'s columns
  Vec ghosts_ = nullptr;
};

}  // namespace signorini::petsc
