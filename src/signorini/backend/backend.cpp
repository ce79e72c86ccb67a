#include "signorini/backend/backend.hpp"

#include <cmath>
#include <utility>

#include "signorini/core/error.hpp"

namespace signorini {

DeviceVector::DeviceVector(Backend& backend, Index n)
    : backend_(&backend), data_(n > 0 ? backend.allocate(n) : nullptr), size_(n) {}

DeviceVector::~DeviceVector() {
  reset();
}

DeviceVector::DeviceVector(DeviceVector&& other) noexcept
    : backend_(std::exchange(other.backend_, nullptr)),
      data_(std::exchange(other.data_, nullptr)),
      size_(std::exchange(other.size_, 0)) {}

DeviceVector& DeviceVector::operator=(DeviceVector&& other) noexcept {
  if (this != &other) {
    reset();
    backend_ = std::exchange(other.backend_, nullptr);
    data_ = std::exchange(other.data_, nullptr);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

void DeviceVector::reset() noexcept {
  if (backend_ != nullptr && data_ != nullptr) backend_->release(data_);
  data_ = nullptr;
  size_ = 0;
}

namespace {
class StoredWork final : public RecordedWork {
 public:
  StoredWork(std::function<void()> work, std::string reason, bool ran)
      : work_(std::move(work)), reason_(std::move(reason)), ran_(ran) {}
  void replay() override { work_(); }
  [[nodiscard]] std::string why_not_graph() const override { return reason_; }
  [[nodiscard]] bool ran_while_recording() const override { return ran_; }

 private:
  std::function<void()> work_;
  std::string reason_;
  bool ran_;
};
}  // namespace

std::unique_ptr<DeviceSparseMatrix> Backend::upload_transpose(const SparseMatrix& A,
                                                              HostArrays /*arrays*/) {
  return upload(SparseMatrix(A.transpose()));
}

void Backend::spmv_transpose(const DeviceSparseMatrix& /*A*/, const DeviceVector& /*x*/,
                             DeviceVector& /*y*/, double /*alpha*/, double /*beta*/) {
  throw NumericalError(description() + " has no transposed sparse product");
}

std::unique_ptr<RecordedWork> Backend::call_by_call(std::function<void()> work, std::string reason,
                                                    bool ran) {
  return std::make_unique<StoredWork>(std::move(work), std::move(reason), ran);
}

std::unique_ptr<RecordedWork> Backend::record(std::function<void()> work) {
  return call_by_call(std::move(work), "this backend has no graphs: calls are replayed", false);
}

DeviceVector to_device(Backend& backend, const Vector& host) {
  DeviceVector v(backend, host.size());
  upload_into(host, v);
  return v;
}

Vector to_host(const DeviceVector& v) {
  Vector out(v.size());
  if (v.size() > 0) v.backend()->download(v.data(), v.size(), out.data());
  return out;
}

void upload_into(const Vector& host, DeviceVector& v) {
  if (host.size() > 0) v.backend()->upload(host.data(), host.size(), v.data());
}

double norm(Backend& backend, const DeviceVector& x) {
  return std::sqrt(backend.dot(x, x));
}

}  // namespace signorini
