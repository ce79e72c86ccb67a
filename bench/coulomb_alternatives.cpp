// Coulomb's law two ways with the paper's Uzawa-GNM, and the semismooth Newton method, on the
// same discrete problems (docs/performance.md, "Coulomb: inside the Uzawa loop or outside"):
//   inside:  one Uzawa-GNM run whose step (i) takes the slip bound mu times the pressure of the
//            current multipliers (the library's Coulomb law, friction_law.hpp);
//   outside: Tresca problems solved to convergence in turn, the slip bound mu times the previous
//            solution's pressure (from the frictionless pressure), each warm-started from the
//            last, until the pressure changes by less than the Uzawa tolerance;
//   ssn:     semismooth Newton on the whole KKT system (the Coulomb law directly).
// All on the sparse direct path (one symbolic analysis per solver), from one model.
//
//   build/release/bench/signorini_coulomb_alternatives PROBLEM.toml [--set KEY=VALUE ...]

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/friction_law.hpp"
#include "signorini/core/error.hpp"
#include "signorini/input/problem_file.hpp"
#include "signorini/problem/model.hpp"

namespace {

using namespace signorini;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Run {
  explicit Run(std::string n) : name(std::move(n)) {}
  std::string name;
  int outer = 0;    // Uzawa steps (Newton steps for ssn), all solves together
  int inner = 0;    // GNM steps
  int factors = 0;  // numeric factorisations
  int solves = 0;   // Tresca problems (outside)
  double seconds = 0.0;
  ContactResult last;
};

void add(Run& run, const ContactResult& r) {
  run.outer += r.summary.outer_iterations;
  for (const OuterStepRecord& s : r.summary.steps) {
    run.inner += s.inner_iterations;
    run.factors += s.factorizations;
  }
  ++run.solves;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 2) {
      std::fprintf(stderr, "usage: %s PROBLEM.toml [--set KEY=VALUE ...]\n", argv[0]);
      return 2;
    }
    std::vector<std::string> overrides;
    for (int i = 2; i + 1 < argc; i += 2) overrides.emplace_back(argv[i + 1]);
    const LoadedProblem loaded = read_problem_file(argv[1], overrides);
    const Model model = build_model(loaded.spec);
    // (A benchmark of Coulomb's law itself: it asks for the law's coefficients.)
    const auto friction = std::dynamic_pointer_cast<const FrictionLaw>(model.problem.law);
    if (!friction || friction->mu().maxCoeff() <= 0.0)
      throw InputError(std::string(argv[1]) +
                       ": expected a contact boundary with Coulomb friction");
    const ContactProblem& p = model.problem;
    const Index nc = p.contact.size();
    const int dim = model.mesh.dim();
    const Vector mu = friction->mu();
    ContactSolverOptions base = model.solver;
    base.schur_complement = false;  // the sparse direct path for all three
    base.uzawa_tolerance = std::min(base.uzawa_tolerance, 1e-10);

    std::vector<Run> runs;
    {  // inside: the library's Coulomb law
      Run run("inside the Uzawa loop");
      const auto start = std::chrono::steady_clock::now();
      run.last = solve_contact(p, base);
      run.seconds = seconds_since(start);
      add(run, run.last);
      runs.push_back(std::move(run));
    }
    {  // outside: Tresca problems, the bound from the previous pressure
      Run run("outside: Tresca solves");
      const auto start = std::chrono::steady_clock::now();
      // The first bound: mu times the frictionless pressure.
      ContactProblem tresca = p;  // (the same problem, its law replaced at each solve)
      tresca.law = std::make_shared<const FrictionLaw>(FrictionKind::Tresca, dim, Vector::Zero(nc));
      const ContactSolverOptions o = base;
      ContactResult r = solve_contact(tresca, o);
      add(run, r);
      for (int k = 0; k < 200; ++k) {
        tresca.law =
            std::make_shared<const FrictionLaw>(FrictionKind::Tresca, dim, mu.cwiseProduct(r.l));
        ContactSolver solver(tresca, o);
        solver.warm_start(r);
        const ContactResult next = solver.solve();
        add(run, next);
        const double change = (next.l - r.l).norm() / std::max(next.l.norm(), 1e-300);
        r = next;
        if (!r.summary.converged() || change < base.uzawa_tolerance) break;
      }
      run.seconds = seconds_since(start);
      run.last = std::move(r);
      runs.push_back(std::move(run));
    }
    {  // semismooth Newton
      Run run("semismooth Newton");
      ContactSolverOptions o = base;
      o.method = ContactMethod::SemismoothNewton;
      const auto start = std::chrono::steady_clock::now();
      run.last = solve_contact(p, o);
      run.seconds = seconds_since(start);
      add(run, run.last);
      run.inner = 0;
      runs.push_back(std::move(run));
    }
    fmt::print("{}: {} free unknowns, {} contact nodes, mu up to {:g}\n", argv[1], p.A.rows(), nc,
               mu.maxCoeff());
    fmt::print("{:<24} {:>9} {:>8} {:>11} {:>6} {:>6} {:>10} {:>12}\n", "method", "converged",
               "solves", "outer steps", "GNM", "LLT", "seconds", "|u - u_ref|");
    const Vector& ref = runs.back().last.u;
    for (const Run& r : runs)
      fmt::print("{:<24} {:>9} {:>8} {:>11} {:>6} {:>6} {:>10.3f} {:>12.2e}\n", r.name,
                 r.last.summary.converged() ? "yes" : "NO", r.solves, r.outer, r.inner, r.factors,
                 r.seconds, (r.last.u - ref).norm() / ref.norm());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "signorini_coulomb_alternatives: %s\n", e.what());
    return 2;
  }
}
