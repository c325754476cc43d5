// Legacy VTK, ASCII DATASET UNSTRUCTURED_GRID (https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html):
// POINTS, CELLS (the classic "n size" list of "k i0 .. ik-1", or version 5's OFFSETS and
// CONNECTIVITY), CELL_TYPES, and CELL_DATA arrays (SCALARS, FIELD) as markers. POINT_DATA is
// read past. BINARY files are refused.
#include <algorithm>
#include <stdexcept>

#include "io/mesh/mesh_text.h"
#include "io/mesh/mesh_vtk_cells.h"

namespace hs::io {
namespace {

struct LegacyReader {
  MeshTokens tokens;
  long long limit;

  std::vector<double> numbers(long long count, const std::string& what) {
    std::vector<double> values;
    values.reserve(static_cast<std::size_t>(std::min(count, limit)));
    for (long long i = 0; i < count; ++i) values.push_back(tokens.real(what));
    return values;
  }

  std::vector<long long> integers(long long count, const std::string& what) {
    std::vector<long long> values;
    values.reserve(static_cast<std::size_t>(std::min(count, limit)));
    for (long long i = 0; i < count; ++i) values.push_back(tokens.integer(what));
    return values;
  }

  // CELLS n size: version <= 4 lists each cell as "k i0 .. ik-1"; version 5 gives
  // "CELLS offsets connectivity" and then OFFSETS type / CONNECTIVITY type arrays.
  void cellsSection(VtkCells& cells) {
    const long long first = tokens.count("the number of cells", limit);
    const long long second = tokens.count("the size of the cell list", limit);
    if (tokens.peek() == "OFFSETS") {
      tokens.expect("OFFSETS");
      (void)tokens.next("the offsets' type");
      cells.offsets = integers(first, "a cell offset");
      tokens.expect("CONNECTIVITY");
      (void)tokens.next("the connectivity's type");
      cells.connectivity = integers(second, "a point index");
      if (first == 0) tokens.fail("expected at least one offset (cells + 1)");
      if (cells.offsets.front() != 0) tokens.fail("expected the first offset to be 0");
      return;
    }
    cells.offsets.push_back(0);
    long long used = 0;
    for (long long c = 0; c < first; ++c) {
      const long long k = tokens.count("the number of points of a cell", 1000);
      used += k + 1;
      if (used > second) tokens.fail("cell " + std::to_string(c) + " goes past the size " + std::to_string(second) + " given by CELLS");
      for (long long i = 0; i < k; ++i) cells.connectivity.push_back(tokens.integer("a point index"));
      cells.offsets.push_back(static_cast<long long>(cells.connectivity.size()));
    }
    if (used != second) tokens.fail("the cells use " + std::to_string(used) + " numbers; CELLS said " + std::to_string(second));
  }

