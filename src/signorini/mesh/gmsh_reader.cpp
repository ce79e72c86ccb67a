#include "signorini/mesh/gmsh_reader.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <unordered_map>

#include "signorini/core/error.hpp"
#include "signorini/mesh/cell_orientation.hpp"
#include "signorini/mesh/cell_overlap.hpp"
#include "signorini/mesh/facet_matching.hpp"

namespace signorini {

namespace {

// Gmsh element types: nodes per element (0: unknown to us), for types 1..31.
constexpr std::array<int, 32> kGmshNodes{0,  2,  3,  4,  4, 8, 6,  5,  3,  6, 9,
                                         10, 27, 18, 14, 1, 8, 20, 15, 13, 9, 10,
                                         12, 15, 15, 21, 4, 5, 6,  20, 35, 56};

// Nodes of the largest cell we read (Hex27): the length of the cells' sort keys.
constexpr std::size_t kMaxSortKey = 27;

int gmsh_nodes(int type) {
  return type >= 1 && type < static_cast<int>(kGmshNodes.size())
             ? kGmshNodes[static_cast<std::size_t>(type)]
             : 0;
}

// The cell or facet type of a Gmsh element type we read; nullopt for others.
std::optional<CellType> cell_type_of(int gmsh_type) {
  switch (gmsh_type) {
    case 1:
      return CellType::Line2;
    case 8:
      return CellType::Line3;
    case 2:
      return CellType::Tri3;
    case 9:
      return CellType::Tri6;
    case 3:
      return CellType::Quad4;
    case 16:
      return CellType::Quad8;
    case 10:
      return CellType::Quad9;
    case 4:
      return CellType::Tet4;
    case 11:
      return CellType::Tet10;
    case 5:
      return CellType::Hex8;
    case 12:
      return CellType::Hex27;
    default:
      return std::nullopt;
  }
}

bool is_3d_type(int t) {
  return (t >= 4 && t <= 7) || (t >= 11 && t <= 14) || (t >= 17 && t <= 19) || t >= 29;
}

// One element as read: its Gmsh type and tag, the physical groups it is in, its node tags.
struct RawElements {
  std::vector<int> types;
  std::vector<Index> tags;
  std::vector<int> group;  // index into Parsed::groups: the element's physical tags
  std::vector<Index> offsets{0};
  std::vector<Index> nodes;
  std::vector<std::size_t> positions;  // where in the file (for messages)
};

class Reader {
 public:
  Reader(const std::string& s, std::string name) : s_(s), name_(std::move(name)) {}

  [[noreturn]] void fail(const std::string& what) const { fail_at(pos_, what); }
  [[noreturn]] void fail_at(std::size_t pos, const std::string& what) const {
    if (binary_ && pos > binary_start_)
      throw InputError(name_ + ": byte " + std::to_string(pos) + ": " + what);
    const auto line =
        1 + std::count(s_.begin(),
                       s_.begin() + static_cast<std::ptrdiff_t>(std::min(pos, s_.size())), '\n');
    throw InputError(name_ + ":" + std::to_string(line) + ": " + what);
  }

  [[nodiscard]] std::size_t pos() const { return pos_; }
  /// Throws unless `count` items of at least `bytes_each` bytes fit in what is left of the file,
  /// before anything is allocated for them (a corrupted count must not ask for petabytes).
  void check_count(long long count, std::size_t bytes_each, const char* what) const {
    if (count < 0 ||
        static_cast<unsigned long long>(count) >
            (s_.size() - std::min(pos_, s_.size())) / std::max<std::size_t>(1, bytes_each))
      fail("the file announces " + std::to_string(count) + " " + what +
           ", more than the rest of the file can hold (truncated or corrupted?)");
  }
  [[nodiscard]] bool at_end() {
    skip_space();
    return pos_ >= s_.size();
  }
  void set_binary(bool b) {
    binary_ = b;
    binary_start_ = pos_;
  }
  [[nodiscard]] bool binary() const { return binary_; }

