#include "signorini/contact/friction_ssn.hpp"

#include <fmt/format.h>

#include <Eigen/SparseCholesky>
#include <Eigen/UmfPackSupport>
#include <algorithm>
#include <stdexcept>

#include "signorini/contact/contact_methods.hpp"
#include "signorini/core/error.hpp"

namespace signorini {

FrictionSsnResult solve_friction_ssn(const ContactProblem& p, const SparseMatrix& T,
                                     const FrictionLawSpec& law, const FrictionSsnOptions& o) {
  const ContactSet& cs = p.contact;
  const Index nc = cs.size();
  if (nc == 0) throw InputError("friction: no contact nodes");
  if (T.rows() % nc != 0 || T.cols() != p.A.rows())
    throw InputError("friction: T must have (dim - 1) rows per contact node over the free dofs");
  const Index d = 1 + T.rows() / nc;
  if (d < 2 || d > 3) throw InputError("friction: 1 or 2 tangential rows per contact node");
  if (law.bound.size() != nc || !(law.bound.array() >= 0.0).all() || !law.bound.allFinite())
    throw InputError("friction: one finite bound >= 0 (s or mu) per contact node expected");
  ContactProblem frictional = p;
  add_tangential_rows(frictional.contact, T);
  return solve_friction_ssn(frictional, FrictionLaw(law.kind, static_cast<int>(d), law.bound), o);
}

FrictionSsnResult solve_friction_ssn(const ContactProblem& p, const ContactLaw& law,
                                     const FrictionSsnOptions& o, const Vector& u0,
                                     const Vector& l0) {
  const ContactSet& cs = p.contact;
  const Index n = p.A.rows(), nc = cs.size(), d = cs.components;
  if (nc == 0) throw InputError("friction: no contact nodes");
  if (p.partitioned())
    throw InputError("friction: a partitioned problem (the distributed path) is not supported");
  if (d < 2 || law.components() != d || law.nodes() != nc)
    throw InputError("friction: a frictional contact set and its law (one bound per node)");
  // B = [N; T] node by node: row d j the normal, rows d j + 1 .. the tangents.
  const SparseMatrix& B = cs.N;
  const Vector g_hat = row_offsets(cs);
  const Vector w = row_weights(cs);
  const SparseMatrix BtW = SparseMatrix(B.transpose()) * w.asDiagonal();
  const Eigen::SparseMatrix<double, Eigen::RowMajor> B_rows = B;  // for the rows of a node
  // The complementarity constant: a tenth of the body's normal stiffness per area at the contact
  // (automatic_r with the factor 0.1). Measured on the paper's strip with Coulomb's law: from
  // about half of that stiffness up (Uzawa-GNM's r is 10 times it) the iteration cycles at
  // mu = 5, below a twentieth it slows at mu = 20; a tenth converged in 3-9 steps for mu from
  // 0.3 to 5 on every mesh tried (docs/method.md, "Friction").
  const double c = o.c > 0.0 ? o.c : automatic_r(p, 0.1);

  FrictionSsnResult r;
  Vector lambda = Vector::Zero(d * nc);
  const bool frictional = law.has_friction();
  if (u0.size() == n && l0.size() == d * nc) {
    r.u = u0;
    lambda = l0;
  } else if (frictional) {
    // From the frictionless solution (the same law with zero bounds): from x = A^-1 b the plain
    // iteration stalls on some frictional problems (Tresca with bounds of 2 times a pressure on
    // the paper's problem), from the frictionless one it does not.
    const FrictionLaw frictionless(static_cast<int>(d), Vector::Zero(nc), Vector::Zero(nc));
    const FrictionSsnResult start = solve_friction_ssn(p, frictionless, o);
    r.u = start.u;
    lambda = Eigen::Map<const Vector>(start.force.data(), d * nc);
  } else {
    Eigen::SimplicialLDLT<SparseMatrix> A_factor(p.A);
    if (A_factor.info() != Eigen::Success) throw NumericalError("friction: A is not SPD");
    r.u = A_factor.solve(p.b);
  }
  // F(x, lambda) and, where asked, the KKT matrix J of its generalised derivative. The merit
  // that the steps must reduce measures F1 and F2 against fixed scales, those of the start (the
  // loads, or the contact forces where there are none: a body moved onto the obstacle by its
  // prescribed displacements has b = 0).
  double force_scale = 0.0, lambda_scale = 0.0;
  struct State {
    Vector F1, F2;
    double merit = 0.0;
  };
  const auto evaluate = [&](const Vector& x, const Vector& l,
                            std::vector<Eigen::Triplet<double>>* jac) {
    const Vector z = l + c * (B * x - g_hat);
    Vector projected = Vector::Zero(d * nc);
    r.in_contact.assign(static_cast<std::size_t>(nc), false);
    r.sliding.assign(static_cast<std::size_t>(nc), false);
    for (Index j = 0; j < nc; ++j) {
      Eigen::MatrixXd D = Eigen::MatrixXd::Zero(d, d);
      if (cs.movable[static_cast<std::size_t>(j)]) {
        const Eigen::VectorXd zj = z.segment(d * j, d);
        const NodeProjection pj = law.project_node(j, zj);
        projected.segment(d * j, d) = pj.force;
        D = pj.derivative;
        r.in_contact[static_cast<std::size_t>(j)] = pj.in_contact;
        r.sliding[static_cast<std::size_t>(j)] = pj.sliding;
      }
      if (jac == nullptr) continue;
      // Rows n + d j + a: -c (D B_j)_a dx + ((I - D) dlambda_j)_a (duplicates are summed).
      for (Index a = 0; a < d; ++a)
        for (Index e = 0; e < d; ++e) {
          if (D(a, e) != 0.0)
            for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(B_rows, d * j + e);
                 it; ++it)
              jac->emplace_back(n + d * j + a, it.col(), -c * D(a, e) * it.value());
          const double v = (a == e ? 1.0 : 0.0) - D(a, e);
          if (v != 0.0) jac->emplace_back(n + d * j + a, n + d * j + e, v);
        }
    }
    State st;
    const Vector reaction = BtW * l;
    st.F1 = p.A * x - p.b + reaction;
    st.F2 = l - projected;
    if (force_scale == 0.0) {  // the start
      force_scale = std::max({p.b.norm(), (BtW * projected).norm(), reaction.norm(), 1e-300});
      lambda_scale = std::max({projected.norm(), l.norm(), 1e-300});
    }
    // As kkt_residuals measures them: against the larger of the loads and the contact forces.
    r.equilibrium = st.F1.norm() / std::max({p.b.norm(), reaction.norm(), 1e-300});
    r.projection = st.F2.norm() / std::max(l.norm(), 1e-300);
    st.merit = st.F1.norm() / force_scale + st.F2.norm() / lambda_scale;
    return st;
  };

