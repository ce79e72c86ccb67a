#pragma once
// Fill-reducing orderings for the sparse Cholesky factorisations, computed on the graph of the
// mesh nodes rather than of the dofs: adjacent unknowns whose columns have the same pattern (the
// components of one node) are ordered as one, which makes the ordering several times cheaper and,
// for nested dissection, better (docs/performance.md). Unknowns can be forced to the end, in a
// given order (the contact unknowns of the Schur complement).

#include <vector>

#include "signorini/core/enum_names.hpp"
#include "signorini/core/types.hpp"

namespace signorini {

enum class OrderingMethod { Auto, Amd, Metis };

inline constexpr EnumNames<OrderingMethod, 3> kOrderingMethodNames{{
    {OrderingMethod::Auto, "auto"},
    {OrderingMethod::Amd, "amd"},
    {OrderingMethod::Metis, "metis"},
}};

/// A permutation p (new position k holds old unknown p[k]) of the unknowns of the symmetric
/// matrix A (pattern only, both triangles stored), with the unknowns `last` at the end in the
/// given order (AMD then is CAMD, which orders the rest knowing that they follow). Auto is AMD: on
/// the paper's meshes up to 1920x640 (2.5 million unknowns) METIS saves up to 20 % of the flops but
/// no factorisation time, and costs far more to compute.
std::vector<Index> fill_reducing_ordering(const SparseMatrix& A, const std::vector<Index>& last,
                                          OrderingMethod method = OrderingMethod::Auto);

}  // namespace signorini
