#include "signorini/contact/contact_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "signorini/contact/condensed_problem.hpp"
#include "signorini/contact/contact_methods.hpp"
#include "signorini/contact/distributed_engine.hpp"
#include "signorini/contact/friction_law.hpp"
#include "signorini/contact/kkt_residuals.hpp"
#include "signorini/contact/method_table.hpp"
#include "signorini/contact/modified_lagrangian.hpp"
#include "signorini/core/error.hpp"
#include "signorini/interface/tangent_basis.hpp"

namespace signorini {

double relative_change(const Vector& l_new, const Vector& l_old) {
  const double diff = (l_new - l_old).norm();
  const double norm = l_new.norm();
  if (norm > 0.0) return diff / norm;
  return diff == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
}

namespace {

std::string residual_list(const KktResiduals& k) {
  return fmt::format("equilibrium {:.2e}, penetration {:.2e}, sign {:.2e}, complementarity {:.2e}",
                     k.equilibrium, k.penetration, k.sign, k.complementarity);
}

// What to try when a solve stops short (the message ends with it): the augmentation parameter
// when it is far from the automatic one, the limits, and another method only where it meets the
// failure: advice that the next run would find untrue is worse than none.
// `contact_nodes` sizes the automatic iteration limits (gnm_iteration_limit).
std::string advice(const SolveSummary& s, const ContactSolverOptions& o, Index contact_nodes) {
  std::vector<std::string> tips;
  const int gnm_limit_value = gnm_iteration_limit(o, contact_nodes);
  const bool uzawa_gnm = s.method == ContactMethod::UzawaGnm;
  if (uzawa_gnm && !s.r_automatic && s.automatic_r > 0.0) {
    const double ratio = s.r / s.automatic_r;
    if (ratio > 1e3 || ratio < 1e-3)
      tips.push_back(fmt::format(
          "solver.r = {:.3g} is {:.1e} times the automatic r = {:.3g} for this problem: remove "
          "solver.r to use the automatic choice",
          s.r, ratio, s.automatic_r));
  }
  // GNM stopped by its limit: its active set still moving, as semismooth Newton's would (the
  // same steps, with the multipliers fixed), so that method is no way out.
  const bool gnm_limit = uzawa_gnm && s.termination == Termination::IterationLimit &&
                         !s.steps.empty() && s.steps.back().inner_iterations >= gnm_limit_value;
  switch (s.termination) {
    case Termination::IterationLimit:
      if (gnm_limit)
        tips.emplace_back(
            fmt::format("raise solver.max_gnm_iterations (it was {})", gnm_limit_value));
      else if (uzawa_gnm)
        tips.emplace_back("raise solver.max_uzawa_iterations");
      else if (s.method == ContactMethod::ClassicalUzawa)
        tips.emplace_back("raise solver.max_classical_iterations");
      else  // semismooth Newton: no active set comes twice, so more steps end it
        tips.emplace_back(fmt::format("raise solver.max_newton_iterations (it was {})",
                                      newton_iteration_limit(o, contact_nodes)));
      break;
    case Termination::LinearSolverFailure:
      if (o.linear.type == LinearSolverType::ConjugateGradient)
        tips.emplace_back(
            "raise solver.linear.cg_max_iterations or use solver.linear.type = \"cholmod\"");
      break;
    case Termination::TimeLimit:
      tips.emplace_back("raise solver.time_limit (or 0: none)");
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
  switch (s.method) {
    case ContactMethod::UzawaGnm:
      if (!gnm_limit && s.termination != Termination::TimeLimit)
        tips.emplace_back("solver.method = \"semismooth_newton\" needs no r");
      break;
    case ContactMethod::SemismoothNewton:
      // Its active set may cycle; GNM's Armijo steps decrease a convex function and cannot.
      if (s.termination == Termination::ActiveSetCycling)
        tips.emplace_back("solver.method = \"uzawa_gnm\", whose line search cannot cycle");
      break;
    case ContactMethod::ClassicalUzawa:
      // Its steps converge linearly; Uzawa-GNM solves the same problem in Newton steps.
      if (s.termination == Termination::IterationLimit || s.termination == Termination::TimeLimit)
        tips.emplace_back("solver.method = \"uzawa_gnm\" (Newton steps: far fewer of them)");
      break;
  }
  std::string out;
  for (const std::string& t : tips) out += (out.empty() ? "" : "; ") + t;
  return out;
}

}  // namespace

struct ContactSolver::Impl {
  const ContactProblem* problem;  // the user's, or `changed` after set_loads/set_gaps
  std::unique_ptr<ContactProblem> changed;
  ContactSolverOptions given;    // as the user gave them (r may be "auto")
  ContactSolverOptions options;  // r resolved
  double r_auto = 0.0;
  SolvePath path = SolvePath::CondensedDirect;
  const MethodRow* row = nullptr;  // what runs the solves (method_table.hpp)
  std::unique_ptr<CondensedProblem> condensed;
  TimingTable setup_timings;          // "contact solve" of the set-up, condensation phases
  bool setup_reported = false;        // the set-up's time went into a solve's "contact solve"
  TimingTable condensation_reported;  // condensation phases already in a solve's timings
  std::optional<MethodStart> start;   // warm start: u (full problem) and l
  const MultigridHierarchy* multigrid = nullptr;

