#pragma once
// The contact problem condensed onto the normal displacements of its contact nodes (with
// friction: onto every free dof of its contact nodes).
//
// The contact terms of (16) involve only (x . nu)_j. Rotating each contact node's free dofs so
// that one of them is the normal displacement (a Householder reflection per node) and
// eliminating every other unknown by a Schur complement turns (14) into a dense problem of the
// same form with one unknown per movable contact node:
//   minimise 1/2 v^T S v - g^T v  subject to  s_j v_j <= g_j,
// where S and g come from one sparse factorisation (linalg/schur_complement.hpp) and s_j is the
// length of nu_j over the node's free dofs (signed where nu_j is along one axis and that dof is
// taken as it is, without rotation). Every method then iterates on the small dense problem
// at no cost per iteration beyond the contact boundary, and the displacement is recovered at the
// end by one solve. The solution is that of the full problem (tested to 1e-10).
//
// With friction (contact.components = d) the tangential rows of N need the tangential
// displacements too: the problem is condensed, without rotation, onto the free dofs that N's rows
// touch (those of the contact nodes, d per node where none is clamped), and the reduced N is N's
// columns there. The dense problem is then d times larger per side, still small beside the
// sparse one in 2D (docs/solvers.md, "Friction").

#include <memory>

#include "signorini/contact/contact_problem.hpp"
#include "signorini/contact/normal_rotation.hpp"
#include "signorini/core/timing_table.hpp"
#include "signorini/linalg/schur_complement.hpp"

namespace signorini {

class CondensedProblem {
 public:
  /// Rotates, orders, factorises and condenses; see timings() for the phases.
  /// `threads`: the solver's thread count (ContactSolverOptions::threads; 0: the machine's),
  /// which decides whether the factorisation splits in two parts.
  explicit CondensedProblem(const ContactProblem& full, int threads = 0);
  /// The parts the factorisation was split in (1 or 2), one thread each.
  [[nodiscard]] Index parts() const { return schur_->parts(); }

  /// The condensed problem: A = S (dense, stored as a sparse matrix), b = g, and a contact set
  /// with the same nodes, normals, weights, gaps and movable flags, whose N has s_j in the column
  /// of node j's normal unknown.
  [[nodiscard]] const ContactProblem& reduced() const { return reduced_; }
  /// Displacement in the free dofs of the full problem for condensed unknowns v (one solve).
  [[nodiscard]] Vector expand(const Vector& v) const;
  /// New loads b of the full problem (same A): the condensed load g again (one forward
  /// substitution with the factor kept from the set-up).
  void set_load(const Vector& b);
  /// New gaps of the contact nodes (the condensed problem has the same).
  void set_gaps(const Vector& gaps) { reduced_.contact.gaps = gaps; }
  /// Friction: the slip origin of the contact set (ContactSet::slip_origin; the reduced N has
  /// the same rows).
  void set_slip_origin(const Vector& origin) { reduced_.contact.slip_origin = origin; }
  /// The condensed unknowns v of a displacement u of the full problem: its normal components at
  /// the movable contact nodes (with friction: its values at the kept dofs), for a warm start.
  [[nodiscard]] Vector condense(const Vector& u) const;
  [[nodiscard]] TimingTable timings() const;

 private:
  ContactProblem reduced_;
  NormalRotation rotation_;  // x = Q y
  // The (rotated) unknowns kept: node j's normal displacement per movable node; with friction
  // the free dofs of the contact nodes.
  std::vector<Index> kept_;
  std::unique_ptr<SchurComplement> schur_;
  TimingTable timings_;
};

}  // namespace signorini
