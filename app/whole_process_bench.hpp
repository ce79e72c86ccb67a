#pragma once
// `signorini bench --whole-process` and `--peers`: the paper's problem solved by the tool as a
// separate process per run (`signorini solve ... -q`), measured as from the shell (wall time,
// and CPU time, page faults and peak memory from wait4), and optionally the same discrete
// problem solved by PETSc's SNESVI (bench/peers/petsc_snesvi.py) in the same run, program by
// program after a warm-up run each, with the energies compared (docs/performance.md, "Whole process
// and the PETSc peer").

#include <string>
#include <utility>
#include <vector>

#include "signorini/core/types.hpp"

namespace signorini::app {

struct WholeProcessOptions {
  std::vector<std::pair<Index, Index>> meshes;  ///< nx x ny
  int repeats = 3;                              ///< best of N by wall time
  /// Untimed runs of each program before its timed repeats (not with `interleave`).
  int warmup = 1;
  /// Repeat by repeat across the programs (the order before 2026-12-02) instead of program by
  /// program: each run then follows another program's, and pays for that program's memory.
  bool interleave = false;
  bool peers = false;                     ///< also run the PETSc peer
  std::vector<std::string> peer_configs;  ///< the peer's --config values; empty: its default
  std::string json_file;                  ///< also write the rows as JSON here
};

/// Runs the measurements and prints the table. Returns kSuccess, kNotConverged (a run did not
/// converge) or kInternalError (the peer's energy differs from the tool's by more than 1e-8
/// relative); throws InputError when the tool or the peer cannot run.
int run_whole_process_bench(const WholeProcessOptions& options);

/// The relative difference |a - b| / |b| of two energies (|a - b| when b is 0).
double relative_difference(double a, double b);

/// The agreement required between the tool's J(u) and the peer's.
inline constexpr double kPeerEnergyTolerance = 1e-8;

}  // namespace signorini::app
