#pragma once
// The same contact problem solved by several methods, for the tests that check that the methods
// agree: each must converge with KKT residuals below 1e-8.

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/problem/model.hpp"

namespace signorini::testing {

/// Solves `model` with `options` by each method in turn into `results`. Call it inside
/// ASSERT_NO_FATAL_FAILURE: a method that does not converge stops the test.
inline void solve_by_each(const Model& model, ContactSolverOptions options,
                          std::initializer_list<ContactMethod> methods,
                          std::vector<ContactResult>& results) {
  for (const ContactMethod method : methods) {
    SCOPED_TRACE(std::string(enum_to_string(kContactMethodNames, method)));
    options.method = method;
    results.push_back(solve_contact(model.problem, options, &model.multigrid));
    ASSERT_TRUE(results.back().summary.converged()) << results.back().summary.message;
    EXPECT_LT(results.back().summary.kkt.max(), 1e-8);
  }
}

/// Every result equals the first: u to u_tolerance and l to l_tolerance, relative 2-norms.
inline void expect_same_solution(const std::vector<ContactResult>& results, double u_tolerance,
                                 double l_tolerance) {
  for (std::size_t i = 1; i < results.size(); ++i) {
    EXPECT_LT((results[i].u - results[0].u).norm(), u_tolerance * results[0].u.norm()) << i;
    EXPECT_LT((results[i].l - results[0].l).norm(), l_tolerance * results[0].l.norm()) << i;
  }
}

}  // namespace signorini::testing
