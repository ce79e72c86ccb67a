// The CPU backend's kernels against Eigen (the reference the CUDA backend is compared with in
// tests/backend/cuda_backend_gpu_test.cpp), and its memory accounting.

#include "signorini/backend/host_backend.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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
