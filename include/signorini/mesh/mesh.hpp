#pragma once
// An unstructured mesh whose cells may be of several types (triangles and quadrilaterals of first
// and second order in one 2D mesh, say), with named boundary parts (sets of boundary facets).
// Callers go through cell(), cell_type(), facet_nodes() and node(); nothing assumes a structured
// grid or one cell type, so meshes read from files and 3D cells fit the same interface.

#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "signorini/core/types.hpp"
#include "signorini/mesh/cell_type.hpp"

namespace signorini {

/// A facet of the mesh, named by the cell it belongs to and its local facet number.
struct Facet {
  Index cell = 0;
  int local = 0;
};

/// A named part of the boundary. Facets are kept in the order given (the rectangle generator
/// lists them along the edge), which the contact set uses to order its nodes.
struct BoundaryPart {
  std::string name;
  std::vector<Facet> facets;
};

class Mesh {
 public:
  /// Cells of one type. `coordinates` is dim x num_nodes; `connectivity` holds
  /// nodes_per_cell(type) node numbers per cell. Throws InputError on node numbers out of range
  /// or a dimension mismatch.
  Mesh(CellType type, Eigen::MatrixXd coordinates, std::vector<Index> connectivity);
  /// Cells of several types: cell c has type types[c] and the next nodes_per_cell(types[c])
  /// numbers of `connectivity`. Every type must have the dimension of the coordinates.
  Mesh(std::vector<CellType> types, Eigen::MatrixXd coordinates, std::vector<Index> connectivity);

  [[nodiscard]] int dim() const { return static_cast<int>(coordinates_.rows()); }
  [[nodiscard]] Index num_nodes() const { return coordinates_.cols(); }
  [[nodiscard]] Index num_cells() const { return static_cast<Index>(types_.size()); }
  [[nodiscard]] CellType cell_type(Index c) const { return types_[static_cast<std::size_t>(c)]; }
  /// The distinct cell types, in the order of CellType.
  [[nodiscard]] std::vector<CellType> cell_types() const;
  /// The most nodes any cell has.
  [[nodiscard]] int max_nodes_per_cell() const { return max_nodes_per_cell_; }

  /// Coordinates of a node (dim entries).
  [[nodiscard]] auto node(Index i) const { return coordinates_.col(i); }
  /// A node as a point of space (z = 0 in 2D), for formulas and geometry written once for 2D
  /// and 3D.
  [[nodiscard]] Point point(Index i) const {
    Point x = Point::Zero();
    for (int k = 0; k < dim(); ++k) x(k) = coordinates_(k, i);
    return x;
  }
  [[nodiscard]] const Eigen::MatrixXd& coordinates() const { return coordinates_; }
  /// Node numbers of a cell.
  [[nodiscard]] std::span<const Index> cell(Index c) const {
    const auto k = static_cast<std::size_t>(c);
    return {connectivity_.data() + offsets_[k],
            static_cast<std::size_t>(offsets_[k + 1] - offsets_[k])};
  }
  /// Node numbers of a facet, in the orientation of facet_local_nodes().
  [[nodiscard]] std::vector<Index> facet_nodes(const Facet& f) const;

  /// Names the cells' regions (Gmsh's physical surfaces, say): region_of_cell[c] indexes
  /// `names`. Without a call every cell is in region 0, named "". Throws InputError on sizes or
  /// indices that do not fit.
  void set_cell_regions(std::vector<std::string> names, std::vector<int> region_of_cell);
  [[nodiscard]] int cell_region(Index c) const {
    return regions_.empty() ? 0 : regions_[static_cast<std::size_t>(c)];
  }
  [[nodiscard]] const std::vector<std::string>& region_names() const { return region_names_; }
  /// The numbers the cells have in the file they were read from (Gmsh element tags), so that
  /// messages name a cell as the user knows it; -1 where none was set.
  void set_cell_source_tags(std::vector<Index> tags);
  [[nodiscard]] Index cell_source_tag(Index c) const {
    return source_tags_.empty() ? -1 : source_tags_[static_cast<std::size_t>(c)];
  }

  /// Adds (or replaces) a named boundary part. Throws InputError if a facet does not exist.
  void set_boundary_part(std::string name, std::vector<Facet> facets);
  [[nodiscard]] bool has_boundary_part(std::string_view name) const;
  /// Throws InputError naming the known parts if `name` is not one of them.
  [[nodiscard]] const BoundaryPart& boundary_part(std::string_view name) const;
  [[nodiscard]] std::vector<std::string> boundary_part_names() const;
  /// Distinct nodes of a boundary part, sorted by number.
  [[nodiscard]] std::vector<Index> boundary_part_nodes(std::string_view name) const;

 private:
  void check();

  std::vector<CellType> types_;
  Eigen::MatrixXd coordinates_;
  std::vector<Index> connectivity_;
  std::vector<Index> offsets_;  // cell c: connectivity_[offsets_[c] .. offsets_[c + 1])
  int max_nodes_per_cell_ = 0;
  std::map<std::string, BoundaryPart, std::less<>> parts_;
  std::vector<std::string> region_names_{""};
  std::vector<int> regions_;        // per cell, or empty: all in region 0
  std::vector<Index> source_tags_;  // per cell, or empty
};

}  // namespace signorini
