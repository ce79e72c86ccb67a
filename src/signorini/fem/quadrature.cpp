#include "signorini/fem/quadrature.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace signorini {

std::vector<QuadraturePoint1D> gauss_legendre(int n) {
  switch (n) {
    case 1:
      return {{0.0, 2.0}};
    case 2: {
      const double a = 1.0 / std::sqrt(3.0);
      return {{-a, 1.0}, {a, 1.0}};
    }
    case 3: {
      const double a = std::sqrt(3.0 / 5.0);
      return {{-a, 5.0 / 9.0}, {0.0, 8.0 / 9.0}, {a, 5.0 / 9.0}};
    }
    case 4: {
      const double s = 2.0 / 7.0 * std::sqrt(6.0 / 5.0);
      const double a = std::sqrt(3.0 / 7.0 - s);
      const double b = std::sqrt(3.0 / 7.0 + s);
      const double wa = (18.0 + std::sqrt(30.0)) / 36.0;
      const double wb = (18.0 - std::sqrt(30.0)) / 36.0;
      return {{-b, wb}, {-a, wa}, {a, wa}, {b, wb}};
    }
    case 5: {
      const double s = 2.0 * std::sqrt(10.0 / 7.0);
      const double a = std::sqrt(5.0 - s) / 3.0;
      const double b = std::sqrt(5.0 + s) / 3.0;
      const double wa = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0;
      const double wb = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
      return {{-b, wb}, {-a, wa}, {0.0, 128.0 / 225.0}, {a, wa}, {b, wb}};
    }
    default:
      throw std::invalid_argument("gauss_legendre: " + std::to_string(n) +
                                  " points requested, 1..5 available");
  }
}

}  // namespace signorini
