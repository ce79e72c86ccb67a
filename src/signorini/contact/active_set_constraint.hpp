#pragma once
// The contact problem with its active set S known, on a backend: minimise the energy
// 1/2 x^T A x - b^T x under (N x)_j = g_j for j in S and nothing else, which is the whole
// problem's solution once S is right (docs/method.md section 1: the KKT conditions with S fixed
// are linear). Each contact row of N holds the dofs of its own node, so the constrained subspace
// {x : (N x)_j = 0, j in S} is a product of one small subspace per node and its projection is
// local, P v = v - sum_{j in S} n_j (n_j . v) / |n_j|^2. The solve starts from x moved onto the
// constraints, x = P x + sum_{j in S} n_j g_j / |n_j|^2, and corrects it by z, the solution of
// P A P z = P (b - A x) by CG preconditioned by P M P, where M is the preconditioner of the
// Newton matrix A + N^T diag(c) N, c_j = r h_j on S (a multigrid V-cycle or Jacobi): the penalty
// stands in for the constraint there, and P makes it exact. No penalty enters the answer: the
// multipliers are the reactions, h_j l_j = n_j . (b - A x) / |n_j|^2 on S.
//
// Used by semismooth Newton's steps on the iterative path (projected_active_set_solver.hpp) and
// by Uzawa-GNM's active-set finish (backend_newton_space.hpp, docs/solvers.md).

#include <memory>
#include <utility>

#include "signorini/backend/backend.hpp"
#include "signorini/contact/backend_newton_matrix.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/core/timing_table.hpp"
#include "signorini/iterative/pcg.hpp"
#include "signorini/linalg/linear_solver.hpp"

namespace signorini {

/// Whether every dof lies in at most one contact row of N (then the projection is local); where
/// not, `first_shared` gets two rows that share one.
[[nodiscard]] bool contact_rows_disjoint(const SparseMatrix& N,
                                         std::pair<Index, Index>* first_shared = nullptr);

class ActiveSetConstraint {
 public:
  /// `newton` is the Newton matrix whose preconditioner serves (the caller keeps it set for the
  /// active set it passes to solve). The contact rows must be disjoint (contact_rows_disjoint).
  /// CG and three vectors of n entries are the caller's, lent for each solve (a Newton space
  /// lends those of its Newton systems: no more memory of the mesh's size).
  struct Workspace {
    Pcg& pcg;
    DeviceVector& z;
    DeviceVector& rhs;
    DeviceVector& work;
  };
  ActiveSetConstraint(const ContactProblem& problem, const LinearSolverOptions& linear,
                      BackendNewtonMatrix& newton, Backend& backend, Workspace workspace);
  ~ActiveSetConstraint();

  /// x <- the minimiser under S's constraints, from x, to ||P (b - A x)|| <= tolerance
  /// max(||b||, ||b - A x||) (b_norm = ||b||); l gets the multipliers (0 off S, and on the nodes
  /// that do not move), gap_residual N x - g. The CG iterations timed as "linear solve". On
  /// return the workspace's `work` holds b - A x at the new x.
  LinearSolveStats solve(const ActiveSet& S, DeviceVector& x, const DeviceVector& b, double b_norm,
                         double tolerance, Vector& l, Vector& gap_residual, TimingTable& timings);

 private:
  class Projected;
  void project(DeviceVector& v);

  const ContactProblem& p_;
  const LinearSolverOptions& linear_;
  BackendNewtonMatrix& newton_;
  Backend& be_;
  Index n_, nc_;
  Vector inverse_norm2_;  // 1 / |n_j|^2 (0 where n_j = 0)
  std::unique_ptr<Projected> projected_;
  Workspace w_;
  DeviceVector contact_, minus_w_;
  ActiveSet weights_for_;  // the S whose -1/|n_j|^2 minus_w_ holds (empty: none yet)
};

}  // namespace signorini
