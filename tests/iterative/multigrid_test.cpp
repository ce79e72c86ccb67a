// The algorithms of the backend path on the CPU backend (docs/gpu.md): conjugate gradients with
// Jacobi and with the multigrid V-cycle solve H x = b for the generalised Hessian of the paper's
// benchmark as CHOLMOD does; the eigenvalue estimate is close to the true one; the V-cycle is a
// symmetric positive definite operator; and its iteration count hardly grows with the mesh.

#include <gtest/gtest.h>

#include <map>

#include "signorini/backend/host_backend.hpp"
#include "signorini/iterative/chebyshev_smoother.hpp"
#include "signorini/iterative/eigenvalue_estimate.hpp"
#include "signorini/iterative/galerkin_product.hpp"
#include "signorini/iterative/jacobi_preconditioner.hpp"
#include "signorini/iterative/multigrid_preconditioner.hpp"
#include "signorini/iterative/pcg.hpp"
#include "signorini/linalg/cholmod_solver.hpp"
#include "signorini/problem/rectangle_hierarchy.hpp"
#include "symmetric_preconditioner.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

// H = A + r N^T diag(h) N with every contact node active: the stiffest Newton matrix of (17).
struct Fixture {
  const Model& model;
  std::vector<SparseMatrix> P;
  Vector c;
  explicit Fixture(Index nx) : model(testing::paper_model(nx)) {
    const ProblemSpec spec = paper_benchmark(nx, nx / 3);
    P = make_rectangle_prolongations(spec.mesh, spec.clamps, model.dofs);
    c = 1e8 * model.problem.contact.weights;
  }
  [[nodiscard]] SparseMatrix hessian() const {
    const SparseMatrix& N = model.problem.contact.N;
    return SparseMatrix(model.problem.A + SparseMatrix(N.transpose() * c.asDiagonal() * N));
  }
};

// The V-cycle of the fixture's H on the CPU backend, the weights set before the set-up.
struct Cycle {
  HostBackend be;
  PenalizedOperator op;
  MultigridPreconditioner mg;
  explicit Cycle(const Fixture& f)
      : op(be, f.model.problem.A, f.model.problem.contact.N),
        mg(weighted(op, f.c), f.model.problem.A, f.model.problem.contact.N, f.P, {}) {}
  static PenalizedOperator& weighted(PenalizedOperator& op, const Vector& c) {
    op.set_weights(c);
    return op;
  }
};

Vector direct_solution(const SparseMatrix& H, const Vector& b) {
  CholmodSolver chol;
  chol.analyze(H);
  chol.factorize(H);
  Vector x;
  chol.solve(b, x);
  return x;
}

TEST(GalerkinProduct, EqualsEigensTripleProduct) {
  Fixture f(60);
  const SparseMatrix& A = f.model.problem.A;
  for (const SparseMatrix& P : {f.P[0], SparseMatrix(f.P[0] * f.P[1])}) {
    const SparseMatrix fast = galerkin_product(A, P);
    const SparseMatrix reference = SparseMatrix(P.transpose() * A * P).pruned();
    EXPECT_EQ(fast.rows(), P.cols());
    EXPECT_LT((Matrix(fast) - Matrix(reference)).norm(), 1e-13 * Matrix(reference).norm());
    EXPECT_LT((Matrix(fast) - Matrix(fast).transpose()).norm(), 1e-13 * Matrix(fast).norm());
  }
}

TEST(PenalizedOperator, AppliesTheGeneralisedHessian) {
  Fixture f(60);
  HostBackend be;
  PenalizedOperator op(be, f.model.problem.A, f.model.problem.contact.N);
  op.set_weights(f.c);
  const Vector x = Vector::LinSpaced(op.size(), -1.0, 2.0);
  DeviceVector y(be, op.size()), diag(be, op.size());
  op.apply(to_device(be, x), y);
  const SparseMatrix H = f.hessian();
  EXPECT_LT(testing::relative_difference(to_host(y), H * x), 1e-14);
  op.diagonal(diag);
  EXPECT_LT(testing::relative_difference(to_host(diag), Vector(H.diagonal())), 1e-15);
}

