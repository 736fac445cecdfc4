// The shader panel in process (Qt's QTest on an Xvfb of the test's own,
// viewer.cxx): it shows the GLSL that runs and highlights the lines that
// the generator marked for each term and effect; its stages can be edited
// and applied (the hands-on), a refused edit marked at its lines while the
// program before keeps drawing, reverted and saved.
#include "desktop/inspector_window.h"
#include "in_process.h"
#include "settings/command_line.h"
#include "viewer.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkWindowToImageFilter.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTabWidget>
#include <QTest>
#include <QTextCursor>
#include <QTextDocument>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>

using namespace shadelab;
using namespace shadelab_test;

namespace
{
// The lines (0-based) of source that end in the generator's marker naming
// term ("": any term).
std::set<int> MarkedLines(const std::string& source, const std::string& term)
{
  static const std::regex marker(
    "// shadelab: ((ambient|diffuse|specular)(, (ambient|diffuse|specular))*)$");
  std::set<int> lines;
  std::istringstream in(source);
  std::string line;
  std::smatch match;
  for (int n = 0; std::getline(in, line); ++n)
  {
    if (std::regex_search(line, match, marker) && match[1].str().find(term) != std::string::npos)
    {
      lines.insert(n);
    }
  }
  return lines;
}
}

TEST(ShaderPanel, ShowsTheGlslThatRunsAndHighlightsTheLinesOfEachTerm)
{
  Inspector inspector(SpotView(Shading::Gouraud), "shadelab view");
  ASSERT_EQ(inspector.Load(), 0);
  const auto application = MakeApplication();
  InspectorWindow window(inspector);
  ASSERT_TRUE(window.Open({ 240, 180 }));
  const auto* vertex = window.findChild<QPlainTextEdit*>("vertex source");
  const auto* fragment = window.findChild<QPlainTextEdit*>("fragment source");
  const auto* tabs = window.findChild<QTabWidget*>();
  ASSERT_TRUE(vertex && fragment && tabs);
  // The code that computes each term: its lines are the marked ones.
  const std::map<std::string, std::vector<std::string>> computes{
    { "ambient", { "shadelabKa * shadelabIa" } },
    { "diffuse", { "NdotL * shadelabKd", "Il * term" } },
    { "specular", { "d = shadelabSpecularD(", "* shadelabKs", "Il * term" } },
  };
  const TempDir dir;
  for (const Shading rule : { Shading::Gouraud, Shading::Phong })
  {
    SCOPED_TRACE(ToString(rule));
    if (rule == Shading::Phong)
    {
      QTest::keyClick(window.findChild<QComboBox*>("rule"), Qt::Key_Down); // gouraud, phong
    }
    ASSERT_EQ(inspector.GetState().Scene.ShadingRule, rule);
    // What `render --dump-shaders` writes for the picture the view shows
    // (in floats: an 8-bit file's program ends with the capture's
    // quantisation step, which the window leaves to its framebuffer).
    std::vector<std::string> args{ "render", TestMesh("teapot.obj").string(), "-o",
      (dir / "picture.exr").string(), "--dump-shaders", dir.path().string() };
    const std::vector<std::string> scene = SceneArguments(inspector.ShownScene());
    args.insert(args.end(), scene.begin(), scene.end());
    const RunResult run = RunShadelab(args);
    ASSERT_EQ(run.ExitCode, 0) << run.Stderr;
    const std::string dumped = dir / (std::string(ToString(rule)) + "-blinn");
    EXPECT_EQ(vertex->toPlainText().toStdString(), Slurp(dumped + ".vert"));
    EXPECT_EQ(fragment->toPlainText().toStdString(), Slurp(dumped + ".frag"));

    // Gouraud lights in the vertex stage, phong in the fragment stage.
    const bool perVertex = rule == Shading::Gouraud;
    const auto* lit = perVertex ? vertex : fragment;
    const auto* unlit = perVertex ? fragment : vertex;
    const std::string source = lit->toPlainText().toStdString();
    EXPECT_NE(source.find("shadelabIlluminate("), std::string::npos);
    EXPECT_EQ(unlit->toPlainText().toStdString().find("shadelabIlluminate("), std::string::npos);
    for (const char* term : { "ambient", "diffuse", "specular", "total" })
    {
      window.findChild<QPushButton*>(QString("highlight ") + term)->click();
      const bool all = std::string(term) == "total";
      const std::set<int> marked = MarkedLines(source, all ? "" : term);
      ASSERT_FALSE(marked.empty()) << term;
      if (!all)
      {
        EXPECT_EQ(marked, LinesWith(source, computes.at(term)))
          << term << ": marked where computed";
        EXPECT_EQ(tabs->currentWidget(), lit) << term;
        EXPECT_EQ(lit->textCursor().blockNumber(), *marked.begin()) << term << ": shown first";
      }
      EXPECT_EQ(Highlighted(lit), marked) << term;
      EXPECT_TRUE(Highlighted(unlit).empty()) << term;
    }
  }
}