  // Up to and including the end of the current line: where binary data starts (skip_space could
  // eat bytes of the data that happen to look like white space).
  void skip_newline() {
    while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
    if (pos_ < s_.size()) ++pos_;
  }
  void skip_space() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  // The next whitespace-separated word.
  std::string word(const char* what) {
    skip_space();
    if (pos_ >= s_.size())
      fail(std::string("file ends where ") + what + " was expected (truncated?)");
    const std::size_t b = pos_;
    while (pos_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    return s_.substr(b, pos_ - b);
  }
  long long integer(const char* what) {
    skip_space();
    if (pos_ >= s_.size())
      fail(std::string("file ends where ") + what + " was expected (truncated?)");
    const char* b = s_.c_str() + pos_;
    char* e = nullptr;
    const long long v = std::strtoll(b, &e, 10);
    if (e == b || (*e != '\0' && !std::isspace(static_cast<unsigned char>(*e))))
      fail(std::string("expected ") + what + " (an integer), found '" + peek_word() + "'");
    pos_ += static_cast<std::size_t>(e - b);
    return v;
  }
  double real(const char* what) {
    skip_space();
    if (pos_ >= s_.size())
      fail(std::string("file ends where ") + what + " was expected (truncated?)");
    const char* b = s_.c_str() + pos_;
    char* e = nullptr;
    const double v = std::strtod(b, &e);
    if (e == b) fail(std::string("expected ") + what + " (a number), found '" + peek_word() + "'");
    pos_ += static_cast<std::size_t>(e - b);
    return v;
  }
  // The rest of the line (for the quoted names of $PhysicalNames).
  std::string rest_of_line() {
    const std::size_t e = s_.find('\n', pos_);
    const std::size_t end = e == std::string::npos ? s_.size() : e;
    std::string out = s_.substr(pos_, end - pos_);
    pos_ = end;
    return out;
  }
  template <class T>
  T get(const char* what) {
    if (pos_ + sizeof(T) > s_.size())
      fail(std::string("file ends inside ") + what + " (truncated?)");
    T v;
    std::memcpy(&v, s_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  // An integer of either representation.
  long long count(const char* what, bool size_t_field) {
    if (!binary_) return integer(what);
    if (size_t_field) return static_cast<long long>(get<std::uint64_t>(what));
    return get<std::int32_t>(what);
  }
  double number(const char* what) { return binary_ ? get<double>(what) : real(what); }

  // After binary data: the newline before "$End...".
  void expect(const std::string& marker) {
    const std::string w = word(marker.c_str());
    if (w != marker) fail("expected " + marker + ", found '" + w.substr(0, 40) + "'");
  }
  // Skips an unknown section up to its end marker.
  void skip_section(const std::string& name) {
    const std::string end = "$End" + name.substr(1);
    const std::size_t e = s_.find(end, pos_);
    if (e == std::string::npos) fail("section " + name + " has no " + end + " (truncated?)");
    pos_ = e + end.size();
  }

 private:
  std::string peek_word() const {
    std::size_t e = pos_;
    while (e < s_.size() && !std::isspace(static_cast<unsigned char>(s_[e])) && e - pos_ < 40) ++e;
    return s_.substr(pos_, e - pos_);
  }

  const std::string& s_;
  std::string name_;
  std::size_t pos_ = 0;
  bool binary_ = false;
  std::size_t binary_start_ = 0;
};

struct Parsed {
  int major = 0;
  std::map<std::pair<int, int>, std::string> physical_names;         // (dim, tag) -> name
  std::map<std::pair<int, int>, std::vector<int>> entity_physicals;  // (dim, entity) -> tags
  // The distinct lists of physical tags, so that an element stores one index: group 0 is none.
  std::vector<std::vector<int>> groups{{}};
  std::map<std::vector<int>, int> group_index{{{}, 0}};
  int group_of(const std::vector<int>& tags) {
    const auto [it, added] = group_index.try_emplace(tags, static_cast<int>(groups.size()));
    if (added) groups.push_back(tags);
    return it->second;
  }
  std::vector<Index> node_tags;
  std::vector<double> xyz;  // 3 per node
  // By dimension: the highest present holds the cells, the one below the boundary parts.
  RawElements volumes, surfaces, lines;
};

void read_physical_names(Reader& r, Parsed& p) {
  const long long n = r.integer("the number of physical names");
  for (long long k = 0; k < n; ++k) {
    const auto dim = static_cast<int>(r.integer("a physical dimension"));
    const auto tag = static_cast<int>(r.integer("a physical tag"));
    std::string rest = r.rest_of_line();
    const std::size_t a = rest.find('"'), b = rest.rfind('"');
    if (a == std::string::npos || b <= a) r.fail("expected a quoted physical name");
    p.physical_names[{dim, tag}] = rest.substr(a + 1, b - a - 1);
  }
  r.expect("$EndPhysicalNames");
}

void read_entities(Reader& r, Parsed& p) {
  long long counts[4];
  for (long long& c : counts) c = r.count("the number of entities", true);
  for (int dim = 0; dim < 4; ++dim)
    for (long long k = 0; k < counts[dim]; ++k) {
      const auto tag = static_cast<int>(r.count("an entity tag", false));
      for (int i = 0; i < (dim == 0 ? 3 : 6); ++i) (void)r.number("an entity coordinate");
      const long long nphys = r.count("the number of physical tags", true);
      std::vector<int>& phys = p.entity_physicals[{dim, tag}];
      for (long long i = 0; i < nphys; ++i)
        phys.push_back(static_cast<int>(r.count("a physical tag", false)));
      if (dim > 0) {
        const long long nb = r.count("the number of bounding entities", true);
        for (long long i = 0; i < nb; ++i) (void)r.count("a bounding entity", false);
      }
    }
  r.expect("$EndEntities");
}

void read_nodes_41(Reader& r, Parsed& p) {
  const long long blocks = r.count("the number of node blocks", true);
  const long long total = r.count("the number of nodes", true);
  (void)r.count("the smallest node tag", true);
  (void)r.count("the largest node tag", true);
  r.check_count(total, r.binary() ? 32 : 8, "nodes");
  p.node_tags.reserve(static_cast<std::size_t>(total));
  p.xyz.reserve(static_cast<std::size_t>(3 * total));
  for (long long b = 0; b < blocks; ++b) {
    const auto dim = static_cast<int>(r.count("an entity dimension", false));
    (void)r.count("an entity tag", false);
    const auto parametric = r.count("the parametric flag", false);
    const long long n = r.count("the number of nodes in a block", true);
    for (long long k = 0; k < n; ++k)
      p.node_tags.push_back(static_cast<Index>(r.count("a node tag", true)));
    const int extra = parametric != 0 ? dim : 0;
    for (long long k = 0; k < n; ++k) {
      for (int i = 0; i < 3; ++i) p.xyz.push_back(r.number("a node coordinate"));
      for (int i = 0; i < extra; ++i) (void)r.number("a parametric coordinate");
    }
  }
  if (static_cast<long long>(p.node_tags.size()) != total)
    r.fail("$Nodes announces " + std::to_string(total) + " nodes, its blocks hold " +
           std::to_string(p.node_tags.size()));
  r.expect("$EndNodes");
}

void read_nodes_22(Reader& r, Parsed& p) {
  const long long n = r.integer("the number of nodes");
  if (r.binary()) r.skip_newline();  // the binary data starts on the next line
  for (long long k = 0; k < n; ++k) {
    p.node_tags.push_back(static_cast<Index>(r.count("a node tag", false)));
    for (int i = 0; i < 3; ++i) p.xyz.push_back(r.number("a node coordinate"));
  }
  r.expect("$EndNodes");
}

void add_element(Reader& r, Parsed& p, int type, Index tag, int group, const Index* nodes, int k,
                 std::size_t where) {
  const std::optional<CellType> ct = cell_type_of(type);
  if (!ct) {
    if (type == 15) return;  // a point element: nothing to do
    if (is_3d_type(type))
      r.fail_at(where, "element " + std::to_string(tag) + " has Gmsh type " + std::to_string(type) +
                           ", a 3D element that is not supported (supported: tetrahedra of 4 "
                           "and 10 nodes, hexahedra of 8 and 27)");
    r.fail_at(where, "element " + std::to_string(tag) + " has Gmsh type " + std::to_string(type) +
                         ", which is not supported (supported: lines of 2 and 3 nodes, "
                         "triangles of 3 and 6, quadrilaterals of 4, 8 and 9)");
  }
  const int dim = cell_dimension(*ct);
  RawElements& e = dim == 3 ? p.volumes : dim == 2 ? p.surfaces : p.lines;
  // A line in no group bounds nothing (a surface in none may yet be a cell of a 2D mesh).
  if (dim == 1 && group == 0) return;
  e.types.push_back(type);
  e.tags.push_back(tag);
  e.group.push_back(group);
  e.nodes.insert(e.nodes.end(), nodes, nodes + k);
  e.offsets.push_back(static_cast<Index>(e.nodes.size()));
  e.positions.push_back(where);
}

void read_elements_41(Reader& r, Parsed& p) {
  const long long blocks = r.count("the number of element blocks", true);
  (void)r.count("the number of elements", true);
  (void)r.count("the smallest element tag", true);
  (void)r.count("the largest element tag", true);
  std::vector<Index> nodes;
  for (long long b = 0; b < blocks; ++b) {
    const auto dim = static_cast<int>(r.count("an entity dimension", false));
    const auto entity = static_cast<int>(r.count("an entity tag", false));
    const auto type = static_cast<int>(r.count("an element type", false));
    const long long n = r.count("the number of elements in a block", true);
    const int k = gmsh_nodes(type);
    if (k == 0) r.fail("element type " + std::to_string(type) + " is not a Gmsh type known here");
    const auto it = p.entity_physicals.find({dim, entity});
    const int group = it == p.entity_physicals.end() ? 0 : p.group_of(it->second);
    r.check_count(n, static_cast<std::size_t>(r.binary() ? 8 * (k + 1) : 2 * (k + 1)),
                  "elements in a block");
    if (dim >= 2) {  // room for the block at once, not by doubling
      RawElements& e = dim == 3 ? p.volumes : p.surfaces;
      e.nodes.reserve(e.nodes.size() + static_cast<std::size_t>(n * k));
      for (auto* v : {&e.tags, &e.offsets}) v->reserve(v->size() + n);
    }
    nodes.resize(static_cast<std::size_t>(k));
    for (long long e = 0; e < n; ++e) {
      const std::size_t where = r.pos();
      const auto tag = static_cast<Index>(r.count("an element tag", true));
      for (int i = 0; i < k; ++i)
        nodes[static_cast<std::size_t>(i)] = static_cast<Index>(r.count("a node tag", true));
      add_element(r, p, type, tag, group, nodes.data(), k, where);
    }
  }
  r.expect("$EndElements");
}

void read_elements_22(Reader& r, Parsed& p) {
  const long long n = r.integer("the number of elements");
  std::vector<Index> nodes;
  if (!r.binary()) {
    for (long long e = 0; e < n; ++e) {
      const std::size_t where = r.pos();
      const auto tag = static_cast<Index>(r.integer("an element tag"));
      const auto type = static_cast<int>(r.integer("an element type"));
      const long long ntags = r.integer("the number of element tags");
      std::vector<int> tags;
      for (long long i = 0; i < ntags; ++i) tags.push_back(static_cast<int>(r.integer("a tag")));
      const int k = gmsh_nodes(type);
      if (k == 0)
        r.fail_at(where, "element " + std::to_string(tag) + " has Gmsh type " +
                             std::to_string(type) + ", which is not a known Gmsh type");
      nodes.resize(static_cast<std::size_t>(k));
      for (int i = 0; i < k; ++i)
        nodes[static_cast<std::size_t>(i)] = static_cast<Index>(r.integer("a node tag"));
      // The first tag is the physical group (0: none), the second the elementary entity.
      const int group = !tags.empty() && tags[0] != 0 ? p.group_of({tags[0]}) : 0;
      add_element(r, p, type, tag, group, nodes.data(), k, where);
    }
  } else {
    r.skip_newline();
    long long done = 0;
    while (done < n) {
      const auto type = r.get<std::int32_t>("an element block header");
      const auto count = r.get<std::int32_t>("an element block header");
      const auto ntags = r.get<std::int32_t>("an element block header");
      const int k = gmsh_nodes(type);
      if (k == 0 || count <= 0 || ntags < 0)
        r.fail("element block of Gmsh type " + std::to_string(type) + " cannot be read");
      // (In size_t: 1 + ntags would overflow an int for a header that says 2^31 - 1 tags.)
      r.check_count(
          count,
          4 * (std::size_t{1} + static_cast<std::size_t>(ntags) + static_cast<std::size_t>(k)),
          "elements in a block");
      nodes.resize(static_cast<std::size_t>(k));
      for (int e = 0; e < count; ++e) {
        const std::size_t where = r.pos();
        const auto tag = static_cast<Index>(r.get<std::int32_t>("an element"));
        std::vector<int> tags(static_cast<std::size_t>(ntags));
        for (int& t : tags) t = r.get<std::int32_t>("an element");
        for (int i = 0; i < k; ++i)
          nodes[static_cast<std::size_t>(i)] = r.get<std::int32_t>("an element");
        const int group = !tags.empty() && tags[0] != 0 ? p.group_of({tags[0]}) : 0;
        add_element(r, p, type, tag, group, nodes.data(), k, where);
      }
      done += count;
    }
  }
  r.expect("$EndElements");
}

Parsed parse(const std::string& content, const std::string& name) {
  Reader r(content, name);
  Parsed p;
  bool have_format = false, have_nodes = false, have_elements = false;
  while (!r.at_end()) {
    const std::string section = r.word("a section");
    if (section.empty() || section[0] != '$')
      r.fail("expected a section such as $Nodes, found '" + section.substr(0, 40) + "'");
    if (section == "$MeshFormat") {
      const std::string version = r.word("the format version");
      const long long file_type = r.integer("the file type");
      const long long data_size = r.integer("the data size");
      if (version == "4.1")
        p.major = 4;
      else if (version.rfind("2.", 0) == 0)
        p.major = 2;
      else
        r.fail("format " + version +
               " is not supported: save the mesh as 4.1 or 2.2 (Gmsh: "
               "-format msh41 or msh22)");
      if (data_size != 8) r.fail("data size " + std::to_string(data_size) + ", expected 8");
      if (file_type == 1) {
        r.skip_newline();
        r.set_binary(true);
        if (r.get<std::int32_t>("the byte-order check") != 1)
          r.fail("a binary file of the other byte order: save it on this machine or as ASCII");
      }
      r.expect("$EndMeshFormat");
      have_format = true;
      continue;
    }
    if (!have_format) r.fail("the file does not start with $MeshFormat: not a Gmsh mesh file");
    // In a binary file each section's numbers follow its header line.
    const auto binary_body = [&] {
      if (r.binary()) r.skip_newline();
    };
    if (section == "$PhysicalNames") {
      read_physical_names(r, p);
    } else if (section == "$Entities" && p.major == 4) {
      binary_body();
      read_entities(r, p);
    } else if (section == "$Nodes") {
      if (p.major == 4) {
        binary_body();
        read_nodes_41(r, p);
      } else {
        read_nodes_22(r, p);
      }
      have_nodes = true;
    } else if (section == "$Elements") {
      if (p.major == 4) {
        binary_body();
        read_elements_41(r, p);
      } else {
        read_elements_22(r, p);
      }
      have_elements = true;
    } else {
      r.skip_section(section);
    }
  }
  if (!have_format) r.fail("empty file: not a Gmsh mesh file");
  if (!have_nodes) r.fail("the file has no $Nodes section");
  if (!have_elements) r.fail("the file has no $Elements section");
  return p;
}

std::string physical_name(const Parsed& p, int dim, int tag) {
  const auto it = p.physical_names.find({dim, tag});
  return it != p.physical_names.end() ? it->second : std::to_string(tag);
}

}  // namespace

Mesh parse_gmsh_mesh(const std::string& content, const std::string& name) {
  const Parsed p = parse(content, name);
  // The highest dimension present decides: volumes are the cells of a 3D mesh and its physical
  // surfaces the boundary parts; without volumes, surfaces and physical curves make a 2D mesh.
  const int dim = p.volumes.types.empty() ? 2 : 3;
  const RawElements& raw = dim == 3 ? p.volumes : p.surfaces;
  const RawElements& bounds = dim == 3 ? p.surfaces : p.lines;
  // Gmsh saves only the elements of physical groups where a geometry defines any: a .geo with
  // physical curves but no physical surface gives lines alone.
  if (raw.types.empty() && !bounds.types.empty())
    throw InputError(name +
                     ": no 2D elements (triangles or quadrilaterals), only lines: where a "
                     "geometry has physical groups, Gmsh saves only their elements, so the "
                     "body's surfaces need one too (e.g. Physical Surface(\"body\") = {1};)");
  if (raw.types.empty())
    throw InputError(name +
                     ": no 2D elements (triangles or quadrilaterals): is it meshed in 2D "
                     "(gmsh -2)?");
  // Node tags to positions in $Nodes: an array where the tags are compact (as Gmsh writes
  // them), a hash table where they are not.
  Index max_tag = 0;
  for (const Index t : p.node_tags) {
    if (t < 0) throw InputError(name + ": negative node tag " + std::to_string(t));
    max_tag = std::max(max_tag, t);
  }
  const bool compact = max_tag <= 4 * static_cast<Index>(p.node_tags.size()) + 1024;
  std::vector<Index> slot;
  std::unordered_map<Index, Index> sparse_slot;
  // A tag defined twice would leave one of its points unused, silently: refused.
  const auto defined_twice = [&](std::size_t first, std::size_t second) {
    const auto at = [&](std::size_t k) {
      return fmt::format("({:g}, {:g}, {:g})", p.xyz[3 * k], p.xyz[3 * k + 1], p.xyz[3 * k + 2]);
    };
    return InputError(fmt::format(
        "{}: node {} is defined twice in $Nodes, at {} and at {}: expected each node tag once",
        name, p.node_tags[second], at(first), at(second)));
  };
  if (compact) {
    slot.assign(static_cast<std::size_t>(max_tag + 1), -1);
    for (std::size_t k = 0; k < p.node_tags.size(); ++k) {
      Index& s = slot[static_cast<std::size_t>(p.node_tags[k])];
      if (s >= 0) throw defined_twice(static_cast<std::size_t>(s), k);
      s = static_cast<Index>(k);
    }
  } else {
    for (std::size_t k = 0; k < p.node_tags.size(); ++k)
      if (const auto [it, added] = sparse_slot.try_emplace(p.node_tags[k], static_cast<Index>(k));
          !added)
        throw defined_twice(static_cast<std::size_t>(it->second), k);
  }
  const auto node_slot = [&](const RawElements& e, std::size_t i, Index tag) {
    Index k = -1;
    if (compact) {
      if (tag >= 0 && tag <= max_tag) k = slot[static_cast<std::size_t>(tag)];
    } else if (const auto it = sparse_slot.find(tag); it != sparse_slot.end()) {
      k = it->second;
    }
    if (k < 0)
      throw InputError(name + ": element " + std::to_string(e.tags[i]) + " uses node " +
                       std::to_string(tag) + ", which $Nodes does not define");
    return k;
  };
  // Number the nodes that cells use, in the order of their tags.
  std::vector<char> used(p.node_tags.size(), 0);
  for (std::size_t i = 0; i < raw.types.size(); ++i)
    for (Index k = raw.offsets[i]; k < raw.offsets[i + 1]; ++k)
      used[static_cast<std::size_t>(node_slot(raw, i, raw.nodes[static_cast<std::size_t>(k)]))] = 1;
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < used.size(); ++k)
    if (used[k] != 0) order.push_back(k);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return p.node_tags[a] < p.node_tags[b]; });
  std::vector<Index> number(p.node_tags.size(), -1);
  Eigen::MatrixXd xy(dim, static_cast<Index>(order.size()));
  double zmin = INFINITY, zmax = -INFINITY, size = 0.0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t s = order[k];
    number[s] = static_cast<Index>(k);
    for (int d = 0; d < dim; ++d) xy(d, static_cast<Index>(k)) = p.xyz[3 * s + d];
    zmin = std::min(zmin, p.xyz[3 * s + 2]);
    zmax = std::max(zmax, p.xyz[3 * s + 2]);
  }
  if (!xy.allFinite()) throw InputError(name + ": a node coordinate is not finite");
  size = (xy.rowwise().maxCoeff() - xy.rowwise().minCoeff()).maxCoeff();
  if (dim == 2 && zmax - zmin > 1e-9 * std::max(size, 1e-300))
    throw InputError(name + ": the 2D elements do not lie in one plane z = constant (z from " +
                     std::to_string(zmin) + " to " + std::to_string(zmax) +
                     "); if it is a 3D body, its volumes need a physical group too (e.g. "
                     "Physical Volume(\"body\") = {1};): where a geometry has physical groups, "
                     "Gmsh saves only their elements");

