#include "signorini/output/vtu_file.hpp"

#include <fmt/format.h>

#include <array>
#include <bit>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace signorini {

namespace {

template <class T>
std::string bytes_of(const T* data, std::size_t count) {
  std::string out(count * sizeof(T), '\0');
  if (count > 0) std::memcpy(out.data(), data, out.size());
  return out;
}

// Names are ours (identifiers), but an attribute value must stay well-formed whatever it holds.
std::string xml_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// A data array's attributes: type, name (none when empty), components and their names.
std::string array_attributes(const std::string& type, const std::string& name, int components,
                             const std::vector<std::string>& component_names) {
  std::string out = fmt::format(" type=\"{}\"", type);
  if (!name.empty()) out += fmt::format(" Name=\"{}\"", xml_escaped(name));
  out += fmt::format(" NumberOfComponents=\"{}\"", components);
  for (std::size_t i = 0; i < component_names.size(); ++i)
    out += fmt::format(" ComponentName{}=\"{}\"", i, xml_escaped(component_names[i]));
  return out;
}

// The XML declaration and the opening VTKFile tag of a file of this type, in the machine's byte
// order, with UInt64 block headers.
std::string vtk_file_header(const char* type) {
  const char* byte_order =
      std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  return fmt::format(
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"{}\" version=\"1.0\" byte_order=\"{}\" "
      "header_type=\"UInt64\">\n",
      type, byte_order);
}

}  // namespace

VtkCellType vtk_cell_type(CellType type) {
  switch (type) {
    case CellType::Line2:
      return VtkCellType::Line;
    case CellType::Line3:
      return VtkCellType::QuadraticEdge;
    case CellType::Tri3:
      return VtkCellType::Triangle;
    case CellType::Tri6:
      return VtkCellType::QuadraticTriangle;
    case CellType::Quad4:
      return VtkCellType::Quad;
    case CellType::Quad8:
      return VtkCellType::QuadraticQuad;
    case CellType::Quad9:
      return VtkCellType::BiquadraticQuad;
    case CellType::Tet4:
      return VtkCellType::Tetra;
    case CellType::Tet10:
      return VtkCellType::QuadraticTetra;
    case CellType::Hex8:
      return VtkCellType::Hexahedron;
    case CellType::Hex27:
      return VtkCellType::TriquadraticHexahedron;
  }
  return VtkCellType::Quad;
}

int vtk_points_per_cell(VtkCellType type) {
  switch (type) {
    case VtkCellType::Line:
      return 2;
    case VtkCellType::Triangle:
    case VtkCellType::QuadraticEdge:
      return 3;
    case VtkCellType::Quad:
    case VtkCellType::Tetra:
      return 4;
    case VtkCellType::QuadraticTriangle:
      return 6;
    case VtkCellType::Hexahedron:
    case VtkCellType::QuadraticQuad:
      return 8;
    case VtkCellType::BiquadraticQuad:
      return 9;
    case VtkCellType::QuadraticTetra:
      return 10;
    case VtkCellType::TriquadraticHexahedron:
      return 27;
  }
  return 0;
}

