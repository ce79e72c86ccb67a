#pragma once
// A vector field given as a function of position: tractions p(x), body forces f(x). The problem
// file builds these from muParser expressions; library users pass any callable.

#include <functional>

#include "signorini/core/types.hpp"

namespace signorini {

/// Returns the field's components at x (2D problems use the first two).
using VectorField = std::function<Eigen::Vector3d(const Point& x)>;
/// A scalar field, e.g. the initial gap g(x).
using ScalarField = std::function<double(const Point& x)>;

}  // namespace signorini
