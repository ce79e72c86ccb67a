#pragma once
// Gauss-Legendre rules on [-1, 1] and their tensor products on the reference square.

#include <vector>

namespace signorini {

struct QuadraturePoint1D {
  double x;
  double w;
};

/// The n-point Gauss-Legendre rule on [-1, 1], exact for polynomials of degree 2n - 1 (n = 1..5).
std::vector<QuadraturePoint1D> gauss_legendre(int n);

}  // namespace signorini
