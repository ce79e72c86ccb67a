#include "signorini/backend/host_backend.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <new>
#include <optional>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "signorini/backend/node_block_matrix.hpp"
#include "signorini/core/error.hpp"

namespace signorini {

namespace {

// Signed loop bounds for OpenMP.
using Loop = std::int64_t;

// Loops run on OpenMP threads from kParallelFrom entries up, plainly below, where even an
// inactive parallel region costs a call per loop (a tenth of a CG iteration on 60x20).
constexpr Loop kParallelFrom = 20000;
// A sparse product does some hundred operations a row, so it is worth threads from far fewer
// rows: from this many stored entries (a coarse multigrid level of a few thousand unknowns in
// 3D, which ran on one thread through Eigen's product before).
constexpr Index kParallelProductFrom = 200000;

// Matrices count in bytes_in_use() as on a GPU (CSR arrays), so that the CPU backend predicts the
// memory a GPU run needs; a shared matrix counts too, though here it takes no memory of its own.
// A matrix holds its CSR arrays itself (`owned`), or views the column-major arrays of a caller's
// matrix as the CSR arrays of its transpose (upload_transpose with HostArrays::Share), or, for a
// large square copy whose pattern is made of node blocks, holds those instead of CSR arrays
// (`blocks`: fewer bytes for each product to stream, node_block_matrix.hpp).
class HostSparseMatrix final : public DeviceSparseMatrix {
 public:
  using Csr = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
  using CsrView = Eigen::Map<const Csr>;

  /// A copy of A in CSR form.
  HostSparseMatrix(const SparseMatrix& A, std::size_t& in_use, std::size_t& peak)
      : DeviceSparseMatrix(A.rows(), A.cols(), A.nonZeros()), owned(A), in_use_(in_use) {
    owned.makeCompressed();
    point_at_owned();
    count(peak);
  }
  /// A^T, from the compressed A's column-major arrays: shared, or copied as they are; a large
  /// copy in node blocks, of the upper blocks only where A is `symmetric`.
  HostSparseMatrix(const SparseMatrix& A, HostArrays arrays, bool symmetric, std::size_t& in_use,
                   std::size_t& peak)
      : DeviceSparseMatrix(A.cols(), A.rows(), A.nonZeros()), in_use_(in_use) {
    const CsrView transpose(A.cols(), A.rows(), A.nonZeros(), A.outerIndexPtr(), A.innerIndexPtr(),
                            A.valuePtr());
    if (arrays == HostArrays::Share) {
      outer = A.outerIndexPtr();
      inner = A.innerIndexPtr();
      values = A.valuePtr();
    } else {
      if (A.rows() == A.cols() && A.nonZeros() >= kParallelProductFrom)
        blocks = symmetric ? NodeBlockMatrix::from_symmetric_csr(A.cols(), A.outerIndexPtr(),
                                                                 A.innerIndexPtr(), A.valuePtr())
                           : NodeBlockMatrix::from_csr(A.cols(), A.outerIndexPtr(),
                                                       A.innerIndexPtr(), A.valuePtr());
      if (!blocks) {
        owned = transpose;
        point_at_owned();
      }
    }
    count(peak);
  }
  ~HostSparseMatrix() override { in_use_ -= bytes_; }
  HostSparseMatrix(const HostSparseMatrix&) = delete;
  HostSparseMatrix& operator=(const HostSparseMatrix&) = delete;

  [[nodiscard]] CsrView view() const { return {rows(), cols(), nonzeros(), outer, inner, values}; }

  const int* outer = nullptr;
  const int* inner = nullptr;
  const double* values = nullptr;
  std::optional<NodeBlockMatrix> blocks;  // instead of the CSR arrays, where set

 private:
  void point_at_owned() {
    outer = owned.outerIndexPtr();
    inner = owned.innerIndexPtr();
    values = owned.valuePtr();
  }
  void count(std::size_t& peak) {
    bytes_ = static_cast<std::size_t>(rows() + 1) * sizeof(int) +
             static_cast<std::size_t>(nonzeros()) * (sizeof(int) + sizeof(double));
    in_use_ += bytes_;
    peak = std::max(peak, in_use_);
  }
  Csr owned;
  std::size_t& in_use_;
  std::size_t bytes_ = 0;
};

class HostDenseMatrix final : public DeviceDenseMatrix {
 public:
  HostDenseMatrix(const Matrix& A, std::size_t& in_use, std::size_t& peak)
      : DeviceDenseMatrix(A.rows(), A.cols()), values(A), in_use_(in_use) {
    bytes_ = static_cast<std::size_t>(A.size()) * sizeof(double);
    in_use_ += bytes_;
    peak = std::max(peak, in_use_);
  }
  ~HostDenseMatrix() override { in_use_ -= bytes_; }
  HostDenseMatrix(const HostDenseMatrix&) = delete;
  HostDenseMatrix& operator=(const HostDenseMatrix&) = delete;
  Matrix values;

