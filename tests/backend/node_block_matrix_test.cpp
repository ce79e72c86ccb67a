// The node-block form of the CPU's large square matrices against Eigen's CSR products.

#include "signorini/backend/node_block_matrix.hpp"

#include <gtest/gtest.h>

#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "signorini/backend/host_backend.hpp"

namespace signorini {
namespace {

using Csr = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// A matrix with the pattern of a node graph: node a has `width[a]` consecutive unknowns (as
// free dofs do, some components clamped), nodes a and b couple when |a - b| <= 2, and with
// `far` node 0 with the last node too (a band as wide as the matrix: the upper blocks of the
// first rows reach every thread's rows); entry (i, j) is value(i, j).
template <class Value>
Csr node_graph_matrix(const std::vector<int>& width, Value value, bool far) {
  std::vector<int> start(width.size() + 1, 0);
  for (std::size_t a = 0; a < width.size(); ++a) start[a + 1] = start[a] + width[a];
  std::vector<Eigen::Triplet<double>> t;
  const auto nodes = static_cast<int>(width.size());
  const auto couple = [&](int a, int b) {
    for (int i = start[a]; i < start[a + 1]; ++i)
      for (int j = start[b]; j < start[b + 1]; ++j)
        t.emplace_back(i, j, value(i, j) + (i == j ? 10.0 : 0.0));
  };
  for (int a = 0; a < nodes; ++a)
    for (int b = std::max(0, a - 2); b <= std::min(nodes - 1, a + 2); ++b) couple(a, b);
  if (far) {
    couple(0, nodes - 1);
    couple(nodes - 1, 0);
  }
  Csr A(start.back(), start.back());
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

// Values arbitrary (not symmetric), the pattern symmetric.
Csr node_matrix(const std::vector<int>& width) {
  return node_graph_matrix(
      width, [](int i, int j) { return 1.0 + 0.01 * i - 0.003 * j; }, false);
}

// Symmetric values.
Csr symmetric_node_matrix(const std::vector<int>& width, bool far = false) {
  return node_graph_matrix(
      width, [](int i, int j) { return 1.0 + 0.01 * (i + j) + 1e-4 * i * j; }, far);
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

TEST(NodeBlockMatrix, UpperBlocksOfASymmetricMatrixGiveItsProducts) {
  // Every thread count from one to five (runs of row groups whose transposed blocks reach into
  // the rows of one, several or all later runs), with and without a far coupling.
  for (const bool far : {false, true}) {
    const Csr A = symmetric_node_matrix(widths(60), far);
    ASSERT_LT((Csr(A.transpose()) - A).norm(), 1e-14 * A.norm());
    const auto full =
        NodeBlockMatrix::from_csr(A.rows(), A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr());
    const auto upper = NodeBlockMatrix::from_symmetric_csr(A.rows(), A.outerIndexPtr(),
                                                           A.innerIndexPtr(), A.valuePtr());
    ASSERT_TRUE(full.has_value());
    ASSERT_TRUE(upper.has_value());
    EXPECT_FALSE(full->symmetric());
    EXPECT_TRUE(upper->symmetric());
    EXPECT_EQ(upper->size(), A.rows());
    EXPECT_EQ(upper->num_groups(), 60);
    // Nodes couple with up to two on each side: the upper blocks are the diagonal one and up to
    // two more, about three in five of all, and fewer bytes by as much.
    EXPECT_EQ(upper->num_blocks(), (full->num_blocks() + 60) / 2);
    EXPECT_LT(upper->bytes(), full->bytes() * 7 / 10);
    const Vector x = Vector::LinSpaced(A.rows(), -1.0, 2.0).array().sin();
    const Vector y0 = Vector::LinSpaced(A.rows(), 3.0, 1.0);
    const Vector expected = 2.0 * (A * x) - 0.5 * y0;
#ifdef _OPENMP
    const int threads_before = omp_get_max_threads();
    for (int threads = 1; threads <= 5; ++threads) {
      omp_set_num_threads(threads);
#endif
      for (const bool parallel : {false, true}) {
        Vector y = y0;
        upper->multiply(x.data(), y.data(), 2.0, -0.5, parallel);
        EXPECT_LT((y - expected).norm(), 1e-13 * expected.norm()) << parallel << far;
        y.setConstant(std::numeric_limits<double>::quiet_NaN());
        upper->multiply(x.data(), y.data(), 1.0, 0.0, parallel);  // beta = 0 ignores y
        EXPECT_LT((y - A * x).norm(), 1e-13 * (A * x).norm()) << parallel << far;
      }
#ifdef _OPENMP
    }
    omp_set_num_threads(threads_before);
#endif
    Vector yt = y0;
    upper->multiply_transpose(x.data(), yt.data(), 1.5, 2.0);  // A^T = A
    const Vector expected_t = 1.5 * (A * x) + 2.0 * y0;
    EXPECT_LT((yt - expected_t).norm(), 1e-13 * expected_t.norm());
  }
}

TEST(NodeBlockMatrix, UpperBlocksFormTheSymmetricPartOfANearlySymmetricMatrix) {
  // A matrix symmetric up to rounding (a Galerkin product): the product is that of the matrix
  // whose lower blocks mirror the upper ones, exactly symmetric.
  Csr A = symmetric_node_matrix(widths(30));
  for (int i = 0; i < A.rows(); ++i)
    for (Csr::InnerIterator it(A, i); it; ++it)
      if (it.col() < i) it.valueRef() *= 1.0 + 1e-12;
  const auto upper = NodeBlockMatrix::from_symmetric_csr(A.rows(), A.outerIndexPtr(),
                                                         A.innerIndexPtr(), A.valuePtr());
  ASSERT_TRUE(upper.has_value());
  const Csr U = A.triangularView<Eigen::Upper>();
  const Csr mirrored = Csr(U) + Csr(Csr(U.transpose()).triangularView<Eigen::StrictlyLower>());
  const Vector x = Vector::LinSpaced(A.rows(), 0.5, -1.5);
  Vector y(A.rows());
  upper->multiply(x.data(), y.data(), 1.0, 0.0, true);
  EXPECT_LT((y - mirrored * x).norm(), 1e-14 * (A * x).norm());
  EXPECT_GT((y - A * x).norm(), 1e-14 * (A * x).norm());  // not A's own lower entries
  // Exactly symmetric: e_i' (A e_j) = e_j' (A e_i) to the last bit, within the diagonal blocks
  // of the first rows and between them.
  Vector ei = Vector::Zero(A.rows()), ej = ei, Aei(A.rows()), Aej(A.rows());
  for (int i = 0; i < 9; ++i)
    for (int j = i + 1; j < 12; ++j) {
      ei.setZero();
      ej.setZero();
      ei[i] = 1.0;
      ej[j] = 1.0;
      upper->multiply(ei.data(), Aei.data(), 1.0, 0.0, false);
      upper->multiply(ej.data(), Aej.data(), 1.0, 0.0, false);
      EXPECT_EQ(Aei[j], Aej[i]) << i << " " << j;
    }
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
  // the matrix multiplied in place (HostArrays::Share), which stays CSR; a symmetric one's copy
  // holds the upper blocks only.
  const SparseMatrix A = node_matrix(widths(12000));  // some 33,000 unknowns
  ASSERT_GT(A.rows(), 20000);
  HostBackend be;
  const auto copied = be.upload_transpose(A, HostArrays::Copy);
  const auto shared = be.upload_transpose(A, HostArrays::Share);
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

  const SparseMatrix S = symmetric_node_matrix(widths(12000));
  const auto symmetric = be.upload_symmetric(S, HostArrays::Copy);
  const auto in_place = be.upload_symmetric(S, HostArrays::Share);
  const Vector Sx = S * x;
  be.spmv(*symmetric, to_device(be, x), y1);
  be.spmv(*in_place, to_device(be, x), y2);
  EXPECT_LT((to_host(y1) - Sx).norm(), 1e-13 * Sx.norm());
  EXPECT_LT((to_host(y2) - Sx).norm(), 1e-13 * Sx.norm());
  be.spmv_transpose(*symmetric, to_device(be, x), y1);
  EXPECT_LT((to_host(y1) - Sx).norm(), 1e-13 * Sx.norm());
}

}  // namespace
}  // namespace signorini