  // Cells, counterclockwise in 2D, positively oriented in 3D.
  std::vector<CellType> types;
  std::vector<Index> cells;
  std::vector<Index> tags;
  std::vector<int> region_tag;
  types.reserve(raw.types.size());
  // Cells in an order that does not depend on the format: Gmsh numbers the elements differently
  // in 2.2 and 4.1, but not the nodes. Sorted by their node tags (sorted, compared as words), the
  // same mesh in any format assembles in the same order: the same sums, the same bits.
  const std::size_t nc = raw.types.size();
  // The sorted node tags of cell i, the order's key.
  const auto sorted_tags = [&](std::size_t i) {
    std::array<Index, kMaxSortKey> k;
    k.fill(-1);
    const auto b = static_cast<std::size_t>(raw.offsets[i]);
    const auto e = static_cast<std::size_t>(raw.offsets[i + 1]);
    std::copy(raw.nodes.begin() + static_cast<std::ptrdiff_t>(b),
              raw.nodes.begin() + static_cast<std::ptrdiff_t>(e), k.begin());
    std::sort(k.begin(), k.begin() + static_cast<std::ptrdiff_t>(e - b));
    return k;
  };
  // First by the smallest node tag (a sort of 8-byte words), then runs of equal smallest tags
  // (a few cells each, a few dozen around a node of a tetrahedral mesh) by the whole key, each
  // key made once.
  std::vector<std::pair<Index, std::size_t>> by_first(nc);
  for (std::size_t i = 0; i < nc; ++i) {
    const auto b = raw.nodes.begin() + static_cast<std::ptrdiff_t>(raw.offsets[i]);
    const auto e = raw.nodes.begin() + static_cast<std::ptrdiff_t>(raw.offsets[i + 1]);
    by_first[i] = {*std::min_element(b, e), i};
  }
  std::sort(by_first.begin(), by_first.end());
  std::vector<std::size_t> canonical(nc);
  std::vector<std::pair<std::array<Index, kMaxSortKey>, std::size_t>> run_keys;
  for (std::size_t run = 0; run < nc;) {
    std::size_t end = run + 1;
    while (end < nc && by_first[end].first == by_first[run].first) ++end;
    if (end - run > 1) {
      run_keys.clear();
      for (std::size_t k = run; k < end; ++k)
        run_keys.emplace_back(sorted_tags(by_first[k].second), by_first[k].second);
      std::sort(run_keys.begin(), run_keys.end());
      for (std::size_t k = run; k < end; ++k) canonical[k] = run_keys[k - run].second;
    } else {
      canonical[run] = by_first[run].second;
    }
    run = end;
  }
  for (const std::size_t i : canonical) {
    const CellType t = *cell_type_of(raw.types[i]);
    const std::size_t first = cells.size();
    for (Index k = raw.offsets[i]; k < raw.offsets[i + 1]; ++k)
      cells.push_back(number[static_cast<std::size_t>(
          node_slot(raw, i, raw.nodes[static_cast<std::size_t>(k)]))]);
    Index* v = cells.data() + first;
    if (dim == 2) {
      if (signed_corner_area2(t, v, xy) < 0.0) mirror_cell(t, v);
    } else if (const double det = min_corner_det(t, v, xy); !(det > 0.0)) {
      // Gmsh writes positive volumes; a hand-written or converted file may not, and a cell
      // turned inside out must not reach the assembly as a negative stiffness.
      throw InputError(name + ": element " + std::to_string(raw.tags[i]) + " (" +
                       std::string(enum_to_string(kCellTypeNames, t)) + ") is " +
                       (det < 0.0 ? "inverted: det J < 0 at a corner (Gmsh's node order gives "
                                    "det J > 0)"
                                  : "degenerate: det J = 0 at a corner"));
    }
    types.push_back(t);
    tags.push_back(raw.tags[i]);
    const std::vector<int>& groups = p.groups[static_cast<std::size_t>(raw.group[i])];
    region_tag.push_back(groups.empty() ? -1 : groups.front());
  }
  Mesh mesh(std::move(types), std::move(xy), std::move(cells));
  mesh.set_cell_source_tags(std::move(tags));
  check_cells_do_not_overlap(
      mesh, name, [&](Index c) { return "element " + std::to_string(mesh.cell_source_tag(c)); });

