// The probe in the window, in process (an Xvfb of the test's own,
// viewer.cxx): a Ctrl+click on the mesh explains that pixel with the same
// numbers as `shadelab probe` headless for the view's settings, draws N, L
// and H (or R) along them, follows a change of the settings, and is
// cleared; a Ctrl+click off the mesh hits nothing; a plain click and a
// Ctrl+drag probe nothing. A term's line picked in the readout highlights
// the shader lines that compute that term.
#include "desktop/inspector_window.h"
#include "in_process.h"
#include "probe/probe_json.h"
#include "probe/probe_text.h"
#include "settings/command_line.h"
#include "shadelabShaderSource.h"
#include "viewer.h"

#include <vtkCommand.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderWindowInteractor.h>

#include <QApplication>
#include <QPlainTextEdit>
#include <QTabWidget>
#include <QTextBlock>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <set>
#include <sstream>

using namespace shadelab;
using namespace shadelab_test;
using nlohmann::json;

namespace
{
// The window's and the command line's probe compute from the same mesh,
// camera and lights in double precision; the camera reaches the command
// line as text, whose rounding moves a result by far less than this.
constexpr double Near = 1e-6;

// `shadelab probe --json` headless for the scene the view shows.
json Headless(const Inspector& inspector, Pixel at)
{
  const SceneOptions scene = inspector.ShownScene();
  std::vector<std::string> args{ "probe", scene.Mesh, "--json", "--pixel",
    std::to_string(at.X) + "," + std::to_string(at.Y) };
  const std::vector<std::string> options = SceneArguments(scene);
  args.insert(args.end(), options.begin(), options.end());
  const RunResult run = RunShadelab(args);
  EXPECT_EQ(run.ExitCode, 0) << run.Stderr;
  return json::parse(run.Stdout); // throws, failing the test, on malformed JSON
}

// The lines of `edit` that the generator marked as computing `term`
// (shadelabShaderSource.h's TermMarker), and the lines shown highlighted.
std::set<int> MarkedFor(const QPlainTextEdit* edit, const std::string& term)
{
  std::set<int> lines;
  std::istringstream source(edit->toPlainText().toStdString());
  std::string line;
  for (int n = 0; std::getline(source, line); ++n)
  {
    const std::size_t marker = line.find(TermMarker);
    if (marker != std::string::npos && line.find(term, marker) != std::string::npos)
    {
      lines.insert(n);
    }
  }
  return lines;
}

// Puts the readout's cursor on its first line that starts (after the
// indent) with `quantity`.
void PickLine(QPlainTextEdit* readout, const QString& quantity)
{
  for (QTextBlock block = readout->document()->begin(); block.isValid(); block = block.next())
  {
    if (block.text().trimmed().startsWith(quantity))
    {
      QTextCursor cursor(block);
      readout->setTextCursor(cursor);
      return;
    }
  }
  ADD_FAILURE() << "no readout line starts with " << quantity.toStdString();
}

void ExpectNear(const json& a, const json& b, double near, const std::string& what)
{
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    EXPECT_NEAR(a[i].get<double>(), b[i].get<double>(), near) << what << "[" << i << "]";
  }
}

// The direction an arrow points along: its transform's image of VTK's
// arrow axis, +X, made unit.
json Direction(vtkActor* arrow)
{
  vtkMatrix4x4* m = arrow->GetMatrix();
  const double x = m->GetElement(0, 0), y = m->GetElement(1, 0), z = m->GetElement(2, 0);
  const double length = std::hypot(x, y, z);
  return { x / length, y / length, z / length };
}

json Unit(const json& v)
{
  const double length = std::hypot(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  return { v[0].get<double>() / length, v[1].get<double>() / length, v[2].get<double>() / length };
}

// Each arrow's name, in order, and that each points along the headless
// probe's vector of that name.
std::vector<std::string> CheckArrows(const Inspector& inspector, const json& headless)
{
  std::vector<std::string> names;
  for (const Inspector::ProbeArrow& arrow : inspector.GetProbeArrows())
  {
    names.push_back(arrow.Name);
    const json& light = headless["lights"][0];
    const json& expected = arrow.Name == "N" ? headless["normal"]
      : arrow.Name == "L1"                   ? light["L"]
      : arrow.Name == "H1"                   ? light["H"]
                                             : light["R"];
    ExpectNear(Direction(arrow.Actor), Unit(expected), Near, arrow.Name);
  }
  return names;
}

// A left click at window pixel (x, y) from the top left, through the
// interactor as Qt's widget passes it, moving `dx` pixels before the release.
void Click(vtkRenderWindowInteractor* mouse, int x, int y, bool control, int dx = 0)
{
  mouse->SetEventInformationFlipY(x, y, control, 0);
  mouse->InvokeEvent(vtkCommand::LeftButtonPressEvent);
  if (dx != 0)
  {
    mouse->SetEventInformationFlipY(x + dx, y, control, 0);
    mouse->InvokeEvent(vtkCommand::MouseMoveEvent);
  }
  mouse->InvokeEvent(vtkCommand::LeftButtonReleaseEvent);
}
}

