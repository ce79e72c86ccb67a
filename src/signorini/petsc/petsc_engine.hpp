#pragma once
// The distributed engine of a build with PETSc (contact/distributed_engine.hpp,
// docs/distributed.md): initialises MPI and PETSc, and finalises them when it goes. One per
// process, made by the main() of signorini-mpi and of the MPI tests, which pass it to
// build_model (the model's problem then carries it to its solver).

#include <mpi.h>

#include <string>
#include <vector>

#include "signorini/contact/distributed_engine.hpp"

namespace signorini {

class PetscEngine final : public DistributedEngine {
 public:
  /// PetscInitialize (MPI_Init through it) without the command line: PETSc's own options come
  /// from solver.petsc_options or the PETSC_OPTIONS variable.
  PetscEngine();
  /// Finalises PETSc and MPI.
  ~PetscEngine() override;
  PetscEngine(const PetscEngine&) = delete;
  PetscEngine& operator=(const PetscEngine&) = delete;

  [[nodiscard]] int rank() const override { return rank_; }
  [[nodiscard]] int size() const override { return size_; }
  [[nodiscard]] std::string description() const override;
  [[nodiscard]] std::unique_ptr<DistributedNewtonSpace> newton_space(
      const ContactProblem& problem, const ContactSolverOptions& options, const Vector& x0,
      TimingTable& timings) override;
  [[nodiscard]] std::unique_ptr<DistributedActiveSetSolver> active_set_solver(
      const ContactProblem& problem, const ContactSolverOptions& options, const Vector& x0,
      TimingTable& timings) override;
  /// PT-Scotch's partition where PETSc has it, else ParMETIS's, else PETSc's even split
  /// ("average"); -mat_partitioning_type among the PETSc options chooses another ("current":
  /// the even split of the numbering).
  [[nodiscard]] std::vector<int> partition(const NodeGraph& graph,
                                           const std::string& engine_options) override;
  void note_partition(const std::string& how) override { partitioner_ = how; }
  void sum(double* values, Index count) const override;
  [[nodiscard]] double max(double value) const override;
  [[nodiscard]] bool any(bool flag) const override;
  void broadcast(std::vector<char>& bytes) const override;
  void send_from_root(int to, const std::vector<char>& bytes) const override;
  [[nodiscard]] std::vector<char> receive_from_root() const override;
  [[nodiscard]] std::vector<std::vector<char>> allgather(
      const std::vector<char>& bytes) const override;
  [[nodiscard]] std::vector<std::vector<char>> exchange(
      const std::vector<std::vector<char>>& to_each) const override;
  [[nodiscard]] bool meet_within(double seconds) const override;
  [[noreturn]] void abort(int status) const override;

 private:
  /// Unless OMP_NUM_THREADS says otherwise, this rank's OpenMP threads: the cores of its node
  /// shared evenly among the node's ranks (at least one).
  void share_the_cores() const;
  int rank_ = 0;
  int size_ = 1;
  std::string partitioner_;                         // the last partition's, for the description
  MPI_Comm meeting_comm_ = MPI_COMM_NULL;           // meet_within's own (a duplicate)
  mutable MPI_Request meeting_ = MPI_REQUEST_NULL;  // an open meeting (one that timed out)
};

}  // namespace signorini
