#pragma once
// The discrete contact problem (14) in the free dofs: minimise 1/2 <A x, x> - <b, x> subject to
// (N x)_j <= g_j for the contact nodes j.

#include <algorithm>
#include <memory>
#include <vector>

#include "signorini/contact/contact_law.hpp"
#include "signorini/interface/contact_set.hpp"

namespace signorini {

class DistributedEngine;  // (contact/distributed_engine.hpp, in a build with PETSc)

struct ContactProblem {
  SparseMatrix A;  ///< reduced stiffness, SPD, both triangles stored
  Vector b;        ///< load vector (a partitioned problem: this rank's rows only)
  ContactSet contact;
  /// The law on the contact rows (contact_law.hpp: frictionless, Tresca, Coulomb): null for the
  /// paper's frictionless unilateral law. Shared, as a law holds no state of a solve; its
  /// components per node must be contact.components.
  std::shared_ptr<const ContactLaw> law = {};
  /// Optional aids for a distributed solve (docs/distributed.md), empty unless build_model plans
  /// one: the near-null space of A for algebraic multigrid (the rigid-body modes on the free
  /// dofs, n x 3 in 2D, n x 6 in 3D; a partitioned problem: this rank's rows only), and the mesh
  /// node of each free dof (all n, or on the ranks' parts of the mesh this rank's rows only), so
  /// that the dofs of a node stay on one rank and go to PETSc as one block.
  Matrix near_null_space = {};
  std::vector<Index> node_of_unknown = {};
  /// Non-empty for a partitioned problem (docs/distributed.md): rank `rank` of a distributed run
  /// owns the free dofs [row_starts[rank], row_starts[rank + 1]); A holds only their columns (by
  /// symmetry their rows), as an n x (end_row() - first_row()) matrix whose column k is unknown
  /// first_row() + k's (column_of), so that no array of A has all n entries on every rank; b
  /// and the near-null space hold only their rows. The contact set is whole on every rank. Products
  /// with A and the sums over the unknowns (the energy, the KKT residuals) are then sums over the
  /// ranks (contact/distributed_engine.hpp). Only the distributed path solves such a problem.
  std::vector<Index> row_starts = {};
  int rank = 0;
  /// A partitioned problem on the ranks' parts of the mesh (docs/distributed.md): the unknowns
  /// whose values this rank's solution holds (ContactResult::u), increasing: its own
  /// [first_row(), end_row()) and the other free dofs of the nodes of its part of the mesh, so
  /// that no rank holds a vector of all n unknowns. Empty: the solution has all n.
  std::vector<Index> solution_unknowns = {};
  /// The engine of the distributed run this problem belongs to (its ranks and the solver's
  /// distributed objects, passed along as PETSc passes a communicator): null in a serial
  /// program. Not owned; build_model sets it from its argument. A partitioned problem needs it.
  DistributedEngine* engine = nullptr;

  [[nodiscard]] bool partitioned() const { return !row_starts.empty(); }
  /// The solution holds solution_unknowns only (the same on every rank: a branch on it is
  /// collective-safe).
  [[nodiscard]] bool part_solution() const { return !solution_unknowns.empty(); }
  /// Where unknown i is in the solution: i itself, or its place in solution_unknowns (-1 where
  /// the part does not have it).
  [[nodiscard]] Index solution_index(Index i) const {
    if (!part_solution()) return i;
    const auto it = std::lower_bound(solution_unknowns.begin(), solution_unknowns.end(), i);
    return it != solution_unknowns.end() && *it == i ? it - solution_unknowns.begin() : -1;
  }
  /// The first unknown whose row this process holds, and one past the last: [0, n) unless
  /// partitioned.
  [[nodiscard]] Index first_row() const {
    return partitioned() ? row_starts[static_cast<std::size_t>(rank)] : 0;
  }
  [[nodiscard]] Index end_row() const {
    return partitioned() ? row_starts[static_cast<std::size_t>(rank) + 1] : A.rows();
  }
  /// The column of A that holds unknown i's column (i in [first_row(), end_row())).
  [[nodiscard]] Index column_of(Index i) const { return i - first_row(); }
  /// The rows of a vector of all n unknowns, or of a solution (ContactResult::u), that this
  /// process holds (all of it unless partitioned), as b is held.
  [[nodiscard]] Vector held_rows(const Vector& v) const {
    if (!partitioned()) return v;
    if (end_row() == first_row()) return Vector();
    const Index first = v.size() == A.rows() ? first_row() : solution_index(first_row());
    return v.segment(first, end_row() - first_row());
  }
};

/// The law of `problem`: *problem.law, or the unilateral law.
[[nodiscard]] inline const ContactLaw& contact_law(const ContactProblem& problem) {
  return problem.law != nullptr ? *problem.law : unilateral_contact_law();
}

/// Throws InputError where the problem's law does not fit its contact set: another number of
/// components per node than the set's rows of N per node, or parameters for another number of
/// nodes.
void require_law_fits(const ContactProblem& problem);

}  // namespace signorini
