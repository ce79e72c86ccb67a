// Smoothed-aggregation coarsening (docs/gpu.md): aggregates cover every node and are connected;
// the prolongations carry the rigid-body modes to every level; with them, multigrid-preconditioned
// CG solves the paper's Newton matrix as CHOLMOD does, on meshes that do not halve, in a number of
// iterations that hardly grows with the mesh.

#include "signorini/iterative/smoothed_aggregation.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <map>
#include <set>

#include "signorini/backend/host_backend.hpp"
#include "signorini/core/error.hpp"
#include "signorini/fem/rigid_body_modes.hpp"
#include "signorini/iterative/galerkin_product.hpp"
#include "signorini/iterative/multigrid_preconditioner.hpp"
#include "signorini/iterative/pcg.hpp"
#include "signorini/linalg/cholmod_solver.hpp"
#include "signorini/mesh/box_mesh.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/problem/model.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

// The 8-neighbour graph of an m x m grid of nodes (the node graph of Q1 elements).
void grid_graph(Index m, std::vector<Index>& offsets, std::vector<Index>& adjacency) {
  offsets.assign(1, 0);
  adjacency.clear();
  for (Index j = 0; j < m; ++j)
    for (Index i = 0; i < m; ++i) {
      for (Index dj = -1; dj <= 1; ++dj)
        for (Index di = -1; di <= 1; ++di) {
          const Index a = i + di, b = j + dj;
          if ((di != 0 || dj != 0) && a >= 0 && a < m && b >= 0 && b < m)
            adjacency.push_back(b * m + a);
        }
      offsets.push_back(static_cast<Index>(adjacency.size()));
    }
}

TEST(AggregateNodes, CoverAGridWithConnectedPatches) {
  for (const Index m : {9, 10, 17}) {
    std::vector<Index> offsets, adjacency;
    grid_graph(m, offsets, adjacency);
    const std::vector<Index> agg = aggregate_nodes(offsets, adjacency);
    ASSERT_EQ(static_cast<Index>(agg.size()), m * m);
    std::map<Index, std::vector<Index>> members;
    for (Index a = 0; a < m * m; ++a) {
      ASSERT_GE(agg[static_cast<std::size_t>(a)], 0);
      members[agg[static_cast<std::size_t>(a)]].push_back(a);
    }
    // Numbers 0 .. count-1, each aggregate connected in the graph.
    EXPECT_EQ(members.rbegin()->first + 1, static_cast<Index>(members.size()));
    for (const auto& [id, nodes] : members) {
      std::set<Index> reached{nodes.front()};
      std::vector<Index> stack{nodes.front()};
      while (!stack.empty()) {
        const Index a = stack.back();
        stack.pop_back();
        for (Index k = offsets[static_cast<std::size_t>(a)];
             k < offsets[static_cast<std::size_t>(a) + 1]; ++k) {
          const Index b = adjacency[static_cast<std::size_t>(k)];
          if (agg[static_cast<std::size_t>(b)] == id && reached.insert(b).second)
            stack.push_back(b);
        }
      }
      EXPECT_EQ(reached.size(), nodes.size()) << "aggregate " << id << " of the " << m << " grid";
    }
    // 3 x 3 patches: about m^2 / 9 aggregates.
    EXPECT_LE(static_cast<double>(members.size()), static_cast<double>(m * m) / 9.0 * 1.6) << m;
    if (m == 9) {
      EXPECT_EQ(members.size(), 9U);
    }
  }
}

TEST(AggregateNodes, IsolatedNodesAreAggregatesOfTheirOwn) {
  const std::vector<Index> offsets{0, 0, 0, 0};
  const std::vector<Index> agg = aggregate_nodes(offsets, {});
  EXPECT_EQ(agg, (std::vector<Index>{0, 1, 2}));
}

