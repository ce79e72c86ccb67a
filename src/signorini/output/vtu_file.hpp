#pragma once
// VTK XML UnstructuredGrid files (.vtu), the format that ParaView, VisIt and meshio read: points,
// cells and named point-data arrays. The arrays are stored as raw binary appended after the XML
// header (<AppendedData encoding="raw">, a UInt64 byte count before each array, the machine's
// byte order), so that doubles are written exactly and a 10^6-node mesh takes seconds, not
// minutes, to write and read.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "signorini/core/types.hpp"
#include "signorini/mesh/cell_type.hpp"

namespace signorini {

/// VTK's numbers for the cell shapes (vtkCellType.h); node orders agree with ours.
enum class VtkCellType : std::uint8_t {
  Line = 3,
  Triangle = 5,
  Quad = 9,
  Tetra = 10,
  Hexahedron = 12,
  QuadraticEdge = 21,
  QuadraticTriangle = 22,
  QuadraticQuad = 23,
  QuadraticTetra = 24,
  BiquadraticQuad = 28,
  TriquadraticHexahedron = 29,
};

VtkCellType vtk_cell_type(CellType type);
/// The number of points of a VTK cell of this type.
int vtk_points_per_cell(VtkCellType type);

class VtuFile {
 public:
  /// `points` is dim x n with dim 1 to 3; missing coordinates are written as 0 (VTK points have
  /// three).
  explicit VtuFile(const Eigen::MatrixXd& points);

  /// Appends one cell with the given point numbers.
  void add_cell(VtkCellType type, std::span<const Index> points);
  /// A cell of ours (Gmsh's node order, mesh/cell_type.hpp), its nodes put in VTK's order.
  void add_cell(CellType type, std::span<const Index> nodes);

  /// A point-data array of `components` doubles per point, point after point. `component_names`
  /// (optional, one per component) label the components in ParaView. Throws std::invalid_argument
  /// if the size is not components x points.
  void add_point_data(const std::string& name, int components, const std::vector<double>& values,
                      const std::vector<std::string>& component_names = {});
  /// A point-data array of one byte per point (flags).
  void add_point_data(const std::string& name, const std::vector<std::uint8_t>& values);

  /// A cell-data array of one Int32 per cell (the cells added so far).
  void add_cell_data(const std::string& name, const std::vector<std::int32_t>& values);

  [[nodiscard]] Index num_points() const { return num_points_; }
  [[nodiscard]] Index num_cells() const { return static_cast<Index>(types_.size()); }

  /// The .pvtu file (PUnstructuredGrid) of a data set split into pieces like this one: the
  /// same arrays, and `pieces` as the pieces' file names (relative to the .pvtu). Call before
  /// take_text().
  [[nodiscard]] std::string parallel_text(const std::vector<std::string>& pieces) const;

  /// The whole file. Each array is freed once copied into it, so that the data is never held
  /// twice; this is left an empty file of no points.
  [[nodiscard]] std::string take_text();

 private:
  struct Array {
    std::string name;
    std::string type;  // VTK's type name: Float64, Int64, UInt8
    int components = 1;
    std::vector<std::string> component_names;
    std::string bytes;  // the values in the machine's byte order
  };

  Index num_points_;
  std::string point_bytes_;
  std::vector<std::int64_t> connectivity_;
  std::vector<std::int64_t> offsets_;
  std::vector<std::uint8_t> types_;
  std::vector<Array> point_data_;
  std::vector<Array> cell_data_;
};

}  // namespace signorini
