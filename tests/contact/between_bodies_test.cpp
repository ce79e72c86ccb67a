// Contact rows between two deformable bodies (InterfaceKind::BetweenBodies): each row touches
// the dofs of its node on one body and of its partner on the other, (N x)_j = nu_j . (u_j -
// u_partner), which A does not couple. Two blocks of different materials, one on the other,
// pressed together by a prescribed shortening: with matching nodes on the interface the contact
// pressure is uniform and known (the compliances of the two blocks in series), and every host
// path and method must give it to round-off; with non-matching nodes (node-to-segment rows whose
// partners share nodes) the methods that take any rows must agree with each other and with the
// balance of forces. The mortar discretisation of two meshes is issue 55's; these rows are its
// algebra.

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "../expect_contains.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/friction_law.hpp"
#include "signorini/contact/friction_ssn.hpp"
#include "signorini/contact/method_table.hpp"
#include "signorini/contact/modified_lagrangian.hpp"
#include "signorini/core/error.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/iterative/smoothed_aggregation.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

constexpr double kShortening = 0.01;  // of the two blocks together, at the top
const IsotropicMaterial kLower{200.0, 0.3}, kUpper{70.0, 0.2};

// Two unit blocks, the lower on [0, 1] x [0, 1] with nx x ny quad4 cells, the upper on [0, 1] x
// [1, 2] with mx x ny, each with its own nodes on y = 1. The lower rests on rollers (u_y = 0 on
// its bottom, u_x = 0 at its bottom-left corner); the upper's top is moved down by kShortening
// (u_x = 0 at its top-left corner): no rigid motion is free, and nothing holds the blocks
// together but contact.
struct TwoBlocks {
  Index nx, mx, ny;
  Mesh mesh;
  ElasticityOptions elasticity;
  DofMap dofs;
  ContactProblem problem;

  TwoBlocks(Index nx_, Index mx_, Index ny_)
      : nx(nx_), mx(mx_), ny(ny_), mesh(make_mesh()), dofs(mesh.num_nodes(), 2) {
    elasticity.region_materials = {kLower, kUpper};
    for (Index i = 0; i <= nx; ++i) dofs.clamp(lower(i, 0), 1);
    dofs.clamp(lower(0, 0), 0);
    for (Index i = 0; i <= mx; ++i) dofs.prescribe(upper(i, ny), 1, -kShortening);
    dofs.clamp(upper(0, ny), 0);
    dofs.finalize();
    problem.A = assemble_stiffness(mesh, dofs, elasticity);
    // b = -K u_D: the prescribed shortening loads the free dofs.
    problem.b =
        dofs.restrict_to_free(Vector(-internal_forces(mesh, elasticity, dofs.prescribed_values())));
    problem.contact = interface_rows();
  }

  [[nodiscard]] Index lower(Index i, Index j) const { return j * (nx + 1) + i; }
  [[nodiscard]] Index upper(Index i, Index j) const {
    return (nx + 1) * (ny + 1) + j * (mx + 1) + i;
  }

