// The paper's benchmark through the library's public API: build the model of a problem, solve
// the contact problem, check the answer and write the result files. Built against the installed
// package (CMakeLists.txt here); the test suite builds and runs it.
//
//   contact_example [NX NY] [OUTPUT_FOLDER]

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <signorini/signorini.hpp>
#include <string>

int main(int argc, char** argv) {
  try {
    const signorini::Index nx = argc > 2 ? std::atol(argv[1]) : 60;
    const signorini::Index ny = argc > 2 ? std::atol(argv[2]) : 20;

    // A problem described in code (a problem file works too: signorini::read_problem_file).
    signorini::ProblemSpec spec = signorini::paper_benchmark(nx, ny);
    spec.solver.method = signorini::ContactMethod::UzawaGnm;

    const signorini::Model model = signorini::build_model(spec);  // mesh, A, b, contact boundary
    // model.solver: spec.solver with the path planned from the problem's size (docs/solvers.md).
    const signorini::ContactResult result =
        signorini::solve_contact(model.problem, model.solver, &model.multigrid);
    const signorini::SolveSummary& s = result.summary;

    std::printf("signorini %s: %s after %d Uzawa steps, J(u) = %.10e, %d active contact nodes\n",
                SIGNORINI_VERSION, s.converged() ? "converged" : "NOT converged",
                s.outer_iterations, s.energy, static_cast<int>(s.num_active));
    if (argc > 3 || argc == 2) {
      const std::string folder = argv[argc > 3 ? 3 : 1];
      signorini::write_results(folder, result, model, spec);
      std::printf("results in %s\n", folder.c_str());
    }
    return s.converged() ? 0 : 3;
  } catch (const signorini::InputError& e) {
    std::fprintf(stderr, "contact_example: bad input: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "contact_example: %s\n", e.what());
    return 1;
  }
}
