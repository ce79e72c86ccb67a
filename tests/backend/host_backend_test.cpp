// The CPU backend's kernels against Eigen (the reference the CUDA backend is compared with in
// tests/backend/cuda_backend_gpu_test.cpp), and its memory accounting.

#include "signorini/backend/host_backend.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace signorini {
namespace {

TEST(HostBackend, KernelsMatchEigen) {
  HostBackend be;
  const Index n = 1001;
  const Vector x = Vector::LinSpaced(n, -1.0, 1.0).array().sin();
  const Vector y = Vector::LinSpaced(n, 0.5, 3.0);
  DeviceVector dx = to_device(be, x), dy = to_device(be, y), dz(be, n);
  EXPECT_NEAR(be.dot(dx, dy), x.dot(y), 1e-14 * std::abs(x.dot(y)));
  be.axpbyz(2.0, dx, -3.0, dy, dz);
  EXPECT_LT((to_host(dz) - (2.0 * x - 3.0 * y)).norm(), 1e-13);
  be.axpby(0.5, dx, 2.0, dy);  // y = 0.5 x + 2 y
  EXPECT_LT((to_host(dy) - (0.5 * x + 2.0 * y)).norm(), 1e-13);
  be.multiply(dx, dx, dz);
  EXPECT_LT((to_host(dz) - x.cwiseAbs2()).norm(), 1e-14);
  DeviceVector dr = to_device(be, y);
  be.reciprocal(dr, dr);
  EXPECT_LT((to_host(dr) - y.cwiseInverse()).norm(), 1e-14);
  be.fill(dz, 4.0);
  EXPECT_EQ(to_host(dz), Vector::Constant(n, 4.0));
  be.copy(dx, dz);
  EXPECT_EQ(to_host(dz), x);
}

TEST(HostBackend, SparseAndDenseProducts) {
  HostBackend be;
  SparseMatrix A(3, 4);
  A.insert(0, 0) = 1.0;
  A.insert(0, 3) = 2.0;
  A.insert(2, 1) = -1.0;
  A.makeCompressed();
  const Vector x = Vector::LinSpaced(4, 1.0, 4.0);
  const auto dA = be.upload(A);
  EXPECT_EQ(dA->rows(), 3);
  EXPECT_EQ(dA->nonzeros(), 3);
  DeviceVector y(be, 3);
  be.fill(y, std::numeric_limits<double>::quiet_NaN());
  be.spmv(*dA, to_device(be, x), y);  // beta = 0 ignores y, NaN or not
  EXPECT_EQ(to_host(y), Vector(A * x));
  be.spmv(*dA, to_device(be, x), y, 2.0, 1.0);
  EXPECT_EQ(to_host(y), Vector(3.0 * (A * x)));
  const Matrix D = Matrix::Random(3, 4);
  const auto dD = be.upload(D);
  be.gemv(*dD, to_device(be, x), y);
  EXPECT_LT((to_host(y) - D * x).norm(), 1e-14);
}

TEST(HostBackend, TransposeFromTheColumnArraysCopiedOrShared) {
  HostBackend be;
  SparseMatrix P(4, 3);  // a rectangular "prolongation": its transpose is the restriction
  P.insert(0, 0) = 1.0;
  P.insert(1, 0) = 0.5;
  P.insert(1, 1) = 0.5;
  P.insert(2, 1) = 1.0;
  P.insert(3, 2) = -2.0;
  P.makeCompressed();
  const Vector r = Vector::LinSpaced(4, 1.0, 4.0);
  const auto copied = be.upload_transpose(P, HostArrays::Copy);
  const auto shared = be.upload_transpose(P, HostArrays::Share);
  EXPECT_EQ(copied->rows(), 3);
  EXPECT_EQ(shared->cols(), 4);
  DeviceVector y(be, 3);
  be.spmv(*copied, to_device(be, r), y);
  EXPECT_EQ(to_host(y), Vector(P.transpose() * r));
  be.spmv(*shared, to_device(be, r), y);
  EXPECT_EQ(to_host(y), Vector(P.transpose() * r));
  // The shared one multiplies by P's own arrays (no copy): a change of P shows in it at once.
  P.valuePtr()[0] = 3.0;
  be.spmv(*shared, to_device(be, r), y);
  EXPECT_EQ(to_host(y), Vector(P.transpose() * r));
  be.spmv(*copied, to_device(be, r), y);
  EXPECT_EQ(to_host(y)(0), 1.0 * r(0) + 0.5 * r(1));
  // Large enough for the threaded product: a symmetric tridiagonal matrix shared as itself.
  const Index n = 30000;
  SparseMatrix T(n, n);
  std::vector<Eigen::Triplet<double>> t;
  for (Index i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + 1e-4 * static_cast<double>(i));
    if (i > 0) {
      t.emplace_back(i, i - 1, -1.0);
      t.emplace_back(i - 1, i, -1.0);
    }
  }
  T.setFromTriplets(t.begin(), t.end());
  const Vector x = Vector::LinSpaced(n, -1.0, 1.0).array().cos();
  const auto dT = be.upload_symmetric(T, HostArrays::Share);
  DeviceVector ty(be, n);
  be.spmv(*dT, to_device(be, x), ty);
  EXPECT_LT((to_host(ty) - T * x).norm(), 1e-13 * (T * x).norm());
}

