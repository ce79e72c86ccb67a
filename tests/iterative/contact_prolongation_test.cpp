// The prolongations smoothed with the Newton matrix at the active contact unknowns
// (iterative/contact_prolongation.hpp) against the smoothing done again from scratch, and its
// use by the multigrid preconditioner.

#include "signorini/iterative/contact_prolongation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "signorini/backend/host_backend.hpp"
#include "signorini/core/error.hpp"
#include "signorini/iterative/multigrid_preconditioner.hpp"
#include "signorini/iterative/pcg.hpp"
#include "signorini/iterative/penalized_operator.hpp"
#include "signorini/iterative/smoothed_aggregation.hpp"
#include "symmetric_preconditioner.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

// A clamped block of 8 x 8 x 6 hexahedra, its smoothed-aggregation hierarchy, and contact rows
// on the nodes of its top face with an oblique unit normal (all three components), the first
// half of them active with a stiff weight (ten times the diagonal).
struct Case {
  testing::ClampedBlock block = testing::clamped_block(8, 8, 6);
  MultigridHierarchy h;
  SparseMatrix N;
  Vector c;
  // max_coarse: the coarsest level's size (the default leaves one prolongation; 60 three).
  explicit Case(Index max_coarse = SmoothedAggregationOptions{}.max_coarse_unknowns) {
    SmoothedAggregationOptions options;
    options.max_coarse_unknowns = max_coarse;
    h = smoothed_aggregation_hierarchy(block.A, block.modes, free_dof_nodes(block.dofs), options);
    const std::vector<Index> node_of = free_dof_nodes(block.dofs);
    const double top = block.mesh.coordinates().row(2).maxCoeff();
    const Eigen::Vector3d normal(0.3, -0.4, std::sqrt(1.0 - 0.25));
    std::vector<Eigen::Triplet<double, int>> t;
    int rows = 0;
    for (Index i = 0; i + 2 < static_cast<Index>(node_of.size()); ++i) {
      const Index node = node_of[static_cast<std::size_t>(i)];
      if (block.mesh.node(node)(2) < top ||
          (i > 0 && node_of[static_cast<std::size_t>(i - 1)] == node))
        continue;  // the first unknown of each top node (its three are consecutive)
      for (int k = 0; k < 3; ++k) t.emplace_back(rows, static_cast<int>(i + k), normal(k));
      ++rows;
    }
    N = SparseMatrix(rows, block.A.cols());
    N.setFromTriplets(t.begin(), t.end());
    c = Vector::Zero(rows);
    for (Index j = 0; j < rows / 2; ++j) c(j) = 10.0 * block.A.diagonal().maxCoeff();
  }
  [[nodiscard]] SparseMatrix newton_matrix() const {
    return SparseMatrix(block.A + SparseMatrix(N.transpose() * c.asDiagonal() * N));
  }
};

double max_abs(const SparseMatrix& M) {
  double m = 0.0;
  for (Index k = 0; k < M.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(M, k); it; ++it) m = std::max(m, std::abs(it.value()));
  return m;
}

TEST(ContactProlongation, IsTheTentativeProlongationSmoothedWithTheNewtonMatrix) {
  const Case k;
  ASSERT_FALSE(k.h.prolongations.empty());
  ASSERT_GT(k.h.omegas[0], 0.0);
  ASSERT_GT(k.N.rows(), 20);
  const SparseMatrix& P = k.h.prolongations.front();
  const ContactProlongation cp(k.block.A, k.N, P, k.h.tentatives[0], k.h.omegas[0]);
  const SparseMatrix change = cp.change(k.c);
  // P_H = (I - omega D_H^-1 H) T from scratch, H = A + N^T diag(c) N.
  const SparseMatrix PH =
      smoothed_prolongation(k.newton_matrix(), k.h.tentatives[0], k.h.omegas[0]);
  const SparseMatrix error = PH - (P + change);
  EXPECT_LT(max_abs(error), 1e-13 * max_abs(PH));
  EXPECT_GT(max_abs(change), 0.01 * max_abs(P));  // (a real change)
  // Only the rows of the active rows' unknowns change.
  std::vector<char> active_unknown(static_cast<std::size_t>(P.rows()), 0);
  for (Index j = 0; j < k.N.rows(); ++j)
    if (k.c(j) > 0.0)
      for (Index i = 0; i < k.N.cols(); ++i)
        if (k.N.coeff(j, i) != 0.0) active_unknown[static_cast<std::size_t>(i)] = 1;
  for (Index col = 0; col < change.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(change, col); it; ++it)
      EXPECT_TRUE(active_unknown[static_cast<std::size_t>(it.row())]) << it.row();
  // No active row, no change.
  EXPECT_EQ(cp.change(Vector::Zero(k.N.rows())).nonZeros(), 0);
}

