#include "signorini/problem/resultants.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>

#include "signorini/contact/distributed_engine.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/interface/tangent_basis.hpp"

namespace signorini {

namespace {

// Sum of the forces of a full node-major vector over `dofs`, and their moment about `reference`.
struct Sum {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  void add(const Mesh& mesh, const Eigen::Vector3d& reference, Index dof, double value) {
    const int dim = mesh.dim();
    Eigen::Vector3d f = Eigen::Vector3d::Zero();
    f(dof % dim) = value;
    force += f;
    moment += (mesh.point(dof / dim) - reference).cross(f);
  }
};

std::string vector_text(const Eigen::Vector3d& v, int dim) {
  return dim == 2 ? fmt::format("({:.6e}, {:.6e})", v(0) + 0.0, v(1) + 0.0)
                  : fmt::format("({:.6e}, {:.6e}, {:.6e})", v(0) + 0.0, v(1) + 0.0, v(2) + 0.0);
}

}  // namespace

Resultants compute_resultants(const Model& model, const ContactResult& result) {
  return compute_resultants(model, result.u, result.l, result.tangential, result.load_factor,
                            result.load_step);
}

Resultants compute_resultants(const Model& model, const Vector& u, const Vector& l,
                              const Matrix& tangential, double load_factor, int load_step) {
  const Mesh& mesh = model.mesh;
  const int dim = mesh.dim();
  // On a rank's part of the mesh (docs/distributed.md) each rank sums what it accounts for: the
  // loads and contact forces of the nodes, and the internal forces of the cells, that
  // Model::node_rank and cell_rank give it; the sums then add up over the ranks.
  const bool part = model.is_part();
  const int rank = model.problem.rank;
  Resultants r;
  const Vector centroid = part ? model.whole.centroid : Vector(mesh.coordinates().rowwise().mean());
  for (int k = 0; k < dim; ++k) r.reference(k) = centroid(k);
  std::vector<bool> counted(static_cast<std::size_t>(mesh.num_nodes()), true);
  if (part)
    for (Index v = 0; v < mesh.num_nodes(); ++v)
      counted[static_cast<std::size_t>(v)] = model.node_rank(v) == rank;

  // The foundation's force on the body, -h_j l_j nu_j at contact node j, on the full dofs; with
  // friction also -h_j l_t,j along the node's tangents (B^T W l of the equilibrium).
  const ContactSet& c = model.problem.contact;
  Vector contact = Vector::Zero(model.dofs.num_dofs());
  const bool friction = tangential.cols() == c.size() && tangential.size() > 0;
  const Matrix along = friction ? cartesian_tangential(c.normals, tangential) : Matrix();
  for (Index j = 0; j < c.size(); ++j) {
    const Index node = model.local_node(c.nodes[static_cast<std::size_t>(j)]);
    if (node < 0 || !counted[static_cast<std::size_t>(node)]) continue;
    Eigen::VectorXd force = -c.weights(j) * l(j) * c.normals.col(j);
    if (friction) force -= c.weights(j) * along.col(j);
    for (int k = 0; k < dim; ++k) contact(node * dim + k) += force(k);
  }

  Sum applied, foundation;
  const Vector loads = model.applied_loads(load_factor, load_step);
  for (Index i = 0; i < model.dofs.num_dofs(); ++i) {
    if (!counted[static_cast<std::size_t>(i / dim)]) continue;
    if (loads(i) != 0.0) applied.add(mesh, r.reference, i, loads(i));
    if (contact(i) != 0.0) foundation.add(mesh, r.reference, i, contact(i));
  }

  // K u only where it is needed: in the cells that touch a clamped dof (on a part those that
  // the rank accounts for).
  const Vector full_u = model.full_displacement(u, load_factor, load_step);
  // The cells that this rank accounts for and that hold a dof (node, k) where flagged(node, k).
  const auto counted_cells_holding = [&](auto flagged) {
    return [&, flagged](Index cell) {
      if (part && model.cell_rank(cell) != rank) return false;
      for (const Index node : mesh.cell(cell))
        for (int k = 0; k < dim; ++k)
          if (flagged(node, k)) return true;
      return false;
    };
  };
  const Vector Ku = internal_forces(
      mesh, model.elasticity, full_u,
      counted_cells_holding([&](Index node, int k) { return model.dofs.is_clamped(node, k); }));
  // The strain energy 1/2 u.Ku of the whole displacement u = x + w, w the prescribed values
  // (J of the free unknowns x leaves out the energy of w): 1/2 x.Ax from A's rows (no pass over
  // the cells: that cost 2.4 s at a million hex8 unknowns), plus u.Kw - 1/2 w.Kw with K w over
  // the cells that touch a prescribed value.
  const Vector w = model.full_displacement(Vector::Zero(u.size()), load_factor, load_step);
  const Vector Kw = internal_forces(
      mesh, model.elasticity, w,
      counted_cells_holding([&](Index node, int k) { return w(node * dim + k) != 0.0; }));
  const Vector held = model.problem.held_rows(u);
  double energy =
      0.5 * held.dot(held_stiffness_rows(model.problem, u)) + full_u.dot(Kw) - 0.5 * w.dot(Kw);
  std::vector<Sum> reactions;
  for (const ClampedPart& clamped : model.clamped_parts) {
    Sum reaction;
    for (const Index dof : clamped.dofs) {
      const bool node_counted = counted[static_cast<std::size_t>(dof / dim)];
      const double value = Ku(dof) - (node_counted ? loads(dof) + contact(dof) : 0.0);
      if (value != 0.0) reaction.add(mesh, r.reference, dof, value);
    }
    reactions.push_back(reaction);
  }
  if (part) {  // the sums over the ranks, in one message
    std::vector<double> sums;
    const auto put = [&](const Sum& s) {
      sums.insert(sums.end(), s.force.data(), s.force.data() + 3);
      sums.insert(sums.end(), s.moment.data(), s.moment.data() + 3);
    };
    put(applied);
    put(foundation);
    for (const Sum& s : reactions) put(s);
    sums.push_back(energy);
    sum_over_ranks(model.problem, sums.data(), static_cast<Index>(sums.size()));
    energy = sums.back();
    std::size_t at = 0;
    const auto take = [&](Sum& s) {
      s.force = Eigen::Vector3d(sums[at], sums[at + 1], sums[at + 2]);
      s.moment = Eigen::Vector3d(sums[at + 3], sums[at + 4], sums[at + 5]);
      at += 6;
    };
    take(applied);
    take(foundation);
    for (Sum& s : reactions) take(s);
  }
  r.strain_energy = energy;
  r.applied = applied.force;
  r.applied_moment = applied.moment;
  r.contact = foundation.force;
  r.contact_moment = foundation.moment;
  double scale = r.applied.norm() + r.contact.norm();
  double moment_scale = r.applied_moment.norm() + r.contact_moment.norm();
  Eigen::Vector3d total = r.applied + r.contact;
  Eigen::Vector3d total_moment = r.applied_moment + r.contact_moment;
  for (std::size_t i = 0; i < reactions.size(); ++i) {
    const Sum& reaction = reactions[i];
    r.reactions.push_back({model.clamped_parts[i].boundary, reaction.force, reaction.moment});
    total += reaction.force;
    total_moment += reaction.moment;
    scale += reaction.force.norm();
    moment_scale += reaction.moment.norm();
  }
  r.balance = total;
  r.moment_balance = total_moment;
  r.relative_balance = scale > 0.0 ? total.norm() / scale : 0.0;
  // Moments that cancel by symmetry (a block pressed straight down) are no scale: the forces
  // times the body's size are.
  double size = model.whole.radius;
  if (!part)
    for (Index v = 0; v < mesh.num_nodes(); ++v)
      size = std::max(size, (mesh.point(v) - r.reference).norm());
  moment_scale = std::max(moment_scale, scale * size);
  r.relative_moment_balance = moment_scale > 0.0 ? total_moment.norm() / moment_scale : 0.0;
  return r;
}

std::string resultants_report(const Resultants& r, int dim) {
  std::string s = "resultants (forces on the body):\n";
  s += fmt::format("  applied load          {}\n", vector_text(r.applied, dim));
  for (const ClampReaction& c : r.reactions)
    s += fmt::format("  reaction of '{}'{:<{}} {}\n", c.boundary, "",
                     std::max(0, 9 - static_cast<int>(c.boundary.size())),
                     vector_text(c.force, dim));
  s += fmt::format("  contact (foundation)  {}\n", vector_text(r.contact, dim));
  s += fmt::format("  balance               {}   relative {:.1e} (moments {:.1e})\n",
                   vector_text(r.balance, dim), r.relative_balance, r.relative_moment_balance);
  s += fmt::format(
      "strain energy 1/2 u.Ku {:.10e} (the whole displacement's, prescribed values "
      "included)\n",
      r.strain_energy);
  return s;
}

}  // namespace signorini
