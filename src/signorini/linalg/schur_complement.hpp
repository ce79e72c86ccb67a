#pragma once
// Static condensation of an SPD matrix onto a small set C of unknowns by one sparse Cholesky
// factorisation: with C ordered last (AMD on the node graph, C appended after it;
// fill_reducing_ordering.hpp),
//   P A P^T = L L^T,  L = [L_II 0; L_CI L_CC],
// and the Schur complement S = A_CC - A_CI A_II^-1 A_IC equals L_CC L_CC^T. The trailing block of
// the factor is read out of CHOLMOD's supernodes, so S costs no extra solves. The contact solvers
// use it to iterate on the contact boundary alone (docs/performance.md).
//
// Large matrices are condensed in two parts on two threads: a vertex separator (METIS,
// vertex_separator.hpp) splits the unknowns outside C into two interiors I_1, I_2 that A does not
// couple and a separator s. Each part's principal submatrix A(I_k + b_k), with b_k the unknowns of
// the interface B = [s; C] that I_k touches, is factorised as above with b_k last, which gives
// A_Bk A_kk^-1 A_kB = A(b_k, b_k) - L_bb L_bb^T. Their sum makes the interface's Schur complement
// S_B (dense, |s| + |C| square), and its dense Cholesky factor L_B, with s first, eliminates s:
// its trailing block gives S = L_cc L_cc^T. The flops of the two sparse factorisations are about
// those of the one, and they run at once.

#include <memory>
#include <vector>

#include "signorini/core/timing_table.hpp"
#include "signorini/core/types.hpp"

namespace signorini {

class SchurComplement {
 public:
  /// Orders, analyses and factorises A (SPD, both triangles stored) with the unknowns `last`
  /// ordered last, then forms S. Throws NumericalError if A is not positive definite.
  /// `parts`: 1 (one factorisation), 2 (two parts on two threads; one when A does not split),
  /// 0 (automatic_parts()).
  SchurComplement(const SparseMatrix& A, const std::vector<Index>& last, Index parts = 0);
  /// The same, releasing A as soon as CHOLMOD holds its copy, so that the largest problems fit
  /// in memory.
  SchurComplement(SparseMatrix&& A, const std::vector<Index>& last, Index parts = 0);
  ~SchurComplement();
  SchurComplement(const SchurComplement&) = delete;
  SchurComplement& operator=(const SchurComplement&) = delete;

  /// S = A_CC - A_CI A_II^-1 A_IC, |C| x |C|, in the order of `last`: the one copy of S, a
  /// dense matrix with every entry stored (linalg/dense_storage.hpp), formed once in place.
  [[nodiscard]] const SparseMatrix& matrix() const { return S_; }
  /// Hands S over (the condensed problem keeps it as its matrix); matrix() is empty afterwards.
  [[nodiscard]] SparseMatrix release_matrix() { return std::move(S_); }
  /// The condensed load g = b_C - A_CI A_II^-1 b_I (one forward substitution, whose result is
  /// kept for solve_with_condensed_forces()).
  [[nodiscard]] Vector condensed_load(const Vector& b);
  /// x = A^-1 (b + E_C f) for the b of the last condensed_load() and forces f on C (in the order
  /// of `last`): only a back substitution, since the forward substitution of E_C f touches the
  /// trailing block alone, L^-1 P E_C f = [0; L_CC^-1 f].
  [[nodiscard]] Vector solve_with_condensed_forces(const Vector& f) const;
  /// x = A^-1 rhs with the factorisation (one forward and one back substitution).
  [[nodiscard]] Vector solve(const Vector& rhs) const;
  /// The parts that were factorised (1 or 2).
  [[nodiscard]] Index parts() const;
  /// Two parts from kTwoPartUnknowns unknowns on when two threads may run (`threads`; 0: as
  /// many as the machine runs at once), one otherwise.
  static constexpr Index kTwoPartUnknowns = 100'000;
  [[nodiscard]] static Index automatic_parts(Index unknowns, int threads = 0);
  /// Phases: "condensation analysis", "condensation factorization", "condensation Schur
  /// complement", "condensation solve".
  [[nodiscard]] const TimingTable& timings() const { return timings_; }

 private:
  void build(const SparseMatrix& A, SparseMatrix* owned, Index parts);
  void build_one_part(const SparseMatrix& A, SparseMatrix* owned);
  // false (nothing built, A kept) when A does not split or the split does not pay.
  bool build_two_parts(const SparseMatrix& A, SparseMatrix* owned);
  // CHOLMOD's state, the factors' dense blocks and the last forward substitution; freed by its
  // destructor, also when construction throws.
  struct Impl;
  std::unique_ptr<Impl> impl_;
  SparseMatrix S_;
  mutable TimingTable timings_;
};

}  // namespace signorini
