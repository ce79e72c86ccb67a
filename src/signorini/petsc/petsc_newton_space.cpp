#include "signorini/petsc/petsc_newton_space.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>

#include "signorini/contact/active_set_constraint.hpp"
#include "signorini/core/error.hpp"
#include "signorini/petsc/petsc_algebra.hpp"
#include "signorini/petsc/petsc_check.hpp"

namespace signorini {

using petsc::check;

namespace {

// The padding of the problem's unknowns (node_padding.hpp): from the node of each of all n
// unknowns where the problem has them, else (the ranks' parts of the mesh) from the rank's own
// and the ghosts that its columns of A reach.
petsc::NodePadding node_padding(const ContactProblem& problem, MPI_Comm comm) {
  const Index n = problem.A.rows();
  const auto [first, last] = petsc::owned_rows(problem, comm);
  const auto& nodes = problem.node_of_unknown;
  // (Every rank takes the same branch: the second is collective.)
  int whole = nodes.empty() || static_cast<Index>(nodes.size()) == n ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &whole, 1, MPI_INT, MPI_MIN, comm);
  if (whole != 0) return {nodes, n};
  if (static_cast<Index>(nodes.size()) != last - first)
    throw NumericalError("the nodes of the unknowns: neither all of them nor this rank's");
  // The slots of the others' unknowns that this rank reads: those of its part of the solution
  // (ContactProblem::solution_unknowns, rank_solution), else those its columns of A reach.
  std::vector<Index> ghosts;
  if (problem.part_solution()) {
    for (const Index i : problem.solution_unknowns)
      if (i < first || i >= last) ghosts.push_back(i);
    return {nodes, first, last, n, ghosts, comm};
  }
  for (Index col = first; col < last; ++col)
    for (SparseMatrix::InnerIterator it(problem.A, problem.column_of(col)); it; ++it)
      if (it.row() < first || it.row() >= last) ghosts.push_back(it.row());
  std::sort(ghosts.begin(), ghosts.end());
  ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
  return {nodes, first, last, n, ghosts, comm};
}

}  // namespace

