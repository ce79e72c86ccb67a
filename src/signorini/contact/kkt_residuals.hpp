#pragma once
// KKT residuals of a pair (u, l) for the discrete problem (14):
//   A u - b + N^T H l = 0,  N u - g <= 0,  l >= 0,  l (N u - g) = 0   (H = diag(h)).

#include "signorini/contact/contact_law.hpp"
#include "signorini/contact/contact_problem.hpp"
#include "signorini/contact/solve_summary.hpp"

namespace signorini {

/// Relative residuals as defined at KktResiduals. With friction (contact.components = d), l has
/// d values per node; the problem's law (contact_law(problem)) says what its conditions are.
KktResiduals kkt_residuals(const ContactProblem& problem, const Vector& u, const Vector& l);

}  // namespace signorini