TEST(Probe, CtrlClickExplainsThePixelAsTheCommandLineDoesWithArrowsAlongNLH)
{
  ViewOptions options = SpotView(Shading::Phong);
  // A light away from the camera, so that L, H and N point three ways.
  Light light;
  light.Position = { 3, 4, 1 };
  options.Scene.Lights = { light };
  Inspector inspector(options, "shadelab view");
  ASSERT_EQ(inspector.Load(), 0);
  const auto application = MakeApplication();
  InspectorWindow window(inspector);
  ASSERT_TRUE(window.Open(options.Scene.Size));
  vtkRenderWindowInteractor* mouse = inspector.GetWindow()->GetInteractor();
  auto* readout = window.findChild<QPlainTextEdit*>("probe readout");
  ASSERT_NE(readout, nullptr);

  // A plain click turns the camera, a Ctrl+drag spins it: neither probes.
  const Pixel on{ 120, 95 }; // the cow's side, at the view's centre
  Click(mouse, on.X, on.Y, false);
  Click(mouse, on.X, on.Y, true, 10);
  EXPECT_FALSE(inspector.GetProbe());

  Click(mouse, on.X, on.Y, true);
  ASSERT_TRUE(inspector.GetProbe());
  json window_probe = ProbeJson(*inspector.GetProbe());
  json headless = Headless(inspector, on);
  EXPECT_EQ(window_probe["pixel"], headless["pixel"]);
  ASSERT_TRUE(window_probe["hit"].get<bool>());
  ASSERT_TRUE(headless["hit"].get<bool>());
  EXPECT_EQ(window_probe["triangle"], headless["triangle"]);
  for (const char* key : { "oracle", "position", "normal", "view", "ambient" })
  {
    ExpectNear(window_probe[key], headless[key], Near, key);
  }
  for (const char* key : { "L", "H", "diffuse", "specular" })
  {
    ExpectNear(window_probe["lights"][0][key], headless["lights"][0][key], Near, key);
  }
  // The window's 8-bit pixel (without the arrows) against the float
  // render: the same picture, so within the window's rounding, half a
  // level, and one level for llvmpipe's own rounding of the same shader.
  ExpectNear(window_probe["rendered"], headless["rendered"], 1.5 / 255, "rendered");
  EXPECT_EQ(CheckArrows(inspector, headless), (std::vector<std::string>{ "N", "L1", "H1" }));
  EXPECT_EQ(readout->toPlainText().toStdString(), ProbeText(*inspector.GetProbe()));
  EXPECT_NE(readout->toPlainText().indexOf("the window's 8-bit pixel"), -1);

  // A term's line picked in the readout: the shader panel highlights that
  // term's lines only, in the stage that lights (phong: the fragment's).
  const auto* fragment = window.findChild<QPlainTextEdit*>("fragment source");
  const auto* tabs = window.findChild<QTabWidget*>();
  ASSERT_TRUE(fragment && tabs);
  for (const auto& [quantity, term] :
    { std::pair{ "ka*Ia", "ambient" }, { "kd*Il", "diffuse" }, { "ks*Il", "specular" } })
  {
    PickLine(readout, quantity);
    const std::set<int> marked = MarkedFor(fragment, term);
    ASSERT_FALSE(marked.empty()) << term;
    EXPECT_EQ(Highlighted(fragment), marked) << term;
    EXPECT_EQ(tabs->currentWidget(), fragment) << term;
  }
  PickLine(readout, "N ="); // not a term's line: the highlight stays
  EXPECT_EQ(Highlighted(fragment), MarkedFor(fragment, "specular"));

  // Another reflection model: the same pixel explained again, R for H.
  inspector.Edit([](ViewState& s) { s.Scene.ReflectionModel = Reflection::Phong; });
  ASSERT_TRUE(inspector.GetProbe());
  headless = Headless(inspector, on);
  ExpectNear(
    ProbeJson(*inspector.GetProbe())["lights"][0]["R"], headless["lights"][0]["R"], Near, "R");
  EXPECT_EQ(CheckArrows(inspector, headless), (std::vector<std::string>{ "N", "L1", "R1" }));
  EXPECT_EQ(readout->toPlainText().toStdString(), ProbeText(*inspector.GetProbe()));

  // Shadows: the light's shadow ray, and whether the window's own map
  // decided alike at the pixel, as headless (its map, its own context).
  inspector.Edit([](ViewState& s) { s.Scene.Shadows = true; });
  ASSERT_TRUE(inspector.GetProbe());
  headless = Headless(inspector, on);
  const json& shadowed = ProbeJson(*inspector.GetProbe())["lights"][0];
  EXPECT_EQ(shadowed["shadowed"], headless["lights"][0]["shadowed"]);
  ASSERT_TRUE(shadowed.contains("shadow_map_agrees")) << shadowed.dump();
  EXPECT_EQ(shadowed["shadow_map_agrees"], headless["lights"][0]["shadow_map_agrees"]);
  inspector.Edit([](ViewState& s) { s.Scene.Shadows = false; });

  // Cleared: no probe, no arrows, and it stays cleared when the settings change.
  inspector.ClearProbe();
  inspector.Edit([](ViewState& s) { s.Scene.ReflectionModel = Reflection::BlinnPhong; });
  EXPECT_FALSE(inspector.GetProbe());
  EXPECT_TRUE(inspector.GetProbeArrows().empty());

  // Off the mesh: the corner is background, here and headless.
  Click(mouse, 2, 2, true);
  ASSERT_TRUE(inspector.GetProbe());
  EXPECT_FALSE(inspector.GetProbe()->Hit);
  EXPECT_FALSE(Headless(inspector, { 2, 2 })["hit"].get<bool>());
  EXPECT_TRUE(inspector.GetProbeArrows().empty());
  EXPECT_NE(readout->toPlainText().indexOf("no triangle under its centre"), -1);
}

