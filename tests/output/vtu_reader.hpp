#pragma once
// A small reader of the .vtu files that output/vtu_file.hpp writes (raw appended data, UInt64
// headers, the machine's byte order), written apart from the writer so that the tests check the
// file against the format and not against the writer's own idea of it.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

namespace signorini::testing {

struct VtuArray {
  std::string name;
  std::string type;
  int components = 1;
  std::map<std::string, std::string> attributes;
  std::vector<double> values;  // every type converted to double (exact for our integers)
};

struct VtuContents {
  long points = 0;
  long cells = 0;
  std::map<std::string, VtuArray> point_data;
  std::map<std::string, VtuArray> cell_data;
  VtuArray coordinates, connectivity, offsets, types;
};

inline std::map<std::string, std::string> xml_attributes(const std::string& tag) {
  std::map<std::string, std::string> out;
  static const std::regex attribute(R"re(([A-Za-z_][A-Za-z0-9_]*)="([^"]*)")re");
  for (auto it = std::sregex_iterator(tag.begin(), tag.end(), attribute);
       it != std::sregex_iterator(); ++it)
    out[(*it)[1]] = (*it)[2];
  return out;
}

template <class T>
std::vector<double> decode(const std::string& bytes) {
  if (bytes.size() % sizeof(T) != 0) throw std::runtime_error("array size is not a multiple");
  std::vector<double> out(bytes.size() / sizeof(T));
  for (std::size_t i = 0; i < out.size(); ++i) {
    T v;
    std::memcpy(&v, bytes.data() + i * sizeof(T), sizeof(T));
    out[i] = static_cast<double>(v);
  }
  return out;
}

/// Parses a whole file; throws std::runtime_error on anything unexpected.
inline VtuContents read_vtu_text(const std::string& text) {
  const auto fail = [](const std::string& why) { return std::runtime_error("vtu: " + why); };
  const std::size_t appended_tag = text.find("<AppendedData encoding=\"raw\">");
  if (appended_tag == std::string::npos) throw fail("no raw <AppendedData>");
  const std::string header = text.substr(0, appended_tag);
  const std::size_t underscore = text.find('_', appended_tag);
  const std::string footer = "\n  </AppendedData>\n</VTKFile>\n";
  if (text.size() < footer.size() ||
      text.compare(text.size() - footer.size(), footer.size(), footer) != 0)
    throw fail("the file does not end with </AppendedData></VTKFile>");
  const std::string data =
      text.substr(underscore + 1, text.size() - footer.size() - underscore - 1);

  const auto root = xml_attributes(header.substr(header.find("<VTKFile"), 200));
  if (root.at("type") != "UnstructuredGrid" || root.at("header_type") != "UInt64" ||
      root.at("byte_order") != "LittleEndian")
    throw fail("unexpected <VTKFile> attributes");
  const auto piece = xml_attributes(header.substr(header.find("<Piece"), 200));
  VtuContents v;
  v.points = std::stol(piece.at("NumberOfPoints"));
  v.cells = std::stol(piece.at("NumberOfCells"));

  const std::size_t point_data_begin = header.find("<PointData>");
  const std::size_t point_data_end = header.find("</PointData>");
  const std::size_t points_begin = header.find("<Points>");
  const std::size_t cells_begin = header.find("<Cells>");
  std::size_t expected_offset = 0;  // arrays follow one another without gaps
  static const std::regex data_array(R"(<DataArray [^>]*/>)");
  for (auto it = std::sregex_iterator(header.begin(), header.end(), data_array);
       it != std::sregex_iterator(); ++it) {
    const std::size_t at = static_cast<std::size_t>(it->position());
    VtuArray a;
    a.attributes = xml_attributes(it->str());
    a.name = a.attributes.at("Name");
    a.type = a.attributes.at("type");
    a.components = std::stoi(a.attributes.at("NumberOfComponents"));
    if (a.attributes.at("format") != "appended") throw fail(a.name + " is not appended");
    const std::size_t offset = std::stoul(a.attributes.at("offset"));
    if (offset != expected_offset) throw fail(a.name + " does not start where the last ended");
    std::uint64_t size = 0;
    if (offset + sizeof size > data.size()) throw fail(a.name + " lies beyond the data");
    std::memcpy(&size, data.data() + offset, sizeof size);
    if (offset + sizeof size + size > data.size()) throw fail(a.name + " runs beyond the data");
    const std::string bytes = data.substr(offset + sizeof size, size);
    expected_offset = offset + sizeof size + size;
    if (a.type == "Float64")
      a.values = decode<double>(bytes);
    else if (a.type == "Int64")
      a.values = decode<std::int64_t>(bytes);
    else if (a.type == "UInt8")
      a.values = decode<std::uint8_t>(bytes);
    else if (a.type == "Int32")
      a.values = decode<std::int32_t>(bytes);
    else
      throw fail("unexpected type " + a.type);

    if (at > point_data_begin && at < point_data_end) {
      if (static_cast<long>(a.values.size()) != v.points * a.components)
        throw fail(a.name + " has the wrong size");
      v.point_data[a.name] = a;
    } else if (at > points_begin && at < cells_begin) {
      v.coordinates = a;
    } else if (a.name == "region") {  // the one cell-data array
      if (static_cast<long>(a.values.size()) != v.cells) throw fail("region has the wrong size");
      v.cell_data[a.name] = a;
    } else if (a.name == "connectivity") {
      v.connectivity = a;
    } else if (a.name == "offsets") {
      v.offsets = a;
    } else if (a.name == "types") {
      v.types = a;
    }
  }
  if (expected_offset != data.size()) throw fail("data left over after the last array");
  if (static_cast<long>(v.coordinates.values.size()) != 3 * v.points)
    throw fail("wrong number of coordinates");
  if (static_cast<long>(v.offsets.values.size()) != v.cells ||
      static_cast<long>(v.types.values.size()) != v.cells)
    throw fail("wrong number of cells");
  return v;
}

}  // namespace signorini::testing
