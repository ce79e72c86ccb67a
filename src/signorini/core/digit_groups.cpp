#include "signorini/core/digit_groups.hpp"

namespace signorini {

std::string with_thousands(long long n) {
  // Built forwards rather than by std::string::insert, on which g++ 12 warns falsely
  // (-Wrestrict) once it is inlined.
  const std::string digits = std::to_string(n);
  const std::size_t lead = digits[0] == '-' ? 1 : 0;
  std::string out = digits.substr(0, lead);
  for (std::size_t i = lead; i < digits.size(); ++i) {
    if (i > lead && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

}  // namespace signorini
