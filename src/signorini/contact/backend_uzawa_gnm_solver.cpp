// The paper's method (13) with GNM (17) on a backend (docs/gpu.md): the same iteration as
// uzawa_gnm_solver.cpp and generalized_newton.cpp, with every vector of the size of the mesh in
// the backend's memory (the GPU's with solver.device = "cuda") and the Newton systems solved by
// preconditioned conjugate gradients there. The stiffness is uploaded once; per GNM iteration only
// scalars (dot products) and vectors of the contact nodes (N x, N d: n_c values, which decide the
// active set and the Armijo rule) cross between host and device.

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <memory>

#include "signorini/backend/make_backend.hpp"
#include "signorini/contact/armijo_rule.hpp"
#include "signorini/contact/contact_methods.hpp"
#include "signorini/contact/generalized_newton.hpp"
#include "signorini/contact/modified_lagrangian.hpp"
#include "signorini/contact/uzawa_iteration.hpp"
#include "signorini/core/error.hpp"
#include "signorini/iterative/jacobi_preconditioner.hpp"
#include "signorini/iterative/multigrid_preconditioner.hpp"
#include "signorini/iterative/pcg.hpp"

namespace signorini {

namespace {

class BackendGnm {
 public:
  BackendGnm(const ContactProblem& problem, const ContactSolverOptions& options, Backend& be,
             TimingTable& timings)
      : p_(problem),
        o_(options),
        be_(be),
        timings_(timings),
        n_(problem.A.rows()),
        nc_(problem.contact.size()) {
    {
      ScopedTimer t(timings_, "device upload");
      H_ = std::make_unique<PenalizedOperator>(be, problem.A, problem.contact.N);
      b_ = to_device(be, problem.b);
      x_ = DeviceVector(be, n_);
      x_new_ = DeviceVector(be, n_);
      residual_ = DeviceVector(be, n_);
      d_ = DeviceVector(be, n_);
      Ad_ = DeviceVector(be, n_);
      work_ = DeviceVector(be, n_);
      contact_ = DeviceVector(be, nc_);
      be.axpbyz(-1.0, b_, 0.0, b_, residual_);  // A x - b at x = 0
      b_norm_ = problem.b.norm();
      be.synchronize();
    }
    // The multigrid set-up (Galerkin coarse operators on the host, their upload) is timed apart
    // from the set-ups per active set ("preconditioner setup").
    ScopedTimer t(timings_, o_.linear.preconditioner == PreconditionerType::Multigrid
                                ? "multigrid setup"
                                : "preconditioner setup");
    if (o_.linear.preconditioner == PreconditionerType::Multigrid) {
      MultigridOptions mo;
      mo.smoother.degree = o_.linear.chebyshev_degree;
      auto mg = std::make_unique<MultigridPreconditioner>(*H_, problem.A, problem.contact.N,
                                                          problem.multigrid.prolongations, mo,
                                                          problem.multigrid.coarse_operators);
      levels_ = mg->level_sizes();
      preconditioner_ = std::move(mg);
    } else {
      preconditioner_ = std::make_unique<JacobiPreconditioner>(*H_);
    }
    be.synchronize();
    pcg_ = std::make_unique<Pcg>(be, n_);
    weights_active_.assign(static_cast<std::size_t>(nc_), false);
    Nx_ = Vector::Zero(nc_);
  }

  [[nodiscard]] const Vector& Nx() const { return Nx_; }
  [[nodiscard]] Vector solution() const { return to_host(x_); }
  /// Unknowns per multigrid level (empty with Jacobi).
  [[nodiscard]] const std::vector<Index>& levels() const { return levels_; }