  // The KKT matrix's rows of A x - b + B^T W lambda do not change: made once, and each step
  // adds the rows of its D.
  std::vector<Eigen::Triplet<double>> fixed_rows;
  fixed_rows.reserve(static_cast<std::size_t>(p.A.nonZeros() + B.nonZeros()));
  for (Index col = 0; col < n; ++col)
    for (SparseMatrix::InnerIterator it(p.A, col); it; ++it)
      fixed_rows.emplace_back(it.row(), col, it.value());
  for (Index col = 0; col < n; ++col)
    for (SparseMatrix::InnerIterator it(B, col); it; ++it)
      fixed_rows.emplace_back(col, n + it.row(), it.value() * w(it.row()));
  Eigen::UmfPackLU<SparseMatrix> lu;  // SuiteSparse's multifrontal LU: J is not symmetric
  std::vector<bool> previous_contact, previous_sliding;
  double previous = 0.0;
  for (r.iterations = 0; r.iterations <= o.max_iterations; ++r.iterations) {
    std::vector<Eigen::Triplet<double>> jac = fixed_rows;
    const State st = evaluate(r.u, lambda, &jac);
    const double residual = std::max(r.equilibrium, r.projection);
    r.history.push_back(residual);
    if (r.equilibrium <= o.tolerance && r.projection <= o.tolerance) {
      r.converged = true;
      break;
    }
    // The rounding floor: a step that kept every node's state (so its linearisation was exact
    // and Newton's step should have converged at once) and did not halve the residual, which is
    // below floor_tolerance. The tolerance can lie below what a factorisation of the KKT matrix
    // resolves (about 2e-12 on the paper's strip at 240 x 80; there the full step no longer
    // reduces the merit, and the step is halved to nothing).
    const bool same_states = r.in_contact == previous_contact && r.sliding == previous_sliding;
    if (same_states && residual <= o.floor_tolerance && residual > 0.5 * previous) {
      r.converged = true;
      r.at_rounding_floor = true;
      break;
    }
    previous_contact = r.in_contact;
    previous_sliding = r.sliding;
    previous = residual;
    if (r.iterations == o.max_iterations) break;
    SparseMatrix J(n + d * nc, n + d * nc);
    J.setFromTriplets(jac.begin(), jac.end());
    lu.compute(J);
    if (lu.info() != Eigen::Success) throw NumericalError("friction: the KKT matrix is singular");
    Vector rhs(n + d * nc);
    rhs << -st.F1, -st.F2;
    const Vector step = lu.solve(rhs);
    // The full step where it reduces the residual, else halved until it does (a plain
    // semismooth Newton can cycle between active sets: Tresca at large bounds does here).
    double t = 1.0;
    for (int halvings = 0; halvings < 30; ++halvings, t *= 0.5) {
      const Vector x_trial = r.u + t * step.head(n);
      const Vector l_trial = lambda + t * step.tail(d * nc);
      if (evaluate(x_trial, l_trial, nullptr).merit < (1.0 - 1e-4 * t) * st.merit) break;
    }
    r.u += t * step.head(n);
    lambda += t * step.tail(d * nc);
  }
  r.force = Eigen::Map<const Eigen::MatrixXd>(lambda.data(), d, nc);
  return r;
}