PetscNewtonSpace::PetscNewtonSpace(const ContactProblem& problem,
                                   const ContactSolverOptions& options, const Vector& x0,
                                   TimingTable& timings, MPI_Comm comm)
    : p_(problem),
      o_(options),
      timings_(timings),
      comm_(comm),
      padding_(node_padding(problem, comm)) {
  ScopedTimer timer(timings_, "distributed set-up");
  n_ = problem.A.rows();
  nc_ = problem.contact.N.rows();
  components_ = problem.contact.components;
  const bool keeps_levels = petsc::keeps_multigrid_levels(o_);
  // The unknowns in whole node blocks (node_padding.hpp): this rank's range [first, last) of
  // unknowns becomes [lo_, hi_) of slots.
  const auto [first, last] = petsc::owned_rows(problem, comm_);
  first_ = first;
  last_ = last;
  lo_ = padding_.start(first);
  hi_ = padding_.start(last);
  if (padding_.active() || !problem.partitioned())
    modes_ =
        padding_.rows(petsc::rank_rows(problem, problem.near_null_space, first, last), first, last);

  // A in AIJ for GAMG's set-up, and in node blocks for the products (petsc_algebra.hpp,
  // block_rows), each from A on the slots (a padded copy of A, only where a node has padding
  // slots, made for each and freed).
  const auto block = static_cast<PetscInt>(padding_.block());
  const auto from_slots = [&](Mat (*make)(const SparseMatrix&, Index, Index, MPI_Comm, PetscInt)) {
    if (!padding_.active()) return make(problem.A, lo_, hi_, comm_, block);
    return make(padding_.matrix(problem.A, first, last), lo_, hi_, comm_, block);
  };
  PetscMPIInt ranks = 1;
  check(MPI_Comm_size(comm_, &ranks), "MPI");
  ScopedTimer matrices(timings_, "distributed: matrices");
  // On one rank the AIJ copy is A on the slots itself, its arrays in place (sequential_matrix:
  // the padded copy made here, instead of PETSc's copy made entry by entry: 0.45 s at 434,235
  // unknowns), or without padding the model's A itself, which outlives this space
  // (sequential_view: no copy, 1 GB less at a million hex8 unknowns).
  Mat A_aij = nullptr;
  if (ranks == 1) {
    A_aij = padding_.active()
                ? petsc::sequential_matrix(padding_.matrix(problem.A, first, last), comm_, block)
                : petsc::sequential_view(problem.A, comm_, block);
    petsc::mark_spd(A_aij, "A");  // (distributed_rows marks its own)
  } else {
    A_aij = from_slots(&petsc::distributed_rows);
  }
  matrices.stop();
  // The Newton matrix H starts as a copy of A. With GAMG's kept levels, A in node blocks and H
  // are made after the levels' set-up, once the AIJ copy of A is freed, so that the process
  // never holds the AIJ copy, GAMG's set-up and either of them at once (docs/distributed.md,
  // "Memory per rank"); until then the AIJ copy serves.
  const auto make_newton_matrix = [&] {
    check(MatDuplicate(A_, MAT_COPY_VALUES, &H_), "the Newton matrix");
    petsc::mark_spd(H_, "the Newton matrix");
  };
  if (!keeps_levels) {
    A_ = A_aij;
    check(PetscObjectReference(reinterpret_cast<PetscObject>(A_)), "A");
    make_newton_matrix();
  }

  check(MatCreateVecs(A_aij, &x_, &b_), "vectors");
  for (Vec* v : {&x_new_, &residual_, &d_, &Ad_, &work_}) check(VecDuplicate(x_, v), "vectors");
  petsc::set_owned(b_,
                   padding_.rows(petsc::rank_rows(problem, problem.b, first, last), first, last));
  // (x0 has the problem's held rows: all n where it is whole, else the rank's.)
  petsc::set_owned(x_, padding_.rows(petsc::rank_rows(problem, x0, first, last), first, last));
  check(MatMult(A_aij, x_, residual_), "A x");  // A x - b at x0
  check(VecAXPY(residual_, -1.0, b_), "A x - b");

  // The contact rows of this rank: all the dofs of a row lie in one range (row_partition).
  const SparseMatrix Nt = problem.contact.N.transpose();
  for (Index j = 0; j < nc_; ++j) {
    SparseMatrix::InnerIterator it(Nt, j);
    if (!it || it.row() < first || it.row() >= last) continue;
    petsc::ContactRow row{j, {}, {}};
    for (; it; ++it) {
      row.dofs.push_back(static_cast<PetscInt>(padding_.slot(it.row())));
      row.normal.push_back(it.value());
    }
    rows_.push_back(std::move(row));
  }
  ScopedTimer levels(timings_, "distributed: preconditioner");
  set_up_solver(A_aij, keeps_levels);
  check(MatDestroy(&A_aij), "A");
  levels.stop();
  // What the AIJ copy and GAMG's set-up freed goes back to the system: A's and H's node blocks,
  // made next, would fit in it only in part (135 MB higher a peak on one rank at 405,600
  // unknowns without it; docs/distributed.md, "Memory per rank").
  petsc::give_back_freed_memory();
  if (keeps_levels) {
    const ScopedTimer blocks(timings_, "distributed: matrices");
    // On one rank, A and H as shells on the serial tool's upper node blocks of A
    // (upper_block_operator.hpp); else, or where A is not in whole node blocks, PETSc's node
    // blocks, their products on the rank's threads.
    // (Two calls, not one with a conditional: that would copy A where it has no padding.)
    if (ranks == 1 && padding_.active())
      upper_ = petsc::UpperBlockOperator::make(padding_.matrix(problem.A, first, last), comm_);
    else if (ranks == 1)
      upper_ = petsc::UpperBlockOperator::make(problem.A, comm_);
    if (upper_) {
      description_ += "; A and H in upper node blocks";
      A_ = upper_->stiffness();
      H_ = upper_->newton();
      for (Mat M : {A_, H_})
        check(PetscObjectReference(reinterpret_cast<PetscObject>(M)), "the one-rank products");
    } else {
      A_ = from_slots(&petsc::block_rows);
      make_newton_matrix();
      if (petsc::ThreadedProduct::worthwhile(H_)) {
        threaded_A_ = std::make_unique<petsc::ThreadedProduct>(A_);
        threaded_H_ = std::make_unique<petsc::ThreadedProduct>(H_);
      }
    }
    check(KSPSetOperators(ksp_, newton_operator(), newton_operator()), "KSP");
  }
  active_.assign(static_cast<std::size_t>(nc_), false);
  Nx_ = contact_values_of(x_);
}

