// `signorini bench --whole-process` and `--peers` (app/whole_process_bench.hpp): each solve a
// separate process measured from outside, and the PETSc SNESVI peer
// (bench/peers/petsc_snesvi.py) on the same discrete problem. The peer's tests skip themselves
// where petsc4py is missing (Debian: apt-get install python3-petsc4py).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/tool_run.hpp"
#include "expect_contains.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;

using testing::quoted;
using testing::read_text;
using testing::run_tool;
using testing::ToolRun;

const std::string kPeerScript = SIGNORINI_EXAMPLES_DIR "/../bench/peers/petsc_snesvi.py";
const std::string kPaper = SIGNORINI_EXAMPLES_DIR "/paper.toml";

constexpr const char* kNoPetsc4py =
    "petsc4py is not importable by /usr/bin/python3 (apt-get install python3-petsc4py)";

bool petsc4py_available() {
  return std::system("/usr/bin/python3 -c 'import numpy, petsc4py' > /dev/null 2>&1") == 0;
}

// The tokens of the table row of `program` at `mesh` ("30x10", "signorini").
std::vector<std::string> table_row(const std::string& out, const std::string& mesh,
                                   const std::string& program) {
  std::istringstream lines(out);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::vector<std::string> tokens;
    for (std::string w; words >> w;) tokens.push_back(w);
    if (tokens.size() >= 2 && tokens[0] == mesh && tokens[1] == program) return tokens;
  }
  return {};
}

double number(std::string text) {
  std::erase(text, ',');
  return std::stod(text);
}

// J(u) of `signorini solve examples/paper.toml` on an nx x ny mesh, from its summary.json.
double signorini_energy(const testing::TemporaryFolder& dir, int nx, int ny) {
  const fs::path out = dir / fmt::format("solve-{}x{}", nx, ny);
  const ToolRun r = run_tool(dir, fmt::format("solve {} -o {} -q --set mesh.nx={} --set mesh.ny={}",
                                              quoted(kPaper), quoted(out.string()), nx, ny));
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(read_text(out / "summary.json"))["energy"].get<double>();
}

TEST(BenchWholeProcess, TableAndJsonOfTheToolAsASeparateProcess) {
  const testing::TemporaryFolder dir;
  const fs::path json = dir / "whole.json";
  const ToolRun r = run_tool(
      dir, "bench --whole-process --mesh 30x10 --repeat 1 --json " + quoted(json.string()));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_CONTAINS(r.out, "Whole process, best of 1 by wall time");
  EXPECT_EQ(r.out.find("petsc_snesvi"), std::string::npos) << "no peer without --peers:\n" << r.out;

  // mesh, program, wall, user, sys, minor faults, peak MB, timers, J(u), rel. diff, ratio, active
  const std::vector<std::string> row = table_row(r.out, "30x10", "signorini");
  ASSERT_EQ(row.size(), 12U) << r.out;
  const double wall = number(row[2]), timers = number(row[7]), energy = number(row[8]);
  EXPECT_GT(wall, 0.0);
  EXPECT_GE(number(row[3]) + number(row[4]), 0.0);
  EXPECT_GT(number(row[5]), 0.0);  // minor page faults: any process has some
  EXPECT_GT(number(row[6]), 0.0);  // peak MB
  EXPECT_GT(timers, 0.0);
  EXPECT_LT(timers, wall);  // the phase timers run inside the process
  EXPECT_EQ(row[9], "-");
  EXPECT_EQ(row[10], "1.00");

  const auto j = nlohmann::json::parse(read_text(json));
  EXPECT_EQ(j["mode"], "whole_process");
  ASSERT_EQ(j["rows"].size(), 1U);
  const auto& s = j["rows"][0];
  EXPECT_EQ(s["mesh"], "30x10");
  EXPECT_EQ(s["program"], "signorini");
  EXPECT_DOUBLE_EQ(s["wall_seconds"].get<double>(), s["wall_seconds_each"][0].get<double>());
  EXPECT_GT(s["minor_faults"].get<long>(), 0);
  EXPECT_GT(s["peak_rss_bytes"].get<double>(), 1e6);
  EXPECT_EQ(s["converged"], true);
  EXPECT_NEAR(s["energy"].get<double>(), energy, 1e-11 * std::abs(energy));  // 12 digits shown

  // The problem the children solve is examples/paper.toml's.
  const double reference = signorini_energy(dir, 30, 10);
  EXPECT_NEAR(s["energy"].get<double>(), reference, 1e-12 * std::abs(reference));
}