// The environment behind the mesh (--background environment): a pixel off
// the mesh shows in the window what headless draws and explains there, the
// environment along the pixel's ray; the window's 8-bit pixel within its
// rounding of the float render. Turning the camera paints it again: the
// same pixel then looks another way.
TEST(Probe, TheEnvironmentBehindShowsInTheWindowAsHeadless)
{
  TempDir dir;
  std::vector<unsigned char> sky;
  for (int i = 0; i < 16 * 8; ++i)
  {
    sky.insert(sky.end(),
      { static_cast<unsigned char>(20 + 13 * (i % 16)),
        static_cast<unsigned char>(40 + 25 * (i / 16)), 90 });
  }
  WriteImage8(dir / "sky.png", 16, 8, sky);
  ViewOptions options = SpotView(Shading::Phong);
  options.Scene.Environment = (dir / "sky.png").string();
  options.Scene.EnvironmentBackground = true;
  Inspector inspector(options, "shadelab view");
  ASSERT_EQ(inspector.Load(), 0);
  const auto application = MakeApplication();
  InspectorWindow window(inspector);
  ASSERT_TRUE(window.Open(options.Scene.Size));
  vtkRenderWindowInteractor* mouse = inspector.GetWindow()->GetInteractor();
  const Pixel corner{ 3, 4 };
  inspector.Probe(corner);
  ASSERT_TRUE(inspector.GetProbe());
  json window_probe = ProbeJson(*inspector.GetProbe());
  const json headless = Headless(inspector, corner);
  ASSERT_FALSE(window_probe["hit"].get<bool>());
  ASSERT_TRUE(headless.contains("background_environment"));
  ExpectNear(window_probe["background"], headless["background"], Near, "background");
  ExpectNear(window_probe["background"], headless["rendered"], Near, "headless rendered");
  ExpectNear(window_probe["rendered"], headless["rendered"], 0.5 / 255 + 1e-6, "rendered");
  // A turned camera: the pixel shows another texel, and the window still
  // agrees with headless.
  Click(mouse, 120, 95, false, 40);
  Click(mouse, corner.X, corner.Y, true);
  ASSERT_TRUE(inspector.GetProbe());
  window_probe = ProbeJson(*inspector.GetProbe());
  const json turned = Headless(inspector, corner);
  EXPECT_NE(turned["background"], headless["background"]);
  ExpectNear(window_probe["rendered"], turned["rendered"], 0.5 / 255 + 1e-6, "turned");
}