TEST(HostBackend, TransposedProductSmallAndThreaded) {
  HostBackend be;
  ASSERT_TRUE(be.has_transposed_product());
  for (const Index cols : {Index{7}, Index{50000}}) {  // below and above the threaded size
    const Index rows = cols / 3 + 2;
    std::vector<Eigen::Triplet<double>> t;
    for (Index i = 0; i < rows; ++i)
      for (Index k = 0; k < 5; ++k)
        t.emplace_back(i, (7 * i + 13 * k) % cols,
                       1.0 + 0.1 * static_cast<double>(k) - 0.01 * static_cast<double>(i));
    SparseMatrix R(rows, cols);
    R.setFromTriplets(t.begin(), t.end());
    const auto dR = be.upload(R);
    const Vector x = Vector::LinSpaced(rows, -2.0, 3.0);
    const Vector y0 = Vector::LinSpaced(cols, 1.0, 0.0);
    DeviceVector y = to_device(be, y0);
    be.spmv_transpose(*dR, to_device(be, x), y, 0.5, 2.0);
    const Vector expected = 0.5 * (R.transpose() * x) + 2.0 * y0;
    EXPECT_LT((to_host(y) - expected).norm(), 1e-13 * expected.norm()) << cols;
    be.fill(y, std::numeric_limits<double>::quiet_NaN());
    be.spmv_transpose(*dR, to_device(be, x), y);  // beta = 0 ignores y, NaN or not
    EXPECT_LT((to_host(y) - R.transpose() * x).norm(), 1e-13 * (R.transpose() * x).norm());
  }
}

TEST(HostBackend, ChebyshevUpdateIgnoresStaleDirectionWhenAIsZero) {
  HostBackend be;
  const Vector dinv = Vector::Constant(5, 0.5), r = Vector::LinSpaced(5, 1.0, 5.0);
  DeviceVector d(be, 5), x = to_device(be, Vector::Ones(5));
  be.fill(d, std::numeric_limits<double>::quiet_NaN());
  be.chebyshev_update(0.0, 2.0, to_device(be, dinv), to_device(be, r), d, x);
  EXPECT_EQ(to_host(d), r);  // 2 * 0.5 * r
  EXPECT_EQ(to_host(x), Vector(Vector::Ones(5) + r));
  be.chebyshev_update(1.0, 1.0, to_device(be, dinv), to_device(be, r), d, x);
  EXPECT_EQ(to_host(d), Vector(1.5 * r));
}

TEST(HostBackend, RecordedWorkReadsTheVectorsAsTheyAreAtReplay) {
  // As the multigrid cycle needs: recorded once, replayed on a new right-hand side each time.
  HostBackend be;
  DeviceVector x = to_device(be, Vector::Ones(10)), y(be, 10);
  auto recorded = be.record([&] { be.axpbyz(2.0, x, 0.0, x, y); });  // y = 2 x
  upload_into(Vector::Constant(10, 5.0), x);
  recorded->replay();
  EXPECT_EQ(to_host(y), Vector::Constant(10, 10.0));
  upload_into(Vector::Constant(10, -1.0), x);
  recorded->replay();
  EXPECT_EQ(to_host(y), Vector::Constant(10, -2.0));
  EXPECT_FALSE(recorded->is_graph());
  EXPECT_FALSE(recorded->ran_while_recording());
  EXPECT_FALSE(recorded->why_not_graph().empty());
}

TEST(HostBackend, CountsTheMemoryItHolds) {
  HostBackend be;
  EXPECT_EQ(be.bytes_in_use(), 0U);
  {
    DeviceVector a(be, 100), b(be, 50);
    EXPECT_EQ(be.bytes_in_use(), 150U * sizeof(double));
    DeviceVector c = std::move(a);
    EXPECT_EQ(be.bytes_in_use(), 150U * sizeof(double));
  }
  EXPECT_EQ(be.bytes_in_use(), 0U);
  EXPECT_EQ(be.peak_bytes(), 150U * sizeof(double));
  {  // matrices count as their CSR arrays (as on a GPU)
    SparseMatrix A(10, 10);
    A.setIdentity();
    const auto dA = be.upload(A);
    EXPECT_EQ(be.bytes_in_use(), 11 * sizeof(int) + 10 * (sizeof(int) + sizeof(double)));
    const auto dD = be.upload(Matrix(Matrix::Zero(3, 4)));
    EXPECT_EQ(be.bytes_in_use(), 11 * sizeof(int) + 10 * (sizeof(int) + sizeof(double)) + 96);
  }
  EXPECT_EQ(be.bytes_in_use(), 0U);
}

}  // namespace
}  // namespace signorini
