#pragma once
// lambda_max(D_H^-1 H) of a generalised Hessian H = A + N^T diag(c) N from the contact zone alone:
// how a multigrid level's Chebyshev interval follows a new active set without Lanczos steps on
// the level's whole operator (multigrid_preconditioner.cpp, refresh()).
//
// The contact terms stiffen only the unknowns Z that the active rows of N touch (c_j > 0). The
// top eigenvector of D_H^-1 H is either A's own, spread over the level, whose eigenvalue
// lambda_max(D_A^-1 A) does not change with the active set and is estimated once, or one that
// the contact terms raise, which lives where they act. The second is estimated on the principal
// submatrix H_ZZ: by Cauchy's interlacing its lambda_max(D_ZZ^-1 H_ZZ) is at most H's (a
// principal submatrix of the symmetric D^-1/2 H D^-1/2), and where the contact terms set the top
// of the spectrum it is within a per cent of it (docs/performance.md, "The refreshes' eigenvalue
// estimates on the contact zone"). The submatrix has a few thousand unknowns where the level has
// tens of thousands or millions.

#include "signorini/core/types.hpp"

namespace signorini {

/// lambda_max(D_ZZ^-1 H_ZZ) for H = A + N^T diag(c) N restricted to Z, the unknowns touched by
/// the rows j of N with c_j > 0: the largest Ritz value after `steps` Lanczos steps from the fixed
/// start (eigenvalue_estimate.hpp), from below. A: the level's symmetric matrix (both triangles);
/// Nt = N^T (column j is row j of N); c >= 0, one value per row of N. 0 where no c_j > 0. On the
/// host, whatever the backend of the level.
[[nodiscard]] double contact_zone_lambda_max(const SparseMatrix& A, const SparseMatrix& Nt,
                                             const Vector& c, int steps);

}  // namespace signorini
