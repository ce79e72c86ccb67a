#pragma once
// The rows of a contact.csv (docs/output.md) as numbers and the boundary's name: what the tests
// of the tool's runs compare.

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "app/tool_run.hpp"

namespace signorini::testing {

struct ContactCsvRow {
  double x = 0.0, y = 0.0, u_n = 0.0, u_t = 0.0, pressure = 0.0, gap = 0.0, n_x = 0.0, n_y = 0.0,
         s = 0.0;
  std::string boundary;
};

/// The rows of the contact.csv at `path`, after checking its header.
inline std::vector<ContactCsvRow> contact_csv_rows(const std::filesystem::path& path) {
  std::istringstream csv(read_text(path));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "x,y,u_n,u_t,pressure,gap,n_x,n_y,s,boundary") << path;
  std::vector<ContactCsvRow> rows;
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, ',');) f.push_back(field);
    EXPECT_EQ(f.size(), 10U) << line;
    if (f.size() != 10U) continue;
    rows.push_back({std::stod(f[0]), std::stod(f[1]), std::stod(f[2]), std::stod(f[3]),
                    std::stod(f[4]), std::stod(f[5]), std::stod(f[6]), std::stod(f[7]),
                    std::stod(f[8]), f[9]});
  }
  return rows;
}

}  // namespace signorini::testing
