// The CUDA implementation of the backend interface (backend.hpp): one GPU, one stream, and a
// cuBLAS and a cuSPARSE handle bound to that stream. Sparse products go to cuSPARSE (CSR, 32-bit
// indices), dense products and dot products to cuBLAS, the vector updates to the kernels of
// cuda_kernels.cu. Every call has the semantics of the HostBackend call of the same name, the
// reference it is tested against (tests/backend/cuda_backend_gpu_test.cpp).
//
// Compiled by the C++ compiler: nvcc only sees cuda_kernels.cu.

#include "signorini/backend/cuda_backend.hpp"

#include <cublas_v2.h>
#include <cuda_runtime.h>
#include <cusparse.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "signorini/backend/cuda/cuda_kernels.hpp"
#include "signorini/backend/cuda/cuda_libraries.hpp"
#include "signorini/core/error.hpp"

#if CUDART_VERSION < 12000
#error "the CUDA backend needs CUDA 12.0 or newer (64-bit cuBLAS API, const cuSPARSE descriptors)"
#endif

#ifndef SIGNORINI_CUDA_ARCHITECTURES
#define SIGNORINI_CUDA_ARCHITECTURES "unknown"
#endif

namespace signorini {

namespace {

// cuBLAS and cuSPARSE, loaded at their first use (cuda_libraries.hpp).
const cuda::CublasFunctions& blas() {
  return cuda::cuda_libraries().cublas;
}
const cuda::CusparseFunctions& sparse() {
  return cuda::cuda_libraries().cusparse;
}

// Status checks: a failure throws NumericalError naming the call and the library's message.
void check(cudaError_t status, const char* call) {
  if (status == cudaSuccess) return;
  // The runtime keeps the error of a failed call until it is read: clear it, so that the next
  // kernel launch check does not report it again (a sticky error stays anyway).
  (void)cudaGetLastError();
  throw NumericalError(fmt::format("CUDA: {} failed: {}", call, cudaGetErrorString(status)));
}

void check(cublasStatus_t status, const char* call) {
  if (status != CUBLAS_STATUS_SUCCESS)
    throw NumericalError(fmt::format("cuBLAS: {} failed: {}", call, blas().status_string(status)));
}

void check(cusparseStatus_t status, const char* call) {
  if (status != CUSPARSE_STATUS_SUCCESS)
    throw NumericalError(
        fmt::format("cuSPARSE: {} failed: {}", call, sparse().error_string(status)));
}

/// "13.0" from 13000 (CUDART_VERSION, cudaDriverGetVersion).
std::string version_string(int version) {
  return fmt::format("{}.{}", version / 1000, version % 1000 / 10);
}

constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;

// ALG1 with preprocessing is the fastest CSR product; unlike ALG2 it does not promise bitwise
// identical results from run to run (cuSPARSE docs), so GPU iteration counts may differ by one
// between runs where a solve is at the edge of its tolerance (docs/gpu.md).
constexpr cusparseSpMVAlg_t kSpmvAlgorithm = CUSPARSE_SPMV_CSR_ALG1;

constexpr std::size_t kCublasWorkspaceBytes = std::size_t{32} << 20;

std::size_t vector_bytes(Index n) {
  if (n > static_cast<Index>(std::numeric_limits<std::size_t>::max() / sizeof(double)))
    throw NumericalError(fmt::format("CUDA: a vector of {} values does not fit in memory", n));
  return static_cast<std::size_t>(n) * sizeof(double);
}

class CudaBackend;

class CudaSparseMatrix final : public DeviceSparseMatrix {
 public:
  CudaSparseMatrix(CudaBackend& owner, Index rows, Index cols, Index nonzeros)
      : DeviceSparseMatrix(rows, cols, nonzeros), backend(&owner) {}
  ~CudaSparseMatrix() override;
  CudaSparseMatrix(const CudaSparseMatrix&) = delete;
  CudaSparseMatrix& operator=(const CudaSparseMatrix&) = delete;

