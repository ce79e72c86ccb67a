#pragma once
// The backend for a DeviceKind: the CPU always, CUDA where it was built and a GPU is present.

#include <memory>

#include "signorini/backend/backend.hpp"

namespace signorini {

/// Throws InputError (from make_cuda_backend) when CUDA is asked for and cannot be had.
std::unique_ptr<Backend> make_backend(DeviceKind kind);

}  // namespace signorini
