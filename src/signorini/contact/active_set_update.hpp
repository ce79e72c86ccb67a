#pragma once
// The primal-dual active-set update of semismooth Newton (docs/solvers.md): after the problem of
// an active set S has been solved (multipliers l, gap residual N u - g), the nodes of S that
// press (l_j > 0) stay and the free nodes that penetrate ((N u - g)_j > 0) join. Shared by
// semismooth Newton's loop and Uzawa-GNM's active-set finish.

#include "signorini/contact/contact_law.hpp"
#include "signorini/core/types.hpp"
#include "signorini/interface/contact_set.hpp"

namespace signorini {

/// The next active set after S's solve. A node that touches without pressing (l_j = 0 and
/// u_n = g_j: no strict complementarity, as at the corners of quadratic triangles under a uniform
/// pressure) gets l_j and its gap residual within rounding of 0 with either sign: it keeps its
/// state within 1e-13 of the largest values, instead of leaving and rejoining in a cycle. Nodes
/// that cannot move stay out.
[[nodiscard]] ActiveSet next_active_set(const ContactSet& contact, const ActiveSet& S,
                                        const Vector& l, const Vector& gap_residual);

}  // namespace signorini
