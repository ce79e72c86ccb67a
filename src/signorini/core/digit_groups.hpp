#pragma once
// Whole numbers for people: digits in groups of three ("1,045,572"), as the reports and the
// messages print counts of unknowns, nodes and page faults.

#include <string>

namespace signorini {

std::string with_thousands(long long n);

}  // namespace signorini
