#pragma once
// The viewer's windows laid out in an ImGui context without a window (ImGui lays out and builds
// its draw lists without rendering), and what a student would see cut in them:
// - a glyph outside the clip rectangle it was drawn under (a window's edge, a table cell's): the
//   GPU's scissor cuts it;
// - a glyph drawn smaller than it is: ImGui cut it on the CPU at a button's or a header's edge
//   (RenderTextClipped);
// - a table's header shortened with an ellipsis;
// - a window reaching out of the screen.
// A label cut exactly between two glyphs leaves no trace in the draw lists: these checks catch
// any cut that goes through a letter.
#include <imgui.h>
#include <imgui_internal.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace hs::viewer::testing {

class WindowlessImGui {
 public:
  WindowlessImGui() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // the default font, as the viewer uses
    ImGui::StyleColorsLight();
    ImGui::GetStyle().WindowRounding = 0;
    // Lines from the font texture would look like glyphs to the checks below.
    ImGui::GetStyle().AntiAliasedLinesUseTex = false;
  }
  ~WindowlessImGui() { ImGui::DestroyContext(); }
  WindowlessImGui(const WindowlessImGui&) = delete;
  WindowlessImGui& operator=(const WindowlessImGui&) = delete;

  // `count` frames (ImGui sizes windows from the frame before) of `draw` on a width x height screen.
  template <typename Draw>
  void frames(int width, int height, Draw draw, int count = 4) {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(width), float(height));
    io.DeltaTime = 1.0f / 30;
    for (int i = 0; i < count; ++i) {
      ImGui::NewFrame();
      draw();
      ImGui::Render();
    }
  }
};

// Every cut the last frame's draw lists show, one line each naming the window and where.
inline std::vector<std::string> cutText() {
  const ImGuiIO& io = ImGui::GetIO();
  const ImFont* font = io.Fonts->Fonts[0];
  // Each glyph's size on the screen, by the texture coordinates of its top-left corner and of
  // its bottom-right one (a cut keeps one of the two).
  std::map<std::pair<float, float>, ImVec2> byTopLeft, byBottomRight;
  for (const ImFontGlyph& g : font->Glyphs) {
    byTopLeft[{g.U0, g.V0}] = ImVec2(g.X1 - g.X0, g.Y1 - g.Y0);
    byBottomRight[{g.U1, g.V1}] = ImVec2(g.X1 - g.X0, g.Y1 - g.Y0);
  }
  // The whole glyph, or one that lost no more than the atlas's one pixel of empty padding around
  // each glyph (ImGui cuts the padding of a descender in a button without vertical padding).
  auto whole = [&](const ImDrawVert* quad) {
    const ImVec2 drawn(quad[2].pos.x - quad[0].pos.x, quad[2].pos.y - quad[0].pos.y);
    for (const auto* sizes : {&byTopLeft, &byBottomRight}) {
      const ImVec2 uv = sizes == &byTopLeft ? quad[0].uv : quad[2].uv;
      const auto found = sizes->find({uv.x, uv.y});
      if (found != sizes->end())
        return found->second.x - drawn.x <= 1.01f && found->second.y - drawn.y <= 1.01f;
    }
    return false;
  };
  const ImVec2 white = io.Fonts->TexUvWhitePixel;
  auto isGlyph = [&](const ImDrawVert& v) { return v.uv.x != white.x || v.uv.y != white.y; };
  std::vector<std::string> cuts;
  const ImDrawData* data = ImGui::GetDrawData();
  for (int l = 0; data && l < data->CmdListsCount; ++l) {
    const ImDrawList& list = *data->CmdLists[l];
    const std::string owner = list._OwnerName ? list._OwnerName : "?";
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      if (cmd.UserCallback || cmd.TextureId != io.Fonts->TexID) continue;
      const ImVec4 clip = cmd.ClipRect;
      // Glyphs are quads: indices (i, i+1, i+2, i, i+2, i+3) over four vertices.
      for (unsigned k = cmd.IdxOffset; k + 6 <= cmd.IdxOffset + cmd.ElemCount; k += 6) {
        const unsigned first = cmd.VtxOffset + list.IdxBuffer[int(k)];
        if (list.IdxBuffer[int(k + 3)] != list.IdxBuffer[int(k)] || first + 3 >= unsigned(list.VtxBuffer.Size)) continue;
        const ImDrawVert* quad = &list.VtxBuffer[int(first)];
        if (!isGlyph(quad[0]) || !isGlyph(quad[2])) continue;
        const ImVec2 a = quad[0].pos, c = quad[2].pos;
        constexpr float kSlack = 0.5f;  // px: pixel centres
        const bool inside = a.x >= clip.x - kSlack && a.y >= clip.y - kSlack && c.x <= clip.z + kSlack &&
                            c.y <= clip.w + kSlack;
        if (inside && whole(quad)) continue;
        cuts.push_back(owner + ": a glyph at (" + std::to_string(int(a.x)) + ", " + std::to_string(int(a.y)) +
                       (inside ? ") cut on the CPU at an item's edge" : ") outside its clip rectangle (" +
                                                                            std::to_string(int(clip.x)) + ", " +
                                                                            std::to_string(int(clip.y)) + ")-(" +
                                                                            std::to_string(int(clip.z)) + ", " +
                                                                            std::to_string(int(clip.w)) + ")"));
        if (cuts.size() > 20) return cuts;
      }
    }
  }
  // A table's header too long for its column: ImGui shortens it with an ellipsis.
  ImGuiContext& g = *GImGui;
  for (int t = 0; t < g.Tables.GetMapSize(); ++t) {
    const ImGuiTable* table = g.Tables.TryGetMapData(t);
    if (!table || table->LastFrameActive != g.FrameCount) continue;
    for (int c = 0; c < table->ColumnsCount; ++c) {
      const ImGuiTableColumn& column = table->Columns[c];
      if (column.ContentMaxXHeadersIdeal > column.MaxX + 0.5f)
        cuts.push_back(std::string(table->OuterWindow->Name) + ": the header of column " + std::to_string(c + 1) +
                       " needs " + std::to_string(int(column.ContentMaxXHeadersIdeal - column.MinX)) + " px of " +
                       std::to_string(int(column.MaxX - column.MinX)));
    }
  }
  // Windows drawn this frame reach no further than the screen.
  for (const ImGuiWindow* w : g.Windows) {
    if (!w->Active || w->Hidden || (w->Flags & ImGuiWindowFlags_ChildWindow)) continue;
    const ImVec2 max(w->Pos.x + w->Size.x, w->Pos.y + w->Size.y);
    if (w->Pos.x < -0.5f || w->Pos.y < -0.5f || max.x > io.DisplaySize.x + 0.5f || max.y > io.DisplaySize.y + 0.5f)
      cuts.push_back(std::string(w->Name) + ": reaches out of the screen to (" + std::to_string(int(max.x)) + ", " +
                     std::to_string(int(max.y)) + ")");
  }
  return cuts;
}

inline std::string joined(const std::vector<std::string>& lines) {
  std::string all;
  for (const std::string& line : lines) all += line + "\n";
  return all;
}

}  // namespace hs::viewer::testing
