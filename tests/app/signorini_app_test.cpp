// The command-line tool end to end: run `signorini` on the examples in a temporary folder and
// check exit statuses, messages and result files.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/tool_run.hpp"
#include "expect_contains.hpp"
#include "output/summary_keys.hpp"
#include "signorini/backend/cuda_backend.hpp"
#include "signorini/config.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;

using testing::count_lines;
using testing::quoted;
using testing::run_tool;
using testing::ToolRun;

std::string read(const fs::path& p) {
  return testing::read_text(p);
}

const std::string kSmall = quoted(SIGNORINI_EXAMPLES_DIR "/paper_small.toml");

TEST(SignoriniApp, Version) {
  const testing::TemporaryFolder dir;
  const ToolRun r = run_tool(dir, "--version");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind(std::string("signorini ") + SIGNORINI_VERSION + "\n", 0), 0U) << r.out;
  EXPECT_CONTAINS(r.out, "CHOLMOD: ");
  EXPECT_CONTAINS(r.out, "Eigen: ");
  EXPECT_CONTAINS(r.out, "OpenMP: ");
#ifdef SIGNORINI_HAVE_CUDA
  EXPECT_CONTAINS(r.out, "CUDA: built with toolkit ");
  const CudaReport cuda = cuda_report();
  if (cuda.gpus.empty()) {
    EXPECT_CONTAINS(r.out, "no usable GPU: ");
  } else {
    EXPECT_CONTAINS(r.out, "GPU 0: " + cuda.gpus.front().name);
  }
#else
  EXPECT_CONTAINS(r.out, "CUDA: not built");
#endif
  // The distributed engine: built (signorini-mpi) or not, as the build found PETSc.
#ifdef SIGNORINI_TEST_WITH_PETSC
  EXPECT_CONTAINS(r.out, "PETSc: 3.");
#else
  EXPECT_CONTAINS(r.out, "PETSc: not built");
#endif
}

TEST(SignoriniApp, CudaWithoutAGpuIsAClearError) {
  if (!cuda_report().gpus.empty()) GTEST_SKIP() << "a GPU is present (tests/contact/*_gpu_test)";
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "results";
  const ToolRun r = run_tool(dir, "solve " + kSmall + " -o " + quoted(out.string()) +
                                      " --set solver.device=cuda --set solver.linear.type=cg");
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_CONTAINS(r.err, "solver.device = \"cuda\"");
  EXPECT_EQ(r.out.find("model: "), std::string::npos) << "the model was built first:\n" << r.out;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  // The direct solver cannot run on the GPU: the message says what to set.
  const ToolRun direct = run_tool(
      dir, "solve " + kSmall + " -o " + quoted(out.string()) + " --set solver.device=cuda");
  EXPECT_EQ(direct.status, 2);
  EXPECT_CONTAINS(direct.err, "set solver.linear.type = \"cg\"");
  // `check` finds it too, before any solve.
  const ToolRun check = run_tool(dir, "check " + quoted(SIGNORINI_EXAMPLES_DIR "/paper_gpu.toml"));
  EXPECT_EQ(check.status, 2) << check.out << check.err;
  EXPECT_CONTAINS(check.err, "solver.device = \"cuda\"");
}

TEST(SignoriniApp, MultigridConjugateGradientsGiveTheTable1Energy) {
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "results";
  // examples/paper_gpu.toml on the CPU backend, on the smallest Table 1 mesh.
  const ToolRun r = run_tool(dir, "solve " + quoted(SIGNORINI_EXAMPLES_DIR "/paper_gpu.toml") +
                                      " -o " + quoted(out.string()) +
                                      " --quiet --set solver.device=cpu --set mesh.nx=60"
                                      " --set mesh.ny=20");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(testing::read_text(out / "summary.json"));
  EXPECT_NEAR(j["M"].get<double>(), -6.700472e-05, 2e-7 * 6.700472e-05);  // as table1_test
  EXPECT_EQ(j["uzawa_iterations"].get<int>(), 6);
  EXPECT_EQ(j["gnm_iterations"][0].get<int>(), 7);
  EXPECT_EQ(j["outer_iterations"], j["uzawa_iterations"]);  // the method-neutral names
  EXPECT_EQ(j["inner_iterations"], j["gnm_iterations"]);
  EXPECT_EQ(j["multigrid_levels"].size(), 3U);
  EXPECT_EQ(j["problem"]["solver"]["linear"]["preconditioner"], "multigrid");
}

