#pragma once
// The CPU implementation of the backend interface: plain loops over host memory, parallel with
// OpenMP where the build has it. It runs every iterative algorithm in the CPU tests, and is the
// reference the CUDA backend is compared with.

#include <unordered_map>
#include <vector>

#include "signorini/backend/backend.hpp"

namespace signorini {

class HostBackend final : public Backend {
 public:
  [[nodiscard]] DeviceKind kind() const override { return DeviceKind::Cpu; }
  [[nodiscard]] std::string description() const override;

  [[nodiscard]] double* allocate(Index n) override;
  void release(double* data) noexcept override;
  void upload(const double* host, Index n, double* device) override;
  void download(const double* device, Index n, double* host) override;
  [[nodiscard]] std::size_t bytes_in_use() const override { return in_use_; }
  [[nodiscard]] std::size_t peak_bytes() const override { return peak_; }

  [[nodiscard]] std::unique_ptr<DeviceSparseMatrix> upload(const SparseMatrix& A) override;
  [[nodiscard]] std::unique_ptr<DeviceDenseMatrix> upload(const Matrix& A) override;
  [[nodiscard]] std::unique_ptr<DeviceSparseMatrix> upload_transpose(const SparseMatrix& A,
                                                                     HostArrays arrays) override;
  [[nodiscard]] std::unique_ptr<DeviceSparseMatrix> upload_symmetric(
      const SparseMatrix& A, HostArrays arrays = HostArrays::Copy) override;

  void spmv(const DeviceSparseMatrix& A, const DeviceVector& x, DeviceVector& y, double alpha = 1.0,
            double beta = 0.0) override;
  [[nodiscard]] bool has_transposed_product() const override { return true; }
  void spmv_transpose(const DeviceSparseMatrix& A, const DeviceVector& x, DeviceVector& y,
                      double alpha = 1.0, double beta = 0.0) override;
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

 private:
  std::size_t in_use_ = 0;
  std::size_t peak_ = 0;
  std::unordered_map<const double*, std::size_t> sizes_;  // bytes of each allocation
  std::vector<double> partial_sums_;  // spmv_transpose: one y per thread, kept between calls
};

}  // namespace signorini