namespace {
// VTK's node k is our node order[k] where the orders differ (mesh/cell_type.hpp): Tet10 lists the
// mid-edge nodes of 1-3 and 2-3 the other way round; Hex27 lists the edges bottom, top, vertical
// and the face centres x, y, z.
constexpr std::array<int, 10> kTet10ToVtk{0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
constexpr std::array<int, 27> kHex27ToVtk{0,  1,  2,  3,  4,  5,  6,  7,  8,  11, 13, 9,  16, 18,
                                          19, 17, 10, 12, 14, 15, 22, 23, 21, 24, 20, 25, 26};
}  // namespace

void VtuFile::add_cell(CellType type, std::span<const Index> nodes) {
  std::span<const int> order;
  if (type == CellType::Tet10) order = kTet10ToVtk;
  if (type == CellType::Hex27) order = kHex27ToVtk;
  if (order.empty() || nodes.size() != order.size()) {
    add_cell(vtk_cell_type(type), nodes);
    return;
  }
  std::array<Index, 27> vtk{};
  for (std::size_t k = 0; k < order.size(); ++k) vtk[k] = nodes[static_cast<std::size_t>(order[k])];
  add_cell(vtk_cell_type(type), std::span<const Index>(vtk.data(), order.size()));
}

VtuFile::VtuFile(const Eigen::MatrixXd& points) : num_points_(points.cols()) {
  if (points.rows() < 1 || points.rows() > 3)
    throw std::invalid_argument("VtuFile: points must have 1 to 3 coordinates");
  Eigen::MatrixXd xyz = Eigen::MatrixXd::Zero(3, points.cols());
  xyz.topRows(points.rows()) = points;
  point_bytes_ = bytes_of(xyz.data(), static_cast<std::size_t>(xyz.size()));
}

void VtuFile::add_cell(VtkCellType type, std::span<const Index> points) {
  if (static_cast<int>(points.size()) != vtk_points_per_cell(type))
    throw std::invalid_argument("VtuFile: a cell of VTK type " +
                                std::to_string(static_cast<int>(type)) + " has " +
                                std::to_string(vtk_points_per_cell(type)) + " points, got " +
                                std::to_string(points.size()));
  for (const Index p : points) {
    if (p < 0 || p >= num_points_)
      throw std::invalid_argument("VtuFile: point number out of range");
    connectivity_.push_back(p);
  }
  offsets_.push_back(static_cast<std::int64_t>(connectivity_.size()));
  types_.push_back(static_cast<std::uint8_t>(type));
}

void VtuFile::add_point_data(const std::string& name, int components,
                             const std::vector<double>& values,
                             const std::vector<std::string>& component_names) {
  if (components < 1 || static_cast<Index>(values.size()) != components * num_points_)
    throw std::invalid_argument("VtuFile: point data '" + name + "' has the wrong size");
  if (!component_names.empty() && static_cast<int>(component_names.size()) != components)
    throw std::invalid_argument("VtuFile: point data '" + name + "' has the wrong component names");
  point_data_.push_back(
      {name, "Float64", components, component_names, bytes_of(values.data(), values.size())});
}

void VtuFile::add_point_data(const std::string& name, const std::vector<std::uint8_t>& values) {
  if (static_cast<Index>(values.size()) != num_points_)
    throw std::invalid_argument("VtuFile: point data '" + name + "' has the wrong size");
  point_data_.push_back({name, "UInt8", 1, {}, bytes_of(values.data(), values.size())});
}

void VtuFile::add_cell_data(const std::string& name, const std::vector<std::int32_t>& values) {
  if (values.size() != types_.size())
    throw std::invalid_argument("VtuFile: cell data '" + name + "' has the wrong size");
  cell_data_.push_back({name, "Int32", 1, {}, bytes_of(values.data(), values.size())});
}

std::string VtuFile::parallel_text(const std::vector<std::string>& pieces) const {
  const auto array = [](const std::string& indent, const Array& a) {
    return indent + "<PDataArray" +
           array_attributes(a.type, a.name, a.components, a.component_names) + "/>\n";
  };
  std::string xml = vtk_file_header("PUnstructuredGrid");
  xml += "  <PUnstructuredGrid GhostLevel=\"0\">\n";
  xml += "    <PPointData>\n";
  for (const Array& a : point_data_) xml += array("      ", a);
  xml += "    </PPointData>\n";
  if (!cell_data_.empty()) {
    xml += "    <PCellData>\n";
    for (const Array& a : cell_data_) xml += array("      ", a);
    xml += "    </PCellData>\n";
  }
  xml +=
      "    <PPoints>\n      <PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n"
      "    </PPoints>\n";
  for (const std::string& piece : pieces)
    xml += fmt::format("    <Piece Source=\"{}\"/>\n", xml_escaped(piece));
  xml += "  </PUnstructuredGrid>\n</VTKFile>\n";
  return xml;
}

std::string VtuFile::take_text() {
  // Two steps, so that the file is built in one string of its final size: the XML header first
  // (the offsets need only the sizes), then the arrays appended to it, each freed once copied.
  // The largest output (solution.vtu of a 10^7-unknown mesh, 0.7 GB) then never exists twice
  // (docs/performance.md, "Ten million unknowns").
  struct Block {
    const char* data;
    std::size_t size;
    std::function<void()> free;
  };
  std::vector<Block> blocks;
  std::string xml;
  std::uint64_t appended = 0;  // bytes of the appended block so far, from the byte after '_'
  const auto data_array = [&](const std::string& indent, const std::string& name,
                              const std::string& type, int components,
                              const std::vector<std::string>& component_names, Block block) {
    xml += indent + "<DataArray" + array_attributes(type, name, components, component_names);
    xml += fmt::format(" format=\"appended\" offset=\"{}\"/>\n", appended);
    appended += sizeof(std::uint64_t) + block.size;
    blocks.push_back(std::move(block));
  };
  const auto of_string = [&](std::string& bytes) {
    return Block{bytes.data(), bytes.size(), [&bytes] { std::string().swap(bytes); }};
  };
  const auto of_vector = [&](auto& values) {
    using T = typename std::decay_t<decltype(values)>::value_type;
    return Block{reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T),
                 [&values] { std::decay_t<decltype(values)>().swap(values); }};
  };

  xml += vtk_file_header("UnstructuredGrid");
  xml += "  <UnstructuredGrid>\n";
  xml += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", num_points_,
                     types_.size());
  xml += "      <PointData>\n";
  for (Array& a : point_data_)
    data_array("        ", a.name, a.type, a.components, a.component_names, of_string(a.bytes));
  xml += "      </PointData>\n";
  if (!cell_data_.empty()) {
    xml += "      <CellData>\n";
    for (Array& a : cell_data_)
      data_array("        ", a.name, a.type, a.components, a.component_names, of_string(a.bytes));
    xml += "      </CellData>\n";
  }
  xml += "      <Points>\n";
  data_array("        ", "Points", "Float64", 3, {}, of_string(point_bytes_));
  xml += "      </Points>\n";
  xml += "      <Cells>\n";
  data_array("        ", "connectivity", "Int64", 1, {}, of_vector(connectivity_));
  data_array("        ", "offsets", "Int64", 1, {}, of_vector(offsets_));
  data_array("        ", "types", "UInt8", 1, {}, of_vector(types_));
  xml += "      </Cells>\n";
  xml += "    </Piece>\n";
  xml += "  </UnstructuredGrid>\n";
  // meshio drops everything after the last newline of the block, so the data ends with one.
  xml += "  <AppendedData encoding=\"raw\">\n   _";
  const std::string tail = "\n  </AppendedData>\n</VTKFile>\n";
  xml.reserve(xml.size() + appended + tail.size());
  for (Block& b : blocks) {
    const std::uint64_t size = b.size;
    xml.append(reinterpret_cast<const char*>(&size), sizeof size);
    if (b.size > 0) xml.append(b.data, b.size);
    b.free();
  }
  xml += tail;
  *this = VtuFile(Eigen::MatrixXd::Zero(3, 0));
  return xml;
}

}  // namespace signorini