  // The problem to change: copied once, at the first change.
  ContactProblem& own_problem() {
    if (!changed) {
      changed = std::make_unique<ContactProblem>(*problem);
      problem = changed.get();
    }
    return *changed;
  }
};

namespace {

SolvePath choose_path(const ContactProblem& problem, const ContactSolverOptions& o) {
  if (distributed_path(problem, o)) return SolvePath::Distributed;
  if (uses_backend_path(o)) return SolvePath::Backend;
  if (o.schur_complement && o.linear.type == LinearSolverType::Cholmod)
    return SolvePath::CondensedDirect;
  if (o.linear.type == LinearSolverType::ConjugateGradient) return SolvePath::Iterative;
  return SolvePath::SparseDirect;
}

}  // namespace

ContactSolver::ContactSolver(const ContactProblem& problem, const ContactSolverOptions& given,
                             const MultigridHierarchy* multigrid)
    : impl_(std::make_unique<Impl>()) {
  validate(given);
  const Index n = problem.A.rows();
  const Index held = problem.end_row() - problem.first_row();  // (A's columns: column_of)
  if (problem.A.cols() != held || problem.b.size() != held || problem.contact.N.cols() != n)
    throw InputError("contact problem: sizes of A, b and N do not match");
  Impl& m = *impl_;
  m.problem = &problem;
  m.given = given;
  m.options = given;
  // r is resolved here, on the full problem, so that the condensed and backend paths use the
  // same value (method.md section 7).
  m.r_auto = automatic_r(problem, given.auto_r_factor);
  m.options.r = given.r ? *given.r : m.r_auto;
  m.path = choose_path(problem, m.options);
  require_law_fits(problem);
  const ContactLaw& law = contact_law(problem);
  // Friction (method.md, "Friction"): Uzawa-GNM and classical Uzawa run condensed onto the
  // contact nodes' free dofs (CondensedProblem); the backend's and the distributed Newton
  // matrices take the nodes' blocks for Uzawa-GNM; semismooth Newton's friction solver factorises
  // the whole KKT system (the full problem's, in one process). The table says it all.
  const LawKind kind = law_kind(law);
  m.path = table_path(m.path, m.options.method, kind);
  m.row = &method_row(m.path, m.options.method, kind, law.name(), m.options, problem.contact.kind);
  if (problem.partitioned() && m.path != SolvePath::Distributed)
    throw InputError(
        "a partitioned contact problem (each rank holding its part of A) is solved on the "
        "distributed path only (solver.distributed)");
  m.multigrid = multigrid;
  if (m.path == SolvePath::CondensedDirect) {
    ScopedTimer timer(m.setup_timings, "contact solve");
    m.condensed =
        std::make_unique<CondensedProblem>(problem, m.options.threads);  // the sparse factorisation
    timer.stop();
    m.setup_timings.merge(m.condensed->timings());
  }
}

ContactSolver::~ContactSolver() = default;
ContactSolver::ContactSolver(ContactSolver&&) noexcept = default;
ContactSolver& ContactSolver::operator=(ContactSolver&&) noexcept = default;

SolvePath ContactSolver::path() const {
  return impl_->path;
}
const TimingTable& ContactSolver::setup_timings() const {
  return impl_->setup_timings;
}

void ContactSolver::set_loads(const Vector& b) {
  Impl& m = *impl_;
  if (b.size() != m.problem->b.size())
    throw InputError(fmt::format("ContactSolver::set_loads: {} values for {} free dofs", b.size(),
                                 m.problem->b.size()));
  m.own_problem().b = b;
  if (m.condensed) m.condensed->set_load(b);
}

void ContactSolver::set_gaps(const Vector& gaps) {
  Impl& m = *impl_;
  if (gaps.size() != m.problem->contact.size())
    throw InputError(fmt::format("ContactSolver::set_gaps: {} values for {} contact nodes",
                                 gaps.size(), m.problem->contact.size()));
  m.own_problem().contact.gaps = gaps;
  if (m.condensed) m.condensed->set_gaps(gaps);
}

void ContactSolver::warm_start(const ContactResult& previous) {
  const Impl& m = *impl_;
  const ContactSet& c = m.problem->contact;
  const Index k = c.components;
  if (previous.u.size() != solution_size(*m.problem) || previous.l.size() != c.size() ||
      (k > 1 && (previous.tangential.rows() != k - 1 || previous.tangential.cols() != c.size())))
    throw InputError("ContactSolver::warm_start: the result is not one of this problem");
  // The layout of the methods: with friction d values per node.
  impl_->start = MethodStart{k > 1 ? node_multipliers(previous.l, previous.tangential) : previous.l,
                             previous.u};
}

void ContactSolver::set_slip_origin(const Vector& u) {
  Impl& m = *impl_;
  const ContactSet& c = m.problem->contact;
  if (c.components == 1) return;  // frictionless: slip plays no part
  if (u.size() != solution_size(*m.problem))
    throw InputError("ContactSolver::set_slip_origin: a displacement of this problem expected");
  const Index k = c.components;
  const Vector rows = contact_rows(*m.problem, u);
  Vector origin(static_cast<Index>(k - 1) * c.size());
  for (Index j = 0; j < c.size(); ++j)
    origin.segment((k - 1) * j, k - 1) = rows.segment(k * j + 1, k - 1);
  if (m.condensed) m.condensed->set_slip_origin(origin);
  m.own_problem().contact.slip_origin = std::move(origin);
}

void ContactSolver::cold_start() {
  impl_->start.reset();
}

ContactResult ContactSolver::solve() {
  Impl& m = *impl_;
  const ContactProblem& problem = *m.problem;
  // solver.time_limit: a callback around the user's that stops the run once the time is up,
  // at the next iteration (each method's loops honour a callback's stop).
  ContactSolverOptions limited = m.options;
  const auto started = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  };
  bool out_of_time = false;
  if (limited.time_limit > 0.0) {
    limited.callback = [&, user = m.options.callback](const IterationEvent& e) {
      if (user && user(e) == CallbackAction::Stop) return CallbackAction::Stop;
      if (elapsed() <= limited.time_limit) return CallbackAction::Continue;
      out_of_time = true;
      return CallbackAction::Stop;
    };
  }
  const ContactSolverOptions& options = limited;
  MethodStart start;
  if (m.start) {
    start.l = m.start->l;
    start.x = m.condensed ? m.condensed->condense(m.start->x) : m.start->x;
  }

