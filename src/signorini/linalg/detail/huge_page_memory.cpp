#include "signorini/linalg/detail/huge_page_memory.hpp"

#include <SuiteSparse_config.h>
#include <malloc.h>
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <unordered_map>

namespace signorini::detail {

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

// The blocks mapped here and their lengths (a few dozen at a time: the map is never hot).
struct Mappings {
  std::mutex mutex;
  std::unordered_map<void*, std::size_t> bytes;
};

Mappings& mappings() {
  static Mappings* m = new Mappings;  // never destroyed: CHOLMOD may free during exit
  return *m;
}

// A mapping of at least `bytes`, aligned to a huge page (the slack around it unmapped), zero.
void* map_block(std::size_t bytes) {
  const std::size_t length = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* raw =
      mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) return nullptr;
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
  if (aligned > start) munmap(raw, aligned - start);
  const std::uintptr_t end = start + length + kHugePage;
  if (end > aligned + length)
    munmap(reinterpret_cast<void*>(aligned + length), end - aligned - length);
  void* block = reinterpret_cast<void*>(aligned);
  madvise(block, length, MADV_HUGEPAGE);
  const std::lock_guard lock(mappings().mutex);
  mappings().bytes.emplace(block, length);
  return block;
}

// The length of a block mapped here (0: not one of them), forgotten when `forget`.
std::size_t mapped_length(void* block, bool forget) {
  const std::lock_guard lock(mappings().mutex);
  const auto it = mappings().bytes.find(block);
  if (it == mappings().bytes.end()) return 0;
  const std::size_t length = it->second;
  if (forget) mappings().bytes.erase(it);
  return length;
}

}  // namespace

void* huge_page_malloc(std::size_t bytes) {
  if (bytes < kHugePageBlockBytes) return std::malloc(bytes);
  return map_block(bytes);
}

void* huge_page_calloc(std::size_t count, std::size_t size) {
  if (size != 0 && count > SIZE_MAX / size) return nullptr;
  const std::size_t bytes = count * size;
  if (bytes < kHugePageBlockBytes) return std::calloc(count, size);
  return map_block(bytes);  // a fresh mapping is zero
}

void* huge_page_realloc(void* block, std::size_t bytes) {
  if (block == nullptr) return huge_page_malloc(bytes);
  const std::size_t mapped = mapped_length(block, false);
  if (mapped == 0 && bytes < kHugePageBlockBytes) return std::realloc(block, bytes);
  if (mapped != 0 && bytes <= mapped && bytes >= kHugePageBlockBytes) return block;
  // Between the two kinds, or a mapping that grows: a new block and a copy of what fits.
  void* fresh = huge_page_malloc(bytes);
  if (fresh == nullptr) return nullptr;
  const std::size_t old = mapped != 0 ? mapped : malloc_usable_size(block);
  std::memcpy(fresh, block, old < bytes ? old : bytes);
  huge_page_free(block);
  return fresh;
}

void huge_page_free(void* block) {
  if (block == nullptr) return;
  if (const std::size_t length = mapped_length(block, true); length != 0) {
    munmap(block, length);
    return;
  }
  std::free(block);
}

void use_huge_pages_for_cholmod() {
  static std::once_flag once;
  std::call_once(once, [] {
    SuiteSparse_config.malloc_func = huge_page_malloc;
    SuiteSparse_config.calloc_func = huge_page_calloc;
    SuiteSparse_config.realloc_func = huge_page_realloc;
    SuiteSparse_config.free_func = huge_page_free;
  });
}

}  // namespace signorini::detail