TEST(SmoothedAggregation, ProlongationsCarryTheRigidBodyModes) {
  // A floating body: A B = 0, so the smoothing step keeps P_tent's exact reproduction of B and
  // every level's range contains the rigid-body modes (nothing here needs A to be definite).
  const ProblemSpec spec = paper_benchmark(24, 8);
  const Mesh mesh = make_rectangle_mesh(spec.mesh);
  const DofMap dofs = make_dof_map(mesh, {});
  const SparseMatrix A = assemble_stiffness(mesh, dofs, spec.elasticity);
  const Matrix B = rigid_body_modes(mesh, dofs);
  SmoothedAggregationOptions o;
  o.max_coarse_unknowns = 20;
  const MultigridHierarchy h = smoothed_aggregation_hierarchy(A, B, free_dof_nodes(dofs), o);
  ASSERT_GE(h.prolongations.size(), 2U);
  ASSERT_EQ(h.coarse_operators.size(), h.prolongations.size());
  SparseMatrix P = h.prolongations[0];
  for (std::size_t l = 0; l < h.prolongations.size(); ++l) {
    if (l > 0) P = SparseMatrix(P * h.prolongations[l]);
    const Matrix Pd(P);
    // Least squares: B = P Y for some Y.
    const Matrix Y = Pd.colPivHouseholderQr().solve(B);
    EXPECT_LT((Pd * Y - B).norm(), 1e-10 * B.norm()) << "level " << l + 1;
    EXPECT_LT(static_cast<double>(P.cols()), 0.4 * static_cast<double>(P.rows())) << l + 1;
    // Galerkin: the stored coarse operator is P_l^T A_{l-1} P_l.
    const SparseMatrix& finer = l == 0 ? A : h.coarse_operators[l - 1];
    const Matrix reference =
        Matrix(h.prolongations[l].transpose()) * Matrix(finer) * Matrix(h.prolongations[l]);
    EXPECT_LT((Matrix(h.coarse_operators[l]) - reference).norm(), 1e-12 * reference.norm());
  }
  EXPECT_LE(h.coarse_operators.back().rows(), 20);
}

TEST(SmoothedAggregation, ThreeDimensionalProductsMatchEigens) {
  // In 3D each aggregate carries six modes, so the prolongation's and the Galerkin product's
  // columns are formed six at a time (form_column_groups): both against Eigen's own products.
  const testing::ClampedBlock block = testing::clamped_block(6, 5, 4);
  const SparseMatrix& A = block.A;
  SmoothedAggregationOptions o;
  o.max_coarse_unknowns = 30;
  const MultigridHierarchy h =
      smoothed_aggregation_hierarchy(A, block.modes, free_dof_nodes(block.dofs), o);
  ASSERT_GE(h.prolongations.size(), 1U);
  const SparseMatrix& P = h.prolongations[0];
  EXPECT_EQ(P.cols() % 6, 0);  // six modes per aggregate (none too small to carry them)
  const SparseMatrix reference = SparseMatrix(SparseMatrix(P.transpose()) * A * P);
  EXPECT_LT((h.coarse_operators[0] - reference).norm(), 1e-12 * reference.norm());
  // With the bottom clamped, the coarse operator is symmetric positive definite.
  const Matrix C(h.coarse_operators[0]);
  EXPECT_LT((C - C.transpose()).norm(), 1e-12 * C.norm());
  EXPECT_EQ(Eigen::LLT<Matrix>(C).info(), Eigen::Success);
}

