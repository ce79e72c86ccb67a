#pragma once
// The thin layer between the iterative solvers (src/signorini/iterative) and the hardware they
// run on: vectors and matrices that live in a backend's memory, and the handful of kernels that
// conjugate gradients, Chebyshev smoothing and multigrid need (sparse and dense matrix-vector
// products, dot products, vector updates). The algorithms are written once against this
// interface and tested on the CPU backend; the CUDA backend maps the same calls onto cuSPARSE,
// cuBLAS and a few kernels of its own, so that only this layer is GPU-specific (docs/gpu.md).
//
// Every call is asynchronous on a GPU except those that return a value to the host (dot,
// download), which wait for the work queued before them.

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "signorini/backend/device_kind.hpp"
#include "signorini/core/types.hpp"

namespace signorini {

class Backend;

/// A vector of doubles in a backend's memory. Move-only; freed by its backend.
class DeviceVector {
 public:
  DeviceVector() = default;
  /// n zeros in `backend`'s memory.
  DeviceVector(Backend& backend, Index n);
  ~DeviceVector();
  DeviceVector(DeviceVector&& other) noexcept;
  DeviceVector& operator=(DeviceVector&& other) noexcept;
  DeviceVector(const DeviceVector&) = delete;
  DeviceVector& operator=(const DeviceVector&) = delete;

  [[nodiscard]] Index size() const { return size_; }
  [[nodiscard]] double* data() { return data_; }
  [[nodiscard]] const double* data() const { return data_; }
  [[nodiscard]] Backend* backend() const { return backend_; }

 private:
  void reset() noexcept;
  Backend* backend_ = nullptr;
  double* data_ = nullptr;
  Index size_ = 0;
};

/// A sparse matrix in compressed sparse row form in a backend's memory (opaque; each backend
/// derives its own).
class DeviceSparseMatrix {
 public:
  virtual ~DeviceSparseMatrix() = default;
  [[nodiscard]] Index rows() const { return rows_; }
  [[nodiscard]] Index cols() const { return cols_; }
  [[nodiscard]] Index nonzeros() const { return nonzeros_; }

 protected:
  DeviceSparseMatrix(Index rows, Index cols, Index nonzeros)
      : rows_(rows), cols_(cols), nonzeros_(nonzeros) {}

 private:
  Index rows_, cols_, nonzeros_;
};

/// A small dense matrix (column-major) in a backend's memory, for the coarsest multigrid level.
class DeviceDenseMatrix {
 public:
  virtual ~DeviceDenseMatrix() = default;
  [[nodiscard]] Index rows() const { return rows_; }
  [[nodiscard]] Index cols() const { return cols_; }

 protected:
  DeviceDenseMatrix(Index rows, Index cols) : rows_(rows), cols_(cols) {}

 private:
  Index rows_, cols_;
};

/// Kernels recorded once and replayed many times (see Backend::record).
class RecordedWork {
 public:
  virtual ~RecordedWork() = default;
  virtual void replay() = 0;
  /// Why replay() makes the calls again one by one (on the CPU, or where a GPU capture failed);
  /// "" when it launches the work as one device graph (a CUDA graph).
  [[nodiscard]] virtual std::string why_not_graph() const = 0;
  [[nodiscard]] bool is_graph() const { return why_not_graph().empty(); }
  /// True when Backend::record ran the work once (on a GPU, before capturing it): its results
  /// are then already there, and a caller may skip the first replay.
  [[nodiscard]] virtual bool ran_while_recording() const = 0;
};

/// What upload_transpose may do with the host matrix's arrays: copy them, or (on a backend that
/// computes in the host's memory) use them in place.
enum class HostArrays { Copy, Share };

class Backend {
 public:
  virtual ~Backend() = default;
  [[nodiscard]] virtual DeviceKind kind() const = 0;
  /// One line for reports: "CPU, 16 threads" or "NVIDIA H100 80GB HBM3 (sm_90, 79.1 GiB)".
  [[nodiscard]] virtual std::string description() const = 0;

  // Memory. allocate() returns zeroed storage or throws NumericalError naming the size.
  [[nodiscard]] virtual double* allocate(Index n) = 0;
  virtual void release(double* data) noexcept = 0;
  virtual void upload(const double* host, Index n, double* device) = 0;
  virtual void download(const double* device, Index n, double* host) = 0;
  /// Bytes this backend holds now and at most so far (device memory on a GPU).
  [[nodiscard]] virtual std::size_t bytes_in_use() const = 0;
  [[nodiscard]] virtual std::size_t peak_bytes() const = 0;

