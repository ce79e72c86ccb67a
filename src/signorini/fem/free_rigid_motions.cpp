#include "signorini/fem/free_rigid_motions.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <numeric>

namespace signorini {

namespace {

// Union-find over nodes: the root of each node's piece.
class Pieces {
 public:
  explicit Pieces(Index n) : parent_(static_cast<std::size_t>(n)) {
    std::iota(parent_.begin(), parent_.end(), Index{0});
  }
  Index root(Index a) {
    while (parent_[static_cast<std::size_t>(a)] != a) {
      auto& p = parent_[static_cast<std::size_t>(a)];
      p = parent_[static_cast<std::size_t>(p)];  // path halving
      a = p;
    }
    return a;
  }
  void join(Index a, Index b) {
    a = root(a);
    b = root(b);
    if (a != b) parent_[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }

 private:
  std::vector<Index> parent_;
};

// For each node its piece number (0, 1, ... in order of the lowest node), -1 for nodes in no
// cell; returns the number of pieces.
Index label_pieces(const Mesh& mesh, std::vector<Index>& piece) {
  Pieces p(mesh.num_nodes());
  std::vector<bool> used(static_cast<std::size_t>(mesh.num_nodes()), false);
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell(c);
    for (const Index v : nodes) {
      used[static_cast<std::size_t>(v)] = true;
      p.join(nodes[0], v);
    }
  }
  piece.assign(static_cast<std::size_t>(mesh.num_nodes()), -1);
  std::vector<Index> number(static_cast<std::size_t>(mesh.num_nodes()), -1);
  Index count = 0;
  for (Index v = 0; v < mesh.num_nodes(); ++v) {
    if (!used[static_cast<std::size_t>(v)]) continue;
    Index& n = number[static_cast<std::size_t>(p.root(v))];
    if (n < 0) n = count++;
    piece[static_cast<std::size_t>(v)] = n;
  }
  return count;
}

// Rigid mode m at a point, relative to centre c and scaled by the piece's size L so that every
// column is of order one: translations e_k, then rotations about the axes (2D: z only).
Eigen::Vector3d mode_value(int m, int dim, const Eigen::Vector3d& x, const Eigen::Vector3d& c,
                           double L) {
  if (m < dim) return Eigen::Vector3d::Unit(m);
  const Eigen::Vector3d r = (x - c) / L;
  const int axis = dim == 2 ? 2 : m - dim;
  return Eigen::Vector3d::Unit(axis).cross(r);
}

std::string number(double v) {
  return fmt::format("{:.6g}", v + 0.0);
}

}  // namespace

Index count_mesh_pieces(const Mesh& mesh) {
  std::vector<Index> piece;
  return label_pieces(mesh, piece);
}

std::string RigidMotion::description() const {
  const char* axes = "xyz";
  if (rotation.norm() == 0.0) {
    const Eigen::Vector3d d = translation.normalized();
    for (int k = 0; k < 3; ++k)
      if (std::abs(d(k)) > 1.0 - 1e-9) return std::string("translation in ") + axes[k];
    if (d(2) == 0.0) return "translation along (" + number(d(0)) + ", " + number(d(1)) + ")";
    return "translation along (" + number(d(0)) + ", " + number(d(1)) + ", " + number(d(2)) + ")";
  }
  const Eigen::Vector3d a = rotation.normalized();
  if (std::abs(a(2)) > 1.0 - 1e-9 && a.head<2>().norm() < 1e-9)
    return "rotation about (" + number(centre(0)) + ", " + number(centre(1)) + ")";
  return "rotation about the axis (" + number(a(0)) + ", " + number(a(1)) + ", " + number(a(2)) +
         ") through (" + number(centre(0)) + ", " + number(centre(1)) + ", " + number(centre(2)) +
         ")";
}

std::vector<RigidMotion> free_rigid_motions(const Mesh& mesh, const DofMap& dofs) {
  const int dim = mesh.dim();
  const int modes = dim == 2 ? 3 : 6;
  const int rotations = modes - dim;
  std::vector<Index> piece;
  const Index pieces = label_pieces(mesh, piece);
  // The nodes of each piece, in one pass.
  std::vector<std::vector<Index>> members(static_cast<std::size_t>(pieces));
  for (Index v = 0; v < mesh.num_nodes(); ++v)
    if (piece[static_cast<std::size_t>(v)] >= 0)
      members[static_cast<std::size_t>(piece[static_cast<std::size_t>(v)])].push_back(v);
  std::vector<RigidMotion> out;
  for (Index p = 0; p < pieces; ++p) {
    const std::vector<Index>& nodes = members[static_cast<std::size_t>(p)];
    // Centre and size of the piece.
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const Index v : nodes) c += mesh.point(v);
    c /= static_cast<double>(nodes.size());
    double L = 0.0;
    for (const Index v : nodes) L = std::max(L, (mesh.point(v) - c).norm());
    if (!(L > 0.0)) L = 1.0;

    // G = C^T C, C: the value of each rigid mode at each clamped dof of the piece. A mode is
    // free exactly where C vanishes on it: the null space of G.
    Eigen::MatrixXd G = Eigen::MatrixXd::Zero(modes, modes);
    for (const Index v : nodes) {
      const Eigen::Vector3d x = mesh.point(v);
      for (int k = 0; k < dim; ++k) {
        if (!dofs.is_clamped(v, k)) continue;
        // The clamped direction: axis k, or the node's local axis k (DofMap::set_frame).
        Eigen::Vector3d axis = Eigen::Vector3d::Unit(k);
        if (dofs.has_frame(v)) axis.head<2>() = dofs.frame(v).col(k);
        Eigen::VectorXd row(modes);
        for (int m = 0; m < modes; ++m) row(m) = axis.dot(mode_value(m, dim, x, c, L));
        G.noalias() += row * row.transpose();
      }
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(G);
    const double scale = std::max(1.0, G.trace());
    std::vector<Eigen::VectorXd> null;
    for (int m = 0; m < modes; ++m)
      if (eig.eigenvalues()(m) <= 1e-10 * scale) null.push_back(eig.eigenvectors().col(m));
    if (null.empty()) continue;
    Eigen::MatrixXd V(modes, static_cast<Eigen::Index>(null.size()));
    for (std::size_t i = 0; i < null.size(); ++i) V.col(static_cast<Eigen::Index>(i)) = null[i];

    // Pure translations first (the combinations with no rotation), then rotations orthogonal to
    // them, each named by the point it leaves fixed.
    const Eigen::MatrixXd R = V.bottomRows(rotations);
    Eigen::MatrixXd translations = V * Eigen::FullPivLU<Eigen::MatrixXd>(R).kernel();
    if (translations.cols() == 1 && translations.norm() == 0.0) translations.resize(modes, 0);
    const Eigen::HouseholderQR<Eigen::MatrixXd> tq(translations);
    const Eigen::Index nt = translations.cols();
    Eigen::MatrixXd T = tq.householderQ() * Eigen::MatrixXd::Identity(modes, nt);
    if (nt == dim) T = Eigen::MatrixXd::Identity(modes, nt);  // every translation: along the axes
    // The rotations: the part of span(V) orthogonal to the translations.
    Eigen::MatrixXd rest = V - T * (T.transpose() * V);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(rest, Eigen::ComputeThinU);
    const auto add = [&](const Eigen::VectorXd& w) {
      RigidMotion m;
      m.piece = p;
      m.piece_node = nodes.front();
      for (int k = 0; k < dim; ++k) m.translation(k) = w(k);
      if (dim == 2)
        m.rotation(2) = w(2) / L;
      else
        for (int k = 0; k < 3; ++k) m.rotation(k) = w(dim + k) / L;
      for (int k = 0; k < 3; ++k)
        if (std::abs(m.translation(k)) < 1e-12) m.translation(k) = 0.0;
      if (m.rotation.norm() < 1e-12 / L) m.rotation.setZero();
      if (m.rotation.norm() > 0.0) {
        // u(x) = t + w x (x - c); the point of the axis nearest c: c + w x t / |w|^2.
        m.centre = c + m.rotation.cross(m.translation) / m.rotation.squaredNorm();
        for (int k = 0; k < 3; ++k)
          if (std::abs(m.centre(k)) < 1e-12 * L) m.centre(k) = 0.0;
      }
      out.push_back(m);
    };
    for (Eigen::Index i = 0; i < nt; ++i) add(T.col(i));
    for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(null.size()) - nt; ++i)
      add(svd.matrixU().col(i));
  }
  return out;
}

}  // namespace signorini
