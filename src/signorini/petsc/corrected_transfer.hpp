#pragma once
// A multigrid transfer P + dP, and its transpose, as two MATSHELLs for PCMG: the contact
// prolongation's change dP = P_H - P (level_contact_prolongation.hpp), a small matrix whose rows
// are the active contact unknowns, added to the products of P and of its transpose as they are
// (P itself, or a ThreadedProduct's shells of P and of P^T). The restriction stays exactly the
// interpolation's transpose, so the V-cycle stays symmetric.

#include <petscmat.h>

namespace signorini::petsc {

class CorrectedTransfer {
 public:
  /// P: the interpolation (fine x coarse, a matrix or a shell with MatMult and MatMultAdd); R:
  /// its transpose as such a matrix (coarse x fine), or null for P's transposed products. Both
  /// must outlive this object.
  CorrectedTransfer(Mat P, Mat R);
  ~CorrectedTransfer();
  CorrectedTransfer(const CorrectedTransfer&) = delete;
  CorrectedTransfer& operator=(const CorrectedTransfer&) = delete;

  /// The shells of P + dP (fine x coarse) and of its transpose (coarse x fine).
  [[nodiscard]] Mat interpolation() const { return interpolation_; }
  [[nodiscard]] Mat restriction() const { return restriction_; }
  /// dP from here on (held, not owned: it must live until the next call); null: none.
  void set_change(Mat dP) { dP_ = dP; }

  /// y = (P + dP) x or (P + dP)^T x, or w = y + the same (w may be y).
  void interpolate(Vec x, Vec y, Vec w, bool add) const;
  void restrict_residual(Vec x, Vec y, Vec w, bool add) const;

 private:
  Mat P_ = nullptr, R_ = nullptr, dP_ = nullptr;
  Mat interpolation_ = nullptr, restriction_ = nullptr;
};

}  // namespace signorini::petsc
