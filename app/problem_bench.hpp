#pragma once
// `signorini bench --problem FILE`: the cost of a contact solve of any problem file against one
// linear solve of the same discrete problem, in the same run (docs/performance.md, "Any problem
// against one linear solve"): the whole process from the shell (`signorini solve FILE`, a
// child), the contact solve in this process, and one solve of the same stiffness A x = b with the
// path's linear solver (analysis, factorisation and solve on the direct paths; CG with the same
// multigrid hierarchy, its set-up included, on the iterative one), best of N each (at least 2 in
// the process: the two solves are compared warm, after the first round's page faults; the whole
// process is cold, as a user runs it).

#include <string>

namespace signorini::app {

struct ProblemBenchOptions {
  std::string file;       ///< the problem file
  int repeats = 3;        ///< best of N (the whole process once over a million unknowns)
  std::string json_file;  ///< also write the figures as JSON here
};

/// Prints the table; returns kSuccess, or kNotConverged when a solve did not converge. Throws
/// InputError for a bad file, as `signorini solve` would.
int run_problem_bench(const ProblemBenchOptions& options);

}  // namespace signorini::app
