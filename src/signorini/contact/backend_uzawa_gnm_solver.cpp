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
#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/generalized_newton.hpp"
#include "signorini/contact/modified_lagrangian.hpp"
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
      multigrid_ = std::make_unique<MultigridPreconditioner>(*H_, problem.A, problem.contact.N,
                                                             problem.prolongations, mo);
    } else {
      jacobi_ = std::make_unique<JacobiPreconditioner>(*H_);
    }
    be.synchronize();
    pcg_ = std::make_unique<Pcg>(be, n_);
    weights_active_.assign(static_cast<std::size_t>(nc_), false);
    Nx_ = Vector::Zero(nc_);
  }

  [[nodiscard]] const Vector& Nx() const { return Nx_; }
  [[nodiscard]] Vector solution() const { return to_host(x_); }
  [[nodiscard]] std::vector<Index> levels() const {
    return multigrid_ ? multigrid_->level_sizes() : std::vector<Index>{};
  }

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
      Vector w = Vector::Zero(nc_);
      for (Index j = 0; j < nc_; ++j)
        if (active[static_cast<std::size_t>(j)])
          w(j) = -cs.weights(j) * (phi.multipliers()(j) - phi.r() * cs.gaps(j));
      upload_into(w, contact_);
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
        Preconditioner& M = multigrid_ ? static_cast<Preconditioner&>(*multigrid_)
                                       : static_cast<Preconditioner&>(*jacobi_);
        lin = pcg_->solve(*H_, M, work_, x_new_, po);
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
      double t = 1.0;
      if (phi.phi_change(dir, 1.0) >= 0.0) {
        const Vector hz = cs.weights.cwiseProduct(dir.z.cwiseMax(0.0));
        const double slope = dir.residual_dot_d + hz.dot(dir.Nd);
        if (slope < 0.0) {
          double alpha = 1.0;
          int cuts = 0;
          do {
            alpha *= 0.5;
            ++cuts;
            if (cuts > o_.max_armijo_halvings) {
              res.termination = Termination::LineSearchFailure;
              res.message = fmt::format(
                  "Armijo rule found no decrease after {} halvings in GNM iteration {} of Uzawa "
                  "step {} (||G|| = {:.3e})",
                  o_.max_armijo_halvings, m, outer, gradient_norm);
              res.iterations = m;
              res.armijo_reductions += cuts;
              finish();
              return res;
            }
          } while (phi.phi_change(dir, alpha) > o_.armijo_sigma * alpha * slope);
          res.armijo_reductions += cuts;
          ev.armijo = cuts;
          t = alpha;
        }
      }
      const bool full = t == 1.0;
      be_.axpby(t, d_, 1.0, x_);
      be_.axpby(t, Ad_, 1.0, residual_);
      Nx_ = contact_values(x_);
      // G = (A x - b) + N^T (h z_+)
      const Vector hz = cs.weights.cwiseProduct(phi.shifted_multipliers(Nx_).cwiseMax(0.0));
      upload_into(hz, contact_);
      be_.copy(residual_, work_);
      H_->apply_contact_transpose(contact_, work_, 1.0);
      gradient_norm = norm(be_, work_);
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
    res.termination = Termination::IterationLimit;
    res.message = fmt::format(
        "GNM did not converge in {} iterations at Uzawa step {} (residual {:.3e}, tolerance "
        "{:.1e})",
        o_.max_gnm_iterations, outer, res.residual, o_.gnm_tolerance);
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
    if (multigrid_)
      multigrid_->refresh();
    else
      jacobi_->refresh();
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
  std::unique_ptr<JacobiPreconditioner> jacobi_;
  std::unique_ptr<MultigridPreconditioner> multigrid_;
  std::unique_ptr<Pcg> pcg_;
  DeviceVector b_, x_, x_new_, residual_, d_, Ad_, work_, contact_;
  ActiveSet weights_active_;
  Vector Nx_;
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
  ModifiedLagrangian phi(problem, options.r);
  Vector l = Vector::Zero(problem.contact.size());  // l^0 = 0
  s.termination = Termination::IterationLimit;
  bool stopped = false;
  for (int k = 1; k <= options.max_uzawa_iterations; ++k) {
    phi.set_multipliers(l);
    const GnmResult g = gnm.minimize(phi, k);
    OuterStepRecord rec;
    rec.inner_iterations = g.iterations;
    rec.armijo_reductions = g.armijo_reductions;
    rec.linear_iterations = g.linear_iterations;
    rec.factorizations = g.factorizations;
    rec.inner_residual = g.residual;
    if (g.termination != Termination::Converged) {
      rec.active_set_size = (l.array() > 0.0).count();
      s.steps.push_back(rec);
      s.termination = g.termination;
      s.message = g.message;
      stopped = true;
      break;
    }
    // Step (ii) of (13).
    const Vector l_new = phi.shifted_multipliers(gnm.Nx()).cwiseMax(0.0);
    rec.dual_change = relative_change(l_new, l);
    rec.active_set_size = (l_new.array() > 0.0).count();
    l = l_new;
    s.steps.push_back(rec);
    if (options.observer)
      options.observer({IterationEvent::Kind::Outer, k, g.iterations, rec.active_set_size,
                        rec.dual_change, rec.armijo_reductions, rec.linear_iterations});
    if (rec.dual_change < options.uzawa_tolerance) {
      s.termination = Termination::Converged;
      s.message = fmt::format("||l^k - l^(k-1)|| / ||l^k|| = {:.3e} < {:.1e} after {} Uzawa steps",
                              rec.dual_change, options.uzawa_tolerance, k);
      stopped = true;
      break;
    }
  }
  if (!stopped)
    s.message = fmt::format(
        "Uzawa did not converge in {} steps: ||l^k - l^(k-1)|| / ||l^k|| = {:.3e} (tolerance "
        "{:.1e})",
        options.max_uzawa_iterations, s.steps.empty() ? 0.0 : s.steps.back().dual_change,
        options.uzawa_tolerance);
  {
    ScopedTimer t(timings, "device download");
    out.u = gnm.solution();
  }
  s.device = backend->description();
  s.device_peak_bytes = backend->peak_bytes();
  s.multigrid_levels = gnm.levels();
  s.timings = std::move(timings);
  out.l = std::move(l);
  return out;
}

}  // namespace signorini
