// The CUDA backend against the CPU reference (HostBackend): every kernel on random data, to 1e-12
// relative. Built into signorini_gpu_tests (label gpu); without a usable GPU every test skips and
// says why.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

#include "signorini/backend/backend.hpp"
#include "signorini/backend/cuda_backend.hpp"
#include "signorini/backend/host_backend.hpp"
#include "signorini/core/error.hpp"

namespace signorini {
namespace {

constexpr double kTolerance = 1e-12;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const std::vector<Index> kSizes{1, 1000, 100003};

Vector random_vector(Index n, std::mt19937_64& rng, double lo = -1.0, double hi = 1.0) {
  std::uniform_real_distribution<double> u(lo, hi);
  Vector v(n);
  for (Index i = 0; i < n; ++i) v[i] = u(rng);
  return v;
}

/// rows x cols with a diagonal (where there is one) and about `per_row` more entries a row; every
/// seventh row is left empty.
SparseMatrix random_sparse(Index rows, Index cols, int per_row, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<Index> column(0, std::max<Index>(cols - 1, 0));
  std::vector<Eigen::Triplet<double, int>> t;
  if (cols > 0) {
    for (Index i = 0; i < rows; ++i) {
      if (i % 7 == 3) continue;
      if (i < cols) t.emplace_back(static_cast<int>(i), static_cast<int>(i), 4.0 + u(rng));
      for (int k = 0; k < per_row; ++k)
        t.emplace_back(static_cast<int>(i), static_cast<int>(column(rng)), u(rng));
    }
  }
  SparseMatrix A(rows, cols);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

/// max |a - b| <= tol max |b|, and a is finite where b is.
void expect_close(const Vector& gpu, const Vector& host, double tol = kTolerance) {
  ASSERT_EQ(gpu.size(), host.size());
  for (Index i = 0; i < host.size(); ++i) {
    if (std::isfinite(host[i])) {
      ASSERT_TRUE(std::isfinite(gpu[i])) << "entry " << i << ": " << gpu[i] << " vs " << host[i];
    }
  }
  if (host.size() == 0) return;
  const double scale = std::max(host.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
  EXPECT_LE((gpu - host).cwiseAbs().maxCoeff(), tol * scale) << "size " << host.size();
}

class GpuBackend : public ::testing::Test {
 protected:
  void SetUp() override {
    const CudaReport report = cuda_report();
    if (report.gpus.empty()) GTEST_SKIP() << "no CUDA GPU: " << report.problem;
    gpu_ = make_cuda_backend(report.gpus.front().ordinal);
  }

  Backend& gpu() { return *gpu_; }
  HostBackend host_;
  std::mt19937_64 rng_{20240611};

 private:
  std::unique_ptr<Backend> gpu_;
};

TEST_F(GpuBackend, KindAndDescription) {
  EXPECT_EQ(gpu().kind(), DeviceKind::Cuda);
  const std::string d = gpu().description();
  EXPECT_NE(d.find("(sm_"), std::string::npos) << d;
  EXPECT_NE(d.find(" GiB)"), std::string::npos) << d;
}

TEST_F(GpuBackend, UploadDownloadRoundTrip) {
  for (const Index n : {Index{0}, Index{1}, Index{1000}, Index{100003}}) {
    const Vector v = random_vector(n, rng_);
    const DeviceVector d = to_device(gpu(), v);
    EXPECT_EQ(d.size(), n);
    const Vector back = to_host(d);
    ASSERT_EQ(back.size(), n);
    EXPECT_TRUE(back == v) << "size " << n;  // bit for bit
  }
}

TEST_F(GpuBackend, NewVectorsAreZero) {
  for (const Index n : kSizes) {
    const DeviceVector d(gpu(), n);
    EXPECT_EQ(to_host(d).cwiseAbs().maxCoeff(), 0.0) << "size " << n;
  }
}

TEST_F(GpuBackend, BytesInUseAndPeak) {
  const std::size_t before = gpu().bytes_in_use();
  const std::size_t host_before = host_.bytes_in_use();
  {
    const DeviceVector a(gpu(), 1000);
    const DeviceVector ha(host_, 1000);
    EXPECT_EQ(gpu().bytes_in_use(), before + 8000);
    EXPECT_EQ(gpu().bytes_in_use() - before, host_.bytes_in_use() - host_before);
    {
      const DeviceVector b(gpu(), 100003);
      EXPECT_EQ(gpu().bytes_in_use(), before + 8000 + 800024);
      EXPECT_GE(gpu().peak_bytes(), before + 8000 + 800024);
    }
    EXPECT_EQ(gpu().bytes_in_use(), before + 8000);
  }
  EXPECT_EQ(gpu().bytes_in_use(), before);
  EXPECT_GE(gpu().peak_bytes(), before + 808024);

  // Matrices are device memory too: row offsets, column indices, values (and a work buffer
  // once a product has run).
  const SparseMatrix A = random_sparse(1000, 1000, 6, rng_);
  {
    const auto dA = gpu().upload(A);
    const auto csr_bytes = static_cast<std::size_t>(1001 * 4 + A.nonZeros() * 12);
    EXPECT_GE(gpu().bytes_in_use(), before + csr_bytes);
    const DeviceVector x = to_device(gpu(), random_vector(1000, rng_));
    DeviceVector y(gpu(), 1000);
    gpu().spmv(*dA, x, y, 1.0, 0.0);
    gpu().synchronize();
  }
  EXPECT_EQ(gpu().bytes_in_use(), before);
}

TEST_F(GpuBackend, AllocationFailureSaysHowMuchAndLeavesTheBackendUsable) {
  const Index huge = Index{1} << 42;  // 32 TiB
  try {
    const DeviceVector v(gpu(), huge);
    FAIL() << "allocated 32 TiB";
  } catch (const NumericalError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("GB"), std::string::npos) << message;
    EXPECT_NE(message.find("cudaMalloc"), std::string::npos) << message;
  }
  // The failed call leaves no error behind for the next kernel.
  DeviceVector x(gpu(), 1000);
  gpu().fill(x, 2.0);
  EXPECT_EQ(gpu().dot(x, x), 4000.0);
}

TEST_F(GpuBackend, MismatchedSizesThrow) {
  DeviceVector x(gpu(), 10);
  DeviceVector y(gpu(), 11);
  EXPECT_THROW(gpu().axpby(1.0, x, 1.0, y), std::invalid_argument);
  EXPECT_THROW((void)gpu().dot(x, y), std::invalid_argument);
  DeviceVector h(host_, 10);
  EXPECT_THROW(gpu().copy(h, x), std::invalid_argument);
}

TEST_F(GpuBackend, SpmvMatchesHost) {
  struct Case {
    double alpha, beta;
  };
  const Case cases[] = {{1.0, 0.0}, {2.5, 0.0}, {1.0, 1.0}, {-0.5, 2.0}, {0.0, -1.5}, {1.0, 0.0}};
  for (const Index n : kSizes) {
    const SparseMatrix A = random_sparse(n, n, 8, rng_);
    const auto hA = host_.upload(A);
    const auto gA = gpu().upload(A);
    EXPECT_EQ(gA->rows(), n);
    EXPECT_EQ(gA->cols(), n);
    EXPECT_EQ(gA->nonzeros(), A.nonZeros());
    const Vector x = random_vector(n, rng_);
    const DeviceVector hx = to_device(host_, x);
    const DeviceVector gx = to_device(gpu(), x);
    // The same matrix again and again: its work buffer and analysis are reused.
    for (const Case& c : cases) {
      const Vector y0 = c.beta == 0.0 ? Vector::Constant(n, kNaN) : random_vector(n, rng_);
      DeviceVector hy = to_device(host_, y0);
      DeviceVector gy = to_device(gpu(), y0);
      host_.spmv(*hA, hx, hy, c.alpha, c.beta);
      gpu().spmv(*gA, gx, gy, c.alpha, c.beta);
      SCOPED_TRACE(::testing::Message() << "n " << n << " alpha " << c.alpha << " beta " << c.beta);
      expect_close(to_host(gy), to_host(hy));
    }
  }
}

TEST_F(GpuBackend, SymmetricUploadSkipsTheConversionAndGivesTheSameProduct) {
  for (const Index n : kSizes) {
    const SparseMatrix B = random_sparse(n, n, 4, rng_);
    const SparseMatrix A = SparseMatrix(B + SparseMatrix(B.transpose()));
    const auto hA = host_.upload(A);
    const auto gA = gpu().upload_symmetric(A);
    EXPECT_EQ(gA->nonzeros(), A.nonZeros());
    const Vector x = random_vector(n, rng_);
    DeviceVector hy(host_, n), gy(gpu(), n);
    host_.spmv(*hA, to_device(host_, x), hy);
    gpu().spmv(*gA, to_device(gpu(), x), gy);
    expect_close(to_host(gy), to_host(hy));
  }
}

TEST_F(GpuBackend, RecordedWorkReplaysTheSameKernels) {
  // The multigrid V-cycle is recorded (a CUDA graph) and replayed: a sequence of products and
  // updates, replayed twice, must give what the calls give one by one.
  const Index n = 100003;
  const SparseMatrix A = random_sparse(n, n, 6, rng_);
  const auto gA = gpu().upload(A);
  const auto hA = host_.upload(A);
  const Vector x = random_vector(n, rng_), d = random_vector(n, rng_, 0.5, 2.0);
  const DeviceVector gx = to_device(gpu(), x), gd = to_device(gpu(), d);
  DeviceVector gy(gpu(), n), gz(gpu(), n);
  const DeviceVector hx = to_device(host_, x), hd = to_device(host_, d);
  DeviceVector hy(host_, n), hz(host_, n);
  auto sequence = [](Backend& b, const DeviceSparseMatrix& M, const DeviceVector& in,
                     const DeviceVector& diag, DeviceVector& y, DeviceVector& z) {
    b.spmv(M, in, y);
    b.multiply(diag, y, z);
    b.axpby(2.0, in, -1.0, z);
    b.spmv(M, z, y, 0.5, 1.0);
  };
  auto recorded = gpu().record([&] { sequence(gpu(), *gA, gx, gd, gy, gz); });
  // A capture that failed would still replay correctly, call by call: say so.
  EXPECT_TRUE(recorded->is_graph()) << recorded->why_not_graph();
  EXPECT_TRUE(recorded->ran_while_recording());
  gpu().fill(gy, kNaN);
  gpu().fill(gz, kNaN);
  recorded->replay();
  recorded->replay();
  sequence(host_, *hA, hx, hd, hy, hz);
  expect_close(to_host(gy), to_host(hy));
  expect_close(to_host(gz), to_host(hz));
}

TEST_F(GpuBackend, SpmvRectangularAndDegenerate) {
  struct Shape {
    Index rows, cols;
    int per_row;
  };
  // Wide, tall, one row, no stored entry, no columns, no rows.
  const Shape shapes[] = {{300, 1000, 9}, {1000, 300, 5}, {1, 100003, 50}, {100003, 7, 2},
                          {50, 40, 0},    {20, 0, 3},     {0, 20, 3}};
  for (const Shape& s : shapes) {
    SparseMatrix A = random_sparse(s.rows, s.cols, s.per_row, rng_);
    if (s.per_row == 0) A.setZero();
    const auto hA = host_.upload(A);
    const auto gA = gpu().upload(A);
    const Vector x = random_vector(s.cols, rng_);
    const DeviceVector hx = to_device(host_, x);
    const DeviceVector gx = to_device(gpu(), x);
    for (const double beta : {0.0, 0.75}) {
      const Vector y0 = beta == 0.0 ? Vector::Constant(s.rows, kNaN) : random_vector(s.rows, rng_);
      DeviceVector hy = to_device(host_, y0);
      DeviceVector gy = to_device(gpu(), y0);
      host_.spmv(*hA, hx, hy, -1.25, beta);
      gpu().spmv(*gA, gx, gy, -1.25, beta);
      SCOPED_TRACE(::testing::Message() << s.rows << " x " << s.cols << " beta " << beta);
      expect_close(to_host(gy), to_host(hy));
    }
  }
}

TEST_F(GpuBackend, GemvMatchesHost) {
  for (const auto& [rows, cols] : std::vector<std::pair<Index, Index>>{
           {1, 1}, {50, 50}, {200, 37}, {37, 200}, {5, 0}, {0, 5}}) {
    const Matrix A = Matrix::Random(rows, cols);
    const auto hA = host_.upload(A);
    const auto gA = gpu().upload(A);
    EXPECT_EQ(gA->rows(), rows);
    EXPECT_EQ(gA->cols(), cols);
    const Vector x = random_vector(cols, rng_);
    const DeviceVector hx = to_device(host_, x);
    const DeviceVector gx = to_device(gpu(), x);
    DeviceVector hy = to_device(host_, Vector::Constant(rows, kNaN));
    DeviceVector gy = to_device(gpu(), Vector::Constant(rows, kNaN));  // output only
    host_.gemv(*hA, hx, hy);
    gpu().gemv(*gA, gx, gy);
    SCOPED_TRACE(::testing::Message() << rows << " x " << cols);
    expect_close(to_host(gy), to_host(hy));
  }
}

TEST_F(GpuBackend, DotMatchesHost) {
  for (const Index n : kSizes) {
    const Vector x = random_vector(n, rng_);
    const Vector y = random_vector(n, rng_);
    const DeviceVector hx = to_device(host_, x);
    const DeviceVector hy = to_device(host_, y);
    const DeviceVector gx = to_device(gpu(), x);
    const DeviceVector gy = to_device(gpu(), y);
    const double scale = x.cwiseAbs().dot(y.cwiseAbs());  // the sum can cancel
    EXPECT_NEAR(gpu().dot(gx, gy), host_.dot(hx, hy), kTolerance * scale) << "size " << n;
    EXPECT_NEAR(gpu().dot(gx, gx), host_.dot(hx, hx), kTolerance * x.squaredNorm());
    EXPECT_NEAR(norm(gpu(), gx), x.norm(), kTolerance * x.norm());
  }
  const DeviceVector empty(gpu(), 0);
  EXPECT_EQ(gpu().dot(empty, empty), 0.0);
}

TEST_F(GpuBackend, AxpbyMatchesHost) {
  for (const Index n : kSizes) {
    const Vector x = random_vector(n, rng_);
    for (const auto& [a, b] :
         std::vector<std::pair<double, double>>{{1.0, 1.0}, {2.0, -0.5}, {0.3, 0.0}, {0.0, 1.7}}) {
      const Vector y0 = b == 0.0 ? Vector::Constant(n, kNaN) : random_vector(n, rng_);
      const DeviceVector hx = to_device(host_, x);
      const DeviceVector gx = to_device(gpu(), x);
      DeviceVector hy = to_device(host_, y0);
      DeviceVector gy = to_device(gpu(), y0);
      host_.axpby(a, hx, b, hy);
      gpu().axpby(a, gx, b, gy);
      SCOPED_TRACE(::testing::Message() << "n " << n << " a " << a << " b " << b);
      expect_close(to_host(gy), to_host(hy));
      // x may be y.
      host_.axpby(a, hy, b, hy);
      gpu().axpby(a, gy, b, gy);
      expect_close(to_host(gy), to_host(hy));
    }
  }
}

TEST_F(GpuBackend, AxpbyzMatchesHostWithAliasing) {
  for (const Index n : kSizes) {
    const Vector x = random_vector(n, rng_);
    const Vector y = random_vector(n, rng_);
    const double a = 1.5;
    const double b = -0.75;
    {  // z apart from x and y
      const DeviceVector hx = to_device(host_, x), hy = to_device(host_, y);
      const DeviceVector gx = to_device(gpu(), x), gy = to_device(gpu(), y);
      DeviceVector hz = to_device(host_, Vector::Constant(n, kNaN));
      DeviceVector gz = to_device(gpu(), Vector::Constant(n, kNaN));
      host_.axpbyz(a, hx, b, hy, hz);
      gpu().axpbyz(a, gx, b, gy, gz);
      expect_close(to_host(gz), to_host(hz));
    }
    {  // z = x
      DeviceVector hx = to_device(host_, x);
      const DeviceVector hy = to_device(host_, y);
      DeviceVector gx = to_device(gpu(), x);
      const DeviceVector gy = to_device(gpu(), y);
      host_.axpbyz(a, hx, b, hy, hx);
      gpu().axpbyz(a, gx, b, gy, gx);
      expect_close(to_host(gx), to_host(hx));
    }
    {  // z = y
      const DeviceVector hx = to_device(host_, x);
      DeviceVector hy = to_device(host_, y);
      const DeviceVector gx = to_device(gpu(), x);
      DeviceVector gy = to_device(gpu(), y);
      host_.axpbyz(a, hx, b, hy, hy);
      gpu().axpbyz(a, gx, b, gy, gy);
      expect_close(to_host(gy), to_host(hy));
    }
    {  // b = 0: y is not read
      const DeviceVector hx = to_device(host_, x), hy = to_device(host_, Vector::Constant(n, kNaN));
      const DeviceVector gx = to_device(gpu(), x), gy = to_device(gpu(), Vector::Constant(n, kNaN));
      DeviceVector hz(host_, n);
      DeviceVector gz(gpu(), n);
      host_.axpbyz(a, hx, 0.0, hy, hz);
      gpu().axpbyz(a, gx, 0.0, gy, gz);
      expect_close(to_host(gz), to_host(hz));
    }
  }
}

TEST_F(GpuBackend, MultiplyMatchesHost) {
  for (const Index n : kSizes) {
    const Vector d = random_vector(n, rng_);
    const Vector x = random_vector(n, rng_);
    const DeviceVector hd = to_device(host_, d), gd = to_device(gpu(), d);
    DeviceVector hx = to_device(host_, x), gx = to_device(gpu(), x);
    DeviceVector hz(host_, n), gz(gpu(), n);
    host_.multiply(hd, hx, hz);
    gpu().multiply(gd, gx, gz);
    expect_close(to_host(gz), to_host(hz));
    host_.multiply(hd, hx, hx);  // z may be x
    gpu().multiply(gd, gx, gx);
    expect_close(to_host(gx), to_host(hx));
  }
}

TEST_F(GpuBackend, ReciprocalMatchesHost) {
  for (const Index n : kSizes) {
    Vector x = random_vector(n, rng_, 0.5, 2.0);
    if (n > 1) x[1] = -3.0;
    DeviceVector hx = to_device(host_, x), gx = to_device(gpu(), x);
    DeviceVector hy(host_, n), gy(gpu(), n);
    host_.reciprocal(hx, hy);
    gpu().reciprocal(gx, gy);
    expect_close(to_host(gy), to_host(hy));
    host_.reciprocal(hx, hx);  // y may be x
    gpu().reciprocal(gx, gx);
    expect_close(to_host(gx), to_host(hx));
  }
}

TEST_F(GpuBackend, CopyAndFill) {
  for (const Index n : kSizes) {
    const Vector x = random_vector(n, rng_);
    const DeviceVector gx = to_device(gpu(), x);
    DeviceVector gy = to_device(gpu(), Vector::Constant(n, kNaN));
    gpu().copy(gx, gy);
    EXPECT_TRUE(to_host(gy) == x) << "size " << n;
    gpu().copy(gy, gy);
    EXPECT_TRUE(to_host(gy) == x) << "size " << n;
    for (const double value : {3.25, 0.0, -1e300}) {
      gpu().fill(gy, value);
      EXPECT_TRUE(to_host(gy) == Vector::Constant(n, value)) << "size " << n << " value " << value;
    }
  }
}

TEST_F(GpuBackend, ChebyshevUpdateMatchesHost) {
  for (const Index n : kSizes) {
    const Vector dinv = random_vector(n, rng_, 0.1, 1.0);
    const Vector r = random_vector(n, rng_);
    const Vector x0 = random_vector(n, rng_);
    const DeviceVector hdinv = to_device(host_, dinv), gdinv = to_device(gpu(), dinv);
    const DeviceVector hr = to_device(host_, r), gr = to_device(gpu(), r);
    DeviceVector hx = to_device(host_, x0), gx = to_device(gpu(), x0);
    // The first step has a = 0 and must not read d (NaN here).
    DeviceVector hd = to_device(host_, Vector::Constant(n, kNaN));
    DeviceVector gd = to_device(gpu(), Vector::Constant(n, kNaN));
    const std::pair<double, double> steps[] = {{0.0, 0.8}, {0.35, 1.1}, {-0.2, 0.9}};
    for (const auto& [a, b] : steps) {
      host_.chebyshev_update(a, b, hdinv, hr, hd, hx);
      gpu().chebyshev_update(a, b, gdinv, gr, gd, gx);
      SCOPED_TRACE(::testing::Message() << "n " << n << " a " << a << " b " << b);
      expect_close(to_host(gd), to_host(hd));
      expect_close(to_host(gx), to_host(hx));
    }
  }
}

TEST_F(GpuBackend, ACgLikeSequenceMatchesHost) {
  // The calls of a few conjugate-gradient steps, queued without synchronisation in between.
  const Index n = 100003;
  const SparseMatrix B = random_sparse(n, n, 3, rng_);
  const SparseMatrix Bt = B.transpose();
  SparseMatrix shift(n, n);
  shift.setIdentity();
  const SparseMatrix A = B + Bt + 10.0 * shift;  // symmetric, diagonally dominant
  const Vector b = random_vector(n, rng_);
  auto run = [&](Backend& be) {
    const auto dA = be.upload(A);
    DeviceVector x(be, n), r = to_device(be, b), p(be, n), q(be, n);
    be.copy(r, p);
    double rr = be.dot(r, r);
    for (int k = 0; k < 5; ++k) {
      be.spmv(*dA, p, q, 1.0, 0.0);
      const double alpha = rr / be.dot(p, q);
      be.axpby(alpha, p, 1.0, x);
      be.axpby(-alpha, q, 1.0, r);
      const double rr_new = be.dot(r, r);
      be.axpby(1.0, r, rr_new / rr, p);
      rr = rr_new;
    }
    be.synchronize();
    return to_host(x);
  };
  expect_close(run(gpu()), run(host_), 1e-10);
}

}  // namespace
}  // namespace signorini
