#include "signorini/fem/dof_map.hpp"

#include <stdexcept>

namespace signorini {

DofMap::DofMap(Index num_nodes, int dim)
    : num_nodes_(num_nodes), dim_(dim), free_(static_cast<std::size_t>(num_nodes * dim), 0) {}

void DofMap::clamp(Index node, int component) {
  if (finalized_) throw std::logic_error("DofMap::clamp after finalize");
  free_[static_cast<std::size_t>(node * dim_ + component)] = -1;
}

void DofMap::prescribe(Index node, int component, double value) {
  clamp(node, component);
  if (value == 0.0 && values_.size() == 0) return;
  if (values_.size() == 0) values_ = Vector::Zero(num_dofs());
  values_(node * dim_ + component) = value;
}

Vector DofMap::prescribed_values() const {
  return values_.size() == 0 ? Vector::Zero(num_dofs()) : values_;
}

void DofMap::finalize() {
  Index next = 0;
  for (auto& f : free_) f = (f < 0) ? -1 : next++;
  num_free_ = next;
  finalized_ = true;
}

Vector DofMap::expand(const Vector& free_values) const {
  Vector full = prescribed_values();
  for (Index d = 0; d < num_dofs(); ++d) {
    const Index f = free_[static_cast<std::size_t>(d)];
    if (f >= 0) full(d) = free_values(f);
  }
  return full;
}

Vector DofMap::restrict_to_free(const Vector& full_values) const {
  Vector out(num_free_);
  for (Index d = 0; d < num_dofs(); ++d) {
    const Index f = free_[static_cast<std::size_t>(d)];
    if (f >= 0) out(f) = full_values(d);
  }
  return out;
}

}  // namespace signorini