PetscNewtonSpace::~PetscNewtonSpace() {
  KSPDestroy(&ksp_);
  multigrid_.reset();
  threaded_H_.reset();  // (their shells were the KSP's operators: after it)
  threaded_A_.reset();
  for (Vec* v : {&b_, &x_, &x_new_, &residual_, &d_, &Ad_, &work_}) VecDestroy(v);
  MatDestroy(&H_);
  MatDestroy(&A_);
  petsc::give_back_freed_memory();  // before the results are written (docs/distributed.md)
}

void PetscNewtonSpace::set_up_solver(Mat A_aij, bool keeps_levels) {
  check(KSPCreate(comm_, &ksp_), "KSP");
  // CG with GAMG: GAMG's levels formed once, from A, and the contact term carried to each
  // (petsc_contact_multigrid.hpp).
  petsc::MultigridBuilder keep_levels;
  if (keeps_levels)
    keep_levels = [&](PC pc) {
      PetscMPIInt ranks = 1;
      check(MPI_Comm_size(comm_, &ranks), "MPI");
      const bool own =
          resolved_petsc_multigrid(o_.petsc_multigrid, ranks) == PetscMultigrid::Aggregation;
      std::string what =
          own ? "smoothed aggregation on each rank's nodes, kept for every active set"
              : "GAMG's levels, kept for every active set";
      if (modes().cols() > 0)  // (on every rank alike, whatever its rows: collective)
        what += fmt::format(", {} rigid-body modes", petsc::attach_near_null_space(A_aij, modes()));
      multigrid_ = std::make_unique<petsc::ContactMultigrid>(
          pc, A_aij, rows_, comm_,
          own ? petsc::ContactMultigrid::Levels::Aggregation
              : petsc::ContactMultigrid::Levels::Gamg);
      std::string sizes;
      for (const PetscInt n : multigrid_->level_sizes())
        sizes += fmt::format("{}{}", sizes.empty() ? "" : ", ", n);
      std::string contact;
      if (const std::size_t k = multigrid_->contact_prolongation_levels(); k > 0)
        contact =
            fmt::format("; the finest {} smoothed with the Newton matrix at the contact",
                        k == 1 ? std::string("prolongation") : fmt::format("{} prolongations", k));
      return fmt::format("{}; levels of {} unknowns{}", what, sizes, contact);
    };
  const petsc::KspChoice choice =
      petsc::configure_ksp(ksp_, keeps_levels ? nullptr : H_, o_, modes(), true, keep_levels);
  direct_ = choice.direct;
  description_ = choice.description;
}

// H(P) = A + sum_{j in P} r h_j n_j n_j^T (17): each active node's rank-one block on its own
// rows. Every rank calls this with the same P (the loop is replicated), so the collective
// assembly is met by all.
void PetscNewtonSpace::set_active(const ActiveSet& active, double r) {
  if (has_active_ && active == active_) return;
  ScopedTimer t(timings_, "preconditioner setup");
  form_newton_matrix(
      [&](Index a, Index b) {
        return a == b && active[static_cast<std::size_t>(a)]
                   ? r * p_.contact.weights(a / components_)
                   : 0.0;
      },
      false);
  active_ = active;
  has_active_ = true;
  has_linearization_ = false;
}