TEST(SignoriniApp, SolvesTheSmallPaperExample) {
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "results";
  const ToolRun r = run_tool(dir, "solve " + kSmall + " -o " + quoted(out.string()));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  // The effective settings, the iteration log, the report and the timing table.
  EXPECT_CONTAINS(r.out, "[solver]\nmethod = \"uzawa_gnm\"\nr = 100000000.0\n");
  EXPECT_CONTAINS(r.out, "  uzawa 1  gnm 1  active ");
  EXPECT_CONTAINS(r.out, "uzawa 1: ||dl||/||l|| = ");
  EXPECT_CONTAINS(r.out, "converged");
  EXPECT_CONTAINS(r.out, "contact solve");

  const nlohmann::json j = nlohmann::json::parse(read(out / "summary.json"));
  for (const char* key : testing::kSummaryKeys) EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["converged"], true);
  EXPECT_EQ(j["n_dofs"], 2562);
  EXPECT_EQ(j["n_contact_nodes"], 61);
  // Table 1 of the paper, 60 x 20: M(u*, l*) = -6.700472e-05 (7 digits printed).
  EXPECT_NEAR(j["M"].get<double>(), -6.700472e-05, 1e-11);

  const std::string csv = read(out / "contact.csv");
  EXPECT_EQ(count_lines(csv), 62U);  // header + 61 contact nodes
  EXPECT_EQ(csv.rfind("x,y,u_n,u_t,pressure,gap,n_x,n_y,s,boundary\n", 0), 0U);
  // The ParaView files (their contents: tests/output/solution_vtu_test.cpp).
  for (const char* vtu : {"solution.vtu", "contact.vtu"})
    EXPECT_EQ(
        read(out / vtu).rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\"", 0), 0U)
        << vtu;
  EXPECT_CONTAINS(r.out, "results: " + out.string() + "/summary.json, " + out.string() +
                             "/contact.csv, " + out.string() + "/solution.vtu, " + out.string() +
                             "/contact.vtu\n");
}

TEST(SignoriniApp, PaperExampleReproducesTheLastRowOfTable1) {
  // examples/paper.toml as it is: 480 x 160, the paper's largest mesh (Table 1: n_p = 154882,
  // GNM 10 at the first Uzawa step, 11 Uzawa steps, M(u*, l*) = -6.715744e-05 to 7 digits).
  const testing::TemporaryFolder dir;
  const ToolRun r = run_tool(dir, "solve " + quoted(SIGNORINI_EXAMPLES_DIR "/paper.toml") +
                                      " --quiet -o " + quoted((dir / "out").string()));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(read(dir / "out" / "summary.json"));
  EXPECT_TRUE(j["converged"].get<bool>());
  EXPECT_EQ(j["n_dofs"].get<long>(), 154882);
  EXPECT_EQ(j["n_contact_nodes"].get<long>(), 481);
  EXPECT_EQ(j["uzawa_iterations"].get<int>(), 11);
  EXPECT_EQ(j["gnm_iterations"][0].get<int>(), 10);
  EXPECT_NEAR(j["M"].get<double>(), -6.715744e-05, 2e-7 * 6.715744e-05);
  EXPECT_LT(j["kkt"]["equilibrium"].get<double>(), 1e-8);
}

TEST(SignoriniApp, QuietPrintsNothingAndOverridesApply) {
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "results";
  const ToolRun r =
      run_tool(dir, "solve " + kSmall + " --set mesh.nx=30 --set mesh.ny=10 " +
                        "--set solver.method=semismooth_newton -q -o " + quoted(out.string()));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "");
  const nlohmann::json j = nlohmann::json::parse(read(out / "summary.json"));
  EXPECT_EQ(j["method"], "semismooth_newton");
  EXPECT_EQ(j["problem"]["mesh"]["nx"], 30);
  EXPECT_EQ(count_lines(read(out / "contact.csv")), 32U);
}

TEST(SignoriniApp, BadFileGivesStatus2AndOneLine) {
  const testing::TemporaryFolder dir;
  const fs::path bad = dir / "bad.toml";
  std::ofstream(bad) << read(SIGNORINI_EXAMPLES_DIR "/paper_small.toml") << "\n[solver.linear]\n"
                     << "typ = \"cg\"\n";
  const fs::path out = dir / "results";
  const ToolRun r = run_tool(dir, "solve " + quoted(bad.string()) + " -o " + quoted(out.string()));
  EXPECT_EQ(r.status, 2);
  // The line of the misspelt key: the example's lines, an empty one, the table header, the key.
  const std::string example = read(SIGNORINI_EXAMPLES_DIR "/paper_small.toml");
  const auto line = std::count(example.begin(), example.end(), '\n') + 3;
  EXPECT_EQ(r.err, "signorini: error: " + bad.string() + ":" + std::to_string(line) +
                       ": unknown key 'solver.linear.typ' (did you mean 'solver.linear.type'?)\n");
  EXPECT_FALSE(fs::exists(out));  // nothing is written for bad input
}

