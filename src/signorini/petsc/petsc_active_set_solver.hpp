#pragma once
// The Newton steps of semismooth Newton (semismooth_newton_solver.cpp) on PETSc objects spread
// over the MPI ranks (docs/distributed.md): the serial sparse path's rotated elimination, with
// PETSc doing the elimination. The contact nodes' dofs are rotated so that each normal
// displacement is one unknown (contact/normal_rotation.hpp); for an active set S the unknowns
// a_j of S are fixed at g_j / s_j by MatZeroRowsColumns (rows and columns replaced by the
// diagonal, the right-hand side moved), and the rest solved by the KSP that the options choose
// (petsc_algebra.hpp). The multipliers come from the reactions, as serially.

#include <petscksp.h>

#include <optional>
#include <string>
#include <vector>

#include "signorini/contact/distributed_engine.hpp"
#include "signorini/contact/normal_rotation.hpp"
#include "signorini/petsc/petsc_algebra.hpp"

namespace signorini {

class PetscActiveSetSolver final : public DistributedActiveSetSolver {
 public:
  PetscActiveSetSolver(const ContactProblem& problem, const ContactSolverOptions& options,
                       const Vector& x0, TimingTable& timings, MPI_Comm comm);
  ~PetscActiveSetSolver() override;
  PetscActiveSetSolver(const PetscActiveSetSolver&) = delete;
  PetscActiveSetSolver& operator=(const PetscActiveSetSolver&) = delete;

  LinearSolveStats solve(const ActiveSet& S, Vector& l, Vector& gap_residual) override;
  /// Gathers x on every rank (a collective call).
  [[nodiscard]] Vector displacement() const override;
  [[nodiscard]] bool iterative() const override { return !direct_; }
  void set_tolerance(double tolerance) override { tolerance_ = tolerance; }
  [[nodiscard]] std::string linear_solver_description() const override {
    return petsc::with_workspace_note(description_, workspace_);
  }

 private:
  const ContactProblem& p_;
  const ContactSolverOptions& o_;
  TimingTable& external_timings_;
  MPI_Comm comm_;
  NormalRotation rotation_;
  Index n_ = 0, nc_ = 0, lo_ = 0, hi_ = 0;
  std::vector<Index> owned_;  // the contact nodes whose normal unknown this rank owns
  Mat Ar_ = nullptr, K_ = nullptr;
  Vec br_ = nullptr, y_ = nullptr, rhs_ = nullptr, fixed_values_ = nullptr, reaction_ = nullptr;
  KSP ksp_ = nullptr;
  double diagonal_ = 1.0;  // of the fixed rows: the mean of A_r's, to keep K's scale
  bool direct_ = false;
  std::string description_;
  std::optional<PetscInt> workspace_;  // ICNTL(14), where a short work space raised it
  double tolerance_ = 0.0;             // 0: o_.linear.cg_tolerance
};

}  // namespace signorini