  /// Copies A (any shape) into the backend as CSR. Throws NumericalError if it does not fit.
  [[nodiscard]] virtual std::unique_ptr<DeviceSparseMatrix> upload(const SparseMatrix& A) = 0;
  [[nodiscard]] virtual std::unique_ptr<DeviceDenseMatrix> upload(const Matrix& A) = 0;
  /// A^T from A's column-major arrays, which are A^T's CSR arrays: no conversion, and no
  /// transposed copy on the host (the restriction P^T of a multigrid level). With
  /// HostArrays::Share a backend that computes in the host's memory keeps a view of A's arrays
  /// instead of a copy, so the largest matrices exist once: A must then outlive the result,
  /// unchanged. A GPU copies them either way.
  [[nodiscard]] virtual std::unique_ptr<DeviceSparseMatrix> upload_transpose(
      const SparseMatrix& A, HostArrays arrays = HostArrays::Copy);
  /// upload(A) for a symmetric A, by default as upload_transpose(A): the result multiplies by
  /// A^T, which for a matrix symmetric only up to rounding (a Galerkin product P^T A P summed in
  /// another order) differs from A x by rounding only. The CPU backend's copy of a large one
  /// keeps the blocks on and above the diagonal only (NodeBlockMatrix::from_symmetric_csr).
  [[nodiscard]] virtual std::unique_ptr<DeviceSparseMatrix> upload_symmetric(
      const SparseMatrix& A, HostArrays arrays = HostArrays::Copy) {
    return upload_transpose(A, arrays);
  }

  // Kernels. Vectors must belong to this backend and have matching sizes; x and y must differ
  // where both appear, unless stated.
  /// y = alpha A x + beta y
  virtual void spmv(const DeviceSparseMatrix& A, const DeviceVector& x, DeviceVector& y,
                    double alpha = 1.0, double beta = 0.0) = 0;
  /// Whether spmv_transpose runs on this backend. The CPU's does (partial sums per thread), so
  /// that a multigrid level there keeps one copy of its prolongation P, as P^T's CSR arrays
  /// shared with the host matrix; a GPU keeps P and P^T and gathers for both products.
  [[nodiscard]] virtual bool has_transposed_product() const { return false; }
  /// y = alpha A^T x + beta y, where has_transposed_product(); a NumericalError elsewhere.
  virtual void spmv_transpose(const DeviceSparseMatrix& A, const DeviceVector& x, DeviceVector& y,
                              double alpha = 1.0, double beta = 0.0);
  /// y = A x (dense)
  virtual void gemv(const DeviceDenseMatrix& A, const DeviceVector& x, DeviceVector& y) = 0;
  [[nodiscard]] virtual double dot(const DeviceVector& x, const DeviceVector& y) = 0;
  /// y = a x + b y (x may be y)
  virtual void axpby(double a, const DeviceVector& x, double b, DeviceVector& y) = 0;
  /// z = a x + b y (z may be x or y)
  virtual void axpbyz(double a, const DeviceVector& x, double b, const DeviceVector& y,
                      DeviceVector& z) = 0;
  /// z = d .* x (elementwise; z may be x)
  virtual void multiply(const DeviceVector& d, const DeviceVector& x, DeviceVector& z) = 0;
  /// y = 1 ./ x (elementwise; y may be x)
  virtual void reciprocal(const DeviceVector& x, DeviceVector& y) = 0;
  virtual void copy(const DeviceVector& x, DeviceVector& y) = 0;
  virtual void fill(DeviceVector& x, double value) = 0;
  /// One step of the Chebyshev recurrence (Saad, Iterative Methods, Alg. 12.1), fused:
  ///   d = a d + b (dinv .* r);  x += d
  virtual void chebyshev_update(double a, double b, const DeviceVector& dinv, const DeviceVector& r,
                                DeviceVector& d, DeviceVector& x) = 0;
  /// Waits for queued work (timings).
  virtual void synchronize() {}

  /// Records `work` (kernel calls of this backend only: no dot, upload, download, allocation)
  /// for replay. On a GPU the calls become one CUDA graph, launched at once instead of call by
  /// call, which matters for the many small kernels of the coarse multigrid levels; `work` may
  /// run once while being recorded. Vectors and scalars are captured as they are at recording:
  /// record again after either changes. The default keeps the function and calls it.
  [[nodiscard]] virtual std::unique_ptr<RecordedWork> record(std::function<void()> work);

 protected:
  /// Recorded work that replays by calling `work` again; `reason` says why (why_not_graph);
  /// `ran` whether record() has run it once already.
  static std::unique_ptr<RecordedWork> call_by_call(std::function<void()> work, std::string reason,
                                                    bool ran);
};

// Conveniences over the interface.
DeviceVector to_device(Backend& backend, const Vector& host);
Vector to_host(const DeviceVector& v);
void upload_into(const Vector& host, DeviceVector& v);
double norm(Backend& backend, const DeviceVector& x);

}  // namespace signorini
