#pragma once
// The function Phi of step (i) (method.md section 3) for fixed multipliers l,
//   Phi(x) = 1/2 <Ax, x> - <b, x> + 1/(2r) sum_j h_j ( ((l_j + r ((N x)_j - g_j))_+)^2 - l_j^2 ),
// with its gradient G, generalised Hessian H and the Newton right-hand side of (17), and the
// modified Lagrangian M(u, l) (10) itself.
//
// With friction (a law of m = d components per node, friction_law.hpp) the same with vectors per
// node: z_j = l_j + r ((N x)_j - g^_j) in R^d, and the penalty term h_j (psi(z_j) - |l_j|^2 / 2)
// / r, psi(z) = (|z|^2 - dist(z, K_j)^2) / 2 with K_j Tresca's admissible forces of bound s_j
// (Coulomb: s_j = mu_j (l_n)_j, fixed during step (i)). grad psi = P, so G = A x - b +
// N^T (h P(z)) and H = A + r N^T diag(h D_j) N with D_j = dP/dz (method.md, "Friction").

#include <vector>

#include "signorini/contact/contact_law.hpp"
#include "signorini/contact/contact_problem.hpp"
#include "signorini/interface/contact_set.hpp"

namespace signorini {

Index count_active(const ActiveSet& active);

class ModifiedLagrangian {
 public:
  /// The problem's law (contact_law(problem)) gives P, its derivative and the penalty change per
  /// node (contact_law.hpp); the problem must outlive this object.
  ModifiedLagrangian(const ContactProblem& problem, double r);
  [[nodiscard]] const ContactLaw& law() const { return law_; }
  /// Values per contact node in l and z (the law's components).
  [[nodiscard]] Index components() const { return m_; }

  /// Sets the multipliers l (fixed during one GNM minimisation). Non-movable nodes keep l_j = 0.
  void set_multipliers(const Vector& l);
  [[nodiscard]] const Vector& multipliers() const { return l_; }
  [[nodiscard]] double r() const { return r_; }

  /// z = l + r (N x - g); non-movable nodes get -infinity (never active).
  [[nodiscard]] Vector shifted_multipliers(const Vector& Nx) const;
  [[nodiscard]] ActiveSet active_set(const Vector& Nx) const;
  /// The generalised derivative of P at z(x): the active set, and with friction each node's
  /// block and offset.
  [[nodiscard]] Linearization linearize(const Vector& Nx) const;
  /// P(z): the multipliers of Uzawa's step (ii) at x (non-movable nodes 0).
  [[nodiscard]] Vector updated_multipliers(const Vector& Nx) const;

  /// G(x) = A x - b + N^T (h z_+): the gradient of Phi, from the residual A x - b (which GNM
  /// keeps up to date with one product A d per step instead of forming A x again).
  [[nodiscard]] Vector gradient(const Vector& residual, const Vector& Nx) const;
  /// h P(z) (n_c values): the contact part of G, G = (A x - b) + N^T (h P(z)).
  [[nodiscard]] Vector contact_forces(const Vector& Nx) const;
  /// h P(z) for given shifted multipliers z (the Armijo rule's slope).
  [[nodiscard]] Vector forces_of(const Vector& z) const;
  /// The pattern of every H below, with A's values (0 at the entries A lacks): A itself where
  /// each contact node's rows touch dofs that A couples (a body against an obstacle: the node's
  /// own dofs); otherwise A's pattern and the pairs of dofs that one node's rows touch (the
  /// node and its partner's face, InterfaceKind::BetweenBodies), which N^T D N fills. One
  /// symbolic analysis of it serves every H.
  [[nodiscard]] const SparseMatrix& hessian_pattern() const;
  /// Writes H = A + r N^T diag(h on the active set) N into `H`, which takes hessian_pattern()'s
  /// pattern (it is given it when it has another number of entries).
  void hessian(const ActiveSet& active, SparseMatrix& H) const;
  /// The same for any law: H = A + r N^T diag(h D_j) N.
  void hessian(const Linearization& lin, SparseMatrix& H) const;
  /// Newton right-hand side b - N^T (h (l - r g) on the active set): H x_m = rhs gives the
  /// minimiser of the quadratic piece active at x_{m-1} (17).
  [[nodiscard]] Vector newton_rhs(const ActiveSet& active) const;
  /// h (l - r g) on the active set, 0 elsewhere (n_c values): newton_rhs = b - N^T of these.
  [[nodiscard]] Vector newton_contact_terms(const ActiveSet& active) const;
  /// For any law: h_j (c_j + D_j (l_j - r g^_j)) per node, which is h (l - r g) on the active
  /// set for one component (H x_new = H x - G written with P(z) = D z + c).
  [[nodiscard]] Vector newton_contact_terms(const Linearization& lin) const;

  /// Phi(x + t d) - Phi(x), evaluated without cancellation (method.md section 4, numerical
  /// note): t <A x - b, d> + t^2/2 <A d, d> + sum_j h_j/(2r) ((z_j + t r (N d)_j)_+^2 - (z_j)_+^2).
  struct Direction {
    double residual_dot_d = 0.0;  ///< <A x - b, d>
    double d_A_d = 0.0;           ///< <A d, d>
    Vector Ad;                    ///< A d: the residual after a step t d is (A x - b) + t A d
    Vector z;                     ///< z(x)
    Vector Nd;                    ///< N d
  };
  /// `residual` is A x - b at the current point x.
  [[nodiscard]] Direction direction(const Vector& residual, const Vector& Nx,
                                    const Vector& d) const;
  [[nodiscard]] double phi_change(const Direction& dir, double t) const;

  /// M(u, l) = J(u) + 1/(2r) sum_j h_j (((l_j + r ((N u)_j - g_j))_+)^2 - l_j^2), equation (10).
  /// With the problem's law.
  [[nodiscard]] static double value(const ContactProblem& problem, double r, const Vector& u,
                                    const Vector& l);

 private:
  const ContactProblem& p_;
  double r_;
  const ContactLaw& law_;
  Index m_ = 1;        // components per node
  Vector g_hat_;       // g^ per row of N (row_offsets)
  Vector h_;           // h per row of N (row_weights)
  Vector parameters_;  // what the law holds fixed in step (i) (friction: the slip bounds)
  Vector l_;
  // P(z) node by node with the parameters of step (i).
  [[nodiscard]] Vector project(const Vector& z) const;
  // sum_j h_j 2 (psi(z0_j + dz_j) - psi(z0_j)) over the movable nodes (the law's potential with
  // the step's parameters), without cancellation where both points are on one smooth piece.
  [[nodiscard]] double penalty_change(const Vector& z0, const Vector& dz) const;
  // H's pattern where it is not A's (hessian_pattern), and the position there of each of A's
  // entries; both empty where it is A's.
  mutable SparseMatrix pattern_;
  mutable std::vector<Index> a_positions_;
  mutable bool pattern_ready_ = false;
  // H = A with hessian_pattern()'s pattern: the start of both hessian()s.
  void start_hessian(SparseMatrix& H) const;
  // Per contact node j, the positions in H's value array of its node block, which entry (a, b)
  // of D_j (column-major; 0 without friction) they take, and (N_a)_p (N_b)_q there.
  struct BlockEntry {
    Index pos;
    int ab;
    double value;
  };
  [[nodiscard]] const std::vector<std::vector<BlockEntry>>& node_entries() const;
  mutable std::vector<std::vector<BlockEntry>> node_entries_;
  mutable bool node_entries_ready_ = false;
};

}  // namespace signorini
