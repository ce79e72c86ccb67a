#include "signorini/interface/contact_boundary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

#include "signorini/core/error.hpp"
#include "signorini/fem/face_geometry.hpp"
#include "signorini/fem/quadrature.hpp"
#include "signorini/fem/reference_element.hpp"

namespace signorini {

namespace {

// Orders the nodes of a 2D boundary part by walking its facets (edges a -> b, oriented with the
// body on the left, a quadratic edge's middle node between its ends) from a start node; chains
// that are not connected follow one another.
std::vector<Index> walk_edges(const Mesh& mesh, const BoundaryPart& part) {
  std::map<Index, std::pair<Index, Index>> next;  // a -> (b, middle node or -1)
  std::map<Index, int> in_degree;
  for (const Facet& f : part.facets) {
    const auto fn = mesh.facet_nodes(f);
    next[fn[0]] = {fn[1], fn.size() > 2 ? fn[2] : -1};
    in_degree[fn[1]] += 1;
    in_degree.try_emplace(fn[0], 0);
  }
  std::vector<Index> order;
  std::map<Index, bool> seen;
  auto walk_from = [&](Index start) {
    Index n = start;
    while (!seen[n]) {
      seen[n] = true;
      order.push_back(n);
      const auto it = next.find(n);
      if (it == next.end()) break;
      if (it->second.second >= 0) order.push_back(it->second.second);
      n = it->second.first;
    }
  };
  for (const auto& [node, deg] : in_degree)  // open chains start where no edge comes in
    if (deg == 0) walk_from(node);
  for (const auto& [node, deg] : in_degree)  // closed loops
    if (!seen[node]) walk_from(node);
  return order;
}

// The contact surface of a 3D boundary part: its nodes in the order the faces first name them,
// weights h_j and normals (method.md section 3, on surfaces). Linear faces and Quad9 faces
// give h_j = int N_j dA and nu_j along int N_j n dA, as lines do in 2D. On a Tri6 face the
// corner functions integrate to zero (h_j = 0 would leave a corner without a constraint of its
// own), so its weights are lumped as Hinton, Rock and Zienkiewicz do it: h_a proportional to
// int N_a^2 dA, scaled to the face's area; its normals are the face's normal at each node,
// weighted so.
BoundaryNodes surface_nodes(const Mesh& mesh, const BoundaryPart& part) {
  BoundaryNodes out;
  std::map<Index, Index> position;
  for (const Facet& f : part.facets)
    for (const Index v : mesh.facet_nodes(f))
      if (position.try_emplace(v, static_cast<Index>(out.nodes.size())).second)
        out.nodes.push_back(v);
  const auto n = static_cast<Index>(out.nodes.size());
  out.normals = Eigen::MatrixXd::Zero(3, n);
  out.weights = Vector::Zero(n);
  Index shares = 0;
  for (const Facet& f : part.facets) shares += static_cast<Index>(mesh.facet_nodes(f).size());
  out.facet_shares = Eigen::MatrixXd::Zero(3, shares);
  Index share = 0;  // the column of the current facet's first node
  ShapeValues N;
  for (const Facet& f : part.facets) {
    const auto fn = mesh.facet_nodes(f);
    const auto k = static_cast<Index>(fn.size());
    std::vector<Index> facet;
    for (const Index v : fn) facet.push_back(position.at(v));
    const CellType type = facet_type(mesh.cell_type(f.cell));
    // dA n at a reference point (fem/face_geometry.hpp); N gets the shape values there.
    const auto area_vector = [&](const Eigen::Vector3d& xi) {
      return face_point(mesh, type, fn, xi, N).area;
    };
    const std::vector<QuadraturePoint> rule = cell_quadrature(type, 3);
    if (type == CellType::Tri6) {
      Vector mass = Vector::Zero(k);
      double area = 0.0;
      for (const QuadraturePoint& q : rule) {
        const double da = area_vector(q.xi).norm() * q.w;
        area += da;
        mass += N.head(k).cwiseAbs2() * da;
      }
      for (Index a = 0; a < k; ++a) {
        const double h = area * mass(a) / mass.sum();
        const Index j = facet[static_cast<std::size_t>(a)];
        out.weights(j) += h;
        out.facet_shares.col(share + a) =
            h * area_vector(reference_node(type, static_cast<int>(a))).normalized();
      }
    } else {
      for (const QuadraturePoint& q : rule) {
        const Eigen::Vector3d dA = area_vector(q.xi) * q.w;
        for (Index a = 0; a < k; ++a) {
          out.weights(facet[static_cast<std::size_t>(a)]) += N(a) * dA.norm();
          out.facet_shares.col(share + a) += N(a) * dA;
        }
      }
    }
    for (Index a = 0; a < k; ++a)
      out.normals.col(facet[static_cast<std::size_t>(a)]) += out.facet_shares.col(share + a);
    share += k;
    out.facets.push_back(std::move(facet));
  }
  return out;
}

void normalize_normals(BoundaryNodes& out, const BoundaryPart& part, const std::string& what) {
  for (Index j = 0; j < static_cast<Index>(out.nodes.size()); ++j) {
    const double len = out.normals.col(j).norm();
    if (!(len > 0.0))
      throw InputError(what + " = '" + part.name + "': node " +
                       std::to_string(out.nodes[static_cast<std::size_t>(j)]) +
                       " has no defined normal (facets cancel out)");
    out.normals.col(j) /= len;
  }
}

}  // namespace

ContactSet make_contact_set(const Mesh& mesh, const BoundaryPart& part, const DofMap& dofs,
                            const ScalarField& gap) {
  RigidObstacle obstacle;
  obstacle.gap = gap;
  return make_contact_set(mesh, part, dofs, obstacle);
}

BoundaryNodes boundary_nodes(const Mesh& mesh, const BoundaryPart& part, const std::string& what) {
  if (part.facets.empty())
    throw InputError(what + " = '" + part.name + "': the boundary part has no facets");
  if (mesh.dim() == 3) {
    BoundaryNodes out = surface_nodes(mesh, part);
    normalize_normals(out, part, what);
    return out;
  }
  BoundaryNodes out;
  out.nodes = walk_edges(mesh, part);
  const auto n = static_cast<Index>(out.nodes.size());
  std::map<Index, Index> position;
  for (Index j = 0; j < n; ++j) position[out.nodes[static_cast<std::size_t>(j)]] = j;

  // Weights h_j = int N_j ds and normals along int N_j nu ds (method.md section 3): on straight
  // two-node edges the trapezoid weights |e|/2 and the length-weighted edge normals; on
  // quadratic edges by Gauss quadrature along the curve (weights |e|/6, 2|e|/3, |e|/6 on a
  // straight one: all positive, so every node carries a constraint of its own).
  out.normals = Eigen::MatrixXd::Zero(2, n);
  out.weights = Vector::Zero(n);
  Index shares = 0;
  for (const Facet& f : part.facets) shares += static_cast<Index>(mesh.facet_nodes(f).size());
  out.facet_shares = Eigen::MatrixXd::Zero(2, shares);
  Index share = 0;  // the column of the current facet's first node
  ShapeValues N;
  ShapeGradients dN;
  const auto rule = gauss_legendre(3);
  for (const Facet& f : part.facets) {
    const auto fn = mesh.facet_nodes(f);
    std::vector<Index> facet;
    for (const Index v : fn) facet.push_back(position.at(v));
    out.facets.push_back(facet);
    if (fn.size() == 2) {
      const Eigen::Vector2d t = mesh.node(fn[1]) - mesh.node(fn[0]);
      const Eigen::Vector2d outward(t(1), -t(0));  // |outward| = facet length
      for (std::size_t a = 0; a < 2; ++a) {
        out.weights(facet[a]) += 0.5 * t.norm();
        out.normals.col(facet[a]) += 0.5 * outward;
        out.facet_shares.col(share + static_cast<Index>(a)) = 0.5 * outward;
      }
      share += 2;
      continue;
    }
    const CellType type = facet_type(mesh.cell_type(f.cell));
    for (const auto& q : rule) {
      const Eigen::Vector3d s(q.x, 0.0, 0.0);
      shape_functions(type, s, N);
      shape_gradients(type, s, dN);
      Eigen::Vector2d dx = Eigen::Vector2d::Zero();  // dx/ds
      for (std::size_t a = 0; a < fn.size(); ++a)
        dx += dN(0, static_cast<Index>(a)) * mesh.node(fn[a]);
      const Eigen::Vector2d outward(dx(1), -dx(0));  // |outward| ds = the arc length element
      for (std::size_t a = 0; a < fn.size(); ++a) {
        const Index j = facet[a];
        out.weights(j) += N(static_cast<Index>(a)) * dx.norm() * q.w;
        out.facet_shares.col(share + static_cast<Index>(a)) +=
            N(static_cast<Index>(a)) * outward * q.w;
      }
    }
    for (std::size_t a = 0; a < fn.size(); ++a)
      out.normals.col(facet[a]) += out.facet_shares.col(share + static_cast<Index>(a));
    share += static_cast<Index>(fn.size());
  }
  normalize_normals(out, part, what);
  return out;
}

namespace {

// "(0.5, 0.25, 0)": a point in messages, z left out in 2D.
std::string point_text(const Mesh& mesh, const Point& x) {
  std::string out = "(" + std::to_string(x(0)) + ", " + std::to_string(x(1));
  if (mesh.dim() == 3) out += ", " + std::to_string(x(2));
  return out + ")";
}

// The exact normals where the geometry is known (method.md section 3): the facets' average
// approximates a curved surface's normal to O(h) (O(h^2) at best on a regular mesh), which
// tilts the gap measured along it and the direction of the contact force; the given field is
// exact at the nodes. It must point out of the body: within 100 degrees of the facets' normal.
// Not 90: where a curved part ends at an edge of the body (the rim of a hemisphere against its
// flat top), the exact normal lies at 90 degrees from the flat face and the facets' normal there
// leans a little either way, on second-order faces (whose corner normals are the face's own
// there) more than on first-order ones; a normal given the wrong way round is 180 degrees off.
constexpr double kLeastNormalCosine = -0.17364817766693033;  // cos(100 degrees)

void set_surface_normals(const Mesh& mesh, const VectorField& field, BoundaryNodes& b) {
  const int dim = mesh.dim();
  for (Index j = 0; j < static_cast<Index>(b.nodes.size()); ++j) {
    const Point x = mesh.point(b.nodes[static_cast<std::size_t>(j)]);
    const Eigen::VectorXd v = field(x).head(dim);
    const double length = v.norm();
    if (!(length > 0.0))
      throw InputError("contact.surface_normal is zero at x = " + point_text(mesh, x) +
                       ": expected the body's outward normal there (any length, not zero)");
    if (!(v.dot(b.normals.col(j)) > kLeastNormalCosine * length))
      throw InputError("contact.surface_normal at x = " + point_text(mesh, x) +
                       " points into the body (more than 100 degrees from the facets' outward "
                       "normal): expected the outward normal");
    b.normals.col(j) = v / length;
  }
}

}  // namespace

double interference_limit(const Eigen::VectorXd& extent) {
  double smallest = 0.0;
  for (const double e : extent)
    if (e > 0.0 && (smallest == 0.0 || e < smallest)) smallest = e;
  return 0.1 * smallest;
}

void check_body_outside(const Mesh& mesh, const RigidObstacle& obstacle, double limit,
                        const std::string& what) {
  if (obstacle.shape == ObstacleShape::Gap) return;  // (make_contact_rows checks its gaps)
  validate(obstacle);
  Index deepest = -1;
  double depth = limit;
  for (Index v = 0; v < mesh.num_nodes(); ++v) {
    const double d = -obstacle_distance(obstacle, mesh.point(v), Eigen::Vector3d::Zero()).distance;
    if (d > depth) {
      depth = d;
      deepest = v;
    }
  }
  if (deepest < 0) return;
  throw InputError(fmt::format(
      "{}: the body starts inside the obstacle ({}): node {} at x = {} lies {:g} deep, more than "
      "the {:g} (a tenth of the body's smallest extent) allowed as an initial interference; "
      "expected the body outside the obstacle (does the obstacle's normal point towards the "
      "body?)",
      what, describe(obstacle, mesh.dim()), deepest, point_text(mesh, mesh.point(deepest)), depth,
      limit));
}

void check_contact_can_occur(const ContactSet& cs, const std::string& boundary) {
  if (cs.num_movable() == 0)
    throw InputError(
        "contact.boundary = '" + boundary +
        "': no contact node can move towards the obstacle (each is clamped in its normal "
        "direction or faces away from the obstacle): expected a part that faces the obstacle and "
        "is not wholly clamped");
}

ContactSet make_contact_set(const Mesh& mesh, const BoundaryPart& part, const DofMap& dofs,
                            const RigidObstacle& obstacle, const VectorField& surface_normal) {
  const Eigen::VectorXd extent =
      mesh.coordinates().rowwise().maxCoeff() - mesh.coordinates().rowwise().minCoeff();
  const double limit = interference_limit(extent);
  const std::string what = "contact.boundary = '" + part.name + "'";
  check_body_outside(mesh, obstacle, limit, what);
  ContactSet cs = make_contact_rows(mesh, part, dofs, obstacle, surface_normal, limit);
  check_contact_can_occur(cs, part.name);
  return cs;
}

ContactSet make_contact_rows(const Mesh& mesh, const BoundaryPart& part, const DofMap& dofs,
                             const RigidObstacle& obstacle, const VectorField& surface_normal,
                             double limit) {
  validate(obstacle);
  BoundaryNodes b = boundary_nodes(mesh, part, "contact.boundary");
  if (surface_normal) set_surface_normals(mesh, surface_normal, b);
  ContactSet cs;
  cs.nodes = std::move(b.nodes);
  cs.normals = std::move(b.normals);
  cs.weights = std::move(b.weights);
  cs.facets = std::move(b.facets);
  const Index n = cs.size();
  const int dim = mesh.dim();
  cs.gaps.resize(n);
  cs.movable.assign(static_cast<std::size_t>(n), false);
  std::vector<Eigen::Triplet<double, int>> triplets;
  for (Index j = 0; j < n; ++j) {
    const Index node = cs.nodes[static_cast<std::size_t>(j)];
    const Point x = mesh.point(node);
    bool faces = true;
    if (obstacle.shape == ObstacleShape::Gap) {
      // The paper's gap formula, read along the body's normal nu_j (method.md section 3).
      cs.gaps(j) = obstacle.gap(x);
      if (!std::isfinite(cs.gaps(j)))
        throw InputError("contact.gap is not finite at x = " + point_text(mesh, x) +
                         ": expected finite values on the contact boundary");
      if (cs.gaps(j) < -limit)
        throw InputError(fmt::format(
            "contact.gap = {:g} at x = {} (contact.boundary = '{}'): the body starts that deep "
            "inside the obstacle, more than the {:g} (a tenth of the body's smallest extent) "
            "allowed as an initial interference; expected a gap >= -{:g}",
            cs.gaps(j), point_text(mesh, x), part.name, limit, limit));
    } else {
      // A rigid obstacle of known shape (method.md section 3): the constraint acts along its
      // normal at the node's closest point, nu_j = -n(x_j), the gap is the signed distance (the
      // rigid master surface's normal, not the body's: at a corner of the contact part the
      // body's averaged normal would push the body sideways off a frictionless plane). A node
      // whose outward normal points away from the obstacle never touches it.
      Eigen::Vector3d body = Eigen::Vector3d::Zero();
      body.head(dim) = cs.normals.col(j);
      const ObstacleDistance o = obstacle_distance(obstacle, x, -body);
      cs.gaps(j) = o.distance;
      cs.normals.col(j) = -o.normal.head(dim);
      faces = body.dot(-o.normal) > -1e-12;
    }
    // A prescribed displacement moves the node towards the obstacle by nu . u_D: the constraint
    // (N x)_j <= g_j holds on the free dofs with that part taken off the gap. A node with local
    // axes (DofMap::set_frame, 2D) has its row in them.
    cs.gaps(j) -= cs.normals.col(j).dot(dofs.prescribed_at(node));
    if (!faces) continue;  // (no row in N, its multiplier kept at 0, like a clamped node's)
    const Eigen::VectorXd normal =
        dofs.has_frame(node) ? Eigen::VectorXd(dofs.frame(node).transpose() * cs.normals.col(j))
                             : Eigen::VectorXd(cs.normals.col(j));
    double free_normal = 0.0;
    for (int k = 0; k < dim; ++k) {
      const Index d = dofs.free_index(node, k);
      if (d < 0) continue;
      triplets.emplace_back(static_cast<int>(j), static_cast<int>(d), normal(k));
      free_normal += normal(k) * normal(k);
    }
    cs.movable[static_cast<std::size_t>(j)] = free_normal > 1e-24;
  }
  cs.N.resize(n, dofs.num_free());
  cs.N.setFromTriplets(triplets.begin(), triplets.end());
  cs.N.makeCompressed();
  if (obstacle.shape != ObstacleShape::Gap) {
    // The weight against a shape: the node's share of the obstacle's surface that it presses
    // on, its facets projected across nu_j. At a corner of the contact part a side at right
    // angles to the obstacle adds nothing, so that l_j stays the pressure of the face that
    // touches (the uniform pressure of a square's bottom to round-off, not half of it at the
    // corner).
    Vector projected = Vector::Zero(n);
    Index share = 0;
    for (const std::vector<Index>& facet : cs.facets)
      for (const Index j : facet)
        projected(j) += std::max(b.facet_shares.col(share++).dot(cs.normals.col(j)), 0.0);
    // (Not where the facets stand nearly at right angles to nu_j, which would make l_j a force
    // over almost no area: there the plain share, as with a gap formula.)
    for (Index j = 0; j < n; ++j)
      if (projected(j) > 0.01 * cs.weights(j)) cs.weights(j) = projected(j);
  }
  return cs;
}

void append_contact_set(ContactSet& into, const ContactSet& more) {
  if (into.size() == 0 && into.N.cols() == 0) {
    into = more;
    return;
  }
  if (more.kind == InterfaceKind::BetweenBodies) into.kind = InterfaceKind::BetweenBodies;
  const Index n0 = into.size();
  const Index n = n0 + more.size();
  into.nodes.insert(into.nodes.end(), more.nodes.begin(), more.nodes.end());
  Eigen::MatrixXd normals(into.normals.rows(), n);
  normals << into.normals, more.normals;
  into.normals = std::move(normals);
  Vector weights(n), gaps(n);
  weights << into.weights, more.weights;
  gaps << into.gaps, more.gaps;
  into.weights = std::move(weights);
  into.gaps = std::move(gaps);
  SparseMatrix N(n, into.N.cols());
  std::vector<Eigen::Triplet<double, int>> triplets;
  for (const SparseMatrix* m : std::array<const SparseMatrix*, 2>{&into.N, &more.N})
    for (int r = 0; r < m->outerSize(); ++r)
      for (SparseMatrix::InnerIterator it(*m, r); it; ++it)
        triplets.emplace_back(static_cast<int>(it.row() + (m == &more.N ? n0 : 0)),
                              static_cast<int>(it.col()), it.value());
  N.setFromTriplets(triplets.begin(), triplets.end());
  N.makeCompressed();
  into.N = std::move(N);
  into.movable.insert(into.movable.end(), more.movable.begin(), more.movable.end());
  for (std::vector<Index> f : more.facets) {
    for (Index& j : f) j += n0;
    into.facets.push_back(std::move(f));
  }
}

}  // namespace signorini