TEST(Pcg, JacobiAndMultigridMatchCholmod) {
  Fixture f(60);
  const SparseMatrix H = f.hessian();
  const Vector& b = f.model.problem.b;
  const Vector exact = direct_solution(H, b);
  HostBackend be;
  PenalizedOperator op(be, f.model.problem.A, f.model.problem.contact.N);
  op.set_weights(f.c);
  JacobiPreconditioner jacobi(op);
  MultigridPreconditioner mg(op, f.model.problem.A, f.model.problem.contact.N, f.P, {});
  Pcg pcg(be, op.size());
  const DeviceVector bd = to_device(be, b);
  PcgOptions o;
  o.tolerance = 1e-12;
  o.max_iterations = 50000;
  DeviceVector x(be, op.size());
  const PcgResult rj = pcg.solve(op, jacobi, bd, x, o);
  ASSERT_TRUE(rj.converged);
  EXPECT_LT(testing::relative_difference(to_host(x), exact), 1e-8);
  be.fill(x, 0.0);
  const PcgResult rm = pcg.solve(op, mg, bd, x, o);
  ASSERT_TRUE(rm.converged);
  EXPECT_LT(testing::relative_difference(to_host(x), exact), 1e-8);
  // The true residual agrees with the recursive one that stopped the iteration.
  EXPECT_LT((H * to_host(x) - b).norm() / b.norm(), 1e-10);
  EXPECT_LT(rm.iterations * 10, rj.iterations) << rm.iterations << " vs " << rj.iterations;
}

// A first residual handed in (as a GNM step does, from the A x it keeps) gives the run that
// computing it gives, and a wrong one is what the iteration follows (it is not recomputed).
TEST(Pcg, TakesTheFirstResidualWhereGiven) {
  Fixture f(60);
  Cycle cycle(f);
  auto& [be, op, mg] = cycle;
  Pcg pcg(be, op.size());
  const DeviceVector b = to_device(be, f.model.problem.b);
  const Vector start = Vector::LinSpaced(op.size(), -1e-3, 1e-3);
  PcgOptions o;
  o.tolerance = 1e-10;
  DeviceVector x = to_device(be, start);
  const PcgResult computed = pcg.solve(op, mg, b, x, o);
  const Vector x_computed = to_host(x);
  DeviceVector r(be, op.size());
  const DeviceVector x0 = to_device(be, start);
  op.apply(x0, r);
  be.axpby(1.0, b, -1.0, r);  // b - H x0
  o.initial_residual = &r;
  x = to_device(be, start);
  const PcgResult given = pcg.solve(op, mg, b, x, o);
  ASSERT_TRUE(computed.converged && given.converged);
  EXPECT_EQ(given.iterations, computed.iterations);
  EXPECT_LT(testing::relative_difference(to_host(x), x_computed), 1e-14);
  be.fill(r, 0.0);  // "already solved": no iteration
  x = to_device(be, start);
  EXPECT_EQ(pcg.solve(op, mg, b, x, o).iterations, 0);
  EXPECT_EQ(to_host(x), start);
}

TEST(EigenvalueEstimate, LanczosEstimateIsJustBelowTheLargestEigenvalue) {
  Fixture f(30);
  HostBackend be;
  PenalizedOperator op(be, f.model.problem.A, f.model.problem.contact.N);
  op.set_weights(f.c);
  JacobiPreconditioner jacobi(op);
  const DeviceVector start = to_device(be, eigenvalue_estimate_start(op.size()));
  const double estimate = estimate_largest_eigenvalue(op, jacobi, start, 12);
  const double exact = testing::dense_jacobi_lambda_max(Matrix(f.hessian()));
  EXPECT_LE(estimate, exact * (1.0 + 1e-10));
  EXPECT_GT(estimate, 0.9 * exact);  // so that 1.1 * estimate covers the spectrum
}

