// The cell checks of the stiffness assembly (fem/elasticity_assembly.hpp): require_valid_cells
// finds an inverted cell without assembling, with the assembly's own message.

#include "signorini/fem/elasticity_assembly.hpp"

#include <gtest/gtest.h>

#include "signorini/core/error.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

// Two unit squares side by side; the second numbered clockwise when `inverted`.
Mesh two_squares(bool inverted) {
  Eigen::MatrixXd x(2, 6);
  x << 0, 1, 2, 0, 1, 2,  //
      0, 0, 0, 1, 1, 1;
  std::vector<Index> cells = {0, 1, 4, 3, 1, 2, 5, 4};
  if (inverted) std::swap(cells[5], cells[7]);
  return Mesh({CellType::Quad4, CellType::Quad4}, x, cells);
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RequireValidCells, FindsTheInvertedCellAsTheAssemblyDoes) {
  ElasticityOptions options;
  EXPECT_NO_THROW(require_valid_cells(two_squares(false), options));
  const Mesh bad = two_squares(true);
  const DofMap dofs = make_dof_map(bad, {});
  const std::string checked = message_of([&] { require_valid_cells(bad, options); });
  const std::string assembled = message_of([&] { (void)assemble_stiffness(bad, dofs, options); });
  EXPECT_NE(checked.find("mesh cell 1 (quad4, nodes 1 4 5 2): inverted or degenerate quad4"),
            std::string::npos)
      << checked;
  EXPECT_EQ(checked, assembled);
}

}  // namespace
}  // namespace signorini
