#pragma once
// Where the iterative contact solver keeps its vectors and runs its kernels: the CPU (always
// built) or an NVIDIA GPU through CUDA (built when the CUDA toolkit is found, docs/gpu.md).

#include "signorini/core/enum_names.hpp"

namespace signorini {

enum class DeviceKind { Cpu, Cuda };

inline constexpr EnumNames<DeviceKind, 2> kDeviceKindNames{{
    {DeviceKind::Cpu, "cpu"},
    {DeviceKind::Cuda, "cuda"},
}};

}  // namespace signorini