  CudaBackend* backend;
  int* row_offsets = nullptr;  // rows + 1
  int* columns = nullptr;      // nonzeros
  double* values = nullptr;    // nonzeros
  // Null when the matrix has no rows, no columns or no stored entry: spmv() then only scales y.
  cusparseSpMatDescr_t descriptor = nullptr;
  // The work buffer of cusparseSpMV, made and preprocessed on the first product.
  mutable void* buffer = nullptr;
  mutable std::size_t buffer_bytes = 0;
  mutable bool preprocessed = false;
};

class CudaDenseMatrix final : public DeviceDenseMatrix {
 public:
  CudaDenseMatrix(CudaBackend& owner, Index rows, Index cols)
      : DeviceDenseMatrix(rows, cols), backend(&owner) {}
  ~CudaDenseMatrix() override;
  CudaDenseMatrix(const CudaDenseMatrix&) = delete;
  CudaDenseMatrix& operator=(const CudaDenseMatrix&) = delete;

  CudaBackend* backend;
  double* values = nullptr;  // column-major, leading dimension rows
};

/// A dense-vector descriptor of cuSPARSE for the length of one call.
class DenseVectorDescriptor {
 public:
  DenseVectorDescriptor(Index n, const double* values) {
    check(sparse().create_const_dn_vec(&constant_, n, values, CUDA_R_64F),
          "cusparseCreateConstDnVec");
  }
  DenseVectorDescriptor(Index n, double* values) {
    check(sparse().create_dn_vec(&mutable_, n, values, CUDA_R_64F), "cusparseCreateDnVec");
    constant_ = mutable_;
  }
  ~DenseVectorDescriptor() {
    if (constant_ != nullptr) (void)sparse().destroy_dn_vec(constant_);
  }
  DenseVectorDescriptor(const DenseVectorDescriptor&) = delete;
  DenseVectorDescriptor& operator=(const DenseVectorDescriptor&) = delete;

  [[nodiscard]] cusparseConstDnVecDescr_t constant() const { return constant_; }
  [[nodiscard]] cusparseDnVecDescr_t mutable_descriptor() const { return mutable_; }

 private:
  cusparseConstDnVecDescr_t constant_ = nullptr;
  cusparseDnVecDescr_t mutable_ = nullptr;
};

class CudaBackend final : public Backend {
 public:
  explicit CudaBackend(int ordinal);
  ~CudaBackend() override;
  CudaBackend(const CudaBackend&) = delete;
  CudaBackend& operator=(const CudaBackend&) = delete;

  [[nodiscard]] DeviceKind kind() const override { return DeviceKind::Cuda; }
  [[nodiscard]] std::string description() const override { return description_; }

  [[nodiscard]] double* allocate(Index n) override;
  void release(double* data) noexcept override { release_bytes(data); }
  void upload(const double* host, Index n, double* device) override;
  void download(const double* device, Index n, double* host) override;
  [[nodiscard]] std::size_t bytes_in_use() const override { return in_use_; }
  [[nodiscard]] std::size_t peak_bytes() const override { return peak_; }

  [[nodiscard]] std::unique_ptr<DeviceSparseMatrix> upload(const SparseMatrix& A) override;
  [[nodiscard]] std::unique_ptr<DeviceDenseMatrix> upload(const Matrix& A) override;
  [[nodiscard]] std::unique_ptr<DeviceSparseMatrix> upload_transpose(const SparseMatrix& A,
                                                                     HostArrays arrays) override;

  void spmv(const DeviceSparseMatrix& A, const DeviceVector& x, DeviceVector& y, double alpha,
            double beta) override;
  void gemv(const DeviceDenseMatrix& A, const DeviceVector& x, DeviceVector& y) override;
  [[nodiscard]] double dot(const DeviceVector& x, const DeviceVector& y) override;
  void axpby(double a, const DeviceVector& x, double b, DeviceVector& y) override;
  void axpbyz(double a, const DeviceVector& x, double b, const DeviceVector& y,
              DeviceVector& z) override;
  void multiply(const DeviceVector& d, const DeviceVector& x, DeviceVector& z) override;
  void reciprocal(const DeviceVector& x, DeviceVector& y) override;
  void copy(const DeviceVector& x, DeviceVector& y) override;
  void fill(DeviceVector& x, double value) override;
  void chebyshev_update(double a, double b, const DeviceVector& dinv, const DeviceVector& r,
                        DeviceVector& d, DeviceVector& x) override;
  void synchronize() override;
  [[nodiscard]] std::unique_ptr<RecordedWork> record(std::function<void()> work) override;

