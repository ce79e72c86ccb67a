// The CUDA backend's own kernels (see cuda_kernels.hpp). Memory-bound one-pass loops: a
// grid-stride loop with 64-bit indices, 256 threads a block.

#include <algorithm>

#include "signorini/backend/cuda/cuda_kernels.hpp"

namespace signorini::cuda {

namespace {

constexpr int kThreads = 256;
constexpr std::int64_t kMaxBlocks = 65535;

__device__ inline std::int64_t first_index() {
  return static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
}

__device__ inline std::int64_t stride() {
  return static_cast<std::int64_t>(blockDim.x) * gridDim.x;
}

unsigned blocks_for(std::int64_t n) {
  return static_cast<unsigned>(std::min((n + kThreads - 1) / kThreads, kMaxBlocks));
}

__global__ void axpbyz_kernel(double a, const double* x, double b, const double* y, double* z,
                              std::int64_t n) {
  for (std::int64_t i = first_index(); i < n; i += stride()) {
    double t = a * x[i];
    if (b != 0.0) t += b * y[i];
    z[i] = t;
  }
}

__global__ void scale_kernel(double b, double* y, std::int64_t n) {
  for (std::int64_t i = first_index(); i < n; i += stride()) y[i] = b == 0.0 ? 0.0 : b * y[i];
}

__global__ void multiply_kernel(const double* d, const double* x, double* z, std::int64_t n) {
  for (std::int64_t i = first_index(); i < n; i += stride()) z[i] = d[i] * x[i];
}

__global__ void reciprocal_kernel(const double* x, double* y, std::int64_t n) {
  for (std::int64_t i = first_index(); i < n; i += stride()) y[i] = 1.0 / x[i];
}

__global__ void fill_kernel(double* x, double value, std::int64_t n) {
  for (std::int64_t i = first_index(); i < n; i += stride()) x[i] = value;
}

__global__ void chebyshev_kernel(double a, double b, const double* dinv, const double* r, double* d,
                                 double* x, std::int64_t n) {
  for (std::int64_t i = first_index(); i < n; i += stride()) {
    const double di = (a == 0.0 ? 0.0 : a * d[i]) + b * dinv[i] * r[i];
    d[i] = di;
    x[i] += di;
  }
}

}  // namespace

cudaError_t axpbyz(double a, const double* x, double b, const double* y, double* z, std::int64_t n,
                   cudaStream_t stream) {
  if (n <= 0) return cudaSuccess;
  axpbyz_kernel<<<blocks_for(n), kThreads, 0, stream>>>(a, x, b, y, z, n);
  return cudaGetLastError();
}

cudaError_t scale(double b, double* y, std::int64_t n, cudaStream_t stream) {
  if (n <= 0) return cudaSuccess;
  scale_kernel<<<blocks_for(n), kThreads, 0, stream>>>(b, y, n);
  return cudaGetLastError();
}

cudaError_t multiply(const double* d, const double* x, double* z, std::int64_t n,
                     cudaStream_t stream) {
  if (n <= 0) return cudaSuccess;
  multiply_kernel<<<blocks_for(n), kThreads, 0, stream>>>(d, x, z, n);
  return cudaGetLastError();
}

cudaError_t reciprocal(const double* x, double* y, std::int64_t n, cudaStream_t stream) {
  if (n <= 0) return cudaSuccess;
  reciprocal_kernel<<<blocks_for(n), kThreads, 0, stream>>>(x, y, n);
  return cudaGetLastError();
}

cudaError_t fill(double* x, double value, std::int64_t n, cudaStream_t stream) {
  if (n <= 0) return cudaSuccess;
  fill_kernel<<<blocks_for(n), kThreads, 0, stream>>>(x, value, n);
  return cudaGetLastError();
}

cudaError_t chebyshev_update(double a, double b, const double* dinv, const double* r, double* d,
                             double* x, std::int64_t n, cudaStream_t stream) {
  if (n <= 0) return cudaSuccess;
  chebyshev_kernel<<<blocks_for(n), kThreads, 0, stream>>>(a, b, dinv, r, d, x, n);
  return cudaGetLastError();
}

cudaError_t kernel_image_status() {
  cudaFuncAttributes attributes{};
  return cudaFuncGetAttributes(&attributes, axpbyz_kernel);
}

}  // namespace signorini::cuda
