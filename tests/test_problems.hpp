#pragma once
// Shared fixtures for the tests: the paper's benchmark at small sizes, solved once per size.

#include <map>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/problem/model.hpp"

namespace signorini::testing {

/// The paper's benchmark model on nx x nx/3 cells, built once and cached.
inline const Model& paper_model(Index nx) {
  static std::map<Index, Model> cache;
  auto it = cache.find(nx);
  if (it == cache.end()) it = cache.emplace(nx, build_model(paper_benchmark(nx, nx / 3))).first;
  return it->second;
}

/// Relative difference ||a - b|| / ||b||.
inline double relative_difference(const Vector& a, const Vector& b) {
  return (a - b).norm() / b.norm();
}

}  // namespace signorini::testing