  /// Uninitialised device memory, counted in bytes_in_use(); `what` names it in the error.
  [[nodiscard]] void* allocate_bytes(std::size_t bytes, const char* what);
  void release_bytes(void* data) noexcept;

 private:
  /// Makes this backend's GPU the calling thread's current device.
  void bind() const;
  /// Throws std::invalid_argument unless v is a vector of this backend with n values.
  void require(const DeviceVector& v, Index n, const char* call, const char* name) const;
  void copy_to_device(void* device, const void* host, std::size_t bytes);
  std::unique_ptr<DeviceSparseMatrix> upload_csr(Index rows, Index cols, Index nonzeros,
                                                 const int* offsets, const int* column_indices,
                                                 const double* values);
  void destroy_handles() noexcept;

  int device_;
  std::string description_;
  cudaStream_t stream_ = nullptr;
  cublasHandle_t cublas_ = nullptr;
  void* cublas_workspace_ = nullptr;
  cusparseHandle_t cusparse_ = nullptr;
  std::size_t in_use_ = 0;
  std::size_t peak_ = 0;
  std::unordered_map<const void*, std::size_t> sizes_;  // bytes of each allocation
};

CudaSparseMatrix::~CudaSparseMatrix() {
  if (descriptor != nullptr) (void)sparse().destroy_sp_mat(descriptor);
  backend->release_bytes(buffer);
  backend->release_bytes(values);
  backend->release_bytes(columns);
  backend->release_bytes(row_offsets);
}

CudaDenseMatrix::~CudaDenseMatrix() {
  backend->release_bytes(values);
}

CudaBackend::CudaBackend(int ordinal) : device_(ordinal) {
  check(cudaSetDevice(device_), "cudaSetDevice");
  cudaDeviceProp properties{};
  check(cudaGetDeviceProperties(&properties, device_), "cudaGetDeviceProperties");
  description_ =
      fmt::format("{} (sm_{}{}, {:.1f} GiB)", properties.name, properties.major, properties.minor,
                  static_cast<double>(properties.totalGlobalMem) / kGiB);

  // A GPU older than the architectures this build has code for cannot run its kernels.
  const cudaError_t image = cuda::kernel_image_status();
  if (image == cudaErrorNoKernelImageForDevice || image == cudaErrorInvalidDeviceFunction) {
    (void)cudaGetLastError();
    throw InputError(fmt::format(
        "solver.device = \"cuda\": no usable CUDA GPU (GPU {}, {}, is sm_{}{}, and this signorini "
        "has GPU code for CMAKE_CUDA_ARCHITECTURES={} only: reconfigure with "
        "-DCMAKE_CUDA_ARCHITECTURES={}{})",
        device_, properties.name, properties.major, properties.minor, SIGNORINI_CUDA_ARCHITECTURES,
        properties.major, properties.minor));
  }
  check(image, "cudaFuncGetAttributes");

  try {
    check(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking), "cudaStreamCreateWithFlags");
    check(blas().create(&cublas_), "cublasCreate");
    check(blas().set_stream(cublas_, stream_), "cublasSetStream");
    // A fixed cuBLAS workspace (set after cublasSetStream, which resets it): without one, cuBLAS
    // calls inside a graph capture add allocation nodes to the graph (cuBLAS docs, "CUDA Graphs
    // Support"). 32 MiB is NVIDIA's recommendation for Hopper. Not counted in bytes_in_use():
    // it is the library's, not the problem's.
    check(cudaMalloc(&cublas_workspace_, kCublasWorkspaceBytes), "cudaMalloc (cuBLAS workspace)");
    check(blas().set_workspace(cublas_, cublas_workspace_, kCublasWorkspaceBytes),
          "cublasSetWorkspace");
    check(blas().set_pointer_mode(cublas_, CUBLAS_POINTER_MODE_HOST), "cublasSetPointerMode");
    check(sparse().create(&cusparse_), "cusparseCreate");
    check(sparse().set_stream(cusparse_, stream_), "cusparseSetStream");
  } catch (...) {
    destroy_handles();
    throw;
  }
}

CudaBackend::~CudaBackend() {
  (void)cudaSetDevice(device_);
  if (stream_ != nullptr) (void)cudaStreamSynchronize(stream_);
  // Whatever is still allocated (vectors or matrices that outlive their backend, which they
  // must not) goes back to the GPU.
  for (const auto& [data, bytes] : sizes_) (void)cudaFree(const_cast<void*>(data));
  sizes_.clear();
  destroy_handles();
  (void)cudaGetLastError();
}

void CudaBackend::destroy_handles() noexcept {
  if (cusparse_ != nullptr) (void)sparse().destroy(cusparse_);
  if (cublas_ != nullptr) (void)blas().destroy(cublas_);
  if (cublas_workspace_ != nullptr) (void)cudaFree(cublas_workspace_);
  if (stream_ != nullptr) (void)cudaStreamDestroy(stream_);
  cusparse_ = nullptr;
  cublas_ = nullptr;
  cublas_workspace_ = nullptr;
  stream_ = nullptr;
}

void CudaBackend::bind() const {
  int current = -1;
  check(cudaGetDevice(&current), "cudaGetDevice");
  if (current != device_) check(cudaSetDevice(device_), "cudaSetDevice");
}

void CudaBackend::require(const DeviceVector& v, Index n, const char* call,
                          const char* name) const {
  if (v.size() != n)
    throw std::invalid_argument(
        fmt::format("CudaBackend::{}: {} has {} values, {} expected", call, name, v.size(), n));
  if (n > 0 && v.backend() != this)
    throw std::invalid_argument(
        fmt::format("CudaBackend::{}: {} belongs to another backend", call, name));
}

void* CudaBackend::allocate_bytes(std::size_t bytes, const char* what) {
  if (bytes == 0) return nullptr;
  bind();
  void* data = nullptr;
  const cudaError_t status = cudaMalloc(&data, bytes);
  if (status != cudaSuccess) {
    (void)cudaGetLastError();
    std::size_t free = 0;
    std::size_t total = 0;
    const bool known = cudaMemGetInfo(&free, &total) == cudaSuccess;
    (void)cudaGetLastError();
    throw NumericalError(fmt::format(
        "CUDA: cudaMalloc of {:.2f} GB ({}) failed on GPU {}: {}{}",
        static_cast<double>(bytes) * 1e-9, what, device_, cudaGetErrorString(status),
        known ? fmt::format(" ({:.2f} GB free of {:.2f} GB)", static_cast<double>(free) * 1e-9,
                            static_cast<double>(total) * 1e-9)
              : std::string()));
  }
  in_use_ += bytes;
  peak_ = std::max(peak_, in_use_);
  sizes_.emplace(data, bytes);
  return data;
}

void CudaBackend::release_bytes(void* data) noexcept {
  if (data == nullptr) return;
  const auto it = sizes_.find(data);
  if (it != sizes_.end()) {
    in_use_ -= it->second;
    sizes_.erase(it);
  }
  int current = -1;
  const bool switched = cudaGetDevice(&current) == cudaSuccess && current != device_ &&
                        cudaSetDevice(device_) == cudaSuccess;
  (void)cudaFree(data);  // waits for the work queued on the GPU
  if (switched) (void)cudaSetDevice(current);
  (void)cudaGetLastError();
}

double* CudaBackend::allocate(Index n) {
  if (n <= 0) return nullptr;
  const std::size_t bytes = vector_bytes(n);
  void* data = allocate_bytes(bytes, fmt::format("a vector of {} values", n).c_str());
  try {
    check(cudaMemsetAsync(data, 0, bytes, stream_), "cudaMemsetAsync");
  } catch (...) {
    release_bytes(data);
    throw;
  }
  return static_cast<double*>(data);
}

void CudaBackend::copy_to_device(void* device, const void* host, std::size_t bytes) {
  if (bytes == 0) return;
  check(cudaMemcpyAsync(device, host, bytes, cudaMemcpyHostToDevice, stream_),
        "cudaMemcpyAsync (host to device)");
}

void CudaBackend::upload(const double* host, Index n, double* device) {
  if (n <= 0) return;
  bind();
  copy_to_device(device, host, vector_bytes(n));
  check(cudaStreamSynchronize(stream_), "cudaStreamSynchronize");
}

void CudaBackend::download(const double* device, Index n, double* host) {
  if (n <= 0) return;
  bind();
  check(cudaMemcpyAsync(host, device, vector_bytes(n), cudaMemcpyDeviceToHost, stream_),
        "cudaMemcpyAsync (device to host)");
  check(cudaStreamSynchronize(stream_), "cudaStreamSynchronize");
}

std::unique_ptr<DeviceSparseMatrix> CudaBackend::upload(const SparseMatrix& A) {
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> csr(A);
  csr.makeCompressed();
  return upload_csr(csr.rows(), csr.cols(), csr.nonZeros(), csr.outerIndexPtr(),
                    csr.innerIndexPtr(), csr.valuePtr());
}

std::unique_ptr<DeviceSparseMatrix> CudaBackend::upload_transpose(const SparseMatrix& A,
                                                                  HostArrays /*arrays*/) {
  if (!A.isCompressed()) return upload(SparseMatrix(A.transpose()));
  // The CSC arrays of A are the CSR arrays of A^T; device memory holds its own copy always.
  return upload_csr(A.cols(), A.rows(), A.nonZeros(), A.outerIndexPtr(), A.innerIndexPtr(),
                    A.valuePtr());
}

std::unique_ptr<DeviceSparseMatrix> CudaBackend::upload_csr(Index rows, Index cols, Index nonzeros,
                                                            const int* offsets,
                                                            const int* column_indices,
                                                            const double* values) {
  bind();
  auto m = std::make_unique<CudaSparseMatrix>(*this, rows, cols, nonzeros);
  const auto offsets_bytes = static_cast<std::size_t>(rows + 1) * sizeof(int);
  const auto columns_bytes = static_cast<std::size_t>(nonzeros) * sizeof(int);
  const auto values_bytes = static_cast<std::size_t>(nonzeros) * sizeof(double);
  m->row_offsets = static_cast<int*>(allocate_bytes(offsets_bytes, "CSR row offsets"));
  m->columns = static_cast<int*>(allocate_bytes(columns_bytes, "CSR column indices"));
  m->values = static_cast<double*>(allocate_bytes(values_bytes, "CSR values"));
  copy_to_device(m->row_offsets, offsets, offsets_bytes);
  copy_to_device(m->columns, column_indices, columns_bytes);
  copy_to_device(m->values, values, values_bytes);
  // The host arrays may be freed on return: the copies must be done.
  check(cudaStreamSynchronize(stream_), "cudaStreamSynchronize");
  if (rows > 0 && cols > 0 && nonzeros > 0)
    check(sparse().create_csr(&m->descriptor, rows, cols, nonzeros, m->row_offsets, m->columns,
                              m->values, CUSPARSE_INDEX_32I, CUSPARSE_INDEX_32I,
                              CUSPARSE_INDEX_BASE_ZERO, CUDA_R_64F),
          "cusparseCreateCsr");
  return m;
}

std::unique_ptr<DeviceDenseMatrix> CudaBackend::upload(const Matrix& A) {
  bind();
  auto m = std::make_unique<CudaDenseMatrix>(*this, A.rows(), A.cols());
  const std::size_t bytes = vector_bytes(A.size());
  m->values = static_cast<double*>(allocate_bytes(bytes, "a dense matrix"));
  copy_to_device(m->values, A.data(), bytes);
  check(cudaStreamSynchronize(stream_), "cudaStreamSynchronize");
  return m;
}

void CudaBackend::spmv(const DeviceSparseMatrix& A, const DeviceVector& x, DeviceVector& y,
                       double alpha, double beta) {
  const auto& m = static_cast<const CudaSparseMatrix&>(A);
  require(x, m.cols(), "spmv", "x");
  require(y, m.rows(), "spmv", "y");
  if (m.rows() == 0) return;
  bind();
  if (m.descriptor == nullptr) {  // A x = 0
    check(cuda::scale(beta, y.data(), y.size(), stream_), "scale kernel (spmv)");
    return;
  }
  // With beta = 0, y is output only (as on the CPU): a NaN in it must not survive as 0 * NaN.
  if (beta == 0.0)
    check(cudaMemsetAsync(y.data(), 0, vector_bytes(y.size()), stream_), "cudaMemsetAsync");

  const DenseVectorDescriptor vx(x.size(), x.data());
  const DenseVectorDescriptor vy(y.size(), y.data());
  // Once per matrix: the work buffer (its size depends on the matrix, the operation, the
  // algorithm and the type only) and the analysis, kept with the matrix descriptor. Every later
  // product must pass this same buffer (cuSPARSE 12.6 release notes, CUSPARSE-1897), and none of
  // this may run inside a graph capture (Backend::record runs the work once before capturing).
  if (m.buffer == nullptr) {
    std::size_t needed = 0;
    check(sparse().spmv_buffer_size(cusparse_, CUSPARSE_OPERATION_NON_TRANSPOSE, &alpha,
                                    m.descriptor, vx.constant(), &beta, vy.mutable_descriptor(),
                                    CUDA_R_64F, kSpmvAlgorithm, &needed),
          "cusparseSpMV_bufferSize");
    const std::size_t bytes = std::max<std::size_t>(needed, 256);  // never a null buffer
    m.buffer = allocate_bytes(bytes, "the work buffer of cusparseSpMV");
    m.buffer_bytes = bytes;
  }
  if (!m.preprocessed) {
    check(sparse().spmv_preprocess(cusparse_, CUSPARSE_OPERATION_NON_TRANSPOSE, &alpha,
                                   m.descriptor, vx.constant(), &beta, vy.mutable_descriptor(),
                                   CUDA_R_64F, kSpmvAlgorithm, m.buffer),
          "cusparseSpMV_preprocess");
    m.preprocessed = true;
  }
  check(sparse().spmv(cusparse_, CUSPARSE_OPERATION_NON_TRANSPOSE, &alpha, m.descriptor,
                      vx.constant(), &beta, vy.mutable_descriptor(), CUDA_R_64F, kSpmvAlgorithm,
                      m.buffer),
        "cusparseSpMV");
}

void CudaBackend::gemv(const DeviceDenseMatrix& A, const DeviceVector& x, DeviceVector& y) {
  const auto& m = static_cast<const CudaDenseMatrix&>(A);
  require(x, m.cols(), "gemv", "x");
  require(y, m.rows(), "gemv", "y");
  if (m.rows() == 0) return;
  bind();
  if (m.cols() == 0) {  // cuBLAS would leave y as it is
    check(cudaMemsetAsync(y.data(), 0, vector_bytes(y.size()), stream_), "cudaMemsetAsync");
    return;
  }
  const double one = 1.0;
  const double zero = 0.0;  // y is not read (BLAS semantics of beta = 0)
  check(blas().dgemv(cublas_, CUBLAS_OP_N, m.rows(), m.cols(), &one, m.values, m.rows(), x.data(),
                     1, &zero, y.data(), 1),
        "cublasDgemv_64");
}

double CudaBackend::dot(const DeviceVector& x, const DeviceVector& y) {
  require(y, x.size(), "dot", "y");
  if (x.size() == 0) return 0.0;
  require(x, x.size(), "dot", "x");
  bind();
  double result = 0.0;  // pointer mode host: cuBLAS waits for the result
  check(blas().ddot(cublas_, x.size(), x.data(), 1, y.data(), 1, &result), "cublasDdot_64");
  return result;
}

void CudaBackend::axpby(double a, const DeviceVector& x, double b, DeviceVector& y) {
  axpbyz(a, x, b, y, y);
}

void CudaBackend::axpbyz(double a, const DeviceVector& x, double b, const DeviceVector& y,
                         DeviceVector& z) {
  require(x, z.size(), "axpbyz", "x");
  require(y, z.size(), "axpbyz", "y");
  require(z, z.size(), "axpbyz", "z");
  if (z.size() == 0) return;
  bind();
  check(cuda::axpbyz(a, x.data(), b, y.data(), z.data(), z.size(), stream_),
        "axpbyz kernel launch");
}

void CudaBackend::multiply(const DeviceVector& d, const DeviceVector& x, DeviceVector& z) {
  require(d, z.size(), "multiply", "d");
  require(x, z.size(), "multiply", "x");
  require(z, z.size(), "multiply", "z");
  if (z.size() == 0) return;
  bind();
  check(cuda::multiply(d.data(), x.data(), z.data(), z.size(), stream_), "multiply kernel launch");
}

void CudaBackend::reciprocal(const DeviceVector& x, DeviceVector& y) {
  require(x, y.size(), "reciprocal", "x");
  require(y, y.size(), "reciprocal", "y");
  if (y.size() == 0) return;
  bind();
  check(cuda::reciprocal(x.data(), y.data(), y.size(), stream_), "reciprocal kernel launch");
}

void CudaBackend::copy(const DeviceVector& x, DeviceVector& y) {
  require(x, y.size(), "copy", "x");
  require(y, y.size(), "copy", "y");
  if (y.size() == 0 || x.data() == y.data()) return;
  bind();
  check(cudaMemcpyAsync(y.data(), x.data(), vector_bytes(y.size()), cudaMemcpyDeviceToDevice,
                        stream_),
        "cudaMemcpyAsync (device to device)");
}

void CudaBackend::fill(DeviceVector& x, double value) {
  require(x, x.size(), "fill", "x");
  if (x.size() == 0) return;
  bind();
  check(cuda::fill(x.data(), value, x.size(), stream_), "fill kernel launch");
}

void CudaBackend::chebyshev_update(double a, double b, const DeviceVector& dinv,
                                   const DeviceVector& r, DeviceVector& d, DeviceVector& x) {
  require(dinv, x.size(), "chebyshev_update", "dinv");
  require(r, x.size(), "chebyshev_update", "r");
  require(d, x.size(), "chebyshev_update", "d");
  require(x, x.size(), "chebyshev_update", "x");
  if (x.size() == 0) return;
  bind();
  check(cuda::chebyshev_update(a, b, dinv.data(), r.data(), d.data(), x.data(), x.size(), stream_),
        "chebyshev_update kernel launch");
}

void CudaBackend::synchronize() {
  bind();
  check(cudaStreamSynchronize(stream_), "cudaStreamSynchronize");
}

/// Recorded work as an instantiated CUDA graph: one launch replays every kernel of it.
class CudaGraphWork final : public RecordedWork {
 public:
  CudaGraphWork(cudaGraphExec_t exec, cudaStream_t stream) : exec_(exec), stream_(stream) {}
  ~CudaGraphWork() override { (void)cudaGraphExecDestroy(exec_); }
  CudaGraphWork(const CudaGraphWork&) = delete;
  CudaGraphWork& operator=(const CudaGraphWork&) = delete;
  void replay() override { check(cudaGraphLaunch(exec_, stream_), "cudaGraphLaunch"); }
  [[nodiscard]] std::string why_not_graph() const override { return {}; }
  [[nodiscard]] bool ran_while_recording() const override { return true; }  // the eager run

