#pragma once
// The processes of a distributed run and the messages between them (docs/distributed.md): who
// this process is, reductions, broadcasts and exchanges of bytes, the graph partitioner, and a
// failing rank's meeting with the others. Communication and partitioning only: the solver's
// distributed objects are made by the engine of contact/distributed_engine.hpp, which is a
// Communicator too (PETSc's, src/signorini/petsc/).

#include <string>
#include <vector>

#include "signorini/core/types.hpp"
#include "signorini/parallel/node_partition.hpp"

namespace signorini {

class Communicator {
 public:
  virtual ~Communicator() = default;
  [[nodiscard]] virtual int rank() const = 0;
  [[nodiscard]] virtual int size() const = 0;
  /// "PETSc 3.18.5 on 2 MPI ranks".
  [[nodiscard]] virtual std::string description() const = 0;
  /// The rank of every vertex of the mesh's node graph, from the graph partitioner (a collective
  /// call: each rank gives its rows of `graph`). `engine_options`: options for the engine, which
  /// may name the partitioner (PETSc's option string, solver.petsc_options).
  [[nodiscard]] virtual std::vector<int> partition(const NodeGraph& graph,
                                                   const std::string& engine_options) = 0;
  /// Says how the mesh's nodes were shared among the ranks where partition() did not do it
  /// ("blocks of the box's cubes, 2 x 2 x 1"), for description().
  virtual void note_partition(const std::string& how) = 0;
  /// Sums `values` over the ranks, in place on every rank (a collective call).
  virtual void sum(double* values, Index count) const = 0;
  /// The largest of the ranks' `value`, on every rank (a collective call).
  [[nodiscard]] virtual double max(double value) const = 0;
  /// True on every rank when `flag` is true on any (a collective call).
  [[nodiscard]] virtual bool any(bool flag) const = 0;
  /// Rank 0's `bytes` on every rank (a collective call; the others' are replaced).
  virtual void broadcast(std::vector<char>& bytes) const = 0;
  /// From rank 0 to rank `to` (> 0), which takes them with receive_from_root(): what rank 0
  /// alone holds, sent to each rank in turn (its part of the model, problem/model_part.hpp).
  virtual void send_from_root(int to, const std::vector<char>& bytes) const = 0;
  [[nodiscard]] virtual std::vector<char> receive_from_root() const = 0;
  /// Every rank's `bytes`, in the order of the ranks, on every rank (a collective call).
  [[nodiscard]] virtual std::vector<std::vector<char>> allgather(
      const std::vector<char>& bytes) const = 0;
  /// Sends to_each[r] to rank r and returns what each rank sent to this one (a collective call;
  /// to_each has one entry per rank, empty where nothing goes).
  [[nodiscard]] virtual std::vector<std::vector<char>> exchange(
      const std::vector<std::vector<char>>& to_each) const = 0;
  /// Waits up to `seconds` for every rank to call meet_within too, and says whether all did. It
  /// meets on a communicator of its own, so that a rank may call it while the others wait in
  /// another collective call: a failing rank learns whether the others failed with it (then all
  /// may end alike) or it failed alone (then it must abort them). A call that timed out leaves
  /// its meeting open: this rank's next call waits for that same meeting.
  [[nodiscard]] virtual bool meet_within(double seconds) const = 0;
  /// Ends every rank's process with this exit status (a collective abort: a rank that fails
  /// alone stops the others).
  [[noreturn]] virtual void abort(int status) const = 0;
};

}  // namespace signorini
