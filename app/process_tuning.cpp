#include "process_tuning.hpp"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <string_view>

namespace signorini::app {

namespace {

bool heavy_command(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "solve" || arg == "check" || arg == "bench") return true;
    if (!arg.empty() && arg.front() != '-') return false;  // another command
    if (arg == "--help" || arg == "-h" || arg == "--version") return false;
  }
  return false;
}

// "[madvise]" or "[always]": madvise(MADV_HUGEPAGE), which glibc's hugetlb=1 issues, takes
// effect; "[never]": it does not, and only the thresholds would remain worth a re-execution.
bool transparent_huge_pages_available() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string mode;
  std::getline(in, mode);
  return mode.find("[always]") != std::string::npos || mode.find("[madvise]") != std::string::npos;
}

}  // namespace

void tune_process(int argc, char** argv) {
  if (std::getenv(kProcessTunedMarker) != nullptr || !heavy_command(argc, argv)) return;
  if (const char* off = std::getenv("SIGNORINI_PROCESS_TUNING");
      off != nullptr && std::strcmp(off, "off") == 0)
    return;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const bool user_set_malloc = tunables != nullptr && std::strstr(tunables, "glibc.malloc.");
  const bool user_set_blas = std::getenv("OPENBLAS_NUM_THREADS") != nullptr;
  if (user_set_malloc && user_set_blas) return;
  const std::string saved_tunables = tunables != nullptr ? tunables : "";

  // The heap is kept (trim_threshold) and grown in large steps (top_pad), and arrays up to
  // 32 MiB (glibc's ceiling for mmap_threshold) come from it, so the phases reuse memory that an
  // earlier phase faulted in; hugetlb=1 backs heap and mmap'ed arrays by 2 MiB pages, which
  // divides the first-touch faults of the large arrays by 512 (docs/performance.md).
  if (!user_set_malloc && transparent_huge_pages_available()) {
    std::string value = tunables != nullptr && *tunables != '\0' ? std::string(tunables) + ":" : "";
    value += kTunedMallocSettings;
    ::setenv("GLIBC_TUNABLES", value.c_str(), 1);
  }
  if (!user_set_blas) ::setenv("OPENBLAS_NUM_THREADS", "1", 1);
  ::setenv(kProcessTunedMarker, "1", 1);
  ::execv("/proc/self/exe", argv);
  // Not reached unless /proc is missing or exec is refused: go on untuned, with the environment
  // as it was for anything this process starts.
  ::unsetenv(kProcessTunedMarker);
  if (!user_set_blas) ::unsetenv("OPENBLAS_NUM_THREADS");
  if (tunables == nullptr)
    ::unsetenv("GLIBC_TUNABLES");
  else
    ::setenv("GLIBC_TUNABLES", saved_tunables.c_str(), 1);
}

}  // namespace signorini::app
