#include "signorini/problem/unit_system.hpp"

#include <algorithm>

namespace signorini {

const std::vector<std::string>& unit_system_names() {
  static const std::vector<std::string> names = {"m-Pa",   "m-kPa", "m-MPa", "m-GPa",
                                                 "mm-MPa", "mm-N",  "m-N"};
  return names;
}

bool is_unit_system(const std::string& name) {
  const auto& names = unit_system_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string unit_system_choices() {
  std::string out;
  for (const std::string& n : unit_system_names()) out += (out.empty() ? "\"" : ", \"") + n + "\"";
  return out;
}

}  // namespace signorini