TEST(BenchWholeProcess, FlagsThatDoNotGoWithItAreRefused) {
  const testing::TemporaryFolder dir;
  const ToolRun cg = run_tool(dir, "bench --whole-process --cg --mesh 30x10");
  EXPECT_EQ(cg.status, 2);
  EXPECT_CONTAINS(cg.err, "--cg does not go with --whole-process");
  const ToolRun config = run_tool(dir, "bench --whole-process --peer-config gamg --mesh 30x10");
  EXPECT_EQ(config.status, 2);
  EXPECT_CONTAINS(config.err, "--peer-config goes with --peers");
  const ToolRun script = run_tool(dir, "bench --peers --mesh 30x10 --repeat 1",
                                  "SIGNORINI_PEER_SCRIPT=" + quoted((dir / "none.py").string()));
  EXPECT_EQ(script.status, 2);
  EXPECT_CONTAINS(script.err, "SIGNORINI_PEER_SCRIPT = ");
  const ToolRun warmup = run_tool(dir, "bench --warmup 2 --mesh 30x10");
  EXPECT_EQ(warmup.status, 2);
  EXPECT_CONTAINS(warmup.err, "--warmup goes with --whole-process or --peers");
  const ToolRun both = run_tool(dir, "bench --whole-process --interleave --warmup 1 --mesh 30x10");
  EXPECT_EQ(both.status, 2);
  EXPECT_CONTAINS(both.err, "--warmup does not go with --interleave");
}

// Program by program after the warm-up runs (the default), or interleaved: the runs are made in
// that order, and only the timed ones are kept.
TEST(BenchWholeProcess, WarmUpRunsAreMadeAndNotCounted) {
  const testing::TemporaryFolder dir;
  const fs::path json = dir / "whole.json";
  ToolRun r = run_tool(dir,
                       "bench --whole-process --mesh 30x10 --mesh 20x10 --repeat 2 "
                       "--warmup 1 --json " +
                           quoted(json.string()));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_CONTAINS(r.out,
                  "best of 2 by wall time (program by program, after 1 warm-up run(s) each)");
  EXPECT_CONTAINS(r.err,
                  "  running 30x10 signorini (warm-up)\n  running 30x10 signorini (1/2)\n"
                  "  running 30x10 signorini (2/2)\n  running 20x10 signorini (warm-up)\n");
  auto j = nlohmann::json::parse(read_text(json));
  EXPECT_EQ(j["warmup"], 1);
  EXPECT_EQ(j["order"], "program by program");
  ASSERT_EQ(j["rows"].size(), 2U);
  EXPECT_EQ(j["rows"][0]["wall_seconds_each"].size(), 2U);

  r = run_tool(dir, "bench --whole-process --mesh 30x10 --repeat 2 --interleave --json " +
                        quoted(json.string()));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_CONTAINS(r.out, "(programs interleaved repeat by repeat)");
  EXPECT_EQ(r.err.find("warm-up"), std::string::npos) << r.err;
  j = nlohmann::json::parse(read_text(json));
  EXPECT_EQ(j["warmup"], 0);
  EXPECT_EQ(j["order"], "interleaved");
}

TEST(BenchWholeProcess, PeerWithoutPetsc4pyIsSkippedSayingHowToInstallIt) {
  const testing::TemporaryFolder dir;
  // An "interpreter" that cannot import anything.
  const ToolRun r =
      run_tool(dir, "bench --peers --mesh 30x10 --repeat 1", "SIGNORINI_PYTHON=/bin/false");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_CONTAINS(r.out, "peer skipped: petsc4py (or numpy) is not importable by /bin/false");
  EXPECT_CONTAINS(r.out, "apt-get install python3-petsc4py");
  EXPECT_FALSE(table_row(r.out, "30x10", "signorini").empty()) << r.out;
}

// The children run in the user's environment, not in the one the tool's start-up tuning made
// for itself (app/process_tuning.hpp): a stand-in peer records what it was given.
TEST(BenchWholeProcess, ChildrenGetTheUsersEnvironment) {
  const testing::TemporaryFolder dir;
  const fs::path fake = dir / "fake_peer.py";
  const fs::path seen = dir / "seen.txt";
  std::ofstream(fake) << "import json, os, sys\n"
                         "with open("
                      << quoted(seen.string())
                      << ", 'w') as f:\n"
                         "    for k in ('GLIBC_TUNABLES', 'OPENBLAS_NUM_THREADS',\n"
                         "              'SIGNORINI_PROCESS_TUNED', 'MY_SETTING'):\n"
                         "        f.write(f'{k}={os.environ.get(k)}\\n')\n"
                         "out = sys.argv[sys.argv.index('--json') + 1]\n"
                         "json.dump({'config': 'fake', 'energy': 1.0, 'converged': True,\n"
                         "           'seconds': {'total': 0.0}}, open(out, 'w'))\n";
  const ToolRun r =
      run_tool(dir, "bench --peers --mesh 30x10 --repeat 1",
               "SIGNORINI_PYTHON=/usr/bin/python3 SIGNORINI_PEER_SCRIPT=" + quoted(fake.string()) +
                   " MY_SETTING=kept GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX512F");
  // The stand-in's energy is wrong on purpose: the tool says so loudly and fails.
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_CONTAINS(r.out, "<-- ENERGIES DIFFER");
  EXPECT_CONTAINS(r.err, "they differ by");
  EXPECT_EQ(read_text(seen),
            "GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX512F\nOPENBLAS_NUM_THREADS=None\n"
            "SIGNORINI_PROCESS_TUNED=None\nMY_SETTING=kept\n");
}