// An effect's lines are marked, and its button enabled, only where the
// program has them: none before `on`, `count` in the fragment stage after
// it, highlighted by the button, and none again after `off`.
void ExpectMarkedOnlyWhenUsed(InspectorWindow& window, const std::string& effect,
  const std::function<void()>& on, std::size_t count, const std::function<void()>& off)
{
  SCOPED_TRACE(effect);
  const auto* fragment = window.findChild<QPlainTextEdit*>("fragment source");
  auto* button = window.findChild<QPushButton*>(QString::fromStdString("highlight " + effect));
  ASSERT_TRUE(fragment && button);
  const auto marked = [fragment, &effect]
  { return LinesWith(fragment->toPlainText().toStdString(), { "// shadelab: " + effect }); };
  EXPECT_TRUE(marked().empty());
  EXPECT_FALSE(button->isEnabled());
  on();
  const std::set<int> lines = marked();
  EXPECT_EQ(lines.size(), count);
  EXPECT_TRUE(button->isEnabled());
  button->click();
  EXPECT_EQ(Highlighted(fragment), lines);
  off();
  EXPECT_TRUE(marked().empty()) << "switched off, it compiles to no code";
  EXPECT_FALSE(button->isEnabled());
}

// Attenuation's line is in the stage that lights, once per point or spot
// light (phong: the fragment stage); 1, 0, 0 is none.
TEST(ShaderPanel, MarksTheAttenuationOnlyWhereTheSceneHasIt)
{
  Inspector inspector(SpotView(Shading::Phong), "shadelab view");
  ASSERT_EQ(inspector.Load(), 0);
  const auto application = MakeApplication();
  InspectorWindow window(inspector);
  ASSERT_TRUE(window.Open({ 240, 180 }));
  auto* c1 = window.findChild<QDoubleSpinBox*>("attenuation c1");
  ExpectMarkedOnlyWhenUsed(
    window, "attenuation", [c1] { Type(c1, "0.25"); }, 1, [c1] { Type(c1, "0"); });
}

// Fog's lines are the fragment stage's last under every rule: the depth,
// the factor, the colour.
TEST(ShaderPanel, MarksTheFogOnlyWhereTheSceneHasIt)
{
  Inspector inspector(SpotView(Shading::Gouraud), "shadelab view");
  ASSERT_EQ(inspector.Load(), 0);
  const auto application = MakeApplication();
  InspectorWindow window(inspector);
  ASSERT_TRUE(window.Open({ 240, 180 }));
  auto* mode = window.findChild<QComboBox*>("fog");
  ExpectMarkedOnlyWhenUsed(
    window, "fog",
    [&]
    {
      QTest::keyClick(mode, Qt::Key_End); // exp2
      ASSERT_EQ(inspector.GetState().Scene.Fogging.Mode, FogMode::Exp2);
      EXPECT_GT(inspector.GetState().Scene.Fogging.Density, 0) << "seeded from the camera";
    },
    3, [mode] { QTest::keyClick(mode, Qt::Key_Home); }); // none
}

namespace
{
// The upper half of the window's pixels (above the HUD, whose ms/frame
// changes from frame to frame), as the last frame drew them.
std::vector<unsigned char> UpperPixels(Inspector& inspector)
{
  QApplication::processEvents(); // the view's frame drawn
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(inspector.GetWindow());
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  const int* size = image->GetDimensions();
  const auto* rgb = static_cast<const unsigned char*>(image->GetScalarPointer());
  const std::size_t row = static_cast<std::size_t>(size[0]) * 3;
  return { rgb + row * (size[1] / 2), rgb + row * size[1] }; // rows from the bottom
}

// How many channel values of b are below a's, and how many above.
std::pair<int, int> DarkerBrighter(
  const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  int darker = 0, brighter = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    darker += b[i] < a[i];
    brighter += b[i] > a[i];
  }
  return { darker, brighter };
}

// Replaces the first `text` in edit as typing would (the document marked
// edited); fails the test where it is not there.
void EditText(QPlainTextEdit* edit, const QString& text, const QString& by)
{
  QTextCursor found = edit->document()->find(text);
  ASSERT_FALSE(found.isNull()) << text.toStdString();
  found.insertText(by);
}

std::vector<std::string> Items(const QListWidget* list)
{
  std::vector<std::string> items;
  for (int i = 0; i < list->count(); ++i)
  {
    items.push_back(list->item(i)->text().toStdString());
  }
  return items;
}

// The current folder, changed for a test's life: Save writes new stage
// files there, as the screenshot key does.
class InFolder
{
public:
  explicit InFolder(const std::filesystem::path& path)
    : Before(std::filesystem::current_path())
  {
    std::filesystem::current_path(path);
  }
  ~InFolder() { std::filesystem::current_path(this->Before); }

private:
  std::filesystem::path Before;
};
}