// A rank's share of the products (petsc/aggregation_levels.hpp): the unknowns split in two
// "ranks", each holding A's columns of its own unknowns (its rows, by symmetry) with its own
// unknowns numbered first. The two shares of the Galerkin product sum to P^T A P, each rank's
// rows of the smoothed prolongation are those of the whole one, and the aggregation of a rank's
// nodes ignores the rows of the other's unknowns.
TEST(SmoothedAggregation, ARanksSharesOfTheProductsSumToTheWholeOnes) {
  const testing::ClampedBlock block = testing::clamped_block(6, 5, 4);
  const SparseMatrix& A = block.A;
  const Matrix& B = block.modes;
  const std::vector<Index> nodes = free_dof_nodes(block.dofs);
  const Index n = A.rows();
  const AggregationLevel whole = aggregate_level(A, B, nodes, {}, 0.0);
  const double omega = 0.4;
  const SparseMatrix P = smoothed_prolongation(A, whole.tentative, omega);
  const Matrix reference = Matrix(SparseMatrix(P.transpose()) * A * P);

  // Rank 0 owns the unknowns 0 .. k-1 (whole nodes), rank 1 the rest.
  const Index k = 3 * (n / 6);
  Matrix sum = Matrix::Zero(P.cols(), P.cols());
  for (int rank = 0; rank < 2; ++rank) {
    // Its numbering: its own unknowns first, then the other's.
    Eigen::VectorXi order(n);
    for (Index i = 0; i < n; ++i) {
      // (rank 1: k .. n-1, then 0 .. k-1)
      order(i) = static_cast<int>(rank == 0 ? i : (i + k) % n);
    }
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> to_local(n);
    for (Index i = 0; i < n; ++i) to_local.indices()(order(i)) = static_cast<int>(i);
    const Index own = rank == 0 ? k : n - k;
    const SparseMatrix permuted = to_local * A * to_local.transpose();
    const SparseMatrix local = permuted.leftCols(own);
    const SparseMatrix P_local = to_local * P;
    sum += Matrix(galerkin_product(local, P_local)).transpose();
    // Its rows of the smoothed prolongation, from all the rows of T.
    const SparseMatrix T_local = to_local * whole.tentative;
    const Matrix rows = Matrix(smoothed_prolongation_rows(local, T_local, omega));
    EXPECT_LT((rows - Matrix(P_local).topRows(own)).norm(), 1e-13 * Matrix(P).norm()) << rank;
  }
  EXPECT_LT((sum - reference).norm(), 1e-12 * reference.norm());

  // Rank 0's aggregation, with the other rank's rows beside its columns, is that of its own
  // block alone.
  const Matrix B0 = B.topRows(k);
  const std::vector<Index> nodes0(nodes.begin(), nodes.begin() + k);
  const AggregationLevel with_rows =
      aggregate_level(SparseMatrix(A.leftCols(k)), B0, nodes0, {}, 0.0);
  const AggregationLevel alone =
      aggregate_level(SparseMatrix(A.topLeftCorner(k, k)), B0, nodes0, {}, 0.0);
  EXPECT_EQ(with_rows.coarse_node, alone.coarse_node);
  EXPECT_EQ(with_rows.tentative.cols(), alone.tentative.cols());
  EXPECT_LT((Matrix(with_rows.tentative) - Matrix(alone.tentative)).norm(), 1e-14);
}

TEST(SmoothedAggregation, TheHierarchysEstimatesServeTheSmoothers) {
  // The damping of each prolongation needs lambda_max(D^-1 A_l) of the level it leaves, that
  // level's Chebyshev smoother the same number: given them, the multigrid skips its own Lanczos
  // steps and builds the same V-cycle (the two products sum in other orders: rounding apart).
  const ProblemSpec spec = paper_benchmark(48, 16);
  const Model model = build_model(spec);
  const SparseMatrix& A = model.problem.A;
  const SparseMatrix& N = model.problem.contact.N;
  SmoothedAggregationOptions o;
  o.max_coarse_unknowns = 60;  // three levels: a coarse one smoothed too
  const MultigridHierarchy h = smoothed_aggregation_hierarchy(
      A, rigid_body_modes(model.mesh, model.dofs), free_dof_nodes(model.dofs), o);
  ASSERT_EQ(h.jacobi_radii.size(), h.prolongations.size());
  ASSERT_GE(h.prolongations.size(), 2U);  // a coarse level smoothed too
  for (const double radius : h.jacobi_radii) EXPECT_GT(radius, 1.0);
  HostBackend be;
  PenalizedOperator op(be, A, N);
  MultigridOptions estimated, given;
  given.lambda_max = h.jacobi_radii;
  MultigridPreconditioner a(op, A, N, h.prolongations, estimated, h.coarse_operators);
  MultigridPreconditioner b(op, A, N, h.prolongations, given, h.coarse_operators);
  for (std::size_t l = 0; l < h.jacobi_radii.size(); ++l) {
    EXPECT_GT(a.lambda_max(l), 0.0) << l;
    EXPECT_NEAR(a.lambda_max(l), b.lambda_max(l), 1e-12 * a.lambda_max(l)) << l;
  }
  const Vector r = Vector::LinSpaced(op.size(), -1.0, 1.0).array().sin();
  DeviceVector za(be, op.size()), zb(be, op.size());
  a.apply(to_device(be, r), za);
  b.apply(to_device(be, r), zb);
  EXPECT_LT((to_host(za) - to_host(zb)).norm(), 1e-10 * to_host(za).norm());
}

