// Surface meshes (.obj, .stl ASCII and binary, .ply, .off) through Assimp, Debian's
// libassimp-dev (BSD-3): polygons cut into fans, the scene's node transforms applied, vertices
// at the same position merged (an STL gives each triangle its own three), triangles that
// collapse when merged dropped. The OBJ's objects and groups ("o", "g") become markers by name.
#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "io/mesh/mesh_import.h"
#include "io/mesh/mesh_text.h"

namespace hs::io {
namespace {

// The bits of a position, as a merge key: -0 and +0 are one point.
struct PositionKey {
  std::uint32_t bits[3];
  bool operator==(const PositionKey& o) const { return std::memcmp(bits, o.bits, sizeof bits) == 0; }
};
struct PositionHash {
  std::size_t operator()(const PositionKey& k) const {
    return (std::size_t(k.bits[0]) * 73856093u) ^ (std::size_t(k.bits[1]) * 19349663u) ^ (std::size_t(k.bits[2]) * 83492791u);
  }
};

struct SurfaceBuilder {
  const std::string& name;
  ImportedMesh mesh;
  std::unordered_map<PositionKey, pbd::Index, PositionHash> vertexAt;
  std::map<std::string, std::size_t> markerOf;

  pbd::Index vertex(const aiVector3D& p) {
    const pbd::Vec3 v(static_cast<pbd::Real>(p.x), static_cast<pbd::Real>(p.y), static_cast<pbd::Real>(p.z));
    if (!v.allFinite())
      throw std::invalid_argument(name + ": vertex (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " +
                                  std::to_string(p.z) + ") is not finite; expected finite coordinates");
    PositionKey key{};
    for (int k = 0; k < 3; ++k) {
      const float f = static_cast<float>(v[k]) + 0.0f;  // -0 + 0 = +0
      std::memcpy(&key.bits[k], &f, sizeof f);
    }
    const auto [it, added] = vertexAt.try_emplace(key, static_cast<pbd::Index>(mesh.vertices.size()));
    if (added) mesh.vertices.push_back(v);
    return it->second;
  }

  void addMesh(const aiMesh& m, const aiMatrix4x4& transform, const std::string& group) {
    SurfaceMarker* marker = nullptr;
    if (!group.empty()) {
      const auto [it, added] = markerOf.try_emplace(group, mesh.markers.size());
      if (added) mesh.markers.push_back({group, -1, {}});
      marker = &mesh.markers[it->second];
    }
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      const aiFace& face = m.mFaces[f];
      if (face.mNumIndices < 3) continue;  // points and lines
      std::vector<pbd::Index> corners;
      for (unsigned k = 0; k < face.mNumIndices; ++k) {
        const unsigned i = face.mIndices[k];
        if (i >= m.mNumVertices)
          throw std::invalid_argument(name + ": face " + std::to_string(f) + " uses vertex " + std::to_string(i) +
                                      ", expected one of the " + std::to_string(m.mNumVertices) + " vertices");
        corners.push_back(vertex(transform * m.mVertices[i]));
      }
      // A polygon as a fan from its first corner: exact for the convex polygons meshers write.
      for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
        const pbd::Triangle triangle{corners[0], corners[k], corners[k + 1]};
        if (triangle[0] == triangle[1] || triangle[1] == triangle[2] || triangle[0] == triangle[2]) continue;
        if (marker != nullptr) marker->triangles.push_back(static_cast<pbd::Index>(mesh.triangles.size()));
        mesh.triangles.push_back(triangle);
      }
    }
  }

  // Depth first, children in file order; the root's own name is the file's, not a group.
  void addNode(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, bool root, bool groups) {
    const aiMatrix4x4 transform = parent * node.mTransformation;
    // Assimp names the faces before any "o" or "g" line "defaultobject": no group of the file.
    std::string group = groups && !root ? std::string(node.mName.C_Str()) : std::string();
    if (group == "defaultobject") group.clear();
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
      if (node.mMeshes[i] >= scene.mNumMeshes) throw std::invalid_argument(name + ": a node names a missing mesh");
      addMesh(*scene.mMeshes[node.mMeshes[i]], transform, group);
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c) addNode(scene, *node.mChildren[c], transform, false, groups);
  }
};

// Assimp's message on one line, control characters replaced, at most 200 characters.
std::string oneLine(std::string_view text) {
  std::string out;
  for (char c : text.substr(0, 200)) out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out.empty() ? std::string("no message") : out;
}

