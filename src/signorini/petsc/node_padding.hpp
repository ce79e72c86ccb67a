#pragma once
// The unknowns of the PETSc path in whole node blocks (docs/distributed.md, "Node blocks").
//
// A node on a roller has one or two free unknowns where the others have three. Blocks of one size
// let PETSc store A in 3 x 3 blocks (MPIBAIJ: 12 ms a product against AIJ's 14 ms at 100,860
// unknowns) and let GAMG aggregate nodes rather than single unknowns (a graph a third the
// size). So each node gets
// `block` slots: its free unknowns first, in their order, then padding slots, whose rows and
// columns hold only a diagonal entry (that of the node's first unknown), zero right-hand side and
// zero near-null space. Such a slot is decoupled: CG leaves it at zero, and it changes no other
// unknown's value.

#include <mpi.h>

#include <vector>

#include "signorini/core/types.hpp"

namespace signorini::petsc {

class NodePadding {
 public:
  /// `node_of_unknown`: the mesh node of each of the n unknowns, a node's unknowns consecutive.
  /// Blocks of the most unknowns any node has; none (every slot an unknown) where all nodes have
  /// as many, or where the nodes are not known.
  NodePadding(const std::vector<Index>& node_of_unknown, Index n);
  /// The same where each rank knows only its own unknowns [first, last) of n (`own_nodes`: the
  /// node of each), as on the ranks' parts of the mesh (docs/distributed.md): the ranks agree
  /// on the block through `comm` (a collective call), number their nodes' slots one rank after
  /// the other, and learn the slots of the others' unknowns that this rank's columns of A
  /// reach (`ghosts`, increasing) from their owners.
  NodePadding(const std::vector<Index>& own_nodes, Index first, Index last, Index n,
              const std::vector<Index>& ghosts, MPI_Comm comm);

  /// Whether some node has padding slots.
  [[nodiscard]] bool active() const { return size_ != n_; }
  /// Slots per node: the block size of the PETSc matrices.
  [[nodiscard]] Index block() const { return block_; }
  /// Unknowns and padding slots together.
  [[nodiscard]] Index size() const { return size_; }
  /// The slot of unknown i (where each rank knows its own: one of its own or of its ghosts).
  [[nodiscard]] Index slot(Index i) const;
  /// The first slot of the node of unknown i, where i starts its node's unknowns (a rank's range
  /// [lo, hi) of unknowns becomes [start(lo), start(hi)) of slots; start(n) = size()).
  [[nodiscard]] Index start(Index i) const;

  /// A's columns [lo, hi) (by symmetry its rows) on the slots, the padding slots of their nodes
  /// with a diagonal entry: size() x (start(hi) - start(lo)), column s of the slots at
  /// s - start(lo). A holds all its columns, or only these (n x (hi - lo), column i at i - lo).
  [[nodiscard]] SparseMatrix matrix(const SparseMatrix& A, Index lo, Index hi) const;
  /// The rows [first, last) of a vector (`rows`: last - first entries, or rows of a matrix) on
  /// their slots [start(first), start(last)), zero on the padding slots.
  [[nodiscard]] Vector rows(const Vector& rows, Index first, Index last) const;
  [[nodiscard]] Matrix rows(const Matrix& rows, Index first, Index last) const;
  /// The entries of the unknowns [first, last) from the rank's slots [start(first), start(last))
  /// (all of them: [0, n) from the size() slots).
  [[nodiscard]] Vector own_unknowns(const Vector& slots, Index first, Index last) const;

 private:
  Index n_ = 0, size_ = 0, block_ = 1;
  std::vector<Index> slot_;  // per unknown (distributed: per own unknown); empty where not active
  // Distributed only: the own unknowns [first_, last_) on the slots [begin_, end_), and the
  // slots of the ghosts.
  bool distributed_ = false;
  Index first_ = 0, last_ = 0, begin_ = 0, end_ = 0;
  std::vector<Index> ghosts_, ghost_slots_;
};

}  // namespace signorini::petsc