  [[nodiscard]] Mesh make_mesh() const {
    const Index n = (nx + 1) * (ny + 1) + (mx + 1) * (ny + 1);
    Eigen::MatrixXd x(2, n);
    std::vector<Index> cells;
    std::vector<int> region;
    const auto block = [&](Index cols, double y0, const auto& node) {
      for (Index j = 0; j <= ny; ++j)
        for (Index i = 0; i <= cols; ++i)
          x.col(node(i, j)) << static_cast<double>(i) / static_cast<double>(cols),
              y0 + static_cast<double>(j) / static_cast<double>(ny);
      for (Index j = 0; j < ny; ++j)
        for (Index i = 0; i < cols; ++i) {
          cells.insert(cells.end(),
                       {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)});
          region.push_back(y0 == 0.0 ? 0 : 1);
        }
    };
    block(nx, 0.0, [&](Index i, Index j) { return lower(i, j); });
    block(mx, 1.0, [&](Index i, Index j) { return upper(i, j); });
    Mesh m(CellType::Quad4, std::move(x), std::move(cells));
    m.set_cell_regions({"lower", "upper"}, std::move(region));
    return m;
  }

  // One row per node of the upper block's bottom (the side that carries the multipliers), its
  // outward normal (0, -1): (N x)_j = -(u_y at the node - u_y at its partner point on the lower
  // block's top, interpolated on the edge under it), <= 0 (gap 0). h_j: the node's share of the
  // upper bottom's length.
  [[nodiscard]] ContactSet interface_rows() const {
    ContactSet c;
    c.kind = InterfaceKind::BetweenBodies;
    c.normals = Eigen::MatrixXd::Zero(2, mx + 1);
    c.normals.row(1).setConstant(-1.0);
    c.weights = Vector::Constant(mx + 1, 1.0 / static_cast<double>(mx));
    c.weights(0) = c.weights(mx) = 0.5 / static_cast<double>(mx);
    c.gaps = Vector::Zero(mx + 1);
    c.movable.assign(static_cast<std::size_t>(mx + 1), true);
    std::vector<Eigen::Triplet<double, int>> t;
    for (Index j = 0; j <= mx; ++j) {
      c.nodes.push_back(upper(j, 0));
      const auto row = static_cast<int>(j);
      t.emplace_back(row, static_cast<int>(dofs.free_index(upper(j, 0), 1)), -1.0);
      const double s = static_cast<double>(j * nx) / static_cast<double>(mx);  // in edges
      const Index e = std::min<Index>(static_cast<Index>(s), nx - 1);
      const double xi = s - static_cast<double>(e);
      for (const auto& [i, w] : {std::pair{e, 1.0 - xi}, std::pair{e + 1, xi}})
        if (w != 0.0) t.emplace_back(row, static_cast<int>(dofs.free_index(lower(i, ny), 1)), w);
    }
    c.N.resize(mx + 1, dofs.num_free());
    c.N.setFromTriplets(t.begin(), t.end());
    c.N.makeCompressed();
    return c;
  }

  // The pressure of the two blocks in series: the shortening over their compliances in plane
  // strain with free sides, (1 - nu^2) / E per unit height each.
  [[nodiscard]] static double pressure() {
    const auto compliance = [](const IsotropicMaterial& m) { return (1.0 - m.nu * m.nu) / m.E; };
    return kShortening / (compliance(kLower) + compliance(kUpper));
  }
};

struct Way {
  const char* name;
  ContactMethod method;
  LinearSolverType linear;
  bool condensed;
};

constexpr std::array kWays{
    Way{"uzawa_gnm sparse", ContactMethod::UzawaGnm, LinearSolverType::Cholmod, false},
    Way{"uzawa_gnm condensed", ContactMethod::UzawaGnm, LinearSolverType::Cholmod, true},
    Way{"uzawa_gnm cg", ContactMethod::UzawaGnm, LinearSolverType::ConjugateGradient, false},
    Way{"classical_uzawa sparse", ContactMethod::ClassicalUzawa, LinearSolverType::Cholmod, false},
    Way{"classical_uzawa condensed", ContactMethod::ClassicalUzawa, LinearSolverType::Cholmod,
        true},
    Way{"semismooth_newton sparse", ContactMethod::SemismoothNewton, LinearSolverType::Cholmod,
        false},
    Way{"semismooth_newton condensed", ContactMethod::SemismoothNewton, LinearSolverType::Cholmod,
        true},
};

ContactSolverOptions options_of(const Way& w) {
  ContactSolverOptions o;
  o.method = w.method;
  o.linear.type = w.linear;
  o.schur_complement = w.condensed;
  o.uzawa_tolerance = 1e-13;
  o.linear.cg_tolerance = 1e-14;
  o.max_classical_iterations = 200000;
  return o;
}

TEST(BetweenBodies, RowsBetweenBodiesWidenTheHessiansPatternOnly) {
  const TwoBlocks blocks(4, 4, 3);
  const ModifiedLagrangian phi(blocks.problem, 1.0);
  // Each row couples an upper node's u_y with its partner's, which A does not: 5 rows, each
  // adding the two entries (p, q) and (q, p).
  EXPECT_EQ(phi.hessian_pattern().nonZeros(), blocks.problem.A.nonZeros() + 2 * 5);
  // A body against an obstacle keeps A's pattern, A itself.
  const ContactProblem& paper = testing::paper_model(20).problem;
  const ModifiedLagrangian obstacle(paper, 1.0);
  EXPECT_EQ(&obstacle.hessian_pattern(), &paper.A);
  // H = A + r N^T diag(h on the active set) N, entry by entry, against the product.
  ActiveSet all(5, true);
  SparseMatrix H;
  phi.hessian(all, H);
  const SparseMatrix& N = blocks.problem.contact.N;
  const Matrix expected = Matrix(blocks.problem.A) +
                          Matrix(N.transpose() * blocks.problem.contact.weights.asDiagonal() * N);
  EXPECT_LT((Matrix(H) - expected).norm(), 1e-12 * expected.norm());
}

