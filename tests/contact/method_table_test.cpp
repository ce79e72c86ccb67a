// What runs where (src/signorini/contact/method_table.hpp): every path, method and kind of law
// has either one row or a refusal that says what to use; the rows are the ones the solver runs.

#include "signorini/contact/method_table.hpp"

#include <gtest/gtest.h>

#include <string>

#include "signorini/contact/friction_law.hpp"
#include "signorini/core/error.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

constexpr SolvePath kPaths[] = {SolvePath::CondensedDirect, SolvePath::SparseDirect,
                                SolvePath::Iterative, SolvePath::Backend, SolvePath::Distributed};
constexpr ContactMethod kMethods[] = {ContactMethod::UzawaGnm, ContactMethod::ClassicalUzawa,
                                      ContactMethod::SemismoothNewton};
constexpr LawKind kKinds[] = {LawKind::Unilateral, LawKind::OtherScalar, LawKind::Frictional};

std::string refusal(SolvePath path, ContactMethod method, LawKind kind) {
  try {
    (void)method_row(path, method, kind, "a law", ContactSolverOptions{});
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(MethodTable, EveryCombinationRunsOneRowOrIsRefusedWithAReason) {
  int rows = 0, refused = 0;
  for (const SolvePath path : kPaths)
    for (const ContactMethod method : kMethods)
      for (const LawKind kind : kKinds) {
        const std::string why = refusal(path, method, kind);
        if (why.empty()) {
          const MethodRow& row = method_row(path, method, kind, "a law", {});
          EXPECT_EQ(row.path, path);
          EXPECT_EQ(row.method, method);
          EXPECT_TRUE(row.takes(kind));
          EXPECT_NE(row.run, nullptr);
          ++rows;
        } else {
          // (Every refusal names what runs instead.)
          EXPECT_NE(why.find("\"uzawa_gnm\""), std::string::npos) << why;
          ++refused;
        }
      }
  // Uzawa-GNM runs every law everywhere; classical Uzawa everywhere but the backend path;
  // semismooth Newton the unilateral law everywhere and friction on the host's sparse paths.
  EXPECT_EQ(rows, 5 * 3 + 4 * 3 + 5 + 2);
  EXPECT_EQ(refused, 5 * 3 * 3 - rows);
}

TEST(MethodTable, RefusalsSayWhy) {
  const auto has = [](const std::string& text, const char* part) {
    return text.find(part) != std::string::npos;
  };
  EXPECT_TRUE(has(refusal(SolvePath::Backend, ContactMethod::ClassicalUzawa, LawKind::Unilateral),
                  "the multigrid preconditioner runs \"uzawa_gnm\" and \"semismooth_newton\""));
  EXPECT_TRUE(
      has(refusal(SolvePath::SparseDirect, ContactMethod::SemismoothNewton, LawKind::OtherScalar),
          "solves the unilateral contact law only, not \"a law\""));
  EXPECT_TRUE(
      has(refusal(SolvePath::Distributed, ContactMethod::SemismoothNewton, LawKind::Frictional),
          "in one process, not on the distributed path"));
  EXPECT_TRUE(has(refusal(SolvePath::Backend, ContactMethod::SemismoothNewton, LawKind::Frictional),
                  "on the host's sparse paths"));
  // Semismooth Newton with friction leaves the condensed path for the sparse direct one.
  EXPECT_EQ(
      table_path(SolvePath::CondensedDirect, ContactMethod::SemismoothNewton, LawKind::Frictional),
      SolvePath::SparseDirect);
  EXPECT_EQ(table_path(SolvePath::CondensedDirect, ContactMethod::UzawaGnm, LawKind::Frictional),
            SolvePath::CondensedDirect);
}

TEST(MethodTable, TheLawKindIsTheLawsOwn) {
  EXPECT_EQ(law_kind(unilateral_contact_law()), LawKind::Unilateral);
  const UnilateralContactLaw another;  // the same law by another object: not the paper's own
  EXPECT_EQ(law_kind(another), LawKind::OtherScalar);
  const FrictionLaw tresca(FrictionKind::Tresca, 2, Vector::Ones(3));
  EXPECT_EQ(law_kind(tresca), LawKind::Frictional);
}

}  // namespace
}  // namespace signorini