// Assimp's importers report some bad input only to its log and carry on (the OFF reader clamps
// an out-of-range vertex index to the last vertex): errors logged while reading are caught
// here and refuse the file. Assimp's logger is one per process; heartsim reads on one thread.
class LoggedErrors : public Assimp::LogStream {
 public:
  LoggedErrors() {
    m_created = Assimp::DefaultLogger::isNullLogger();
    if (m_created) Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);
    Assimp::DefaultLogger::get()->attachStream(this, Assimp::Logger::Err);
  }
  ~LoggedErrors() override {
    Assimp::DefaultLogger::get()->detachStream(this, Assimp::Logger::Err);
    if (m_created) Assimp::DefaultLogger::kill();
  }
  LoggedErrors(const LoggedErrors&) = delete;
  LoggedErrors& operator=(const LoggedErrors&) = delete;
  void write(const char* message) override {
    if (m_first.empty()) m_first = message;
  }
  const std::string& first() const { return m_first; }

 private:
  bool m_created = false;
  std::string m_first;
};

// A PLY header as far as the checks below need it: the format and each element's properties.
struct PlyProperty {
  bool list = false;
  bool integer = false;  // the (list's item) type is an integer type
};
struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};
struct PlyHeader {
  bool ascii = false;
  std::vector<PlyElement> elements;
  std::size_t bodyStart = 0;  // byte offset of the first line after end_header
  long bodyLine = 0;          // its line number
};

bool isPlyIntegerType(std::string_view type) {
  for (std::string_view t : {"char", "uchar", "short", "ushort", "int", "uint", "int8", "uint8", "int16", "uint16",
                             "int32", "uint32"})
    if (type == t) return true;
  return false;
}

// Assimp's PLY reader loops without end on a header line that is not one of its keywords
// (fuzz_mesh_surface found "element" with bytes >= 0x80 inside). The header is checked here
// first: printable ASCII lines, each starting with a keyword of the format, up to end_header,
// element counts no larger than the file.
PlyHeader checkPlyHeader(std::string_view bytes, const std::string& name) {
  PlyHeader header;
  std::size_t pos = 0;
  for (long line = 1; pos < bytes.size(); ++line) {
    const std::size_t end = std::min(bytes.find('\n', pos), bytes.size());
    std::string_view text = bytes.substr(pos, end - pos);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    const auto fail = [&](const std::string& what) {
      throw std::invalid_argument(name + ":" + std::to_string(line) + ": " + what);
    };
    for (char c : text)
      if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || static_cast<unsigned char>(c) >= 0x7f)
        fail("expected a PLY header line of printable ASCII, got '" + excerpt(text) + "'");
    const std::string_view keyword = text.substr(0, text.find_first_of(" \t"));
    if (line == 1 && keyword != "ply") fail("expected 'ply', got '" + excerpt(text) + "'");
    if (keyword == "end_header") {
      header.bodyStart = std::min(end + 1, bytes.size());
      header.bodyLine = line + 1;
      return header;
    }
    if (keyword.empty())
      fail("expected format, element, property, comment, obj_info or end_header, got '" + excerpt(text) + "'");
    MeshTokens tokens(text, name, '\0', line);
    (void)tokens.next(keyword);
    if (keyword == "format") {
      header.ascii = tokens.next("a format") == "ascii";
    } else if (keyword == "element") {  // "element NAME COUNT": no more elements than bytes in the file
      PlyElement element;
      element.name = tokens.next("an element name");
      element.count = tokens.count("an element count", countLimit(bytes));
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {  // "property TYPE NAME" or "property list COUNT_TYPE TYPE NAME"
      if (header.elements.empty()) fail("expected an element line before 'property'");
      PlyProperty property;
      std::string_view type = tokens.next("a property type");
      if (type == "list") {
        property.list = true;
        (void)tokens.next("a list's count type");
        type = tokens.next("a list's item type");
      }
      property.integer = isPlyIntegerType(type);
      header.elements.back().properties.push_back(property);
    } else if (line > 1 && keyword != "comment" && keyword != "obj_info") {
      fail("expected format, element, property, comment, obj_info or end_header, got '" + excerpt(text) + "'");
    }
    pos = end + 1;
  }
  throw std::invalid_argument(name + ": the PLY header has no end_header (truncated?)");
}