// H = A + N^T diag(c) N of the paper's benchmark with every contact node active, solved by CG
// with an aggregation V-cycle.
struct Solved {
  int iterations = 0;
  double error = 0.0;
  std::size_t levels = 0;
};

Solved solve_with_aggregation(Index nx, Index ny) {
  const ProblemSpec spec = paper_benchmark(nx, ny);
  const Model model = build_model(spec);
  const SparseMatrix& A = model.problem.A;
  const SparseMatrix& N = model.problem.contact.N;
  const Vector c = 1e8 * model.problem.contact.weights;
  const MultigridHierarchy h = smoothed_aggregation_hierarchy(
      A, rigid_body_modes(model.mesh, model.dofs), free_dof_nodes(model.dofs));
  HostBackend be;
  PenalizedOperator op(be, A, N);
  op.set_weights(c);
  MultigridPreconditioner mg(op, A, N, h.prolongations, {}, h.coarse_operators);
  Pcg pcg(be, op.size());
  PcgOptions o;
  o.tolerance = 1e-10;
  DeviceVector x(be, op.size());
  const Vector& b = model.problem.b;
  const PcgResult r = pcg.solve(op, mg, to_device(be, b), x, o);
  EXPECT_TRUE(r.converged) << nx << "x" << ny;
  const SparseMatrix H = SparseMatrix(A + SparseMatrix(N.transpose() * c.asDiagonal() * N));
  CholmodSolver chol;
  chol.analyze(H);
  chol.factorize(H);
  Vector exact;
  chol.solve(b, exact);
  return {r.iterations, (to_host(x) - exact).norm() / exact.norm(), mg.level_sizes().size()};
}

TEST(SmoothedAggregation, ConjugateGradientsMatchCholmodInFewIterationsOnMeshesThatDoNotHalve) {
  std::map<Index, Solved> runs;
  for (const Index nx : {61, 121, 241}) runs[nx] = solve_with_aggregation(nx, nx / 3);
  for (const auto& [nx, s] : runs) {
    EXPECT_LT(s.error, 1e-7) << nx;
    EXPECT_GE(s.levels, 2U) << nx;
  }
  EXPECT_LE(runs[241].iterations, runs[61].iterations + 10)
      << runs[61].iterations << ", " << runs[121].iterations << ", " << runs[241].iterations;
  EXPECT_LE(runs[241].iterations, 60);
}

TEST(SmoothedAggregation, RefusesMismatchedInput) {
  const SparseMatrix A = Matrix::Identity(4, 4).sparseView();
  EXPECT_THROW(smoothed_aggregation_hierarchy(A, Matrix::Ones(3, 1), {0, 1, 2, 3}), NumericalError);
  EXPECT_THROW(smoothed_aggregation_hierarchy(A, Matrix::Ones(4, 1), {0, 1, 2}), NumericalError);
}

}  // namespace
}  // namespace signorini