  ContactResult result;
  {
    TimingTable solve_time;
    ScopedTimer timer(solve_time, "contact solve");
    if (m.path == SolvePath::CondensedDirect) {
      ContactSolverOptions reduced_options = options;
      reduced_options.linear.type = LinearSolverType::Dense;
      result = m.row->run(m.condensed->reduced(), reduced_options, start, m.multigrid);
      result.u = m.condensed->expand(result.u);
    } else {
      result = m.row->run(problem, options, start, m.multigrid);
    }
    timer.stop();
    // The set-up's time goes into the first solve's "contact solve" (the one-shot report is the
    // whole cost); the condensation phases of each solve (expansion, new loads) into its own.
    TimingTable t;
    if (!m.setup_reported && m.condensed)
      t.add("contact solve", m.setup_timings.seconds("contact solve"));
    m.setup_reported = true;
    if (m.condensed) {
      const TimingTable now = m.condensed->timings();
      for (const auto& [phase, seconds] : now.phases()) {
        const double fresh = seconds - m.condensation_reported.seconds(phase);
        if (fresh > 0.0) t.add(phase, fresh);
      }
      m.condensation_reported = now;
    }
    t.merge(result.summary.timings);
    t.merge(solve_time);
    result.summary.timings = std::move(t);
  }
  SolveSummary& s = result.summary;
  s.method = options.method;
  s.path = m.path;
  s.threads = m.condensed ? static_cast<int>(m.condensed->parts()) : 1;
  s.warm_started = m.start.has_value();
  s.outer_iterations = static_cast<int>(s.steps.size());
  s.r = *options.r;
  s.r_automatic = !m.given.r.has_value();
  s.automatic_r = m.r_auto;
  s.kkt_tolerance = options.kkt_tolerance;
  s.kkt = kkt_residuals(problem, result.u, result.l);
  s.energy = quadratic_energy(problem, result.u);
  s.lagrangian = ModifiedLagrangian::value(problem, *options.r, result.u, result.l);
  const ContactSet& c = problem.contact;
  if (c.components > 1) {
    // The methods' layout (d values per node) split into the pressure and the tangential part.
    const Index k = c.components;
    const Vector flat = std::move(result.l);
    const Vector rows = contact_rows(problem, result.u) - row_offsets(c);  // the tangential slip
    result.l.resize(c.size());
    result.tangential.resize(k - 1, c.size());
    result.slip.resize(c.size());
    for (Index j = 0; j < c.size(); ++j) {
      result.l(j) = flat(k * j);
      result.tangential.col(j) = flat.segment(k * j + 1, k - 1);
      result.slip(j) = rows.segment(k * j + 1, k - 1).norm();
    }
  }
  s.contact_force = c.weights.dot(result.l);
  s.contact_force_vector.setZero();
  s.contact_force_vector.head(c.normals.rows()) = -(c.normals * c.weights.cwiseProduct(result.l));
  if (result.tangential.size() > 0)  // friction: the tangential forces too
    s.contact_force_vector.head(c.normals.rows()) -=
        cartesian_tangential(c.normals, result.tangential) * c.weights;
  s.num_active = (result.l.array() > 0.0).count();

  // Converged means the KKT conditions hold, not only that the method's rule was met: a
  // penalty so large that the Newton systems lose their digits, or a tolerance on the change
  // of l that stops early, must not pass for an answer (method.md section 7).
  if (out_of_time && s.termination == Termination::StoppedByCallback) {
    s.termination = Termination::TimeLimit;
    s.message = fmt::format(
        "stopped at solver.time_limit = {:g} s, after {:.3g} s and {} outer iteration(s)",
        options.time_limit, elapsed(), s.outer_iterations);
  }
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
  if (!s.converged() && s.termination != Termination::StoppedByCallback)
    if (const std::string tips = advice(s, options, problem.contact.size()); !tips.empty())
      s.message += "; to try: " + tips;
  return result;
}

ContactResult solve_contact(const ContactProblem& problem, const ContactSolverOptions& options,
                            const MultigridHierarchy* multigrid) {
  return ContactSolver(problem, options, multigrid).solve();
}

}  // namespace signorini