  // One attribute block of CELL_DATA or POINT_DATA with `tuples` entries; cell-data scalars and
  // field arrays of one component are kept.
  void attribute(std::string_view keyword, long long tuples, std::vector<std::pair<std::string, std::vector<double>>>* keep) {
    if (keyword == "SCALARS") {
      const std::string name(tokens.next("an array name"));
      (void)tokens.next("a data type");
      long long components = 1;
      if (tokens.peek() != "LOOKUP_TABLE") components = tokens.count("the number of components (1 to 4)", 4);
      if (components < 1) tokens.fail("expected 1 to 4 components, got 0");
      tokens.expect("LOOKUP_TABLE");
      (void)tokens.next("a lookup table name");
      std::vector<double> values = numbers(tuples * components, "a value of " + excerpt(name));
      if (keep != nullptr && components == 1) keep->emplace_back(name, std::move(values));
    } else if (keyword == "VECTORS" || keyword == "NORMALS") {
      (void)tokens.next("an array name");
      (void)tokens.next("a data type");
      (void)numbers(3 * tuples, "a vector component");
    } else if (keyword == "LOOKUP_TABLE") {
      (void)tokens.next("a lookup table name");
      (void)numbers(4 * tokens.count("the table size", limit), "a colour component");
    } else if (keyword == "FIELD") {
      (void)tokens.next("a field name");
      const long long arrays = tokens.count("the number of field arrays", limit);
      for (long long a = 0; a < arrays; ++a) {
        const std::string name(tokens.next("an array name"));
        const long long components = tokens.count("the number of components", 1000);
        const long long count = tokens.count("the number of tuples", limit);
        (void)tokens.next("a data type");
        if (count * components > limit) tokens.fail("array " + excerpt(name) + " is larger than the file");
        std::vector<double> values = numbers(count * components, "a value of " + excerpt(name));
        if (keep != nullptr && components == 1 && count == tuples) keep->emplace_back(name, std::move(values));
      }
    } else {
      tokens.fail("expected SCALARS, VECTORS, NORMALS, FIELD, LOOKUP_TABLE, CELL_DATA or POINT_DATA, got '" +
                  excerpt(keyword) + "'");
    }
  }
};

}  // namespace

ImportedMesh parseLegacyVtk(std::string_view text, const std::string& name) {
  LegacyReader reader{MeshTokens(text, name), static_cast<long long>(text.size())};
  MeshTokens& tokens = reader.tokens;
  const std::string_view magic = tokens.restOfLine();
  if (magic.rfind("# vtk DataFile Version", 0) != 0)
    tokens.fail("expected '# vtk DataFile Version x.x', got '" + excerpt(magic) + "'");
  (void)tokens.restOfLine();  // title
  const std::string_view encoding = tokens.next("ASCII or BINARY");
  if (encoding == "BINARY") tokens.fail("binary legacy .vtk is not supported; expected ASCII");
  if (encoding != "ASCII") tokens.fail("expected ASCII, got '" + excerpt(encoding) + "'");
  tokens.expect("DATASET");
  const std::string_view dataset = tokens.next("a dataset type");
  if (dataset != "UNSTRUCTURED_GRID") tokens.fail("expected UNSTRUCTURED_GRID, got '" + excerpt(dataset) + "'");

  ImportedMesh mesh;
  mesh.format = "vtk legacy ascii";
  VtkCells cells;
  bool sawPoints = false, sawCells = false, sawTypes = false;
  long long tuples = 0;
  bool inCellData = false;
  while (!tokens.atEnd()) {
    const std::string_view keyword = tokens.next("a section keyword");
    if (keyword == "POINTS") {
      const long long n = tokens.count("the number of points", reader.limit);
      (void)tokens.next("the points' data type");
      mesh.vertices.reserve(static_cast<std::size_t>(n));
      for (long long i = 0; i < n; ++i) mesh.vertices.push_back(tokens.point("point coordinates"));
      sawPoints = true;
    } else if (keyword == "CELLS") {
      reader.cellsSection(cells);
      sawCells = true;
    } else if (keyword == "CELL_TYPES") {
      cells.types = reader.integers(tokens.count("the number of cell types", reader.limit), "a cell type");
      if (cells.types.size() + 1 != cells.offsets.size())
        tokens.fail(std::to_string(cells.types.size()) + " cell types; expected one per cell, " +
                    std::to_string(cells.offsets.size() - (cells.offsets.empty() ? 0 : 1)));
      sawTypes = true;
    } else if (keyword == "CELL_DATA" || keyword == "POINT_DATA") {
      tuples = tokens.count("the number of tuples", reader.limit);
      inCellData = keyword == "CELL_DATA";
      if (inCellData && tuples + 1 != static_cast<long long>(cells.offsets.size()))
        tokens.fail("CELL_DATA " + std::to_string(tuples) + "; expected the number of cells");
    } else if (keyword == "METADATA") {
      tokens.fail("METADATA blocks are not supported; expected plain VTK 4 or 5 data");
    } else {
      if (tuples == 0 && !inCellData && keyword != "FIELD") tokens.fail("expected POINTS, CELLS, CELL_TYPES, CELL_DATA or POINT_DATA, got '" + excerpt(keyword) + "'");
      reader.attribute(keyword, tuples, inCellData ? &cells.cellData : nullptr);
    }
  }
  if (!sawPoints || !sawCells || !sawTypes)
    tokens.fail(std::string("expected POINTS, CELLS and CELL_TYPES; the file ends without ") +
                (!sawPoints ? "POINTS" : !sawCells ? "CELLS" : "CELL_TYPES") + " (truncated?)");
  assembleVtkCells(mesh, cells, name);
  return mesh;
}

}  // namespace hs::io
