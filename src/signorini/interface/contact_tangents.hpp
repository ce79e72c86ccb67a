#pragma once
// The tangential directions of the contact nodes, for friction (docs/method.md, "Friction"): at
// node j an orthonormal basis t_1 .. t_{d-1} of the plane normal to nu_j, and the operator T
// with (T x)_{j,k} = (x . t_k)_j over the free dofs of node j, as N gives (x . nu)_j
// (contact_set.hpp). Together, (N x)_j and (T x)_j are node j's displacement in the frame
// (nu_j, t_1, .., t_{d-1}).
//
// Used by friction (problem/model.cpp adds T to N: contact/friction_law.hpp); tested in
// tests/interface/contact_tangents_test.cpp.

#include "signorini/fem/dof_map.hpp"
#include "signorini/interface/contact_set.hpp"
#include "signorini/interface/tangent_basis.hpp"

namespace signorini {

/// T: (dim - 1) size() rows (row (dim - 1) j + k for t_k of node j) over the free dofs, in the
/// local axes of a node that has them (DofMap::set_frame), as N's rows are.
[[nodiscard]] SparseMatrix tangential_operator(const ContactSet& contact, const DofMap& dofs);

}  // namespace signorini
