// VTK XML UnstructuredGrid (.vtu; https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html):
// one <Piece> with <Points>, <Cells> (connectivity, offsets, types) and <CellData>. DataArrays
// in format "ascii" or "binary" (base64 of a byte-count header, UInt32 or UInt64 as
// header_type says, then the values, little-endian); compressed and appended data are refused.
// A small scanner of the tags heartsim needs, not a general XML parser.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>

#include "io/mesh/mesh_text.h"
#include "io/mesh/mesh_vtk_cells.h"

namespace hs::io {
namespace {

struct VtuText {
  std::string_view text;
  const std::string& name;

  long lineAt(std::size_t pos) const {
    return 1 + static_cast<long>(std::count(text.begin(), text.begin() + static_cast<long>(std::min(pos, text.size())), '\n'));
  }
  [[noreturn]] void fail(std::size_t pos, const std::string& message) const {
    throw std::invalid_argument(name + ":" + std::to_string(lineAt(pos)) + ": " + message);
  }
  // The text of the tag "<tag ...>" starting at or after `from` (up to the '>'), its position.
  std::optional<std::pair<std::string_view, std::size_t>> findTag(std::string_view tag, std::size_t from,
                                                                  std::size_t until) const {
    for (std::size_t at = text.find(tag, from); at != std::string_view::npos && at < until; at = text.find(tag, at + 1)) {
      const std::size_t after = at + tag.size();
      if (after < text.size() && (text[after] == '>' || text[after] == ' ' || text[after] == '\n' ||
                                  text[after] == '\t' || text[after] == '\r' || text[after] == '/')) {
        const std::size_t close = text.find('>', after);
        if (close == std::string_view::npos) fail(at, "tag " + std::string(tag) + " is not closed by '>' (truncated?)");
        return std::make_pair(text.substr(at, close + 1 - at), at);
      }
    }
    return std::nullopt;
  }
  // Every "<DataArray ...>" tag in [from, until), with its position.
  std::vector<std::pair<std::string_view, std::size_t>> dataArrays(std::size_t from, std::size_t until) const {
    std::vector<std::pair<std::string_view, std::size_t>> tags;
    for (auto tag = findTag("<DataArray", from, until); tag; tag = findTag("<DataArray", tag->second + 1, until))
      tags.push_back(*tag);
    return tags;
  }
};

// The value of attribute `key` in a tag's text, quoted with " or '.
std::optional<std::string_view> attribute(std::string_view tag, std::string_view key) {
  for (std::size_t at = tag.find(key); at != std::string_view::npos; at = tag.find(key, at + 1)) {
    const std::size_t eq = at + key.size();
    if (at == 0 || static_cast<unsigned char>(tag[at - 1]) > ' ' || eq + 1 >= tag.size() || tag[eq] != '=') continue;
    const char quote = tag[eq + 1];
    if (quote != '"' && quote != '\'') continue;
    const std::size_t end = tag.find(quote, eq + 2);
    if (end == std::string_view::npos) return std::nullopt;
    return tag.substr(eq + 2, end - eq - 2);
  }
  return std::nullopt;
}

int base64Value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

// Base64 decoded by groups of four characters; a group with padding ends a block and the next
// group starts another, so the header and data encoded separately (VTK) or together decode alike.
std::optional<std::vector<std::uint8_t>> decodeBase64(std::string_view text) {
  std::vector<std::uint8_t> bytes;
  int group[4];
  int filled = 0, padding = 0;
  for (char c : text) {
    if (static_cast<unsigned char>(c) <= ' ') continue;
    if (c == '=') {
      if (filled < 2) return std::nullopt;
      group[filled++] = 0;
      ++padding;
    } else {
      const int v = base64Value(c);
      if (v < 0 || padding > 0) return std::nullopt;
      group[filled++] = v;
    }
    if (filled == 4) {
      const std::uint32_t triple = (std::uint32_t(group[0]) << 18) | (std::uint32_t(group[1]) << 12) |
                                   (std::uint32_t(group[2]) << 6) | std::uint32_t(group[3]);
      const std::uint8_t out[3] = {std::uint8_t(triple >> 16), std::uint8_t(triple >> 8), std::uint8_t(triple)};
      bytes.insert(bytes.end(), out, out + 3 - padding);
      filled = padding = 0;
    }
  }
  if (filled != 0) return std::nullopt;
  return bytes;
}

template <typename T>
double loadAs(const std::uint8_t* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  return static_cast<double>(value);
}

struct ArrayType {
  std::size_t size;
  double (*load)(const std::uint8_t*);
};

std::optional<ArrayType> arrayType(std::string_view type) {
  if (type == "Float32") return ArrayType{4, loadAs<float>};
  if (type == "Float64") return ArrayType{8, loadAs<double>};
  if (type == "Int8") return ArrayType{1, loadAs<std::int8_t>};
  if (type == "UInt8") return ArrayType{1, loadAs<std::uint8_t>};
  if (type == "Int16") return ArrayType{2, loadAs<std::int16_t>};
  if (type == "UInt16") return ArrayType{2, loadAs<std::uint16_t>};
  if (type == "Int32") return ArrayType{4, loadAs<std::int32_t>};
  if (type == "UInt32") return ArrayType{4, loadAs<std::uint32_t>};
  if (type == "Int64") return ArrayType{8, loadAs<std::int64_t>};
  if (type == "UInt64") return ArrayType{8, loadAs<std::uint64_t>};
  return std::nullopt;
}

struct DataArray {
  std::string name;
  long components = 1;
  std::vector<double> values;
  std::size_t position = 0;
};

struct VtuReader {
  VtuText vtu;
  std::size_t headerSize = 4;  // header_type UInt32 (VTK's default) or UInt64

