#pragma once
// The elementwise kernels of the CUDA backend (cuda_kernels.cu, the only file nvcc compiles):
// plain functions over raw device pointers that queue a grid-stride kernel on `stream` and return
// the launch status (cudaGetLastError). n = 0 queues nothing. Each one has the semantics of the
// HostBackend loop of the same name, including its treatment of zero coefficients (see
// host_backend.cpp: e.g. axpby and axpbyz with b = 0 do not read y, so a NaN there does not leak
// into the result; x is always read).

#include <cuda_runtime_api.h>

#include <cstdint>

namespace signorini::cuda {

/// z = a x + b y; z may be x or y.
cudaError_t axpbyz(double a, const double* x, double b, const double* y, double* z, std::int64_t n,
                   cudaStream_t stream);
/// y = b y (y = 0 when b == 0).
cudaError_t scale(double b, double* y, std::int64_t n, cudaStream_t stream);
/// z = d .* x; z may be d or x.
cudaError_t multiply(const double* d, const double* x, double* z, std::int64_t n,
                     cudaStream_t stream);
/// y = 1 ./ x; y may be x.
cudaError_t reciprocal(const double* x, double* y, std::int64_t n, cudaStream_t stream);
/// x = value.
cudaError_t fill(double* x, double value, std::int64_t n, cudaStream_t stream);
/// d = a d + b (dinv .* r); x += d.
cudaError_t chebyshev_update(double a, double b, const double* dinv, const double* r, double* d,
                             double* x, std::int64_t n, cudaStream_t stream);
/// cudaSuccess if the current device can run the kernels of this build (the build has code for
/// its architecture), else the error of the kernel lookup.
cudaError_t kernel_image_status();

}  // namespace signorini::cuda