ContactResult solve_friction_semismooth_newton(const ContactProblem& problem,
                                               const ContactSolverOptions& options,
                                               const MethodStart& start) {
  const ContactLaw& law = contact_law(problem);
  FrictionSsnOptions o;
  o.max_iterations = newton_iteration_limit(options, problem.contact.size());
  // The complementarity constant: its own automatic value (FrictionSsnOptions::c), not the
  // Uzawa methods' r, which is chosen for another purpose and is 100 times larger.
  const Index rows = problem.contact.N.rows();
  TimingTable timings;
  ScopedTimer timer(timings, "semismooth newton");
  const FrictionSsnResult r =
      solve_friction_ssn(problem, law, o, start.displacement(problem.A.rows()),
                         start.l.size() == rows ? start.l : Vector());
  timer.stop();
  ContactResult out;
  out.u = r.u;
  out.l = Eigen::Map<const Vector>(r.force.data(), rows);
  SolveSummary& s = out.summary;
  s.timings = std::move(timings);
  for (std::size_t k = 1; k < r.history.size(); ++k) {
    OuterStepRecord rec;
    rec.inner_iterations = 1;
    rec.factorizations = 1;  // a sparse LU of the KKT matrix per step
    rec.dual_change = r.history[k];
    s.steps.push_back(rec);
  }
  Index in_contact = 0;
  for (const bool c : r.in_contact) in_contact += c ? 1 : 0;
  if (!s.steps.empty()) s.steps.back().active_set_size = in_contact;
  if (r.converged) {
    s.termination = Termination::Converged;
    s.message =
        r.at_rounding_floor
            ? fmt::format(
                  "KKT residuals {:.1e} (equilibrium) and {:.1e} (projection) at the rounding "
                  "floor of the KKT matrix's factorisation (the states of the nodes settled, the "
                  "residual no longer halving, below {:.0e}) after {} semismooth Newton steps",
                  r.equilibrium, r.projection, o.floor_tolerance, r.iterations)
            : fmt::format(
                  "KKT residuals {:.1e} (equilibrium) and {:.1e} (projection) below {:.0e} after "
                  "{} semismooth Newton steps on the KKT system",
                  r.equilibrium, r.projection, o.tolerance, r.iterations);
  } else {
    s.termination = Termination::IterationLimit;
    s.message = fmt::format(
        "semismooth Newton (friction) did not converge in {} steps: equilibrium {:.3e}, "
        "projection {:.3e} (tolerance {:.0e})",
        r.iterations, r.equilibrium, r.projection, o.tolerance);
  }
  return out;
}

}  // namespace signorini
