// The node-block form of the CPU's large square matrices against Eigen's CSR products.

#include "signorini/backend/node_block_matrix.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "signorini/backend/host_backend.hpp"

namespace signorini {
namespace {

using Csr = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// A matrix with the pattern of a node graph: node a has `width[a]` consecutive unknowns (as
// free dofs do, some components clamped), nodes a and b couple when |a - b| <= 2; values
// arbitrary (not symmetric), the pattern symmetric.
Csr node_matrix(const std::vector<int>& width) {
  std::vector<int> start(width.size() + 1, 0);
  for (std::size_t a = 0; a < width.size(); ++a) start[a + 1] = start[a] + width[a];
  std::vector<Eigen::Triplet<double>> t;
  const auto nodes = static_cast<int>(width.size());
  for (int a = 0; a < nodes; ++a)
    for (int b = std::max(0, a - 2); b <= std::min(nodes - 1, a + 2); ++b)
      for (int i = start[a]; i < start[a + 1]; ++i)
        for (int j = start[b]; j < start[b + 1]; ++j)
          t.emplace_back(i, j, 1.0 + 0.01 * i - 0.003 * j + (i == j ? 10.0 : 0.0));
  Csr A(start.back(), start.back());
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

std::vector<int> widths(int nodes) {
  std::vector<int> w(static_cast<std::size_t>(nodes), 3);
  for (int a = 0; a < nodes; a += 7) w[static_cast<std::size_t>(a)] = 2;  // a clamped component
  for (int a = 3; a < nodes; a += 11) w[static_cast<std::size_t>(a)] = 1;
  return w;
}

TEST(NodeBlockMatrix, ProductsMatchCsr) {
  const Csr A = node_matrix(widths(40));
  const auto blocks =
      NodeBlockMatrix::from_csr(A.rows(), A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr());
  ASSERT_TRUE(blocks.has_value());
  EXPECT_EQ(blocks->size(), A.rows());
  EXPECT_EQ(blocks->num_groups(), 40);  // one group per node
  EXPECT_LT(blocks->bytes(), static_cast<std::size_t>(A.nonZeros()) * 12);
  const Vector x = Vector::LinSpaced(A.rows(), -1.0, 2.0).array().sin();
  const Vector y0 = Vector::LinSpaced(A.rows(), 3.0, 1.0);
  for (const bool parallel : {false, true}) {
    Vector y = y0;
    blocks->multiply(x.data(), y.data(), 2.0, -0.5, parallel);
    const Vector expected = 2.0 * (A * x) - 0.5 * y0;
    EXPECT_LT((y - expected).norm(), 1e-13 * expected.norm());
    y.setConstant(std::numeric_limits<double>::quiet_NaN());
    blocks->multiply(x.data(), y.data(), 1.0, 0.0, parallel);  // beta = 0 ignores y
    EXPECT_LT((y - A * x).norm(), 1e-13 * (A * x).norm());
  }
  Vector yt = y0;
  blocks->multiply_transpose(x.data(), yt.data(), 1.5, 2.0);
  const Vector expected_t = 1.5 * (A.transpose() * x) + 2.0 * y0;
  EXPECT_LT((yt - expected_t).norm(), 1e-13 * expected_t.norm());
}

TEST(NodeBlockMatrix, RefusesPatternsThatAreNotWholeBlocks) {
  Csr A = node_matrix(std::vector<int>(10, 3));
  // One entry more, coupling a single unknown of node 0 with one of node 9: node blocks no more.
  A.coeffRef(0, 27) = 1.0;
  A.makeCompressed();
  EXPECT_FALSE(
      NodeBlockMatrix::from_csr(A.rows(), A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr()));
  // Groups of one (no two consecutive rows alike) save nothing over CSR.
  Csr D(5, 5);
  for (int i = 0; i < 5; ++i) D.insert(i, i) = 1.0 + i;
  D.insert(0, 1) = 2.0;
  D.makeCompressed();
  EXPECT_FALSE(
      NodeBlockMatrix::from_csr(D.rows(), D.outerIndexPtr(), D.innerIndexPtr(), D.valuePtr()));
}

TEST(NodeBlockMatrix, TheCpuBackendCopiesLargeSquareMatricesInBlocks) {
  // Above the threaded size the CPU backend's copy takes the block form: the same products as
  // the matrix multiplied in place (HostArrays::Share), which stays CSR.
  const SparseMatrix A = node_matrix(widths(12000));  // some 33,000 unknowns
  ASSERT_GT(A.rows(), 20000);
  HostBackend be;
  const auto copied = be.upload_symmetric(A, HostArrays::Copy);
  const auto shared = be.upload_symmetric(A, HostArrays::Share);
  const Vector x = Vector::LinSpaced(A.rows(), -1.0, 1.0).array().cos();
  DeviceVector y1(be, A.rows()), y2(be, A.rows());
  be.spmv(*copied, to_device(be, x), y1);
  be.spmv(*shared, to_device(be, x), y2);
  // Shared multiplies by A^T's CSR arrays = A's CSC ones; the copy, by blocks of A^T too.
  const Vector expected = A.transpose() * x;
  EXPECT_LT((to_host(y1) - expected).norm(), 1e-13 * expected.norm());
  EXPECT_LT((to_host(y2) - expected).norm(), 1e-13 * expected.norm());
  be.spmv_transpose(*copied, to_device(be, x), y1);
  EXPECT_LT((to_host(y1) - A * x).norm(), 1e-13 * (A * x).norm());
}

}  // namespace
}  // namespace signorini