  DataArray read(std::string_view tag, std::size_t at, std::size_t expectedTuples) const {
    DataArray array;
    array.position = at;
    array.name = std::string(attribute(tag, "Name").value_or(""));
    const std::string label = "DataArray '" + excerpt(array.name) + "'";
    const std::string_view typeName = attribute(tag, "type").value_or("");
    const std::optional<ArrayType> type = arrayType(typeName);
    if (!type) vtu.fail(at, label + " has type '" + excerpt(typeName) + "'; expected Float32, Float64 or an integer type");
    if (const auto components = attribute(tag, "NumberOfComponents")) {
      const std::string text(*components);
      if (text.empty() || text.size() > 2 || !std::all_of(text.begin(), text.end(), ::isdigit) || std::stol(text) < 1)
        vtu.fail(at, label + ": NumberOfComponents '" + excerpt(*components) + "', expected 1 to 99");
      array.components = std::stol(text);
    }
    const std::string_view format = attribute(tag, "format").value_or("ascii");
    const std::size_t bodyStart = at + tag.size();
    const std::size_t bodyEnd = tag.size() >= 2 && tag[tag.size() - 2] == '/'
                                    ? bodyStart
                                    : vtu.text.find("</DataArray>", bodyStart);
    if (bodyEnd == std::string_view::npos) vtu.fail(at, label + " has no </DataArray> (truncated?)");
    const std::string_view body = vtu.text.substr(bodyStart, bodyEnd - bodyStart);
    const std::size_t count = expectedTuples * static_cast<std::size_t>(array.components);
    if (format == "ascii") {
      MeshTokens tokens(body, vtu.name, '\0', vtu.lineAt(bodyStart));
      array.values.reserve(std::min(count, body.size()));
      for (std::size_t i = 0; i < count; ++i) array.values.push_back(tokens.real("a value of " + label));
      if (!tokens.atEnd()) tokens.fail("more values in " + label + " than the " + std::to_string(count) + " expected");
    } else if (format == "binary") {
      const auto bytes = decodeBase64(body);
      if (!bytes) vtu.fail(bodyStart, label + ": the binary data is not valid base64");
      if (bytes->size() < headerSize) vtu.fail(bodyStart, label + ": binary data shorter than its byte-count header");
      const double declared = headerSize == 4 ? loadAs<std::uint32_t>(bytes->data()) : loadAs<std::uint64_t>(bytes->data());
      const double needed = double(count) * double(type->size);
      if (declared != needed || static_cast<double>(bytes->size() - headerSize) < needed)
        vtu.fail(bodyStart, label + ": " + std::to_string(bytes->size() - headerSize) + " bytes of data, header says " +
                                std::to_string(static_cast<long long>(declared)) + "; expected " +
                                std::to_string(static_cast<long long>(needed)));
      array.values.resize(count);
      for (std::size_t i = 0; i < count; ++i) array.values[i] = type->load(bytes->data() + headerSize + i * type->size);
    } else {
      vtu.fail(at, label + " has format '" + excerpt(format) + "'; expected ascii or binary (appended data is not supported)");
    }
    return array;
  }