 private:
  cudaGraphExec_t exec_;
  cudaStream_t stream_;
};

std::unique_ptr<RecordedWork> CudaBackend::record(std::function<void()> work) {
  bind();
  // Once as it is: lazily made things (the SpMV work buffers and their preprocessing, which
  // allocate and synchronise) exist before the capture, where neither is allowed.
  work();
  check(cudaStreamSynchronize(stream_), "cudaStreamSynchronize");
  check(cudaStreamBeginCapture(stream_, cudaStreamCaptureModeThreadLocal),
        "cudaStreamBeginCapture");
  // Whatever `work` throws, the capture is ended here: a stream left capturing would fail every
  // later call on it.
  std::string problem;
  try {
    work();
  } catch (const std::exception& e) {
    problem = e.what();  // something in `work` cannot be captured: replay it call by call
  } catch (...) {
    problem = "an exception of unknown type";
  }
  cudaGraph_t graph = nullptr;
  const cudaError_t ended = cudaStreamEndCapture(stream_, &graph);
  if (problem.empty() && ended != cudaSuccess)
    problem = std::string("cudaStreamEndCapture: ") + cudaGetErrorString(ended);
  if (problem.empty() && graph == nullptr) problem = "the capture was invalidated";
  cudaGraphExec_t exec = nullptr;
  if (problem.empty()) {
    const cudaError_t made = cudaGraphInstantiate(&exec, graph, 0);
    if (made == cudaSuccess) {
      (void)cudaGraphDestroy(graph);
      return std::make_unique<CudaGraphWork>(exec, stream_);
    }
    problem = std::string("cudaGraphInstantiate: ") + cudaGetErrorString(made);
  }
  if (graph != nullptr) (void)cudaGraphDestroy(graph);
  (void)cudaGetLastError();  // the failed capture's error is not the next call's
  return call_by_call(std::move(work), "CUDA graph capture failed (" + problem + ")", true);
}

}  // namespace