TEST(BetweenBodies, MatchingNodesGiveTheUniformPressureOnEveryHostPath) {
  const TwoBlocks blocks(6, 6, 4);
  const double p = TwoBlocks::pressure();
  for (const Way& w : kWays) {
    SCOPED_TRACE(w.name);
    const ContactResult r = solve_contact(blocks.problem, options_of(w));
    ASSERT_TRUE(r.summary.converged()) << r.summary.message;
    EXPECT_LT(r.summary.kkt.max(), 1e-8);
    // The multipliers are the pressure at every node, to round-off (the patch test).
    EXPECT_LT((r.l.array() - p).abs().maxCoeff(), 1e-8 * p) << r.l.transpose();
    // The interface moves down by the lower block's shortening.
    const Vector u = blocks.dofs.expand(r.u);
    const double lower_shortening = p * (1.0 - kLower.nu * kLower.nu) / kLower.E;
    for (Index i = 0; i <= blocks.nx; ++i)
      EXPECT_NEAR(u(2 * blocks.lower(i, blocks.ny) + 1), -lower_shortening, 1e-10);
  }
}

TEST(BetweenBodies, MultigridOnTheBackendTakesEachBodysRigidModes) {
  const TwoBlocks blocks(8, 8, 8);
  const DofMap& dofs = blocks.dofs;
  // The near-null space: the rigid motions of each body apart (3 per body in 2D), zero on the
  // other body; the aggregates never cross, as A does not couple the bodies.
  const Index n = dofs.num_free();
  Matrix B = Matrix::Zero(n, 6);
  std::vector<Index> node_of(static_cast<std::size_t>(n));
  const Index lower_nodes = (blocks.nx + 1) * (blocks.ny + 1);
  for (Index node = 0; node < blocks.mesh.num_nodes(); ++node) {
    const Index body = node < lower_nodes ? 0 : 3;
    const auto x = blocks.mesh.node(node);
    for (int k = 0; k < 2; ++k)
      if (const Index f = dofs.free_index(node, k); f >= 0) {
        node_of[static_cast<std::size_t>(f)] = node;
        B(f, body + k) = 1.0;
        B(f, body + 2) = k == 0 ? -x(1) : x(0);
      }
  }
  SmoothedAggregationOptions sa;
  sa.max_coarse_unknowns = 40;
  const MultigridHierarchy levels =
      smoothed_aggregation_hierarchy(blocks.problem.A, B, node_of, sa);
  ASSERT_GE(levels.prolongations.size(), 1U);
  ContactSolverOptions o;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.preconditioner = PreconditionerType::Multigrid;
  o.linear.cg_tolerance = 1e-13;
  o.uzawa_tolerance = 1e-12;
  for (const ContactMethod method : {ContactMethod::UzawaGnm, ContactMethod::SemismoothNewton}) {
    o.method = method;
    const ContactResult r = solve_contact(blocks.problem, o, &levels);
    ASSERT_TRUE(r.summary.converged()) << r.summary.message;
    EXPECT_EQ(r.summary.path, SolvePath::Backend);
    EXPECT_LT((r.l.array() - TwoBlocks::pressure()).abs().maxCoeff(), 1e-7 * TwoBlocks::pressure());
  }
}

