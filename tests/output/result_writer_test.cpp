// summary.json and contact.csv of a solved problem: the keys scripts rely on, one CSV row per
// contact node with the documented sign conventions, and files written only whole.

#include "signorini/output/result_writer.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "expect_contains.hpp"
#include "output/summary_keys.hpp"
#include "signorini/config.hpp"
#include "signorini/core/error.hpp"
#include "signorini/input/problem_schema.hpp"
#include "signorini/output/contact_csv.hpp"
#include "signorini/output/summary_json.hpp"
#include "temporary_folder.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;

struct Solved {
  ProblemSpec spec = paper_benchmark(12, 4);
  Model model = build_model(spec);
  ContactResult result = solve_contact(model.problem, spec.solver);
};

const Solved& solved() {
  static const Solved s;
  return s;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The numeric fields of a contact.csv row (all but the last, the boundary's name).
std::vector<double> fields_of(const std::string& line, std::string* name = nullptr) {
  std::vector<double> out;
  std::istringstream in(line);
  std::vector<std::string> fields;
  for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
  for (std::size_t k = 0; k + 1 < fields.size(); ++k) out.push_back(std::stod(fields[k]));
  if (name != nullptr && !fields.empty()) *name = fields.back();
  return out;
}

TEST(SummaryJson, HasTheDocumentedKeys) {
  const Solved& s = solved();
  ASSERT_TRUE(s.result.summary.converged()) << s.result.summary.message;
  const nlohmann::json j = summary_to_json(s.result, s.model, s.spec);
  for (const char* key : testing::kSummaryKeys) EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["converged"], true);
  EXPECT_EQ(j["termination"], "converged");
  ASSERT_TRUE(j.contains("factor_updates"));
  EXPECT_EQ(j["factor_updates"].size(), j["gnm_iterations"].size());
  EXPECT_EQ(j["method"], "uzawa_gnm");
  EXPECT_EQ(j["M"].get<double>(), s.result.summary.lagrangian);
  EXPECT_EQ(j["uzawa_iterations"].get<int>(), s.result.summary.outer_iterations);
  EXPECT_EQ(j["gnm_iterations"].get<std::vector<int>>(), s.result.summary.inner_iterations());
  EXPECT_EQ(j["gnm_iterations"].size(), j["dual_changes"].size());
  EXPECT_EQ(j["n_dofs"].get<Index>(), 2 * 13 * 5);
  EXPECT_EQ(j["n_contact_nodes"].get<Index>(), 13);
  EXPECT_EQ(j["contact_force_vector"].size(), 2U);
  for (const char* k : {"equilibrium", "penetration", "sign", "complementarity"})
    EXPECT_TRUE(j["kkt"].contains(k)) << k;
  EXPECT_TRUE(j["timings"].contains("assembly"));
  EXPECT_TRUE(j["timings"].contains("contact solve"));
  EXPECT_GE(j["timings"]["total"].get<double>(), j["timings"]["contact solve"].get<double>());
  EXPECT_EQ(j["problem"]["name"], "paper");
  EXPECT_EQ(j["problem"]["mesh"]["nx"], 12);
  EXPECT_EQ(j["problem"]["material"]["E"].get<double>(), 21.19e4);
  EXPECT_EQ(j["problem"]["solver"]["r"].get<double>(), 1e8);
  EXPECT_EQ(j["problem"]["solver"]["linear"]["type"], "cholmod");
  EXPECT_EQ(j["signorini_version"], SIGNORINI_VERSION);
}

// Every entry of `expected` is in `actual`, with the same value and JSON type (2, not 2.0).
void expect_within(const nlohmann::json& expected, const nlohmann::json& actual,
                   const std::string& path) {
  if (expected.is_object() && actual.is_object()) {
    for (const auto& [key, value] : expected.items()) {
      ASSERT_TRUE(actual.contains(key)) << path << "." << key;
      expect_within(value, actual[key], path + "." + key);
    }
  } else {
    EXPECT_EQ(actual.dump(), expected.dump()) << path;
  }
}

// The settings block, made from the option tables, says what it always said, key for key and
// type for type: scripts read it. (Options added later only add keys; the GNM and semismooth
// Newton limits became 0, automatic, when they began to scale with the contact set.)
TEST(SummaryJson, ProblemBlockIsUnchanged) {
  const Solved& s = solved();
  const nlohmann::json j = summary_to_json(s.result, s.model, s.spec);
  const nlohmann::json expected = nlohmann::json::parse(R"json({
    "name": "paper", "units": null,
    "mesh": {"type": "rectangle", "origin": [0.0, 0.0], "length": 3.0, "height": 1.0,
             "nx": 12, "ny": 4},
    "material": {"E": 211900.0, "nu": 0.277, "plane_model": "plane_strain"},
    "fem": {"gauss_points": 2, "boundary_gauss_points": 2},
    "clamp": [{"boundary": "left", "components": ["x", "y"]}],
    "traction": [{"boundary": "right", "p": "(0, 1)"},
                 {"boundary": "top", "p": "(0, -2/3 (3 - x))"}],
    "contact": {"boundary": "bottom", "gap": "0"},
    "solver": {"method": "uzawa_gnm", "r": 100000000.0, "auto_r_factor": 10.0,
               "kkt_tolerance": 1e-06, "uzawa_tolerance": 1e-08, "max_uzawa_iterations": 1000,
               "gnm_tolerance": 1e-10, "max_gnm_iterations": 0, "armijo_sigma": 0.0001,
               "max_armijo_halvings": 60, "classical_step": 0.0,
               "max_classical_iterations": 200000, "max_newton_iterations": 0,
               "schur_complement": true, "device": "cpu",
               "linear": {"type": "cholmod", "cg_tolerance": 1e-13, "cg_max_iterations": 0,
                          "preconditioner": "jacobi", "coarsening": "auto",
                          "chebyshev_degree": 2}}})json");
  expect_within(expected, j["problem"], "problem");
  // Every option of the tables is there, under its table's path.
  for (const auto& [key, value] : option_values(s.spec)) {
    nlohmann::json at = j["problem"];
    std::string rest = key;
    for (auto dot = rest.find('.'); dot != std::string::npos; dot = rest.find('.')) {
      at = at[rest.substr(0, dot)];
      rest = rest.substr(dot + 1);
    }
    EXPECT_TRUE(at.contains(rest)) << key;
  }
}