// H = A + sum_j B_j^T (r h_j D_j) B_j (docs/method.md, "Friction"), D_j the derivative of the
// projection onto the friction set at z_j (lin.blocks, column-major). The blocks are exact on
// the fine level; the coarse levels take W's diagonal, as the serial multigrid does
// (multigrid_preconditioner.cpp).
void PetscNewtonSpace::set_linearization(const Linearization& lin, double r) {
  if (lin.blocks.empty()) {
    set_active(lin.active, r);
    return;
  }
  if (has_linearization_ && lin == linearization_) return;
  ScopedTimer t(timings_, "preconditioner setup");
  const Index m = components_;
  form_newton_matrix(
      [&](Index a, Index b) {
        const Index node = a / m;
        return r * p_.contact.weights(node) *
               lin.blocks[static_cast<std::size_t>(m * m * node + a % m + m * (b % m))];
      },
      true);
  linearization_ = lin;
  has_linearization_ = true;
  has_active_ = false;
}

// H = A + sum_j B_j^T W_j B_j over the contact nodes whose unknowns this rank owns, B_j the
// node's rows of N (its normal, and with friction its tangents, all on its own dofs), then the
// preconditioner: the coarse levels with W's diagonal. H differs from A in those nodes' blocks
// alone: each is written whole, A's block (read once) plus its terms, and a block that had terms
// and has none now gets A's back. (Copying all of A into H for each new active set moved 680 MB
// each time at a million hex8 unknowns.)
void PetscNewtonSpace::form_newton_matrix(const std::function<double(Index, Index)>& weight,
                                          bool coupled_rows) {
  const bool read_a = !upper_ && a_blocks_.empty() && !rows_.empty();
  std::vector<std::vector<PetscInt>> block_dofs;  // (on the one-rank shells: H's terms)
  std::vector<std::vector<double>> block_values;
  std::size_t group = 0, offset = 0;
  Vector diagonal = Vector::Zero(nc_);  // W's diagonal, for the coarse levels (this rank's rows)
  int widest = 0;  // the most unknowns that one node's rows touch, for the fine smoother's bound
  std::vector<PetscInt> dofs;
  std::vector<PetscScalar> block;
  for (std::size_t first = 0; first < rows_.size();) {
    const Index node = rows_[first].j / components_;
    std::size_t last = first;
    while (last < rows_.size() && rows_[last].j / components_ == node) ++last;
    dofs.clear();
    for (std::size_t a = first; a < last; ++a)
      for (const PetscInt dof : rows_[a].dofs)
        if (std::find(dofs.begin(), dofs.end(), dof) == dofs.end()) dofs.push_back(dof);
    const std::size_t k = dofs.size();
    const auto at = [&](PetscInt dof) {
      return static_cast<std::size_t>(std::find(dofs.begin(), dofs.end(), dof) - dofs.begin());
    };
    block.assign(k * k, 0.0);
    bool any = false;
    for (std::size_t a = first; a < last; ++a)
      for (std::size_t b = first; b < last; ++b) {
        const double w = weight(rows_[a].j, rows_[b].j);
        if (a == b) diagonal(rows_[a].j) = w;
        if (w == 0.0) continue;
        any = true;
        for (std::size_t p = 0; p < rows_[a].dofs.size(); ++p)
          for (std::size_t q = 0; q < rows_[b].dofs.size(); ++q)
            block[at(rows_[a].dofs[p]) * k + at(rows_[b].dofs[q])] +=
                w * rows_[a].normal[p] * rows_[b].normal[q];
      }
    if (read_a) {
      a_blocks_.resize(offset + k * k);
      check(MatGetValues(A_, static_cast<PetscInt>(k), dofs.data(), static_cast<PetscInt>(k),
                         dofs.data(), a_blocks_.data() + offset),
            "the Newton matrix");
      with_terms_.push_back(0);
    }
    if (any) widest = std::max(widest, static_cast<int>(k));
    if (upper_) {
      if (any) {
        block_dofs.push_back(dofs);
        block_values.push_back(block);
      }
    } else if (any || with_terms_[group] != 0) {
      for (std::size_t i = 0; i < k * k; ++i) block[i] += a_blocks_[offset + i];
      check(MatSetValues(H_, static_cast<PetscInt>(k), dofs.data(), static_cast<PetscInt>(k),
                         dofs.data(), block.data(), INSERT_VALUES),
            "the Newton matrix");
    }
    if (!upper_) with_terms_[group] = any ? 1 : 0;
    offset += k * k;
    ++group;
    first = last;
  }
  if (upper_) {
    upper_->set_contact_blocks(std::move(block_dofs), std::move(block_values));
  } else {
    check(MatAssemblyBegin(H_, MAT_FINAL_ASSEMBLY), "the Newton matrix");
    check(MatAssemblyEnd(H_, MAT_FINAL_ASSEMBLY), "the Newton matrix");
  }
  if (multigrid_) multigrid_->set_weights(diagonal, coupled_rows ? widest : 0);
  if (threaded_H_) threaded_H_->refresh();  // (so that the KSP sees a new operator)
  // The preconditioner is set up again.
  check(KSPSetOperators(ksp_, newton_operator(), newton_operator()), "KSP");
  ++refreshes_;
}

