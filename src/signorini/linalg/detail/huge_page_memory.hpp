#pragma once
// CHOLMOD's large arrays (a supernodal factor's values: hundreds of MB on a large problem) in
// memory advised for transparent huge pages. CHOLMOD zeroes a factor before it assembles it, and
// each first touch of a 4 KiB page is a page fault: at 480x160 on the paper's problem half of
// the 98,600 faults of a run, 0.03-0.04 s. The tool gets huge pages for every array by starting
// itself with glibc's hugetlb tunable (app/process_tuning.cpp); a program that links the library,
// the Python package's interpreter above all, cannot set that after it has started. Blocks of
// at least kHugePageBlockBytes are mapped on their own, aligned to 2 MiB and advised with
// MADV_HUGEPAGE; smaller ones come from malloc as before. Where the kernel has transparent huge
// pages off ("never"), the advice does nothing and the blocks are plain mappings.

#include <cstddef>

namespace signorini::detail {

inline constexpr std::size_t kHugePageBlockBytes = std::size_t{4} << 20;

/// Points SuiteSparse's allocator (SuiteSparse_config's malloc, calloc, realloc and free) at
/// the functions below, once per process, before the first CHOLMOD call of the library. Memory
/// that CHOLMOD had allocated before (another user of CHOLMOD in the process) is still freed by
/// free(): only the blocks mapped here are known to be mappings.
void use_huge_pages_for_cholmod();

void* huge_page_malloc(std::size_t bytes);
void* huge_page_calloc(std::size_t count, std::size_t size);
void* huge_page_realloc(void* block, std::size_t bytes);
void huge_page_free(void* block);

}  // namespace signorini::detail