  // The DataArrays between "<section" and "</section>"; nothing when the section is absent.
  std::vector<DataArray> section(std::string_view sectionTag, std::size_t from, std::size_t until,
                                 std::size_t tuples, bool required) const {
    const auto open = vtu.findTag(sectionTag, from, until);
    if (!open) {
      if (required) vtu.fail(from, "expected a " + std::string(sectionTag) + "> section in the Piece");
      return {};
    }
    const std::string closeTag = "</" + std::string(sectionTag.substr(1)) + ">";
    const std::size_t end = vtu.text.find(closeTag, open->second);
    if (end == std::string_view::npos) vtu.fail(open->second, "expected " + closeTag + " (truncated?)");
    std::vector<DataArray> arrays;
    for (const auto& [tag, at] : vtu.dataArrays(open->second, end)) arrays.push_back(read(tag, at, tuples));
    return arrays;
  }
};

const DataArray& named(const std::vector<DataArray>& arrays, std::string_view name, const VtuText& vtu, std::size_t at) {
  for (const DataArray& a : arrays)
    if (a.name == name) return a;
  vtu.fail(at, "expected a DataArray Name=\"" + std::string(name) + "\" in <Cells>");
}

std::vector<long long> wholeNumbers(const DataArray& array, const VtuText& vtu) {
  std::vector<long long> out;
  out.reserve(array.values.size());
  for (double v : array.values) {
    if (!(v == std::floor(v) && std::abs(v) < 9e15))
      vtu.fail(array.position, "DataArray '" + array.name + "' holds " + std::to_string(v) + "; expected whole numbers");
    out.push_back(static_cast<long long>(v));
  }
  return out;
}

}  // namespace

ImportedMesh parseVtu(std::string_view text, const std::string& name) {
  VtuReader reader{VtuText{text, name}};
  const VtuText& vtu = reader.vtu;
  const auto file = vtu.findTag("<VTKFile", 0, text.size());
  if (!file) vtu.fail(0, "expected a <VTKFile type=\"UnstructuredGrid\"> element");
  if (attribute(file->first, "type").value_or("") != "UnstructuredGrid")
    vtu.fail(file->second, "VTKFile type '" + excerpt(attribute(file->first, "type").value_or("")) + "'; expected UnstructuredGrid");
  if (attribute(file->first, "compressor"))
    vtu.fail(file->second, "compressed .vtu (" + excerpt(*attribute(file->first, "compressor")) +
                               ") is not supported; expected uncompressed ascii or binary data");
  if (attribute(file->first, "byte_order").value_or("LittleEndian") != "LittleEndian")
    vtu.fail(file->second, "byte_order must be LittleEndian");
  const std::string_view headerType = attribute(file->first, "header_type").value_or("UInt32");
  if (headerType != "UInt32" && headerType != "UInt64")
    vtu.fail(file->second, "header_type '" + excerpt(headerType) + "'; expected UInt32 or UInt64");
  reader.headerSize = headerType == "UInt64" ? 8 : 4;
  const auto piece = vtu.findTag("<Piece", file->second, text.size());
  if (!piece) vtu.fail(file->second, "expected a <Piece> element (truncated?)");
  if (vtu.findTag("<Piece", piece->second + 1, text.size())) vtu.fail(piece->second, "more than one <Piece>; expected one");
  auto countAttribute = [&](std::string_view key) {
    const std::string value(attribute(piece->first, key).value_or(""));
    if (value.empty() || value.size() > 10 || !std::all_of(value.begin(), value.end(), ::isdigit))
      vtu.fail(piece->second, "Piece " + std::string(key) + " '" + excerpt(value) + "'; expected a count");
    const auto n = static_cast<std::size_t>(std::stoll(value));
    if (n > text.size()) vtu.fail(piece->second, "Piece " + std::string(key) + " " + value + " is larger than the file");
    return n;
  };
  const std::size_t points = countAttribute("NumberOfPoints"), cellCount = countAttribute("NumberOfCells");
  const std::size_t pieceEnd = text.find("</Piece>", piece->second);
  if (pieceEnd == std::string_view::npos) vtu.fail(piece->second, "expected </Piece> (truncated?)");

  ImportedMesh mesh;
  const std::vector<DataArray> pointArrays = reader.section("<Points", piece->second, pieceEnd, points, true);
  if (pointArrays.size() != 1 || pointArrays[0].components != 3)
    vtu.fail(piece->second, "expected one DataArray of 3 components in <Points>");
  for (std::size_t i = 0; i < points; ++i) {
    const double* p = &pointArrays[0].values[3 * i];
    const pbd::Vec3 v(static_cast<pbd::Real>(p[0]), static_cast<pbd::Real>(p[1]), static_cast<pbd::Real>(p[2]));
    if (!v.allFinite()) vtu.fail(pointArrays[0].position, "point " + std::to_string(i) + " is not finite; expected finite coordinates");
    mesh.vertices.push_back(v);
  }
  // Cells: the three arrays have different lengths, read one by one.
  const auto cellsTag = vtu.findTag("<Cells", piece->second, pieceEnd);
  if (!cellsTag) vtu.fail(piece->second, "expected a <Cells> section in the Piece");
  const std::size_t cellsEnd = text.find("</Cells>", cellsTag->second);
  if (cellsEnd == std::string_view::npos) vtu.fail(cellsTag->second, "expected </Cells> (truncated?)");
  std::vector<DataArray> cellArrays;
  for (const char* arrayName : {"offsets", "types"}) {
    for (const auto& [tag, at] : vtu.dataArrays(cellsTag->second, cellsEnd))
      if (attribute(tag, "Name").value_or("") == arrayName) cellArrays.push_back(reader.read(tag, at, cellCount));
  }
  VtkCells cells;
  cells.offsets = wholeNumbers(named(cellArrays, "offsets", vtu, cellsTag->second), vtu);
  cells.types = wholeNumbers(named(cellArrays, "types", vtu, cellsTag->second), vtu);
  cells.offsets.insert(cells.offsets.begin(), 0);  // VTK stores the ends; a start of 0 first
  const long long connectivitySize = cells.offsets.back();
  if (connectivitySize < 0 || static_cast<std::size_t>(connectivitySize) > text.size())
    vtu.fail(cellsTag->second, "the last offset " + std::to_string(connectivitySize) + " is not a plausible connectivity size");
  for (const auto& [tag, at] : vtu.dataArrays(cellsTag->second, cellsEnd))
    if (attribute(tag, "Name").value_or("") == "connectivity")
      cellArrays.push_back(reader.read(tag, at, static_cast<std::size_t>(connectivitySize)));
  cells.connectivity = wholeNumbers(named(cellArrays, "connectivity", vtu, cellsTag->second), vtu);
  for (const DataArray& array : reader.section("<CellData", piece->second, pieceEnd, cellCount, false))
    if (array.components == 1) cells.cellData.emplace_back(array.name, array.values);
  const bool binary = text.find("format=\"binary\"") != std::string_view::npos;
  mesh.format = binary ? "vtu binary" : "vtu ascii";
  assembleVtkCells(mesh, cells, name);
  return mesh;
}

}  // namespace hs::io