TEST(BenchWholeProcess, PeerSolvesTheSameDiscreteProblem) {
  if (!petsc4py_available()) GTEST_SKIP() << kNoPetsc4py;
  const testing::TemporaryFolder dir;
  const fs::path json = dir / "peer.json";
  const int status = std::system(("/usr/bin/python3 " + quoted(kPeerScript) +
                                  " --nx 30 --ny 10 --quiet --json " + quoted(json.string()))
                                     .c_str());
  ASSERT_EQ(status, 0);
  const auto peer = nlohmann::json::parse(read_text(json));
  EXPECT_EQ(peer["converged"], true);
  EXPECT_EQ(peer["n_unknowns"], 2 * 30 * 11);  // the left edge eliminated
  const double reference = signorini_energy(dir, 30, 10);
  const double energy = peer["energy"].get<double>();
  EXPECT_LE(std::abs(energy - reference), 1e-8 * std::abs(reference))
      << "peer " << energy << ", signorini " << reference;
  const auto summary = nlohmann::json::parse(read_text(dir / "solve-30x10" / "summary.json"));
  EXPECT_EQ(peer["active_nodes"], summary["n_active"]);
}

TEST(BenchWholeProcess, PeersRunSideBySideAndAgree) {
  if (!petsc4py_available()) GTEST_SKIP() << kNoPetsc4py;
  const testing::TemporaryFolder dir;
  const fs::path json = dir / "peers.json";
  const ToolRun r =
      run_tool(dir,
               "bench --peers --mesh 30x10 --repeat 1 --peer-config mumps --peer-config "
               "gamg --json " +
                   quoted(json.string()),
               "SIGNORINI_PYTHON=/usr/bin/python3");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  for (const char* program : {"mumps", "gamg"}) {
    std::istringstream lines(r.out);
    std::string line;
    bool found = false;
    while (std::getline(lines, line))
      found =
          found || (line.find("30x10 petsc_snesvi " + std::string(program)) != std::string::npos);
    EXPECT_TRUE(found) << program << "\n" << r.out;
  }
  const auto j = nlohmann::json::parse(read_text(json));
  ASSERT_EQ(j["rows"].size(), 3U);
  for (std::size_t k = 1; k < 3; ++k) {
    const auto& p = j["rows"][k];
    EXPECT_EQ(p["program"], "petsc_snesvi");
    EXPECT_GT(p["wall_seconds"].get<double>(), 0.0);
    EXPECT_LE(p["relative_energy_difference"].get<double>(), 1e-8);
    EXPECT_EQ(p["converged"], true);
  }
}

// The 3D peer (bench/peers/petsc_snesvi_3d.py) poses examples/box_on_sphere.toml on hex8 cells
// itself: its energy and active nodes are the tool's on the 8 x 8 x 4 mesh.
TEST(BenchWholeProcess, ThreeDimensionalPeerSolvesTheSameDiscreteProblem) {
  if (!petsc4py_available()) GTEST_SKIP() << kNoPetsc4py;
  const testing::TemporaryFolder dir;
  const fs::path json = dir / "peer3d.json";
  const std::string script = SIGNORINI_EXAMPLES_DIR "/../bench/peers/petsc_snesvi_3d.py";
  for (const char* config : {"gamg", "mumps"}) {
    SCOPED_TRACE(config);
    const int status = std::system(("/usr/bin/python3 " + quoted(script) + " --n 8 --config " +
                                    config + " --quiet --json " + quoted(json.string()))
                                       .c_str());
    ASSERT_EQ(status, 0);
    const auto peer = nlohmann::json::parse(read_text(json));
    EXPECT_EQ(peer["converged"], true);
    EXPECT_EQ(peer["n_unknowns"], 3 * 9 * 9 * 4);  // the top face eliminated
    const ToolRun r = run_tool(
        dir, "solve " + quoted(SIGNORINI_EXAMPLES_DIR "/box_on_sphere.toml") + " -q -o " +
                 quoted((dir / "box").string()) +
                 " --set mesh.nx=8 --set mesh.ny=8 --set mesh.nz=4 --set 'mesh.cell=\"hex8\"'");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto summary = nlohmann::json::parse(read_text(dir / "box" / "summary.json"));
    const double reference = summary["energy"].get<double>();
    EXPECT_LE(std::abs(peer["energy"].get<double>() - reference), 1e-8 * std::abs(reference));
    EXPECT_EQ(peer["active_nodes"], summary["n_active"]);
    EXPECT_EQ(peer["n_unknowns"], summary["n_free_dofs"]);
  }
}

}  // namespace
}  // namespace signorini