CudaReport cuda_report() {
  CudaReport report;
  report.built = true;
  try {
    report.toolkit_version = version_string(CUDART_VERSION);
    int driver = 0;
    if (cudaDriverGetVersion(&driver) != cudaSuccess) driver = 0;
    (void)cudaGetLastError();
    if (driver > 0) report.driver_version = version_string(driver);

    int count = 0;
    const cudaError_t status = cudaGetDeviceCount(&count);
    if (status != cudaSuccess) {
      (void)cudaGetLastError();
      report.problem = cudaGetErrorString(status);
      if (driver == 0)
        report.problem = "no CUDA driver found (cudaGetDeviceCount: " + report.problem + ")";
      else if (status == cudaErrorInsufficientDriver)
        report.problem += fmt::format(" (the driver has CUDA {}, this signorini was built with {})",
                                      report.driver_version, report.toolkit_version);
      return report;
    }
    if (count == 0) {
      report.problem = "no CUDA-capable device is detected";
      return report;
    }
    std::string last_error;
    for (int i = 0; i < count; ++i) {
      cudaDeviceProp properties{};
      const cudaError_t read = cudaGetDeviceProperties(&properties, i);
      if (read != cudaSuccess) {
        (void)cudaGetLastError();
        last_error = cudaGetErrorString(read);
        continue;
      }
      GpuInfo gpu;
      gpu.ordinal = i;
      gpu.name = properties.name;
      gpu.major = properties.major;
      gpu.minor = properties.minor;
      gpu.total_memory = properties.totalGlobalMem;
      gpu.multiprocessors = properties.multiProcessorCount;
      report.gpus.push_back(std::move(gpu));
    }
    if (report.gpus.empty())
      report.problem =
          fmt::format("{} CUDA device(s) found, none could be queried: {}", count, last_error);
  } catch (const std::exception& e) {  // std::bad_alloc, fmt
    report.problem = e.what();
  }
  return report;
}

std::unique_ptr<Backend> make_cuda_backend(int ordinal) {
  const CudaReport report = cuda_report();
  if (report.gpus.empty())
    throw InputError(
        fmt::format("solver.device = \"cuda\": no usable CUDA GPU ({})", report.problem));
  const bool present = std::any_of(report.gpus.begin(), report.gpus.end(),
                                   [&](const GpuInfo& gpu) { return gpu.ordinal == ordinal; });
  if (!present)
    throw InputError(fmt::format(
        "solver.device = \"cuda\": no usable CUDA GPU (GPU {} was asked for; this machine has {} "
        "usable, numbered from 0)",
        ordinal, report.gpus.size()));
  return std::make_unique<CudaBackend>(ordinal);
}

std::vector<std::string> load_cuda_libraries() {
  const cuda::CudaLibraries& libraries = cuda::cuda_libraries();
  return {libraries.cublas_path, libraries.cusparse_path};
}

}  // namespace signorini