  // Regions: "" for cells in no physical surface (volume in 3D), then the groups in the order of
  // their tags.
  std::map<int, int> region_index;
  std::vector<std::string> region_names{""};
  for (const int t : region_tag)
    if (t >= 0 && !region_index.contains(t)) region_index[t] = 0;
  for (auto& [t, index] : region_index) {
    index = static_cast<int>(region_names.size());
    region_names.push_back(physical_name(p, dim, t));
  }
  std::vector<int> regions;
  regions.reserve(region_tag.size());
  for (const int t : region_tag) regions.push_back(t < 0 ? 0 : region_index.at(t));
  mesh.set_cell_regions(std::move(region_names), std::move(regions));

  // Boundary parts: each element of a physical group one dimension down (a line in 2D, a
  // triangle or quadrilateral in 3D) matched to the cell facet with the same corners. Their keys
  // go into a table first (a boundary's worth), then every cell facet is looked up in it.
  std::vector<std::vector<Index>> bound_nodes(bounds.types.size());
  std::vector<BoundaryElement> elements(bounds.types.size());
  for (std::size_t i = 0; i < bounds.types.size(); ++i) {
    if (bounds.group[i] == 0) continue;  // a surface of a 3D mesh in no physical group
    for (Index k = bounds.offsets[i]; k < bounds.offsets[i + 1]; ++k) {
      const Index s = node_slot(bounds, i, bounds.nodes[static_cast<std::size_t>(k)]);
      bound_nodes[i].push_back(number[static_cast<std::size_t>(s)]);
    }
    elements[i] = {bound_nodes[i], corners_per_cell(*cell_type_of(bounds.types[i]))};
  }
  const std::vector<std::optional<Facet>> matched = match_facets(mesh, elements);
  std::map<int, std::vector<Facet>> parts;
  for (std::size_t i = 0; i < bounds.types.size(); ++i) {
    if (bounds.group[i] == 0) continue;
    if (!matched[i])
      throw InputError(
          name + (dim == 3 ? ": surface element " : ": line element ") +
          std::to_string(bounds.tags[i]) + " (physical group '" +
          physical_name(p, dim - 1, p.groups[static_cast<std::size_t>(bounds.group[i])].front()) +
          (dim == 3 ? "') is not a face of any 3D element"
                    : "') is not an edge of any 2D element"));
    for (const int t : p.groups[static_cast<std::size_t>(bounds.group[i])])
      parts[t].push_back(*matched[i]);
  }
  for (auto& [t, part] : parts) {
    // In cell order, whatever the order of the elements in the file (the same sums in any
    // format).
    std::sort(part.begin(), part.end(), [](const Facet& a, const Facet& b) {
      return a.cell != b.cell ? a.cell < b.cell : a.local < b.local;
    });
    mesh.set_boundary_part(physical_name(p, dim - 1, t), std::move(part));
  }
  return mesh;
}