NewtonSolveStats PetscNewtonSpace::solve(const Vector& terms) {
  // Newton right-hand side b - N^T terms, then H x_new = rhs from x_new = x (17).
  check(VecCopy(b_, work_), "the right-hand side");
  add_contact_transpose(-terms, work_);
  check(VecCopy(x_, x_new_), "the initial guess");
  return solve_newton_system(work_, x_new_);
}

Vector PetscNewtonSpace::contact_response(const Vector& w, NewtonSolveStats& stats) {
  // H y = N^T w from y = 0 in d_ (free until the next direction()), then N y.
  check(VecSet(work_, 0.0), "N^T w");
  add_contact_transpose(w, work_);
  check(VecSet(d_, 0.0), "the initial guess");
  stats = solve_newton_system(work_, d_);
  return contact_values_of(d_);
}

NewtonSolveStats PetscNewtonSpace::solve_newton_system(Vec rhs, Vec x) {
  const double tolerance = linear_tolerance_ > 0.0 ? linear_tolerance_ : o_.linear.cg_tolerance;
  if (!direct_) petsc::set_ksp_tolerance(ksp_, o_, tolerance, n_);
  petsc::KspOutcome k;
  {
    ScopedTimer t(timings_, "linear solve");
    k = petsc::solve(ksp_, rhs, x, direct_, workspace_);
  }
  NewtonSolveStats out;
  out.converged = k.converged;
  out.iterations = k.iterations;
  out.residual = k.residual;
  out.tolerance = direct_ ? 0.0 : tolerance;
  out.solver = direct_ ? "MUMPS" : "PETSc CG";
  if (!out.converged) out.solver += " (" + k.reason + ")";
  return out;
}

void PetscNewtonSpace::direction(ModifiedLagrangian::Direction& dir) {
  check(VecWAXPY(d_, -1.0, x_, x_new_), "the Newton direction");
  check(MatMult(threaded_A_ ? threaded_A_->shell() : A_, d_, Ad_), "A d");
  PetscScalar rd = 0.0, dAd = 0.0;
  check(VecDot(residual_, d_, &rd), "dot product");
  check(VecDot(Ad_, d_, &dAd), "dot product");
  dir.residual_dot_d = rd;
  dir.d_A_d = dAd;
  dir.Nd = contact_values_of(d_);
}

void PetscNewtonSpace::step(double t) {
  check(VecAXPY(x_, t, d_), "step");
  check(VecAXPY(residual_, t, Ad_), "step");
  Nx_ = contact_values_of(x_);
  last_t_ = t;
}

NewtonStepNorms PetscNewtonSpace::norms(const Vector& contact_forces) {
  // G = (A x - b) + N^T (h z_+)
  check(VecCopy(residual_, work_), "norms");
  add_contact_transpose(contact_forces, work_);
  PetscReal g = 0.0, r = 0.0, x = 0.0, d = 0.0;
  check(VecNorm(work_, NORM_2, &g), "norms");
  check(VecNorm(residual_, NORM_2, &r), "norms");
  check(VecNorm(x_, NORM_2, &x), "norms");
  check(VecNorm(d_, NORM_2, &d), "norms");
  return {g, r, x, last_t_ * d};
}

