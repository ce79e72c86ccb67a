#pragma once
// The GNM vectors and Newton systems of Uzawa-GNM on PETSc objects spread over the MPI ranks
// (docs/distributed.md): A and H(P) = A + r N^T diag(h on P) N as PETSc matrices in node blocks
// (node_padding.hpp; MPIBAIJ for CG with GAMG's kept levels, MPIAIJ otherwise), each rank owning
// one contiguous range of rows (the partition, parallel/node_partition.hpp); x, A x - b and the
// Newton direction as MPI vectors; the Newton systems solved by a KSP (CG with GAMG's levels kept
// for every active set, petsc_contact_multigrid.hpp; CG with Jacobi; or MUMPS's distributed
// Cholesky factorisation; from the same options as the serial paths). The contact-node values (N x,
// N d: n_c numbers) are summed over the ranks, so that every rank holds them all and runs the same
// loop; dot products and norms are PETSc's global reductions.

#include <petscksp.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "signorini/contact/distributed_engine.hpp"
#include "signorini/petsc/node_padding.hpp"
#include "signorini/petsc/petsc_algebra.hpp"
#include "signorini/petsc/petsc_contact_multigrid.hpp"
#include "signorini/petsc/threaded_product.hpp"
#include "signorini/petsc/upper_block_operator.hpp"

namespace signorini {

class PetscNewtonSpace final : public DistributedNewtonSpace {
 public:
  /// Takes this rank's rows of problem.A and problem.b, starts at x0 (the problem's held rows:
  /// ContactProblem::held_rows), sets the KSP up (timed in `timings`).
  PetscNewtonSpace(const ContactProblem& problem, const ContactSolverOptions& options,
                   const Vector& x0, TimingTable& timings, MPI_Comm comm);
  ~PetscNewtonSpace() override;
  PetscNewtonSpace(const PetscNewtonSpace&) = delete;
  PetscNewtonSpace& operator=(const PetscNewtonSpace&) = delete;

  [[nodiscard]] const Vector& contact_values() const override { return Nx_; }
  void set_active(const ActiveSet& active, double r) override;
  /// Friction's nodes' blocks: H = A + N^T W N, W = blockdiag(r h_j D_j) (docs/method.md,
  /// "Friction"); each node's rows of N lie on its own dofs, so on the rank that owns them.
  void set_linearization(const Linearization& lin, double r) override;
  NewtonSolveStats solve(const Vector& terms) override;
  void set_linear_tolerance(double tolerance) override { linear_tolerance_ = tolerance; }
  void direction(ModifiedLagrangian::Direction& dir) override;
  void step(double t) override;
  NewtonStepNorms norms(const Vector& contact_forces) override;
  [[nodiscard]] int factorizations() const override { return refreshes_; }
  /// Projected CG on PETSc's vectors, preconditioned by the KSP's preconditioner of the Newton
  /// matrix of S (active_set_constraint.hpp has the method); the projection is each rank's own,
  /// since each contact row lies on the dofs of one rank.
  std::optional<ActiveSetSolve> solve_on_active_set(const ActiveSet& S, double r,
                                                    double tolerance) override;

  [[nodiscard]] Vector rank_solution() override;
  [[nodiscard]] Vector contact_response(const Vector& w, NewtonSolveStats& stats) override;
  [[nodiscard]] std::string linear_solver_description() const override {
    return petsc::with_workspace_note(description_, workspace_);
  }

 private:
  /// H x = rhs from x as it is, by the KSP (the tolerance of the next solve, timed).
  NewtonSolveStats solve_newton_system(Vec rhs, Vec x);
  Vector contact_values_of(Vec v);
  void add_contact_transpose(const Vector& values, Vec v);  // v += N^T values
  // v <- v - sum_{j in S} n_j (n_j . v) / |n_j|^2 over this rank's contact rows.
  void project(const ActiveSet& S, Vec v);
  // H = A + sum_j B_j^T W_j B_j, W_j(a, b) = weight(row a, row b) of N for two rows of node j
  // (set_active: diag(c) on the normal rows; set_linearization: friction's blocks), and the
  // preconditioner set up for it; `coupled_rows`: the fine smoother's bound counts the unknowns
  // that a node's rows touch together (friction's blocks) rather than each row's own.
  void form_newton_matrix(const std::function<double(Index, Index)>& weight, bool coupled_rows);
  void set_up_solver(Mat A_aij, bool keeps_levels);

  // The rigid-body modes of this rank's slots (a partitioned problem's own rows, unpadded, need
  // no copy).
  [[nodiscard]] const Matrix& modes() const {
    return padding_.active() || !p_.partitioned() ? modes_ : p_.near_null_space;
  }

  const ContactProblem& p_;
  const ContactSolverOptions& o_;
  TimingTable& timings_;
  MPI_Comm comm_;
  petsc::NodePadding padding_;
  Matrix modes_;                            // this rank's rows of the modes on its slots (modes())
  Index n_ = 0, nc_ = 0, lo_ = 0, hi_ = 0;  // nc_: the rows of N (d per node with friction)
  Index first_ = 0, last_ = 0;              // this rank's unknowns (lo_, hi_: its slots)
  Index components_ = 1;                    // rows of N per contact node
  std::vector<petsc::ContactRow> rows_;     // the contact rows whose dofs this rank owns
  Mat A_ = nullptr, H_ = nullptr;
  // A and H's products on the rank's OpenMP threads where it has several (node blocks only):
  // the KSP's operator and A d (threaded_product.hpp).
  std::unique_ptr<petsc::ThreadedProduct> threaded_A_, threaded_H_;
  // One rank with the levels kept: A_ and H_ are its shells (upper_block_operator.hpp).
  std::unique_ptr<petsc::UpperBlockOperator> upper_;
  // Else: A's values in the blocks of this rank's contact nodes (rows_ grouped by node, in
  // order), and per node whether H's block holds contact terms now (form_newton_matrix).
  std::vector<PetscScalar> a_blocks_;
  std::vector<char> with_terms_;
  [[nodiscard]] Mat newton_operator() const { return threaded_H_ ? threaded_H_->shell() : H_; }
  Vec b_ = nullptr, x_ = nullptr, x_new_ = nullptr, residual_ = nullptr, d_ = nullptr,
      Ad_ = nullptr, work_ = nullptr;
  KSP ksp_ = nullptr;
  std::unique_ptr<petsc::ContactMultigrid> multigrid_;  // CG with GAMG's levels kept
  bool direct_ = false;
  std::string description_;
  std::optional<PetscInt> workspace_;  // ICNTL(14), where a short work space raised it
  ActiveSet active_;
  bool has_active_ = false;
  Linearization linearization_;  // the last blocks set (friction)
  bool has_linearization_ = false;
  Vector Nx_;
  double last_t_ = 1.0;
  double linear_tolerance_ = 0.0;  // 0: o_.linear.cg_tolerance
  int refreshes_ = 0;
  // The active-set solve's, made at its first call: whether no dof lies in two contact rows, and
  // |n_j|^2 of every contact row on every rank.
  std::optional<bool> rows_disjoint_;
  Vector norm2_;
};

}  // namespace signorini