TEST(SignoriniApp, MissingFileUnknownBoundaryAndBadOptions) {
  const testing::TemporaryFolder dir;
  const std::string out = quoted((dir / "results").string());
  ToolRun r = run_tool(dir, "solve /no/such.toml -o " + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "signorini: error: cannot read '/no/such.toml': No such file or directory\n");

  r = run_tool(dir, "solve " + kSmall + " --set contact.boundary=floor -o " + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(count_lines(r.err), 1U) << r.err;
  EXPECT_CONTAINS(r.err, "signorini: error: ");
  EXPECT_CONTAINS(r.err, "floor");

  r = run_tool(dir, "solve " + kSmall);  // no -o
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(count_lines(r.err), 1U) << r.err;

  r = run_tool(dir, "frobnicate");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(count_lines(r.err), 1U) << r.err;
}

TEST(SignoriniApp, OutputFolderThatCannotBeCreated) {
  const testing::TemporaryFolder dir;
  std::ofstream(dir / "file") << "x\n";
  const ToolRun r = run_tool(dir, "solve " + kSmall + " -q -o " + quoted((dir / "file").string()));
  EXPECT_EQ(r.status, 2);
  EXPECT_CONTAINS(r.err, "signorini: error: cannot create output folder '");
  EXPECT_EQ(count_lines(r.err), 1U);
}

TEST(SignoriniApp, NotConvergedGivesStatus3AndStillWrites) {
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "results";
  const ToolRun r =
      run_tool(dir, "solve " + kSmall + " -q --set solver.max_uzawa_iterations=2 -o " +
                        quoted(out.string()));
  EXPECT_EQ(r.status, 3);
  EXPECT_EQ(count_lines(r.err), 1U) << r.err;
  EXPECT_CONTAINS(r.err, "not converged (iteration_limit)");
  const nlohmann::json j = nlohmann::json::parse(read(out / "summary.json"));
  EXPECT_EQ(j["converged"], false);
  EXPECT_EQ(j["termination"], "iteration_limit");
  EXPECT_EQ(count_lines(read(out / "contact.csv")), 62U);
}

// solver.time_limit: the iterate reached is written, the status is 3, and the summary says why.
TEST(SignoriniApp, TimeLimitGivesStatus3AndWritesTheIterate) {
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "results";
  const ToolRun r = run_tool(
      dir, "solve " + kSmall + " -q --set solver.time_limit=1e-9 -o " + quoted(out.string()));
  EXPECT_EQ(r.status, 3);
  EXPECT_EQ(count_lines(r.err), 1U) << r.err;
  EXPECT_CONTAINS(r.err, "not converged (time_limit): stopped at solver.time_limit = 1e-09 s");
  const nlohmann::json j = nlohmann::json::parse(read(out / "summary.json"));
  EXPECT_EQ(j["termination"], "time_limit");
  EXPECT_EQ(j["outer_iterations"], 1);
  EXPECT_EQ(count_lines(read(out / "contact.csv")), 62U);
}

TEST(SignoriniApp, FreeRigidMotionIsBadInputBeforeAnySolve) {
  // Clamped in x only: the body can slide along y; it used to reach the factorisation (exit 4).
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "results";
  const ToolRun r = run_tool(
      dir, "solve " + kSmall + " -q --set 'clamp.0.components=[\"x\"]' -o " + quoted(out.string()));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(count_lines(r.err), 1U) << r.err;
  EXPECT_CONTAINS(r.err, "the clamps leave a rigid motion free (translation in y)");
  EXPECT_FALSE(fs::exists(out / "summary.json"));
}

TEST(SignoriniApp, FailedRunKeepsEarlierResults) {
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "results";
  ASSERT_EQ(run_tool(dir, "solve " + kSmall + " -q -o " + quoted(out.string())).status, 0);
  const std::string before = read(out / "summary.json");
  const ToolRun r =
      run_tool(dir, "solve " + kSmall + " -q --set material.nu=0.5 -o " + quoted(out.string()));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(read(out / "summary.json"), before);
}

TEST(SignoriniApp, Check) {
  const testing::TemporaryFolder dir;
  ToolRun r = run_tool(dir, "check " + kSmall);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out,
            "mesh: 1281 nodes, 1200 cells (quad4: 1200); boundary parts: bottom (61 nodes), left "
            "(21 nodes), right (21 nodes), top (61 nodes)\nsolver path: condensed direct: 61 "
            "contact nodes, a dense matrix of about 119 kB\nok: 2562 dofs, 61 contact nodes\n");
  r = run_tool(dir, "check " + kSmall + " --set mesh.nx=0");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "signorini: error: " SIGNORINI_EXAMPLES_DIR
                   "/paper_small.toml: key 'mesh.nx' = 0: expected an integer >= 1\n");
  r = run_tool(dir, "check " + quoted(SIGNORINI_EXAMPLES_DIR "/paper.toml"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_CONTAINS(r.out,
                  "\nok: 154882 dofs, 481 contact nodes\n");  // the paper's n_p and n_d, 480 x 160
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

// The terminal summary says the r used and the resultants, and they balance.
TEST(SignoriniApp, SummaryPrintsTheResultants) {
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "results";
  const ToolRun r = run_tool(dir, "solve " + kSmall + " -o " + quoted(out.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_CONTAINS(r.out, "  r = 1e+08 (given)\n");
  EXPECT_CONTAINS(r.out, "resultants (forces on the body):\n");
  EXPECT_CONTAINS(r.out, "  applied load          (0.000000e+00, -2.000000e+00)\n");
  EXPECT_CONTAINS(r.out, "  reaction of 'left'");
  const nlohmann::json j = nlohmann::json::parse(testing::read_text(out / "summary.json"));
  EXPECT_EQ(j["r"], 1e8);
  EXPECT_EQ(j["r_automatic"], false);
  EXPECT_EQ(j["problem"]["units"], "m-MPa");
  EXPECT_LT(j["resultants"]["relative_balance"].get<double>(), 1e-10);
  const double contact_y = j["resultants"]["contact"][1].get<double>();
  const double reaction_y = j["resultants"]["reactions"][0]["force"][1].get<double>();
  EXPECT_NEAR(contact_y + reaction_y, 2.0, 1e-10);  // they carry the applied -2 together
}

// `signorini bench` prints Table 1 beside the paper's: here its first two rows (best of 1).
TEST(SignoriniApp, BenchPrintsTable1BesideThePapers) {
  const testing::TemporaryFolder dir;
  const fs::path json = dir / "bench.json";
  const ToolRun r =
      run_tool(dir, "bench --repeats 1 --mesh 60x20 --mesh 120x40 --json " + quoted(json.string()));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_CONTAINS(r.out, "estimated time ");
  EXPECT_CONTAINS(r.out, "Table 1 of the paper beside ours");
  // The rows: our iteration counts and energies next to the paper's, computed by the run.
  const nlohmann::json j = nlohmann::json::parse(testing::read_text(json));
  ASSERT_EQ(j["rows"].size(), 2U);
  for (const auto& row : j["rows"]) {
    EXPECT_EQ(row["converged"], true);
    EXPECT_EQ(row["gnm_first"], row["paper"]["gnm_first"]);
    EXPECT_EQ(row["outer_iterations"], row["paper"]["uzawa_iterations"]);
    EXPECT_NEAR(row["M"].get<double>(), row["paper"]["M"].get<double>(),
                2e-7 * std::abs(row["paper"]["M"].get<double>()));
    const std::string line = fmt::format(
        "{:>8} {:>7} {:>4} {:>9} {:>9} {:>6} {:>6} {:>15.7e}", row["mesh"].get<std::string>(),
        row["n_dofs"].get<long>(), row["n_contact_nodes"].get<long>(),
        std::to_string(row["gnm_first"].get<int>()) + "/" +
            std::to_string(row["gnm_later"].get<int>()),
        std::to_string(row["paper"]["gnm_first"].get<int>()) + "/2",
        row["outer_iterations"].get<int>(), row["paper"]["uzawa_iterations"].get<int>(),
        row["M"].get<double>());
    EXPECT_CONTAINS(r.out, line);
  }
  // A flag of the full suite alone is refused, saying why.
  EXPECT_EQ(run_tool(dir, "bench --no-cg").status, 2);
}

}  // namespace
}  // namespace signorini