void PetscNewtonSpace::project(const ActiveSet& S, Vec v) {
  PetscScalar* a = nullptr;
  check(VecGetArray(v, &a), "the projection");
  for (const petsc::ContactRow& row : rows_) {
    const double norm2 = norm2_(row.j);
    if (!S[static_cast<std::size_t>(row.j)] || !(norm2 > 0.0)) continue;
    double dot = 0.0;
    for (std::size_t k = 0; k < row.dofs.size(); ++k) dot += row.normal[k] * a[row.dofs[k] - lo_];
    for (std::size_t k = 0; k < row.dofs.size(); ++k)
      a[row.dofs[k] - lo_] -= row.normal[k] * dot / norm2;
  }
  check(VecRestoreArray(v, &a), "the projection");
}

// The serial method (active_set_constraint.cpp) on PETSc's vectors: x moved onto S's
// constraints, then CG on P A P z = P (b - A x) preconditioned by P M P, M the KSP's
// preconditioner of the Newton matrix of S; the multipliers are the reactions on S.
std::optional<ActiveSetSolve> PetscNewtonSpace::solve_on_active_set(const ActiveSet& S, double r,
                                                                    double tolerance) {
  const ContactSet& c = p_.contact;
  if (!rows_disjoint_) {
    // (Each rank checks the columns of N it holds, its own unknowns' at least; collective.)
    int disjoint = components_ == 1 && contact_rows_disjoint(c.N) ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &disjoint, 1, MPI_INT, MPI_MIN, comm_);
    rows_disjoint_ = disjoint != 0;
    // |n_j|^2, each row's owner adding it.
    norm2_ = Vector::Zero(nc_);
    for (const petsc::ContactRow& row : rows_)
      for (const double v : row.normal) norm2_(row.j) += v * v;
    if (nc_ > 0)
      MPI_Allreduce(MPI_IN_PLACE, norm2_.data(), static_cast<int>(nc_), MPI_DOUBLE, MPI_SUM, comm_);
  }
  if (!*rows_disjoint_) return std::nullopt;
  set_active(S, r);
  // The start: x = P x + sum_{j in S} n_j g_j / |n_j|^2.
  project(S, x_);
  Vector target = Vector::Zero(nc_);
  for (Index j = 0; j < nc_; ++j)
    if (S[static_cast<std::size_t>(j)] && norm2_(j) > 0.0) target(j) = c.gaps(j) / norm2_(j);
  add_contact_transpose(target, x_);
  const Mat A = threaded_A_ ? threaded_A_->shell() : A_;
  Vec& rv = work_;
  Vec& z = x_new_;
  Vec& p = d_;
  Vec& q = Ad_;
  check(MatMult(A, x_, rv), "A x");
  check(VecAYPX(rv, -1.0, b_), "b - A x");
  PetscReal b_norm = 0.0, start_norm = 0.0, rnorm = 0.0;
  check(VecNorm(b_, NORM_2, &b_norm), "norms");
  check(VecNorm(rv, NORM_2, &start_norm), "norms");
  project(S, rv);
  check(VecNorm(rv, NORM_2, &rnorm), "norms");
  const double goal = tolerance * std::max(b_norm, start_norm);
  ActiveSetSolve out;
  out.stats.solver = "projected conjugate gradients (PETSc vectors)";
  out.stats.tolerance = tolerance;
  if (rnorm > goal) {
    check(KSPSetUp(ksp_), "the preconditioner");
    PC pc = nullptr;
    check(KSPGetPC(ksp_, &pc), "the preconditioner");
    const int limit = o_.linear.cg_iteration_limit(n_);
    const double start = rnorm;
    ScopedTimer t(timings_, "linear solve");
    PetscScalar rz = 0.0;
    out.stats.converged = false;
    for (int it = 1; it <= limit; ++it) {
      check(PCApply(pc, rv, z), "the preconditioner");
      project(S, z);
      PetscScalar rz_new = 0.0;
      check(VecDot(rv, z, &rz_new), "dot product");
      if (it == 1)
        check(VecCopy(z, p), "CG");
      else
        check(VecAYPX(p, rz_new / rz, z), "CG");
      rz = rz_new;
      check(MatMult(A, p, q), "A p");
      project(S, q);
      PetscScalar pq = 0.0;
      check(VecDot(p, q, &pq), "dot product");
      if (!(pq > 0.0)) break;  // (breakdown: not positive definite on the subspace)
      const double alpha = rz / pq;
      check(VecAXPY(x_, alpha, p), "CG");
      check(VecAXPY(rv, -alpha, q), "CG");
      check(VecNorm(rv, NORM_2, &rnorm), "norms");
      out.stats.iterations = it;
      if (rnorm <= goal) {
        out.stats.converged = true;
        break;
      }
    }
    out.stats.residual = start > 0.0 ? rnorm / start : 0.0;
  }
  // A x - b, N x and the reactions h_j l_j = n_j . (b - A x) / |n_j|^2 on S at the new x.
  check(MatMult(A, x_, residual_), "A x");
  check(VecAXPY(residual_, -1.0, b_), "A x - b");
  Nx_ = contact_values_of(x_);
  const Vector reaction = contact_values_of(residual_);  // (of A x - b: the sign turned below)
  out.l = Vector::Zero(nc_);
  out.gap_residual = Vector::Zero(nc_);
  for (Index j = 0; j < nc_; ++j) {
    if (!c.movable[static_cast<std::size_t>(j)]) continue;
    if (S[static_cast<std::size_t>(j)] && norm2_(j) > 0.0)
      out.l(j) = -reaction(j) / (norm2_(j) * c.weights(j));
    out.gap_residual(j) = Nx_(j) - c.gaps(j);
  }
  return out;
}