// Assimp's ASCII PLY body reader took more than 2 GB on a valid header over a body of garbage
// (fuzz_mesh_surface, tests/data/meshes/fuzz_findings/open_ply_body_oom.ply). The body is
// checked here first: each element on a line of its own, with exactly its properties' values
// (a list: its length, then that many items), every value a finite number, integers where the
// header says so.
void checkPlyAsciiBody(std::string_view bytes, const PlyHeader& header, const std::string& name) {
  std::size_t pos = header.bodyStart;
  long line = header.bodyLine;
  for (const PlyElement& element : header.elements) {
    for (long long item = 0; item < element.count; ++item) {
      std::string_view text;
      while (text.find_first_not_of(" \t\r") == std::string_view::npos) {  // blank lines are skipped
        if (pos >= bytes.size())
          throw std::invalid_argument(name + ":" + std::to_string(line) + ": expected " +
                                      std::to_string(element.count) + " " + excerpt(element.name) +
                                      " lines, got the end of the file after " + std::to_string(item) +
                                      " (truncated?)");
        const std::size_t end = std::min(bytes.find('\n', pos), bytes.size());
        text = bytes.substr(pos, end - pos);
        pos = end + 1;
        ++line;
      }
      MeshTokens tokens(text, name, '\0', line - 1);
      const auto value = [&](bool integer, const std::string& what) {
        if (tokens.atEnd()) tokens.fail("expected " + what + ", got the end of its line");
        if (integer) (void)tokens.integer(what);
        else (void)tokens.real(what);
      };
      const std::string what = "a value of " + excerpt(element.name) + " " + std::to_string(item);
      for (const PlyProperty& property : element.properties) {
        if (!property.list) {
          value(property.integer, what);
          continue;
        }
        const std::string listLength = "a list length of " + excerpt(element.name) + " " + std::to_string(item);
        if (tokens.atEnd()) tokens.fail("expected " + listLength + ", got the end of its line");
        const long long length = tokens.count(listLength, countLimit(bytes));
        for (long long k = 0; k < length; ++k) value(property.integer, what);
      }
      if (!tokens.atEnd())
        tokens.fail("expected " + std::to_string(element.properties.size()) + " properties of " +
                    excerpt(element.name) + " " + std::to_string(item) + " on its line, got more: '" +
                    excerpt(tokens.peek()) + "'");
    }
  }
}

// Assimp's OFF reader allocates what the header's counts say before reading (a forged count of
// 1e12 faces ran out of memory): the counts are checked against the file's size first.
void checkOffCounts(std::string_view bytes, const std::string& name) {
  MeshTokens tokens(bytes, name, '#');
  std::string_view first = tokens.peek();
  if (first.size() >= 3 && first.substr(first.size() - 3) == "OFF") (void)tokens.next("OFF");
  (void)tokens.count("the number of vertices", countLimit(bytes));
  (void)tokens.count("the number of faces", countLimit(bytes));
}

}  // namespace

ImportedMesh parseSurface(std::string_view bytes, const std::string& extension, const std::string& name) {
  if (bytes.empty()) throw std::invalid_argument(name + ": empty file; expected a ." + extension + " surface mesh");
  if (extension == "ply") {
    const PlyHeader header = checkPlyHeader(bytes, name);
    if (header.ascii) checkPlyAsciiBody(bytes, header, name);
  }
  if (extension == "off") checkOffCounts(bytes, name);
  Assimp::Importer importer;
  LoggedErrors errors;
  // No post-processing but Assimp's validation: its triangulation aborted the process on a
  // malformed PLY (fuzz_mesh_surface), so polygons are cut into fans here; its vertex joining
  // would also compare normals, which an STL has per face, so vertices are merged by position.
  const aiScene* scene =
      importer.ReadFileFromMemory(bytes.data(), bytes.size(), aiProcess_ValidateDataStructure, extension.c_str());
  if (scene == nullptr || scene->mRootNode == nullptr)
    throw std::invalid_argument(name + ": not a readable ." + extension + " mesh (Assimp: " +
                                oneLine(importer.GetErrorString()) + ")");
  if (!errors.first().empty())
    throw std::invalid_argument(name + ": not a valid ." + extension + " mesh (Assimp: " + oneLine(errors.first()) + ")");
  SurfaceBuilder builder{name, {}, {}, {}};
  builder.addNode(*scene, *scene->mRootNode, aiMatrix4x4(), true, extension == "obj");
  builder.mesh.format = extension;
  if (builder.mesh.triangles.empty())
    throw std::invalid_argument(name + ": no triangles; expected a surface mesh with faces");
  // A group without triangles of its own (an OBJ object holding only other groups) is no marker.
  std::erase_if(builder.mesh.markers, [](const SurfaceMarker& m) { return m.triangles.empty(); });
  finishMesh(builder.mesh, name, {});
  return std::move(builder.mesh);
}

}  // namespace hs::io