 private:
  std::size_t& in_use_;
  std::size_t bytes_ = 0;
};

// Runs f(i) for i in [0, n), on threads from kParallelFrom up.
template <class F>
void for_each_index(Loop n, const F& f) {
  if (n >= kParallelFrom) {
#pragma omp parallel for schedule(static)
    for (Loop i = 0; i < n; ++i) f(i);
  } else {
    for (Loop i = 0; i < n; ++i) f(i);
  }
}

}  // namespace

std::string HostBackend::description() const {
#ifdef _OPENMP
  return fmt::format("CPU, {} threads", omp_get_max_threads());
#else
  return "CPU, 1 thread";
#endif
}

double* HostBackend::allocate(Index n) {
  auto* p = new (std::nothrow) double[static_cast<std::size_t>(n)]();
  if (p == nullptr)
    throw NumericalError(fmt::format("out of memory: {} values ({:.2f} GB) on the CPU", n,
                                     static_cast<double>(n) * 8e-9));
  // The size is not known at release(); the tracking below counts what allocate() handed out.
  in_use_ += static_cast<std::size_t>(n) * sizeof(double);
  peak_ = std::max(peak_, in_use_);
  sizes_.emplace(p, static_cast<std::size_t>(n) * sizeof(double));
  return p;
}

void HostBackend::release(double* data) noexcept {
  const auto it = sizes_.find(data);
  if (it != sizes_.end()) {
    in_use_ -= it->second;
    sizes_.erase(it);
  }
  delete[] data;
}

void HostBackend::upload(const double* host, Index n, double* device) {
  std::memcpy(device, host, static_cast<std::size_t>(n) * sizeof(double));
}

void HostBackend::download(const double* device, Index n, double* host) {
  std::memcpy(host, device, static_cast<std::size_t>(n) * sizeof(double));
}

std::unique_ptr<DeviceSparseMatrix> HostBackend::upload(const SparseMatrix& A) {
  return std::make_unique<HostSparseMatrix>(A, in_use_, peak_);
}

std::unique_ptr<DeviceSparseMatrix> HostBackend::upload_transpose(const SparseMatrix& A,
                                                                  HostArrays arrays) {
  if (!A.isCompressed()) return upload(SparseMatrix(A.transpose()));
  return std::make_unique<HostSparseMatrix>(A, arrays, false, in_use_, peak_);
}

std::unique_ptr<DeviceSparseMatrix> HostBackend::upload_symmetric(const SparseMatrix& A,
                                                                  HostArrays arrays) {
  if (!A.isCompressed()) return upload(A);
  return std::make_unique<HostSparseMatrix>(A, arrays, true, in_use_, peak_);
}

std::unique_ptr<DeviceDenseMatrix> HostBackend::upload(const Matrix& A) {
  return std::make_unique<HostDenseMatrix>(A, in_use_, peak_);
}

void HostBackend::spmv(const DeviceSparseMatrix& A, const DeviceVector& x, DeviceVector& y,
                       double alpha, double beta) {
  const auto& h = static_cast<const HostSparseMatrix&>(A);
  if (h.blocks) {
    h.blocks->multiply(x.data(), y.data(), alpha, beta, h.nonzeros() >= kParallelProductFrom);
    return;
  }
  const int* outer = h.outer;
  const int* inner = h.inner;
  const double* v = h.values;
  const double* xs = x.data();
  double* ys = y.data();
  const Loop rows = h.rows();
  if (h.nonzeros() < kParallelProductFrom) {  // Eigen's own product, vectorised
    const HostSparseMatrix::CsrView m = h.view();
    Eigen::Map<const Vector> xm(xs, x.size());
    Eigen::Map<Vector> ym(ys, y.size());
    if (beta == 0.0)
      ym.noalias() = alpha * (m * xm);
    else
      ym = alpha * (m * xm) + beta * ym;
    return;
  }
  const auto row = [&](Loop i) {
    double s = 0.0;
    for (int k = outer[i]; k < outer[i + 1]; ++k) s += v[k] * xs[inner[k]];
    return alpha * s;
  };
  if (beta == 0.0) {
#pragma omp parallel for schedule(static)
    for (Loop i = 0; i < rows; ++i) ys[i] = row(i);
  } else {
#pragma omp parallel for schedule(static)
    for (Loop i = 0; i < rows; ++i) ys[i] = row(i) + beta * ys[i];
  }
}

void HostBackend::spmv_transpose(const DeviceSparseMatrix& A, const DeviceVector& x,
                                 DeviceVector& y, double alpha, double beta) {
  // Row i of A scatters alpha x_i A(i, :) into y: the rows of A are the columns of A^T, so each
  // thread sums its share of the rows into a y of its own, and the partial sums are added after.
  const auto& h = static_cast<const HostSparseMatrix&>(A);
  if (h.blocks) {
    h.blocks->multiply_transpose(x.data(), y.data(), alpha, beta);
    return;
  }
  const int* outer = h.outer;
  const int* inner = h.inner;
  const double* v = h.values;
  const double* xs = x.data();
  double* ys = y.data();
  const Loop rows = h.rows();
  const Loop cols = h.cols();
  int threads = 1;
#ifdef _OPENMP
  threads = omp_get_max_threads();
#endif
  if (h.nonzeros() < kParallelProductFrom || threads == 1) {
    for (Loop j = 0; j < cols; ++j) ys[j] = beta == 0.0 ? 0.0 : beta * ys[j];
    for (Loop i = 0; i < rows; ++i) {
      const double a = alpha * xs[i];
      for (int k = outer[i]; k < outer[i + 1]; ++k) ys[inner[k]] += v[k] * a;
    }
    return;
  }
  partial_sums_.resize(static_cast<std::size_t>(threads) * static_cast<std::size_t>(cols));
  double* parts = partial_sums_.data();
#pragma omp parallel num_threads(threads)
  {
    int t = 0;
#ifdef _OPENMP
    t = omp_get_thread_num();
#endif
    double* part = parts + static_cast<std::ptrdiff_t>(t) * cols;
    std::fill(part, part + cols, 0.0);
#pragma omp for schedule(static)
    for (Loop i = 0; i < rows; ++i) {
      const double a = alpha * xs[i];
      for (int k = outer[i]; k < outer[i + 1]; ++k) part[inner[k]] += v[k] * a;
    }
#pragma omp for schedule(static)
    for (Loop j = 0; j < cols; ++j) {
      double s = beta == 0.0 ? 0.0 : beta * ys[j];
      for (int p = 0; p < threads; ++p) s += parts[static_cast<std::ptrdiff_t>(p) * cols + j];
      ys[j] = s;
    }
  }
}

void HostBackend::gemv(const DeviceDenseMatrix& A, const DeviceVector& x, DeviceVector& y) {
  const auto& m = static_cast<const HostDenseMatrix&>(A).values;
  Eigen::Map<const Vector> xs(x.data(), x.size());
  Eigen::Map<Vector> ys(y.data(), y.size());
  ys.noalias() = m * xs;
}

double HostBackend::dot(const DeviceVector& x, const DeviceVector& y) {
  const double* a = x.data();
  const double* b = y.data();
  const Loop n = x.size();
  if (n < kParallelFrom)  // Eigen's dot: vectorised partial sums
    return Eigen::Map<const Vector>(a, n).dot(Eigen::Map<const Vector>(b, n));
  double s = 0.0;
#pragma omp parallel for reduction(+ : s) schedule(static)
  for (Loop i = 0; i < n; ++i) s += a[i] * b[i];
  return s;
}

void HostBackend::axpby(double a, const DeviceVector& x, double b, DeviceVector& y) {
  axpbyz(a, x, b, y, y);
}

void HostBackend::axpbyz(double a, const DeviceVector& x, double b, const DeviceVector& y,
                         DeviceVector& z) {
  const double* xs = x.data();
  const double* ys = y.data();
  double* zs = z.data();
  const Loop n = z.size();
  if (b == 0.0)
    for_each_index(n, [&](Loop i) { zs[i] = a * xs[i]; });
  else
    for_each_index(n, [&](Loop i) { zs[i] = a * xs[i] + b * ys[i]; });
}

void HostBackend::multiply(const DeviceVector& d, const DeviceVector& x, DeviceVector& z) {
  const double* ds = d.data();
  const double* xs = x.data();
  double* zs = z.data();
  const Loop n = z.size();
  for_each_index(n, [&](Loop i) { zs[i] = ds[i] * xs[i]; });
}

void HostBackend::reciprocal(const DeviceVector& x, DeviceVector& y) {
  const double* xs = x.data();
  double* ys = y.data();
  const Loop n = y.size();
  for_each_index(n, [&](Loop i) { ys[i] = 1.0 / xs[i]; });
}

void HostBackend::copy(const DeviceVector& x, DeviceVector& y) {
  if (x.size() > 0)
    std::memcpy(y.data(), x.data(), static_cast<std::size_t>(x.size()) * sizeof(double));
}

void HostBackend::fill(DeviceVector& x, double value) {
  std::fill(x.data(), x.data() + x.size(), value);
}

void HostBackend::chebyshev_update(double a, double b, const DeviceVector& dinv,
                                   const DeviceVector& r, DeviceVector& d, DeviceVector& x) {
  const double* ds = dinv.data();
  const double* rs = r.data();
  double* dd = d.data();
  double* xs = x.data();
  const Loop n = x.size();
  for_each_index(n, [&](Loop i) {
    dd[i] = (a == 0.0 ? 0.0 : a * dd[i]) + b * ds[i] * rs[i];
    xs[i] += dd[i];
  });
}

}  // namespace signorini
