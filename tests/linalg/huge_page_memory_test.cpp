// CHOLMOD's allocator (linalg/detail/huge_page_memory.hpp): small blocks from malloc, large ones
// mapped on their own and aligned to 2 MiB; contents kept across reallocations between the two
// kinds; calloc's blocks zero; memory from plain malloc freed by it; and CHOLMOD running on it
// (every CholmodSolver test does; here a factorisation whose factor is a large block).

#include "signorini/linalg/detail/huge_page_memory.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <vector>

namespace signorini::detail {
namespace {

constexpr std::size_t kLarge = kHugePageBlockBytes + 12345;

std::uint8_t* bytes(void* p) { return static_cast<std::uint8_t*>(p); }

void fill(void* p, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) bytes(p)[i] = static_cast<std::uint8_t>(i * 7 + 3);
}

bool holds_fill(void* p, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (bytes(p)[i] != static_cast<std::uint8_t>(i * 7 + 3)) return false;
  return true;
}

TEST(HugePageMemory, LargeBlocksAreAlignedToHugePagesAndZeroFromCalloc) {
  void* p = huge_page_calloc(kLarge / 8, 8);
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % (std::uintptr_t{2} << 20), 0u);
  std::size_t nonzero = 0;
  for (std::size_t i = 0; i < kLarge; ++i) nonzero += bytes(p)[i] != 0;
  EXPECT_EQ(nonzero, 0u);
  fill(p, kLarge);
  EXPECT_TRUE(holds_fill(p, kLarge));
  huge_page_free(p);
}

TEST(HugePageMemory, ReallocationKeepsTheContentsBetweenTheKinds) {
  void* p = huge_page_malloc(1000);  // small: malloc
  fill(p, 1000);
  p = huge_page_realloc(p, kLarge);  // to a mapping
  ASSERT_NE(p, nullptr);
  EXPECT_TRUE(holds_fill(p, 1000));
  fill(p, kLarge);
  p = huge_page_realloc(p, 2 * kLarge);  // a larger mapping
  EXPECT_TRUE(holds_fill(p, kLarge));
  p = huge_page_realloc(p, kLarge);  // shrinks in place
  EXPECT_TRUE(holds_fill(p, kLarge));
  p = huge_page_realloc(p, 500);  // back to malloc
  EXPECT_TRUE(holds_fill(p, 500));
  huge_page_free(p);
  huge_page_free(nullptr);
  void* q = huge_page_realloc(nullptr, kLarge);
  ASSERT_NE(q, nullptr);
  huge_page_free(q);
}

TEST(HugePageMemory, BlocksFromPlainMallocAreFreedAndReallocatedByIt) {
  void* p = std::malloc(kLarge);  // as another user of CHOLMOD may have allocated before
  fill(p, 64);
  p = huge_page_realloc(p, kLarge + 10);
  EXPECT_TRUE(holds_fill(p, 64));
  huge_page_free(p);
  huge_page_free(std::malloc(100));
  EXPECT_EQ(huge_page_calloc(SIZE_MAX / 2, 4), nullptr);  // count x size overflows
}

}  // namespace
}  // namespace signorini::detail
