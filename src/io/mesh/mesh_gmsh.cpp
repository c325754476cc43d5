// Gmsh's .msh file, ASCII versions 2.2 and 4.1 (https://gmsh.info/doc/texinfo/gmsh.html,
// "MSH file format"): nodes, linear tetrahedra (element type 4) and triangles (type 2) whose
// physical groups become markers, named by $PhysicalNames. Points and lines (types 15, 1) are
// skipped; any other element type is refused, so that a quadratic or hexahedral mesh is not
// read as an empty one. Unknown sections ($NodeData, $Periodic, ...) are skipped.
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "io/mesh/mesh_import.h"
#include "io/mesh/mesh_text.h"

namespace hs::io {
namespace {

struct GmshReader {
  MeshTokens tokens;
  ImportedMesh mesh;
  std::unordered_map<long long, pbd::Index> vertexOfTag;
  std::map<int, std::string> physicalNames;     // (dimension 2) tag -> name
  std::map<long long, std::vector<int>> surfacePhysicals;  // 4.1: surface entity -> physical tags
  std::map<int, std::size_t> markerOf;           // physical tag -> index in mesh.markers
  std::vector<long long> tetNumbers;

  pbd::Index vertex(long long tag) {
    const auto it = vertexOfTag.find(tag);
    if (it == vertexOfTag.end()) tokens.fail("expected a node tag of $Nodes, got " + std::to_string(tag));
    return it->second;
  }

  void addNode(long long tag, const pbd::Vec3& p) {
    if (!vertexOfTag.try_emplace(tag, static_cast<pbd::Index>(mesh.vertices.size())).second)
      tokens.fail("node tag " + std::to_string(tag) + " given twice");
    mesh.vertices.push_back(p);
  }

  void addTriangle(const pbd::Triangle& triangle, const std::vector<int>& physicals) {
    for (int tag : physicals) {
      auto [it, added] = markerOf.try_emplace(tag, mesh.markers.size());
      if (added) mesh.markers.push_back({std::string(), tag, {}});
      mesh.markers[it->second].triangles.push_back(static_cast<pbd::Index>(mesh.triangles.size()));
    }
    mesh.triangles.push_back(triangle);
  }

  // Node count of the element types that may appear; -1 for a type heartsim refuses.
  static int nodesOf(long long type) {
    switch (type) {
      case 15: return 1;  // point
      case 1: return 2;   // line
      case 2: return 3;   // triangle
      case 4: return 4;   // tetrahedron
      default: return -1;
    }
  }

  void element(long long number, long long type, const std::vector<int>& physicals) {
    const int nodes = nodesOf(type);
    if (nodes < 0)
      tokens.fail("element " + std::to_string(number) + " has type " + std::to_string(type) +
                  "; expected 4 (tetrahedron), 2 (triangle), 1 (line) or 15 (point): only linear meshes are read");
    std::array<pbd::Index, 4> ids{};
    for (int k = 0; k < nodes; ++k) ids[static_cast<std::size_t>(k)] = vertex(tokens.integer("a node tag"));
    if (type == 4) {
      mesh.tets.push_back({ids[0], ids[1], ids[2], ids[3]});
      tetNumbers.push_back(number);
    } else if (type == 2) {
      addTriangle({ids[0], ids[1], ids[2]}, physicals);
    }
  }

  void skipSection(std::string_view name) {
    const std::string end = "$End" + std::string(name.substr(1));
    while (tokens.next(end) != end) {
    }
  }

  void physicalNamesSection(long long limit) {
    const long long count = tokens.count("the number of physical names", limit);
    for (long long i = 0; i < count; ++i) {
      const long long dimension = tokens.integer("a physical dimension");
      const long long tag = tokens.integer("a physical tag");
      std::string_view name = tokens.restOfLine();
      if (name.size() >= 2 && name.front() == '"' && name.back() == '"') name = name.substr(1, name.size() - 2);
      if (dimension == 2 && tag >= -1000000 && tag <= 1000000) physicalNames[static_cast<int>(tag)] = std::string(name);
    }
    tokens.expect("$EndPhysicalNames");
  }

  int physicalTag(long long tag) {
    if (tag < -1000000 || tag > 1000000) tokens.fail("expected a physical tag within +-1e6, got " + std::to_string(tag));
    return static_cast<int>(tag);
  }

  // 2.2: $Nodes: n, then n lines "tag x y z"; $Elements: n, then n lines
  // "number type #tags [physical elementary ...] nodes...".
  void nodes22(long long limit) {
    const long long count = tokens.count("the number of nodes", limit);
    for (long long i = 0; i < count; ++i) {
      const long long tag = tokens.integer("a node tag");
      addNode(tag, tokens.point("node coordinates"));
    }
    tokens.expect("$EndNodes");
  }

  void elements22(long long limit) {
    const long long count = tokens.count("the number of elements", limit);
    for (long long i = 0; i < count; ++i) {
      const long long number = tokens.integer("an element number");
      const long long type = tokens.integer("an element type");
      const long long tagCount = tokens.count("the number of element tags", 100);
      std::vector<int> physicals;
      for (long long k = 0; k < tagCount; ++k) {
        const long long tag = tokens.integer("an element tag");
        if (k == 0 && tag != 0) physicals.push_back(physicalTag(tag));  // 0: in no physical group
      }
      element(number, type, physicals);
    }
    tokens.expect("$EndElements");
  }