Vector PetscNewtonSpace::rank_solution() {
  if (p_.part_solution()) {
    // The part's unknowns, read at their slots from their owners.
    std::vector<PetscInt> slots;
    slots.reserve(p_.solution_unknowns.size());
    for (const Index i : p_.solution_unknowns)
      slots.push_back(static_cast<PetscInt>(padding_.slot(i)));
    return petsc::values_at(x_, slots);
  }
  // Each rank's unknowns from its slots, then put together (no whole padded copy).
  PetscInt m = 0;
  check(VecGetLocalSize(x_, &m), "the solution");
  const PetscScalar* a = nullptr;
  check(VecGetArrayRead(x_, &a), "the solution");
  const Vector own = padding_.own_unknowns(Eigen::Map<const Vector>(a, m), first_, last_);
  check(VecRestoreArrayRead(x_, &a), "the solution");
  return petsc::allgather(own, comm_);
}

// (N v)_j for every contact node on every rank: each rank its own rows, summed over the ranks
// (every other rank adds an exact zero, so the values are those of a serial product).
Vector PetscNewtonSpace::contact_values_of(Vec v) {
  Vector values = Vector::Zero(nc_);
  const PetscScalar* a = nullptr;
  check(VecGetArrayRead(v, &a), "N x");
  for (const petsc::ContactRow& row : rows_) {
    double s = 0.0;
    for (std::size_t k = 0; k < row.dofs.size(); ++k) s += row.normal[k] * a[row.dofs[k] - lo_];
    values(row.j) = s;
  }
  check(VecRestoreArrayRead(v, &a), "N x");
  if (nc_ > 0)
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(nc_), MPI_DOUBLE, MPI_SUM, comm_);
  return values;
}

void PetscNewtonSpace::add_contact_transpose(const Vector& values, Vec v) {
  PetscScalar* a = nullptr;
  check(VecGetArray(v, &a), "N^T l");
  for (const petsc::ContactRow& row : rows_)
    for (std::size_t k = 0; k < row.dofs.size(); ++k)
      a[row.dofs[k] - lo_] += row.normal[k] * values(row.j);
  check(VecRestoreArray(v, &a), "N^T l");
}

}  // namespace signorini
