#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/contact_methods.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "signorini/contact/condensed_problem.hpp"
#include "signorini/contact/kkt_residuals.hpp"
#include "signorini/contact/modified_lagrangian.hpp"
#include "signorini/core/error.hpp"

namespace signorini {

double relative_change(const Vector& l_new, const Vector& l_old) {
  const double diff = (l_new - l_old).norm();
  const double norm = l_new.norm();
  if (norm > 0.0) return diff / norm;
  return diff == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
}

namespace {
ContactResult run_method(const ContactProblem& problem, const ContactSolverOptions& options) {
  switch (options.method) {
    case ContactMethod::UzawaGnm:
      return solve_uzawa_gnm(problem, options);
    case ContactMethod::ClassicalUzawa:
      return solve_classical_uzawa(problem, options);
    case ContactMethod::SemismoothNewton:
      return solve_semismooth_newton(problem, options);
  }
  throw InputError("unknown contact method");
}
}  // namespace

namespace {

std::string residual_list(const KktResiduals& k) {
  return fmt::format("equilibrium {:.2e}, penetration {:.2e}, sign {:.2e}, complementarity {:.2e}",
                     k.equilibrium, k.penetration, k.sign, k.complementarity);
}

// What to try when a solve stops short (the message ends with it): the augmentation parameter
// when it is far from the automatic one, the limits, and the method that needs no r.
std::string advice(const SolveSummary& s, const ContactSolverOptions& o) {
  std::vector<std::string> tips;
  const bool uzawa_gnm = s.method == ContactMethod::UzawaGnm;
  if (uzawa_gnm && !s.r_automatic && s.automatic_r > 0.0) {
    const double ratio = s.r / s.automatic_r;
    if (ratio > 1e3 || ratio < 1e-3)
      tips.push_back(fmt::format(
          "solver.r = {:.3g} is {:.1e} times the automatic r = {:.3g} for this problem: remove "
          "solver.r to use the automatic choice",
          s.r, ratio, s.automatic_r));
  }
  switch (s.termination) {
    case Termination::IterationLimit:
      if (s.method == ContactMethod::UzawaGnm && !s.steps.empty() &&
          s.steps.back().inner_iterations >= o.max_gnm_iterations)
        tips.emplace_back("raise solver.max_gnm_iterations");
      else if (s.method == ContactMethod::UzawaGnm)
        tips.emplace_back("raise solver.max_uzawa_iterations");
      else if (s.method == ContactMethod::ClassicalUzawa)
        tips.emplace_back("raise solver.max_classical_iterations");
      else
        tips.emplace_back("raise solver.max_newton_iterations");
      break;
    case Termination::LinearSolverFailure:
      if (o.linear.type == LinearSolverType::ConjugateGradient)
        tips.emplace_back(
            "raise solver.linear.cg_max_iterations or use solver.linear.type = \"cholmod\"");
      break;
    case Termination::KktResidualsTooLarge:
      if (s.kkt.equilibrium > o.kkt_tolerance &&
          o.linear.type == LinearSolverType::ConjugateGradient)
        tips.emplace_back("tighten solver.linear.cg_tolerance");
      if (std::max({s.kkt.penetration, s.kkt.complementarity, s.kkt.sign}) > o.kkt_tolerance &&
          s.method != ContactMethod::SemismoothNewton)
        tips.emplace_back("lower solver.uzawa_tolerance");
      break;
    default:
      break;
  }
  if (s.method != ContactMethod::SemismoothNewton)
    tips.emplace_back("solver.method = \"semismooth_newton\" needs no r");
  else
    tips.emplace_back("solver.method = \"uzawa_gnm\" converges for any r");
  std::string out;
  for (const std::string& t : tips) out += (out.empty() ? "" : "; ") + t;
  return out;
}

}  // namespace

ContactResult solve_contact(const ContactProblem& problem, const ContactSolverOptions& given) {
  validate(given);
  const Index n = problem.A.rows();
  if (problem.A.cols() != n || problem.b.size() != n || problem.contact.N.cols() != n)
    throw InputError("contact problem: sizes of A, b and N do not match");

  // r is resolved here, on the full problem, so that the condensed and backend paths use the
  // same value (method.md section 7).
  ContactSolverOptions options = given;
  const double r_auto = automatic_r(problem, given.auto_r_factor);
  options.r = given.r ? *given.r : r_auto;

  ContactResult result;
  {
    TimingTable solve_time;
    ScopedTimer timer(solve_time, "contact solve");
    if (uses_backend_path(options)) {
      result = solve_uzawa_gnm_on_backend(problem, options);
    } else if (options.schur_complement && options.linear.type == LinearSolverType::Cholmod) {
      const CondensedProblem condensed(problem);
      ContactSolverOptions reduced_options = options;
      reduced_options.linear.type = LinearSolverType::Dense;
      result = run_method(condensed.reduced(), reduced_options);
      result.u = condensed.expand(result.u);
      TimingTable t = condensed.timings();
      t.merge(result.summary.timings);
      result.summary.timings = std::move(t);
    } else {
      result = run_method(problem, options);
    }
    timer.stop();
    result.summary.timings.merge(solve_time);
  }
  SolveSummary& s = result.summary;
  s.method = options.method;
  s.outer_iterations = static_cast<int>(s.steps.size());
  s.r = *options.r;
  s.r_automatic = !given.r.has_value();
  s.automatic_r = r_auto;
  s.kkt_tolerance = options.kkt_tolerance;
  s.kkt = kkt_residuals(problem, result.u, result.l);
  s.energy = 0.5 * result.u.dot(problem.A * result.u) - problem.b.dot(result.u);
  s.lagrangian = ModifiedLagrangian::value(problem, *options.r, result.u, result.l);
  const ContactSet& c = problem.contact;
  s.contact_force = c.weights.dot(result.l);
  s.contact_force_vector = -(c.normals * c.weights.cwiseProduct(result.l));
  s.num_active = (result.l.array() > 0.0).count();

  // Converged means the KKT conditions hold, not only that the method's rule was met: a
  // penalty so large that the Newton systems lose their digits, or a tolerance on the change
  // of l that stops early, must not pass for an answer (method.md section 7).
  const bool kkt_ok = s.kkt.max() <= options.kkt_tolerance;  // false for NaN too
  if (s.termination == Termination::Converged && !kkt_ok) {
    s.termination = Termination::KktResidualsTooLarge;
    s.message = fmt::format(
        "the method's rule was met ({}), but the KKT residuals are above solver.kkt_tolerance = "
        "{:.1e}: {}",
        s.message, options.kkt_tolerance, residual_list(s.kkt));
  } else if (!s.converged()) {
    s.message += "; KKT residuals: " + residual_list(s.kkt);
  }
  if (!s.converged()) s.message += "; to try: " + advice(s, options);
  return result;
}

}  // namespace signorini