TEST(ContactCsv, OneRowPerContactNodeWithConventions) {
  const Solved& s = solved();
  const std::vector<std::string> lines = lines_of(contact_csv(s.result, s.model));
  ASSERT_EQ(lines.size(), 14U);
  EXPECT_EQ(lines[0], "x,y,u_n,u_t,pressure,gap,n_x,n_y,s,boundary");
  const Vector u = s.model.dofs.expand(s.result.u);
  const ContactSet& c = s.model.problem.contact;
  for (Index j = 0; j < c.size(); ++j) {
    std::string name;
    const std::vector<double> f = fields_of(lines[static_cast<std::size_t>(j + 1)], &name);
    ASSERT_EQ(f.size(), 9U);
    EXPECT_EQ(name, "bottom");
    // Arc length from the first node: on the straight bottom edge, x itself.
    EXPECT_NEAR(f[8], f[0] - s.model.mesh.node(c.nodes[0])(0), 1e-15);
    const Index node = c.nodes[static_cast<std::size_t>(j)];
    EXPECT_EQ(f[0], s.model.mesh.node(node)(0));  // 17 digits: exact round trip
    EXPECT_EQ(f[1], 0.0);
    // The bottom edge: nu = (0, -1), tau = (-nu_y, nu_x) = (1, 0).
    EXPECT_DOUBLE_EQ(f[2], -u(2 * node + 1));
    EXPECT_DOUBLE_EQ(f[3], u(2 * node));
    EXPECT_EQ(f[4], s.result.l(j));
    EXPECT_GE(f[4], 0.0);
    EXPECT_EQ(f[5], 0.0);
    EXPECT_EQ(f[6], 0.0);  // the outward normal of the bottom edge
    EXPECT_EQ(f[7], -1.0);
  }
}

TEST(ResultWriter, WritesEveryFileIntoANewFolder) {
  const Solved& s = solved();
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "a" / "b";
  write_results(out, s.result, s.model, s.spec);
  std::ifstream json_file(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(json_file);
  EXPECT_EQ(j["converged"], true);
  std::ifstream csv(out / "contact.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "x,y,u_n,u_t,pressure,gap,n_x,n_y,s,boundary");
  for (const char* vtu : {"solution.vtu", "contact.vtu"}) EXPECT_TRUE(fs::exists(out / vtu)) << vtu;
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(out)) ++entries;
  EXPECT_EQ(entries, 4U);  // and no temporary file
}

TEST(ResultWriter, FolderThatCannotBeCreated) {
  const Solved& s = solved();
  const testing::TemporaryFolder dir;
  std::ofstream(dir / "file") << "a file, not a folder\n";
  try {
    write_results(dir / "file", s.result, s.model, s.spec);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(e.what(), "cannot create output folder '" + (dir / "file").string() + "': ");
  }
  EXPECT_THROW(write_results(dir / "file" / "below", s.result, s.model, s.spec), InputError);
}

}  // namespace
}  // namespace signorini
