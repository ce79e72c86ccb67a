// Whole-process speed of the tool: the allocator and BLAS settings that a large solve needs,
// applied by re-executing the tool once with them in its environment (docs/performance.md,
// "Whole process").
#pragma once

namespace signorini::app {

// For the commands that assemble and factorise large matrices (solve, check, bench), re-executes
// the running program with
//   GLIBC_TUNABLES  += glibc.malloc.hugetlb=1 (transparent huge pages for the heap),
//                      trim_threshold / mmap_threshold / top_pad (freed memory kept and reused)
//   OPENBLAS_NUM_THREADS = 1 (CHOLMOD's supernodes are small; BLAS threads only compete with
//                             the OpenMP threads of assembly and PCG)
// unless the user set either variable, SIGNORINI_PROCESS_TUNING=off, or the program already
// runs tuned. glibc reads its tunables and OpenBLAS its thread count only at start-up, which is
// why a re-execution is needed. Returns normally (untuned) where the re-execution is not possible.
void tune_process(int argc, char** argv);

/// What tune_process() sets: the marker variable of a tuned process and the malloc tunables it
/// appends to GLIBC_TUNABLES (child_process.cpp takes them out again for the children).
inline constexpr const char* kProcessTunedMarker = "SIGNORINI_PROCESS_TUNED";
inline constexpr const char* kTunedMallocSettings =
    "glibc.malloc.hugetlb=1:glibc.malloc.trim_threshold=4294967296:"
    "glibc.malloc.mmap_threshold=33554432:glibc.malloc.top_pad=67108864";

}  // namespace signorini::app
