#include "signorini/backend/make_backend.hpp"

#include "signorini/backend/cuda_backend.hpp"
#include "signorini/backend/host_backend.hpp"

namespace signorini {

std::unique_ptr<Backend> make_backend(DeviceKind kind) {
  if (kind == DeviceKind::Cuda) return make_cuda_backend(0);
  return std::make_unique<HostBackend>();
}

}  // namespace signorini