// The hands-on in the window: a student halves the diffuse term in phong's
// fragment stage and applies it (Ctrl+Return): the program that runs is the
// edit, and the picture darkens. A syntax error in either stage is listed
// and marked at its line, the edit stays in the panel, and the edit before
// keeps drawing, pixel for pixel. Save writes the stage through the one way
// files are written and the render command names it; Revert draws the
// generated stages again, pixel for pixel.
TEST(ShaderPanel, AppliesAnEditKeepsDrawingThroughARefusedOneSavesAndReverts)
{
  const TempDir dir;
  const InFolder in(dir.path());
  Inspector inspector(SpotView(Shading::Phong), "shadelab view");
  ASSERT_EQ(inspector.Load(), 0);
  const auto application = MakeApplication();
  InspectorWindow window(inspector);
  ASSERT_TRUE(window.Open({ 240, 180 }));
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  auto* vertex = window.findChild<QPlainTextEdit*>("vertex source");
  auto* fragment = window.findChild<QPlainTextEdit*>("fragment source");
  auto* apply = window.findChild<QPushButton*>("apply stages");
  auto* errors = window.findChild<QListWidget*>("stage errors");
  ASSERT_TRUE(vertex && fragment && apply && errors);
  const ShaderSources generated = inspector.GetShownShaders();
  const std::vector<unsigned char> before = UpperPixels(inspector);

  EditText(fragment, "NdotL * shadelabKd", "0.5 * NdotL * shadelabKd");
  const std::string halved = fragment->toPlainText().toStdString();
  QTest::keyClick(fragment, Qt::Key_Return, Qt::ControlModifier);
  EXPECT_TRUE(Items(errors).empty());
  EXPECT_EQ(inspector.GetState().Stages.Fragment, halved);
  EXPECT_TRUE(inspector.GetState().Stages.Vertex.empty()) << "the vertex stage was not edited";
  EXPECT_EQ(inspector.GetShownShaders().Fragment, halved);
  EXPECT_EQ(inspector.GetShownShaders().Vertex, generated.Vertex);
  const std::vector<unsigned char> edited = UpperPixels(inspector);
  const auto [darker, brighter] = DarkerBrighter(before, edited);
  EXPECT_GT(darker, 1000) << "half the diffuse term";
  EXPECT_EQ(brighter, 0);

  // A syntax error in each stage: listed and marked at its line; the edit
  // before keeps drawing.
  for (QPlainTextEdit* stage : { fragment, vertex })
  {
    const bool isFragment = stage == fragment;
    SCOPED_TRACE(isFragment ? "fragment" : "vertex");
    EditText(stage, "void main()", "oops; void main()");
    const int line = static_cast<int>(
      *LinesWith(stage->toPlainText().toStdString(), { "oops;" }).begin()); // 0-based
    apply->click();
    const std::vector<std::string> listed = Items(errors);
    ASSERT_FALSE(listed.empty());
    const std::string at =
      std::string(isFragment ? "fragment" : "vertex") + ", line " + std::to_string(line + 1) + ": ";
    EXPECT_EQ(listed.front().rfind(at, 0), 0u) << listed.front();
    EXPECT_TRUE(Highlighted(stage).count(line)) << "marked at its line";
    EXPECT_NE(stage->toPlainText().indexOf("oops;"), -1) << "the edit stays to be mended";
    EXPECT_EQ(inspector.GetState().Stages.Fragment, halved);
    EXPECT_EQ(inspector.GetShownShaders().Fragment, halved);
    EXPECT_EQ(inspector.GetShownShaders().Vertex, generated.Vertex);
    EXPECT_EQ(UpperPixels(inspector), edited) << "the last good program draws";
    EditText(stage, "oops; ", "");
  }

  // Saved through the one way files are written; the command names the file.
  window.findChild<QPushButton*>("save stages")->click();
  const std::filesystem::path saved = dir / "shadelab-teapot-001.frag";
  ASSERT_TRUE(std::filesystem::is_regular_file(saved));
  EXPECT_EQ(Slurp(saved), halved);
  EXPECT_FALSE(std::filesystem::exists(dir / "shadelab-teapot-001.vert")) << "not edited";
  const std::vector<std::string> command = SceneArguments(inspector.ShownScene());
  const auto named = std::find(command.begin(), command.end(), "--fragment-shader");
  ASSERT_NE(named, command.end());
  EXPECT_EQ(*(named + 1), std::filesystem::absolute(saved).string());
  EXPECT_EQ(std::count(command.begin(), command.end(), "--vertex-shader"), 0);

  // Revert: the generated program, and the picture of before.
  window.findChild<QPushButton*>("revert stages")->click();
  EXPECT_TRUE(inspector.GetState().Stages.Empty());
  EXPECT_EQ(inspector.GetShownShaders().Fragment, generated.Fragment);
  EXPECT_EQ(fragment->toPlainText().toStdString(), generated.Fragment);
  EXPECT_EQ(vertex->toPlainText().toStdString(), generated.Vertex);
  EXPECT_TRUE(Items(errors).empty());
  EXPECT_EQ(UpperPixels(inspector), before);
  const std::vector<std::string> reverted = SceneArguments(inspector.ShownScene());
  EXPECT_EQ(std::count(reverted.begin(), reverted.end(), "--fragment-shader"), 0);
}