  // 4.1 $Entities: #points #curves #surfaces #volumes; each entity its tag, bounding box (a
  // point: its position), physical tags and, but for points, its bounding entities.
  void entities41(long long limit) {
    long long counts[4];
    for (long long& c : counts) c = tokens.count("an entity count", limit);
    for (int dimension = 0; dimension < 4; ++dimension)
      for (long long i = 0; i < counts[dimension]; ++i) {
        const long long tag = tokens.integer("an entity tag");
        for (int k = 0; k < (dimension == 0 ? 3 : 6); ++k) (void)tokens.real("a bounding box coordinate");
        const long long physicalCount = tokens.count("the number of physical tags", 1000);
        std::vector<int> physicals;
        for (long long k = 0; k < physicalCount; ++k) physicals.push_back(physicalTag(tokens.integer("a physical tag")));
        if (dimension == 2) surfacePhysicals[tag] = physicals;
        if (dimension == 0) continue;
        const long long bounding = tokens.count("the number of bounding entities", limit);
        for (long long k = 0; k < bounding; ++k) (void)tokens.integer("a bounding entity tag");
      }
    tokens.expect("$EndEntities");
  }

  // 4.1 $Nodes: #blocks #nodes minTag maxTag; each block: dim entity parametric #nodes, the
  // #nodes tags, then #nodes lines of x y z (and dim parametric coordinates when parametric).
  void nodes41(long long limit) {
    const long long blocks = tokens.count("the number of node blocks", limit);
    (void)tokens.count("the number of nodes", limit);
    (void)tokens.integer("the smallest node tag");
    (void)tokens.integer("the largest node tag");
    for (long long b = 0; b < blocks; ++b) {
      const long long dimension = tokens.count("an entity dimension (0 to 3)", 3);
      (void)tokens.integer("an entity tag");
      const long long parametric = tokens.count("the parametric flag (0 or 1)", 1);
      const long long count = tokens.count("the number of nodes in the block", limit);
      std::vector<long long> tags;
      for (long long i = 0; i < count; ++i) tags.push_back(tokens.integer("a node tag"));
      for (long long tag : tags) {
        addNode(tag, tokens.point("node coordinates"));
        for (long long k = 0; k < parametric * dimension; ++k) (void)tokens.real("a parametric coordinate");
      }
    }
    tokens.expect("$EndNodes");
  }

  // 4.1 $Elements: #blocks #elements minTag maxTag; each block: dim entity type #elements, then
  // #elements lines of "tag nodes...". A triangle's markers: its surface's physical groups.
  void elements41(long long limit) {
    const long long blocks = tokens.count("the number of element blocks", limit);
    (void)tokens.count("the number of elements", limit);
    (void)tokens.integer("the smallest element tag");
    (void)tokens.integer("the largest element tag");
    for (long long b = 0; b < blocks; ++b) {
      const long long dimension = tokens.count("an entity dimension (0 to 3)", 3);
      const long long entity = tokens.integer("an entity tag");
      const long long type = tokens.integer("an element type");
      const long long count = tokens.count("the number of elements in the block", limit);
      static const std::vector<int> none;
      const auto physicals = dimension == 2 ? surfacePhysicals.find(entity) : surfacePhysicals.end();
      for (long long i = 0; i < count; ++i) {
        const long long number = tokens.integer("an element tag");
        element(number, type, physicals == surfacePhysicals.end() ? none : physicals->second);
      }
    }
    tokens.expect("$EndElements");
  }
};

}  // namespace

ImportedMesh parseGmsh(std::string_view text, const std::string& name) {
  GmshReader reader{MeshTokens(text, name), {}, {}, {}, {}, {}, {}};
  MeshTokens& tokens = reader.tokens;
  const long long limit = countLimit(text);
  tokens.expect("$MeshFormat");
  const std::string_view version = tokens.next("a format version");
  const bool v41 = version == "4.1";
  if (version != "2.2" && !v41) tokens.fail("expected format version 2.2 or 4.1, got '" + excerpt(version) + "'");
  const long long fileType = tokens.integer("the file type (0 ASCII, 1 binary)");
  if (fileType == 1) tokens.fail("binary .msh is not supported; expected ASCII (gmsh -save -format msh22 or -bin 0)");
  if (fileType != 0) tokens.fail("expected file type 0 (ASCII), got " + std::to_string(fileType));
  (void)tokens.integer("the data size");
  tokens.expect("$EndMeshFormat");
  bool sawNodes = false, sawElements = false;
  while (!tokens.atEnd()) {
    const std::string_view section = tokens.next("a section");
    if (section.empty() || section[0] != '$') tokens.fail("expected a section such as $Nodes, got '" + excerpt(section) + "'");
    if (section == "$PhysicalNames") {
      reader.physicalNamesSection(limit);
    } else if (section == "$Entities" && v41) {
      reader.entities41(limit);
    } else if (section == "$Nodes") {
      if (sawNodes) tokens.fail("a second $Nodes section; expected one");
      v41 ? reader.nodes41(limit) : reader.nodes22(limit);
      sawNodes = true;
    } else if (section == "$Elements") {
      if (!sawNodes) tokens.fail("$Elements before $Nodes; expected the nodes first");
      if (sawElements) tokens.fail("a second $Elements section; expected one");
      v41 ? reader.elements41(limit) : reader.elements22(limit);
      sawElements = true;
    } else {
      reader.skipSection(section);
    }
  }
  if (!sawNodes || !sawElements)
    tokens.fail(std::string("expected $Nodes and $Elements sections, the file ends without ") +
                (sawNodes ? "$Elements" : "$Nodes") + " (truncated?)");
  for (SurfaceMarker& marker : reader.mesh.markers)
    if (const auto it = reader.physicalNames.find(marker.number); it != reader.physicalNames.end()) marker.name = it->second;
  reader.mesh.format = v41 ? "gmsh 4.1 ascii" : "gmsh 2.2 ascii";
  finishMesh(reader.mesh, name, reader.tetNumbers);
  return std::move(reader.mesh);
}

}  // namespace hs::io