TEST(BetweenBodies, NonMatchingNodesAgreeAcrossMethodsAndBalanceTheLoad) {
  // 5 upper edges over 3 lower ones: each upper node's partner point lies inside a lower edge,
  // and neighbouring rows share the lower nodes (the rows' dofs overlap).
  const TwoBlocks blocks(3, 5, 3);
  std::vector<ContactResult> results;
  for (const Way& w : kWays) {
    if (w.method == ContactMethod::SemismoothNewton) continue;  // (refused: below)
    SCOPED_TRACE(w.name);
    results.push_back(solve_contact(blocks.problem, options_of(w)));
    const ContactResult& r = results.back();
    ASSERT_TRUE(r.summary.converged()) << r.summary.message;
    EXPECT_LT(r.summary.kkt.max(), 1e-8);
    EXPECT_LT(testing::relative_difference(r.u, results.front().u), 1e-8);
    EXPECT_LT(testing::relative_difference(r.l, results.front().l), 1e-7);
  }
  // The contact forces carry the load: their sum is the force that holds the top down, the
  // reaction at the upper block's top, (K u)_y summed over its nodes.
  const ContactResult& r = results.front();
  const Vector force = internal_forces(blocks.mesh, blocks.elasticity, blocks.dofs.expand(r.u));
  double top = 0.0;
  for (Index i = 0; i <= blocks.mx; ++i) top += force(2 * blocks.upper(i, blocks.ny) + 1);
  const double contact = blocks.problem.contact.weights.dot(r.l);
  EXPECT_NEAR(-top, contact, 1e-9 * contact);
  // Semismooth Newton makes each row's normal displacement one unknown: rows that share dofs
  // cannot be rotated apart, and it says so.
  const ContactSolverOptions o = options_of(kWays[5]);
  EXPECT_CONTAINS(testing::input_error_of([&] { (void)solve_contact(blocks.problem, o); }),
                  "touch the same dofs");
}

TEST(BetweenBodies, TrescaFrictionAgreesWithTheKktSystemsSemismoothNewton) {
  // The materials differ, so the blocks' sides expand apart: with a low slip bound the interface
  // slips near the sides and sticks in the middle. Tangential rows between the bodies likewise,
  // (T x)_j = u_x at the node - u_x at its partner.
  TwoBlocks blocks(6, 6, 4);
  ContactSet& c = blocks.problem.contact;
  std::vector<Eigen::Triplet<double, int>> t;
  for (Index j = 0; j <= blocks.mx; ++j) {
    if (const Index f = blocks.dofs.free_index(blocks.upper(j, 0), 0); f >= 0)
      t.emplace_back(static_cast<int>(j), static_cast<int>(f), 1.0);
    if (const Index f = blocks.dofs.free_index(blocks.lower(j, blocks.ny), 0); f >= 0)
      t.emplace_back(static_cast<int>(j), static_cast<int>(f), -1.0);
  }
  SparseMatrix T(blocks.mx + 1, blocks.dofs.num_free());
  T.setFromTriplets(t.begin(), t.end());
  const ContactProblem frictionless = blocks.problem;
  add_tangential_rows(c, T);
  const Vector bound = Vector::Constant(blocks.mx + 1, 0.02 * TwoBlocks::pressure());
  const FrictionLaw law(FrictionKind::Tresca, 2, bound);
  const FrictionSsnResult reference =
      solve_friction_ssn(frictionless, T, {FrictionKind::Tresca, bound});
  ASSERT_TRUE(reference.converged);
  for (const bool condensed : {true, false}) {
    ContactSolverOptions o;
    o.schur_complement = condensed;
    o.uzawa_tolerance = 1e-13;
    const ContactResult r = solve_contact(testing::with_law(blocks.problem, law), o);
    ASSERT_TRUE(r.summary.converged()) << r.summary.message;
    EXPECT_LT(testing::relative_difference(r.u, reference.u), 1e-8);
    EXPECT_LT(testing::relative_difference(r.tangential.row(0).transpose(),
                                           reference.force.row(1).transpose()),
              1e-7);
    // Some nodes slip (at the bound), some stick (inside it).
    const Vector tangential = r.tangential.row(0).transpose().cwiseAbs();
    EXPECT_GT((tangential.array() > bound.array() * (1 - 1e-8)).count(), 0);
    EXPECT_GT((tangential.array() < bound.array() * 0.99).count(), 0);
  }
}

TEST(BetweenBodies, TheDistributedPathRefusesRowsBetweenBodies) {
  ContactSolverOptions o;
  EXPECT_CONTAINS(testing::input_error_of([&] {
                    (void)method_row(SolvePath::Distributed, ContactMethod::UzawaGnm,
                                     LawKind::Unilateral, "unilateral", o,
                                     InterfaceKind::BetweenBodies);
                  }),
                  "in one process so far");
  EXPECT_EQ(method_row(SolvePath::SparseDirect, ContactMethod::UzawaGnm, LawKind::Unilateral,
                       "unilateral", o, InterfaceKind::BetweenBodies)
                .path,
            SolvePath::SparseDirect);
}

}  // namespace
}  // namespace signorini