TEST(ContactProlongation, NeedsOnlyTheContactRowsOfTheTentativeProlongation) {
  const Case k;
  MultigridHierarchy kept = k.h;
  const std::vector<Index> node_of = free_dof_nodes(k.block.dofs);
  keep_contact_rows(kept, k.N, node_of);
  EXPECT_LT(kept.tentatives[0].nonZeros(), k.h.tentatives[0].nonZeros() / 4);
  // All of a touched node's unknowns are kept, also those that its rows leave out: rows of N
  // with their first component alone keep the same rows.
  SparseMatrix first_component = k.N;
  first_component.prune([](Index, Index col, double) { return col % 3 == 0; });
  ASSERT_GT(first_component.nonZeros(), 0);
  MultigridHierarchy by_nodes = k.h;
  keep_contact_rows(by_nodes, first_component, node_of);
  EXPECT_EQ(by_nodes.tentatives[0].nonZeros(), kept.tentatives[0].nonZeros());
  const SparseMatrix& P = k.h.prolongations.front();
  const SparseMatrix whole =
      ContactProlongation(k.block.A, k.N, P, k.h.tentatives[0], k.h.omegas[0]).change(k.c);
  const SparseMatrix part =
      ContactProlongation(k.block.A, k.N, P, kept.tentatives[0], k.h.omegas[0]).change(k.c);
  EXPECT_EQ(max_abs(SparseMatrix(whole - part)), 0.0);
  // A tentative prolongation without the rows that N touches is refused.
  MultigridHierarchy none = k.h;
  keep_contact_rows(none, SparseMatrix(k.N.rows(), k.N.cols()), free_dof_nodes(k.block.dofs));
  EXPECT_THROW(ContactProlongation(k.block.A, k.N, P, none.tentatives[0], k.h.omegas[0]),
               NumericalError);
}

TEST(ContactProlongation, TheMultigridSmoothsEveryLevelAndCarriesTheContactRowsDown) {
  const Case k(60);
  ASSERT_GE(k.h.prolongations.size(), 2U);
  HostBackend be;
  PenalizedOperator H(be, k.block.A, k.N);
  MultigridOptions o;
  o.lambda_max = k.h.jacobi_radii;
  o.tentatives = &k.h.tentatives;
  o.omegas = k.h.omegas;
  MultigridPreconditioner M(H, k.block.A, k.N, k.h.prolongations, o, k.h.coarse_operators);
  for (std::size_t l = 0; l < k.h.prolongations.size(); ++l)
    EXPECT_EQ(M.prolongation_change(l).nonZeros(), 0) << l;  // set up for c = 0
  H.set_weights(k.c);
  M.refresh();
  // Level by level from scratch: the current contact rows N_l (the active rows of N P_H,0 ...
  // P_H,l-1; the others, whose c_j = 0, are left out), H_l = A_l + N_l^T diag(c) N_l, P_H,l =
  // (I - omega_l D_H,l^-1 H_l) T_l; the preconditioner's change must be P_H,l - P_l.
  Vector is_active = Vector::Zero(k.N.rows());
  for (Index j = 0; j < k.N.rows(); ++j) is_active(j) = k.c(j) > 0.0 ? 1.0 : 0.0;
  SparseMatrix Nl = is_active.asDiagonal() * k.N;
  const SparseMatrix* Al = &k.block.A;
  for (std::size_t l = 0; l < k.h.prolongations.size(); ++l) {
    const SparseMatrix& P = k.h.prolongations[l];
    if (l > 0) {
      const SparseMatrix rows = M.contact_rows(l);
      EXPECT_LT(max_abs(SparseMatrix(rows - Nl)), 1e-12 * max_abs(Nl)) << l;
    }
    const SparseMatrix Hl = *Al + SparseMatrix(Nl.transpose() * k.c.asDiagonal() * Nl);
    const SparseMatrix PH = smoothed_prolongation(Hl, k.h.tentatives[l], k.h.omegas[l]);
    const SparseMatrix& change = M.prolongation_change(l);
    EXPECT_LT(max_abs(SparseMatrix(PH - (P + change))), 1e-12 * max_abs(PH)) << l;
    EXPECT_GT(max_abs(change), 1e-3 * max_abs(P)) << l;  // (a real change on every level)
    Nl = Nl * PH;
    Al = &k.h.coarse_operators[l];
  }
  EXPECT_LT(max_abs(SparseMatrix(M.contact_rows(k.h.prolongations.size()) - Nl)),
            1e-12 * max_abs(Nl));
  // The V-cycle stays symmetric positive definite (restriction and prolongation transposes).
  testing::expect_symmetric_positive(be, M, k.block.A.rows());
  // Back to no contact: A's prolongations and contact rows again.
  H.set_weights(Vector::Zero(k.N.rows()));
  M.refresh();
  for (std::size_t l = 0; l < k.h.prolongations.size(); ++l)
    EXPECT_EQ(M.prolongation_change(l).nonZeros(), 0) << l;
  EXPECT_EQ(max_abs(SparseMatrix(M.contact_rows(1) - k.N * k.h.prolongations.front())), 0.0);
}

TEST(ContactProlongation, AMultigridWithoutTheTentativesContactRowsKeepsTheStiffnessProlongation) {
  const Case k;
  MultigridHierarchy none = k.h;
  keep_contact_rows(none, SparseMatrix(k.N.rows(), k.N.cols()),
                    free_dof_nodes(k.block.dofs));  // (rows of no unknown kept)
  none.tentatives[0].coeffRef(0, 0) = 1.0;          // (not empty, but not N's rows)
  HostBackend be;
  PenalizedOperator H(be, k.block.A, k.N);
  MultigridOptions o;
  o.tentatives = &none.tentatives;
  o.omegas = none.omegas;
  MultigridPreconditioner M(H, k.block.A, k.N, k.h.prolongations, o, k.h.coarse_operators);
  H.set_weights(k.c);
  M.refresh();
  EXPECT_EQ(M.prolongation_change(0).nonZeros(), 0);
  EXPECT_EQ(max_abs(SparseMatrix(M.contact_rows(1) - k.N * k.h.prolongations.front())), 0.0);
}

}  // namespace
}  // namespace signorini