// lambda_max(D^-1 H_l) of H_l = P^T ... H ... P, the level's Galerkin product of H: densely up
// to 1,000 unknowns, else by 300 Lanczos steps on the whole level (a Ritz value, converged).
double level_lambda_max(const SparseMatrix& H, const std::vector<SparseMatrix>& P,
                        std::size_t level) {
  SparseMatrix Hl = H;
  for (std::size_t l = 0; l < level; ++l) Hl = galerkin_product(Hl, P[l]);
  if (Hl.rows() > 1000) {
    HostBackend host;
    SymmetricMatrixOperator op(Hl);
    const DeviceVector dinv = to_device(host, Vector(Hl.diagonal().cwiseInverse()));
    DiagonalPreconditioner jacobi(dinv);
    const DeviceVector start = to_device(host, eigenvalue_estimate_start(Hl.rows()));
    return estimate_largest_eigenvalue(op, jacobi, start, 300);
  }
  return testing::dense_jacobi_lambda_max(Matrix(Hl));
}

// After a refresh for an active set, each level's lambda_max is the larger of A_l's (estimated
// once, for c = 0) and the contact zone's, with no Lanczos steps on the level: with oblique
// normals (0.6, -0.8) and the paper's r on every contact node, it covers D_H^-1 H_l's spectrum
// on every level with the smoother's factor 1.1 (as a Lanczos estimate on the whole level does),
// stays close to it, and the V-cycle still preconditions CG as well.
TEST(MultigridPreconditioner, RefreshedEigenvaluesCoverEveryLevelsSpectrum) {
  Fixture f(60);
  SparseMatrix N = f.model.problem.contact.N;  // x and y entries stored for every movable node
  for (Index j = 0; j < N.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(N, j); it; ++it) it.valueRef() = j % 2 == 0 ? 0.6 : -0.8;
  HostBackend be;
  PenalizedOperator op(be, f.model.problem.A, N);
  MultigridOptions o;
  o.max_dense_coarse = 0;  // the coarsest level smoothed too: two coarse levels refreshed
  MultigridPreconditioner mg(op, f.model.problem.A, N, f.P, o);
  ASSERT_EQ(mg.level_sizes().size(), 3U);  // 60x20, 30x10, 15x5
  const SparseMatrix& A = f.model.problem.A;
  std::vector<double> lambda_A;  // estimated with c = 0
  for (std::size_t l = 0; l < 3; ++l) {
    lambda_A.push_back(mg.lambda_max(l));
    const double exact = level_lambda_max(A, f.P, l);
    EXPECT_LE(lambda_A[l], exact * (1.0 + 1e-10)) << l;
    EXPECT_GE(1.1 * lambda_A[l], exact) << l;
  }
  op.set_weights(f.c);
  mg.refresh();
  const SparseMatrix H(A + SparseMatrix(N.transpose() * f.c.asDiagonal() * N));
  for (std::size_t l = 0; l < 3; ++l) {
    const double exact = level_lambda_max(H, f.P, l);
    EXPECT_GE(mg.lambda_max(l), lambda_A[l]) << l;
    EXPECT_GE(1.1 * mg.lambda_max(l), exact) << l << ": " << mg.lambda_max(l) << " vs " << exact;
    EXPECT_LE(mg.lambda_max(l), 1.05 * exact) << l << ": " << mg.lambda_max(l) << " vs " << exact;
  }
  // CG with the refreshed V-cycle against CHOLMOD.
  const Vector b = f.model.problem.b;
  DeviceVector x(be, op.size());
  Pcg pcg(be, op.size());
  PcgOptions po;
  po.tolerance = 1e-10;
  const PcgResult res = pcg.solve(op, mg, to_device(be, b), x, po);
  ASSERT_TRUE(res.converged);
  EXPECT_LT(res.iterations, 30);
  EXPECT_LT(testing::relative_difference(to_host(x), direct_solution(H, b)), 1e-8);
}

