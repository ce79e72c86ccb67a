#pragma once
// A dense symmetric matrix kept in a SparseMatrix with every entry stored (column-major, rows
// 0..n-1 in each column): the condensed contact problems hold their Schur complement this way, so
// that the methods written for sparse problems apply to it unchanged, while the dense Newton
// systems and the Delassus operator read the same values as a dense matrix without a copy.

#include <optional>

#include "signorini/core/types.hpp"

namespace signorini {

/// An n x n matrix with all n^2 entries stored, values zero.
SparseMatrix dense_stored_matrix(Index n);

/// True when every entry of A is stored in column-major order (dense_stored_matrix's layout).
bool is_dense_stored(const SparseMatrix& A);

/// The values of a dense-stored A as a dense matrix (no copy); std::nullopt for any other A.
std::optional<Eigen::Map<const Eigen::MatrixXd>> dense_view(const SparseMatrix& A);

}  // namespace signorini