  /// One step (i) of (13): x = argmin Phi for the multipliers set in phi (method.md section 4).
  GnmResult minimize(const ModifiedLagrangian& phi, int outer) {
    GnmResult res;
    ActiveSet previous;
    bool previous_full = false;
    double gradient_norm = std::numeric_limits<double>::infinity();
    const ContactSet& cs = p_.contact;
    const int refreshes_before = refreshes_;
    auto finish = [&] { res.factorizations = refreshes_ - refreshes_before; };

    for (int m = 1; m <= o_.max_gnm_iterations; ++m) {
      const ActiveSet active = phi.active_set(Nx_);
      IterationEvent ev{IterationEvent::Kind::Inner, outer, m, count_active(active), 0.0, 0, 0};
      // A repeated active set after a full Newton step: x is the minimiser already
      // (generalized_newton.cpp, method.md section 4).
      if (m > 1 && previous_full && active == previous) {
        res.iterations = m;
        res.residual = gradient_norm;
        ev.residual = res.residual;
        if (o_.observer) o_.observer(ev);
        finish();
        return res;
      }
      set_active(active, phi.r());

      // Newton right-hand side b - N^T (h (l - r g) on the active set), then H x_m = rhs (17).
      upload_into(Vector(-phi.newton_contact_terms(active)), contact_);
      be_.copy(b_, work_);
      H_->apply_contact_transpose(contact_, work_, 1.0);
      be_.copy(x_, x_new_);
      PcgResult lin;
      {
        ScopedTimer t(timings_, "linear solve");
        PcgOptions po;
        po.tolerance = o_.linear.cg_tolerance;
        po.max_iterations =
            o_.linear.cg_max_iterations > 0
                ? o_.linear.cg_max_iterations
                : static_cast<int>(std::min<Index>(10 * n_, std::numeric_limits<int>::max()));
        lin = pcg_->solve(*H_, *preconditioner_, work_, x_new_, po);
      }
      res.linear_iterations += lin.iterations;
      ev.linear_iterations = lin.iterations;
      if (!lin.converged) {
        res.termination = Termination::LinearSolverFailure;
        res.message = fmt::format(
            "conjugate gradients did not converge in GNM iteration {} of Uzawa step {} "
            "({} iterations, relative residual {:.3e}, tolerance {:.1e})",
            m, outer, lin.iterations, lin.residual, o_.linear.cg_tolerance);
        res.iterations = m;
        finish();
        return res;
      }

      // d = x_m - x_{m-1}; Armijo rule as in generalized_newton.cpp.
      be_.axpbyz(1.0, x_new_, -1.0, x_, d_);
      H_->apply_stiffness(d_, Ad_);
      ModifiedLagrangian::Direction dir;
      dir.residual_dot_d = be_.dot(residual_, d_);
      dir.d_A_d = be_.dot(Ad_, d_);
      dir.z = phi.shifted_multipliers(Nx_);
      dir.Nd = contact_values(d_);
      const ArmijoStep armijo =
          armijo_step(phi, dir, cs.weights, o_.armijo_sigma, o_.max_armijo_halvings);
      res.armijo_reductions += armijo.halvings;
      ev.armijo = armijo.halvings;
      if (armijo.failed) {
        res.termination = Termination::LineSearchFailure;
        res.message = armijo_failure_message(o_.max_armijo_halvings, m, outer, gradient_norm);
        res.iterations = m;
        finish();
        return res;
      }
      const double t = armijo.t;
      const bool full = t == 1.0;
      be_.axpby(t, d_, 1.0, x_);
      be_.axpby(t, Ad_, 1.0, residual_);
      Nx_ = contact_values(x_);
      // G = (A x - b) + N^T (h z_+)
      upload_into(phi.contact_forces(Nx_), contact_);
      be_.copy(residual_, work_);
      H_->apply_contact_transpose(contact_, work_, 1.0);
      gradient_norm = relative_gradient(norm(be_, work_), b_norm_, norm(be_, residual_));
      const double x_norm = norm(be_, x_);
      const double d_norm = t * norm(be_, d_);
      const double step = x_norm > 0.0 ? d_norm / x_norm : d_norm;
      res.residual = std::max(gradient_norm, step);
      res.iterations = m;
      ev.residual = res.residual;
      if (o_.observer) o_.observer(ev);
      if (res.residual < o_.gnm_tolerance) {
        finish();
        return res;
      }
      previous = active;
      previous_full = full;
    }
    set_gnm_iteration_limit(res, o_, outer);
    finish();
    return res;
  }

 private:
  // c_j = r h_j on the active set: H = A + N^T diag(c) N, and the preconditioner follows.
  void set_active(const ActiveSet& active, double r) {
    if (active == weights_active_) return;
    weights_active_ = active;
    Vector c = Vector::Zero(nc_);
    for (Index j = 0; j < nc_; ++j)
      if (active[static_cast<std::size_t>(j)]) c(j) = r * p_.contact.weights(j);
    ScopedTimer timer(timings_, "preconditioner setup");
    H_->set_weights(c);
    preconditioner_->refresh();
    ++refreshes_;
  }

  Vector contact_values(const DeviceVector& v) {
    H_->apply_contact(v, contact_);
    return to_host(contact_);
  }

  const ContactProblem& p_;
  const ContactSolverOptions& o_;
  Backend& be_;
  TimingTable& timings_;
  Index n_, nc_;
  std::unique_ptr<PenalizedOperator> H_;
  std::unique_ptr<Preconditioner> preconditioner_;
  std::vector<Index> levels_;
  std::unique_ptr<Pcg> pcg_;
  DeviceVector b_, x_, x_new_, residual_, d_, Ad_, work_, contact_;
  ActiveSet weights_active_;
  Vector Nx_;
  double b_norm_ = 0.0;
  int refreshes_ = 0;
};

}  // namespace

ContactResult solve_uzawa_gnm_on_backend(const ContactProblem& problem,
                                         const ContactSolverOptions& options) {
  ContactResult out;
  SolveSummary& s = out.summary;
  TimingTable timings;
  std::unique_ptr<Backend> backend;
  {
    ScopedTimer t(timings, "device setup");
    backend = make_backend(options.device);
  }
  BackendGnm gnm(problem, options, *backend, timings);
  ModifiedLagrangian phi(problem, augmentation_parameter(problem, options));
  run_uzawa_iteration(
      problem, options, phi,
      [&](const ModifiedLagrangian& current, int k, Vector& Nx) {
        const GnmResult g = gnm.minimize(current, k);
        Nx = gnm.Nx();
        return g;
      },
      out);
  {
    ScopedTimer t(timings, "device download");
    out.u = gnm.solution();
  }
  s.device = backend->description();
  s.device_peak_bytes = backend->peak_bytes();
  s.multigrid_levels = gnm.levels();
  s.multigrid_hierarchy = problem.multigrid.kind;
  s.timings = std::move(timings);
  return out;
}

}  // namespace signorini
