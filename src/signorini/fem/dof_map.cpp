#include "signorini/fem/dof_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "signorini/core/error.hpp"

namespace signorini {

DofMap::DofMap(Index num_nodes, int dim)
    : num_nodes_(num_nodes), dim_(dim), free_(static_cast<std::size_t>(num_nodes * dim), 0) {}

DofMap::DofMap(int dim, std::vector<Index> free, Index num_free, Vector values,
               const std::vector<std::pair<Index, Eigen::Matrix2d>>& frames)
    : num_nodes_(static_cast<Index>(free.size()) / dim),
      dim_(dim),
      free_(std::move(free)),
      values_(std::move(values)) {
  if (static_cast<Index>(free_.size()) != num_nodes_ * dim_ ||
      (values_.size() != 0 && values_.size() != num_dofs()))
    throw std::logic_error("DofMap: a given numbering of the wrong size");
  for (const auto& [node, Q] : frames) set_frame(node, Q);
  num_free_ = num_free;
  // The nodes' places in the numbering (node_place): by their first free number, the nodes
  // without one after all the others.
  place_.resize(static_cast<std::size_t>(num_nodes_));
  for (Index node = 0; node < num_nodes_; ++node) {
    Index place = num_free + node;
    for (int k = 0; k < dim_; ++k)
      if (const Index f = free_index(node, k); f >= 0) place = std::min(place, f);
    place_[static_cast<std::size_t>(node)] = place;
  }
  finalized_ = true;
}

DofMap DofMap::part(const std::vector<Index>& nodes) const {
  std::vector<Index> free;
  free.reserve(nodes.size() * static_cast<std::size_t>(dim_));
  Vector values = values_.size() == 0 ? Vector() : Vector(static_cast<Index>(nodes.size()) * dim_);
  std::vector<std::pair<Index, Eigen::Matrix2d>> frames;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    for (int k = 0; k < dim_; ++k) {
      free.push_back(free_index(nodes[i], k));
      if (values.size() != 0) values(static_cast<Index>(i) * dim_ + k) = value(nodes[i], k);
    }
    if (has_frame(nodes[i])) frames.emplace_back(static_cast<Index>(i), frame(nodes[i]));
  }
  return DofMap(dim_, std::move(free), num_free_, std::move(values), frames);
}

void DofMap::set_frame(Index node, const Eigen::Matrix2d& Q) {
  if (dim_ != 2) throw std::logic_error("DofMap::set_frame: local axes are 2D only so far");
  if (finalized_) throw std::logic_error("DofMap::set_frame after finalize");
  if (dim_ != 2) throw std::logic_error("DofMap::set_frame: 2D only");
  if (frame_of_.empty()) frame_of_.assign(static_cast<std::size_t>(num_nodes_), -1);
  int& f = frame_of_[static_cast<std::size_t>(node)];
  if (f < 0) {
    f = static_cast<int>(frames_.size());
    frames_.push_back(Q);
  } else {
    frames_[static_cast<std::size_t>(f)] = Q;
  }
}

Eigen::Matrix2d DofMap::frame(Index node) const {
  return has_frame(node)
             ? frames_[static_cast<std::size_t>(frame_of_[static_cast<std::size_t>(node)])]
             : Eigen::Matrix2d::Identity();
}

Eigen::VectorXd DofMap::prescribed_at(Index node) const {
  if (values_.size() == 0) return Eigen::VectorXd::Zero(dim_);
  const Eigen::VectorXd local = values_.segment(node * dim_, dim_);
  return has_frame(node) ? Eigen::VectorXd(frame(node) * local) : local;
}

void DofMap::rotate_frames(Vector& full, bool to_local) const {
  for (Index node = 0; node < num_nodes_; ++node) {
    if (!has_frame(node)) continue;
    const Eigen::Matrix2d Q = frame(node);
    auto v = full.segment<2>(node * 2);
    v = to_local ? Eigen::Vector2d(Q.transpose() * v) : Eigen::Vector2d(Q * v);
  }
}

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
  return prescribed_values(Vector::Ones(num_dofs()));
}

void DofMap::finalize(const std::vector<Index>& node_order) {
  Index next = 0;
  if (node_order.empty()) {
    for (auto& f : free_) f = (f < 0) ? -1 : next++;
  } else {
    if (static_cast<Index>(node_order.size()) != num_nodes_)
      throw std::logic_error("DofMap::finalize: the node order is not one of the nodes");
    place_.assign(static_cast<std::size_t>(num_nodes_), -1);
    Index place = 0;
    for (const Index node : node_order) {
      if (node < 0 || node >= num_nodes_ || place_[static_cast<std::size_t>(node)] >= 0)
        throw std::logic_error("DofMap::finalize: the node order is not a permutation");
      place_[static_cast<std::size_t>(node)] = place++;
      for (int k = 0; k < dim_; ++k) {
        Index& f = free_[static_cast<std::size_t>(node * dim_ + k)];
        f = (f < 0) ? -1 : next++;
      }
    }
  }
  num_free_ = next;
  finalized_ = true;
}

Vector DofMap::expand(const Vector& free_values) const {
  return expand(free_values, Vector::Ones(num_dofs()));
}

Vector DofMap::expand(const Vector& free_values, const Vector& scales) const {
  return expand(free_values, scales, [](Index f) { return f; });
}

Vector DofMap::expand(const Vector& values, const Vector& scales,
                      const std::function<Index(Index)>& place) const {
  Vector full =
      values_.size() == 0 ? Vector::Zero(num_dofs()) : Vector(scales.cwiseProduct(values_));
  for (Index d = 0; d < num_dofs(); ++d) {
    const Index f = free_[static_cast<std::size_t>(d)];
    if (f < 0) continue;
    const Index at = place(f);
    if (at < 0 || at >= values.size())
      throw InputError(fmt::format("expanding a part's displacement: free dof {} has no value", f));
    full(d) = values(at);
  }
  if (has_frames()) rotate_frames(full, /*to_local=*/false);
  return full;
}

Vector DofMap::prescribed_values(const Vector& scales) const {
  if (values_.size() == 0) return Vector::Zero(num_dofs());
  Vector full = scales.cwiseProduct(values_);
  rotate_frames(full, /*to_local=*/false);
  return full;
}

Vector DofMap::restrict_to_free(const Vector& full_values) const {
  Vector local;  // the components along the frames' axes, where a node has one
  if (has_frames()) {
    local = full_values;
    rotate_frames(local, /*to_local=*/true);
  }
  const Vector& full = has_frames() ? local : full_values;
  Vector out(num_free_);
  for (Index d = 0; d < num_dofs(); ++d) {
    const Index f = free_[static_cast<std::size_t>(d)];
    if (f >= 0) out(f) = full(d);
  }
  return out;
}

}  // namespace signorini