Mesh read_gmsh_mesh(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open the mesh file");
  // In one read into a string of the file's size (no stream buffer grown and copied).
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) throw InputError(file.string() + ": cannot read the mesh file");
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (in.gcount() != static_cast<std::streamsize>(size))
    throw InputError(file.string() + ": cannot read the mesh file");
  return parse_gmsh_mesh(text, file.string());
}

Mesh read_mesh_file(const std::filesystem::path& file) {
  if (file.extension() != ".geo") return read_gmsh_mesh(file);
  if (!std::filesystem::exists(file))
    throw InputError(file.string() + ": cannot open the mesh file");
  // gmsh -3 <geo> -format msh41 -o <tmp>: the program, never the library (GPL). -3 meshes the
  // volumes of a 3D geometry; on a 2D one (no volumes) it writes, byte for byte, the mesh of
  // gmsh -2 (checked on every .geo of examples/gmsh), so one call serves both.
  static int counter = 0;
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() /
      ("signorini-" + std::to_string(::getpid()) + "-" + std::to_string(++counter) + ".msh");
  const std::string geo = file.string(), msh = out.string();
  std::vector<std::string> args{"gmsh", "-3", geo, "-format", "msh41", "-o", msh, "-v", "1"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  // gmsh's messages into a file of their own: its first error line goes into ours.
  const std::string log = msh + ".log";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "gmsh", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0)
    throw InputError(geo +
                     ": meshing a .geo file needs the gmsh program, which is not installed "
                     "(Debian: apt-get install gmsh); or give the .msh file it makes");
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0 && std::filesystem::exists(out);
  // gmsh's first "Error : ..." line (it names the file and the line of a syntax error).
  std::string error;
  {
    std::ifstream messages(log);
    for (std::string line; error.empty() && std::getline(messages, line);)
      if (const auto at = line.find("Error"); at != std::string::npos) {
        error = line.substr(at);
        if (const auto colon = error.find(':'); colon != std::string::npos)
          error = error.substr(colon + 1);
        error.erase(0, error.find_first_not_of(' '));
      }
  }
  std::filesystem::remove(log);
  if (!ok) {
    std::filesystem::remove(out);
    throw InputError(geo + ": gmsh could not mesh it (exit status " +
                     std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")" +
                     (error.empty() ? "; run gmsh -3 on it to see why" : ": gmsh says: " + error));
  }
  try {
    Mesh mesh = read_gmsh_mesh(out);
    std::filesystem::remove(out);
    return mesh;
  } catch (...) {
    std::filesystem::remove(out);
    throw;
  }
}

}  // namespace signorini