TEST(MultigridPreconditioner, IsSymmetricPositiveDefinite) {
  Fixture f(60);
  Cycle cycle(f);
  auto& [be, op, mg] = cycle;
  EXPECT_EQ(mg.level_sizes().size(), 3U);  // 60x20, 30x10, 15x5
  testing::expect_symmetric_positive(be, mg, op.size());
}

// A level small enough to be the dense coarsest one, alone: the preconditioner is then the exact
// solve H^-1 r (on the CPU by the Cholesky factor's triangular solves), after a refresh for a
// new active set too.
TEST(MultigridPreconditioner, TheCoarsestLevelIsSolvedExactly) {
  Fixture f(30);  // 30 x 10: 620 unknowns, below the dense limit
  HostBackend be;
  PenalizedOperator op(be, f.model.problem.A, f.model.problem.contact.N);
  MultigridPreconditioner mg(op, f.model.problem.A, f.model.problem.contact.N, {}, {});
  ASSERT_EQ(mg.level_sizes().size(), 1U);
  const Vector r = f.model.problem.b + Vector::LinSpaced(op.size(), -1.0, 1.0);
  DeviceVector z(be, op.size());
  mg.apply(to_device(be, r), z);
  EXPECT_LT(testing::relative_difference(to_host(z), direct_solution(f.model.problem.A, r)),
            1e-10);  // both direct, in different orders of rounding
  op.set_weights(f.c);
  mg.refresh();
  mg.apply(to_device(be, r), z);
  EXPECT_LT(testing::relative_difference(to_host(z), direct_solution(f.hessian(), r)), 1e-10);
}

TEST(MultigridPreconditioner, HostEstimatesOfSmallLevelsChangeNothing) {
  Fixture f(120);
  HostBackend be;
  PenalizedOperator op(be, f.model.problem.A, f.model.problem.contact.N);
  op.set_weights(f.c);
  MultigridOptions on_backend;
  on_backend.host_estimate_below = 0;
  MultigridPreconditioner a(op, f.model.problem.A, f.model.problem.contact.N, f.P, on_backend);
  MultigridOptions on_host;
  on_host.host_estimate_below = 1000000;  // every level of 120x40
  MultigridPreconditioner b(op, f.model.problem.A, f.model.problem.contact.N, f.P, on_host);
  const DeviceVector r = to_device(be, f.model.problem.b);
  DeviceVector za(be, op.size()), zb(be, op.size());
  a.apply(r, za);
  b.apply(r, zb);
  EXPECT_LT(testing::relative_difference(to_host(zb), to_host(za)), 1e-13);
}

TEST(MultigridPreconditioner, IterationCountHardlyGrowsWithTheMesh) {
  std::map<Index, int> iterations;
  for (const Index nx : {60, 120, 240}) {
    Fixture f(nx);
    Cycle cycle(f);
    HostBackend& be = cycle.be;
    PenalizedOperator& op = cycle.op;
    Pcg pcg(be, op.size());
    PcgOptions o;
    o.tolerance = 1e-10;
    DeviceVector x(be, op.size());
    const PcgResult r = pcg.solve(op, cycle.mg, to_device(be, f.model.problem.b), x, o);
    ASSERT_TRUE(r.converged) << nx;
    iterations[nx] = r.iterations;
  }
  // Jacobi-CG roughly doubles its count per refinement; one V-cycle per iteration does not.
  EXPECT_LE(iterations[240], iterations[60] + 6)
      << iterations[60] << ", " << iterations[120] << ", " << iterations[240];
  EXPECT_LE(iterations[240], 40);
}

}  // namespace
}  // namespace signorini
