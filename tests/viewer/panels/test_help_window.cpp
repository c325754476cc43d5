// The Help window's pages, chosen as a student chooses them: each shows its own page. Drawn in an
// ImGui context without a window (as test_panel_layout.cpp), with the mouse fed through ImGui's
// input: what the page shows is the table submitted in the last frame.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <string>

#include "viewer/panels/help_window.h"

namespace hs::viewer {
namespace {

class HelpWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(1280, 800);
    io.DeltaTime = 1.0f / 30;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  }
  void TearDown() override { ImGui::DestroyContext(); }

  void frame() {
    ImGui::NewFrame();
    bool open = true;
    drawHelpWindow(open, m_page, 1280, 800);
    ImGui::Render();
  }

  // The centre of the page button labelled `label`: the buttons stand in one row from the
  // window's first content position, each its label's width plus the frame padding wide.
  static ImVec2 buttonCentre(const char* label) {
    const ImGuiWindow* window = ImGui::FindWindowByName("Help");
    if (!window) {
      ADD_FAILURE() << "no Help window";
      return ImVec2(0, 0);
    }
    const ImGuiStyle& style = ImGui::GetStyle();
    float x = window->DC.CursorStartPos.x;
    for (const char* page : {"The numbers", "Colours", "Controls", "Mouse and keys"}) {
      const float width = ImGui::CalcTextSize(page).x + 2 * style.FramePadding.x;
      if (std::string(page) == label)
        return ImVec2(x + width / 2, window->DC.CursorStartPos.y + ImGui::GetFrameHeight() / 2);
      x += width + style.ItemSpacing.x;
    }
    ADD_FAILURE() << "no page " << label;
    return ImVec2(0, 0);
  }

  int m_page = 0;

  // The header of the third column (or "two columns") of the table drawn in the last frame.
  static std::string pageShown() {
    ImGuiContext& g = *GImGui;
    std::string shown = "none";
    for (int i = 0; i < g.Tables.GetMapSize(); ++i) {
      ImGuiTable* table = g.Tables.TryGetMapData(i);
      if (!table || table->LastFrameActive != g.FrameCount) continue;
      shown = table->ColumnsCount == 2 ? std::string("two columns") : std::string(ImGui::TableGetColumnName(table, 2));
    }
    return shown;
  }

  void click(const char* label, bool moveFirst = true) {
    ImGuiIO& io = ImGui::GetIO();
    const ImVec2 at = buttonCentre(label);
    io.MousePos = at;  // ImGui 1.86 (Debian's) reads the mouse's state, not a queue of events
    if (moveFirst) frame();
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    for (int i = 0; i < 3; ++i) frame();
  }
};

TEST_F(HelpWindow, EveryPageButtonShowsItsOwnPage) {
  for (int i = 0; i < 3; ++i) frame();
  EXPECT_EQ(pageShown(), "normal (adult, rest)");  // the numbers first
  click("Colours");
  EXPECT_EQ(pageShown(), "");
  click("Controls");
  EXPECT_EQ(pageShown(), "then");
  click("Mouse and keys");
  EXPECT_EQ(pageShown(), "two columns");
  click("The numbers");
  EXPECT_EQ(pageShown(), "normal (adult, rest)");
}

// A pointer that jumps onto a page's button and clicks at once, between two frames (a tap on a
// touch screen, a scripted click), chooses it too: with ImGui's tab bar it did not (the tab lit
// up, the page stayed).
TEST_F(HelpWindow, ATapOnAPageButtonShowsItsPage) {
  for (int i = 0; i < 3; ++i) frame();
  click("Controls", false);
  EXPECT_EQ(pageShown(), "then");
  click("Colours", false);
  EXPECT_EQ(pageShown(), "");
}

}  // namespace
}  // namespace hs::viewer
