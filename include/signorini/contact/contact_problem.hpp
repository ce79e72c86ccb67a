#pragma once
// The discrete contact problem (14) in the free dofs: minimise 1/2 <A x, x> - <b, x> subject to
// (N x)_j <= g_j for the contact nodes j.

#include <vector>

#include "signorini/contact/contact_set.hpp"

namespace signorini {

struct ContactProblem {
  SparseMatrix A;  ///< reduced stiffness, SPD, both triangles stored
  Vector b;        ///< load vector
  ContactSet contact;
};

}  // namespace signorini
