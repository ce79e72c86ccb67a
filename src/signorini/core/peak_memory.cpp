#include "signorini/core/peak_memory.hpp"

#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>

namespace signorini {

namespace {

// The number after `key` on its line of a /proc file ("VmHWM:   123 kB"), in KiB; 0 if absent.
double kib_field(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(key, 0) == 0) {
      std::istringstream value(line.substr(key.size()));
      double kib = 0.0;
      value >> kib;
      return kib;
    }
  }
  return 0.0;
}

}  // namespace

double peak_resident_bytes() {
  return kib_field("/proc/self/status", "VmHWM:") * 1024.0;
}

bool reset_peak_resident() {
  std::ofstream clear("/proc/self/clear_refs");
  if (!clear) return false;
  clear << "5";
  return static_cast<bool>(clear.flush());
}

double physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return 0.0;
  return static_cast<double>(pages) * static_cast<double>(page_size);
}

double available_memory_bytes() {
  return kib_field("/proc/meminfo", "MemAvailable:") * 1024.0;
}

}  // namespace signorini
