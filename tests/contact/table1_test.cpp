// The paper's Table 1 (method.md section 5 and "Conventions"): energies M(u*, l*) to the 7 digits
// the paper prints, GNM iterations at the first Uzawa step, and Uzawa iterations, exactly.
// The 480x160 row is checked by `signorini bench` / examples/paper.toml, not here (it is slower).

#include <gtest/gtest.h>

#include "test_problems.hpp"

namespace signorini {
namespace {

struct Table1Row {
  Index nx;
  Index n_dofs;
  Index n_contact;
  int gnm_first;
  int uzawa;
  double energy;
};

// Each row runs twice: on the condensed problem (the default) and on the plain sparse one.
class Table1 : public ::testing::TestWithParam<std::tuple<Table1Row, bool>> {};

TEST_P(Table1, EnergyAndIterationCountsMatchThePaper) {
  const auto [row, schur] = GetParam();
  const Model& model = testing::paper_model(row.nx);
  EXPECT_EQ(model.dofs.num_dofs(), row.n_dofs);
  EXPECT_EQ(model.problem.contact.size(), row.n_contact);

  ContactSolverOptions options;  // the paper's defaults, with its r (Section 5)
  options.r = 1e8;
  options.schur_complement = schur;
  const ContactResult res = solve_contact(model.problem, options);
  ASSERT_TRUE(res.summary.converged()) << res.summary.message;
  EXPECT_NEAR(res.summary.lagrangian, row.energy, 2e-7 * std::abs(row.energy));
  EXPECT_EQ(res.summary.inner_iterations().front(), row.gnm_first);
  EXPECT_EQ(res.summary.outer_iterations, row.uzawa);
  // At the solution M(u*, l*) = J(u*): the penalty term vanishes by complementarity.
  EXPECT_NEAR(res.summary.lagrangian, res.summary.energy, 1e-10 * std::abs(row.energy));
  // Later Uzawa steps need at most 3 GNM iterations (the paper: 2).
  for (std::size_t k = 1; k < res.summary.steps.size(); ++k)
    EXPECT_LE(res.summary.steps[k].inner_iterations, 3) << "Uzawa step " << k + 1;
}

INSTANTIATE_TEST_SUITE_P(
    Paper, Table1,
    ::testing::Combine(::testing::Values(Table1Row{60, 2562, 61, 7, 6, -6.700472e-05},
                                         Table1Row{120, 9922, 121, 8, 7, -6.711822e-05},
                                         Table1Row{240, 39042, 241, 9, 8, -6.714898e-05}),
                       ::testing::Bool()),
    [](const auto& param_info) {
      const Table1Row& r = std::get<0>(param_info.param);
      return std::to_string(r.nx) + "x" + std::to_string(r.nx / 3) +
             (std::get<1>(param_info.param) ? "_condensed" : "_plain");
    });

}  // namespace
}  // namespace signorini
