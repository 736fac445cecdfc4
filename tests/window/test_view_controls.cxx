// The inspector's control panel in process (Qt's QTest on an Xvfb of the
// test's own, viewer.cxx): each control changes its own setting of the
// picture and nothing else, as the picture's render command (Copy command)
// says it; a key moves the controls that show what it changed; closing the
// window ends it.
#include "desktop/inspector_window.h"
#include "in_process.h"
#include "settings/command_line.h"
#include "viewer.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkCommand.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRendererCollection.h>

#include <QAbstractSpinBox>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QSurfaceFormat>
#include <QTabWidget>
#include <QTest>
#include <QTimer>

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>

using namespace shadelab;
using namespace shadelab_test;

namespace
{
// The render command's options, each to its value (flags to "", repeated
// --light values joined).
std::map<std::string, std::string> Settings(const Inspector& inspector)
{
  std::map<std::string, std::string> settings;
  const std::vector<std::string> words = SceneArguments(inspector.ShownScene());
  for (std::size_t i = 0; i < words.size(); ++i)
  {
    std::string& value = settings[words[i]];
    if (i + 1 < words.size() && words[i + 1].rfind("--", 0) != 0)
    {
      value += words[++i] + ";";
    }
  }
  return settings;
}

// The options whose values differ between two settings.
std::set<std::string> Changed(
  const std::map<std::string, std::string>& a, const std::map<std::string, std::string>& b)
{
  std::set<std::string> changed;
  for (const auto* one : { &a, &b })
  {
    const auto* other = one == &a ? &b : &a;
    for (const auto& [option, value] : *one)
    {
      const auto it = other->find(option);
      if (it == other->end() || it->second != value)
      {
        changed.insert(option);
      }
    }
  }
  return changed;
}

// Where the picture of the scene the view shows is brightest, rendered
// headless (no light handle in it): the mean position of the pixels within
// 10% of its brightest value, the specular highlight.
std::array<double, 2> Highlight(const Inspector& inspector, const TempDir& dir)
{
  const std::filesystem::path png = dir / "highlight.png";
  std::vector<std::string> args{ "render", TestMesh("teapot.obj").string(), "-o", png.string() };
  // Without the edges and glyphs, whose lines are as bright as the light.
  for (const std::string& option : SceneArguments(inspector.ShownScene()))
  {
    if (option != "--edges" && option != "--normal-glyphs")
    {
      args.push_back(option);
    }
  }
  const RunResult run = RunShadelab(args);
  EXPECT_EQ(run.ExitCode, 0) << run.Stderr;
  const Image image = ReadImage(png);
  const auto brightness = [&](int i)
  {
    const float* p = &image.Pixels[static_cast<std::size_t>(i) * image.Channels];
    return p[0] + p[1] + p[2];
  };
  const int count = image.Width * image.Height;
  float brightest = 0;
  for (int i = 0; i < count; ++i)
  {
    brightest = std::max(brightest, brightness(i));
  }
  double x = 0, y = 0, n = 0;
  for (int i = 0; i < count; ++i)
  {
    if (brightest > 0 && brightness(i) >= 0.9f * brightest)
    {
      x += i % image.Width;
      y += i / image.Width;
      n += 1;
    }
  }
  return { x / n, y / n };
}

}

TEST(Controls, EachChangesItsSettingAndNothingElseKeysMoveThemAndClosingEnds)
{
  const ViewOptions options = SpotView(Shading::Phong);
  Inspector inspector(options, "shadelab view");
  ASSERT_EQ(inspector.Load(), 0);
  const auto application = MakeApplication();
  InspectorWindow window(inspector);
  ASSERT_TRUE(window.Open(options.Scene.Size));

  const auto find = [&window](const char* name) -> QWidget*
  {
    QWidget* widget = window.findChild<QWidget*>(name);
    EXPECT_NE(widget, nullptr) << name;
    return widget;
  };
  const auto checkBox = [&window](const QString& text) -> QCheckBox*
  {
    for (QCheckBox* box : window.findChildren<QCheckBox*>())
    {
      if (box->text().startsWith(text))
      {
        return box;
      }
    }
    ADD_FAILURE() << text.toStdString();
    return nullptr;
  };
  // Each control, what it does, and the options it may change.
  struct Case
  {
    const char* What;
    std::function<void()> Do;
    std::set<std::string> Changes;
  };
  const std::vector<Case> cases{
    { "rule", [&] { QTest::keyClick(find("rule"), Qt::Key_Up); }, { "--shading" } },
    { "reflection", [&] { QTest::keyClick(find("reflection"), Qt::Key_Down); },
      { "--reflection" } },
    { "material", [&] { QTest::keyClick(find("material"), Qt::Key_Down); }, { "--material" } },
    { "specular form", [&] { QTest::keyClick(find("specular form"), Qt::Key_Down); },
      { "--specular-form" } },
    { "ka", [&] { Type(window.findChild<QDoubleSpinBox*>("ka red"), "0.5"); }, { "--ka" } },
    { "kd", [&] { Type(window.findChild<QDoubleSpinBox*>("kd blue"), "0.125"); }, { "--kd" } },
    { "ks", [&] { Type(window.findChild<QDoubleSpinBox*>("ks green"), "0.75"); }, { "--ks" } },
    { "ns slider", [&] { QTest::keyClick(window.findChild<QSlider*>(), Qt::Key_PageUp); },
      { "--ns" } },
    { "ns typed", [&] { Type(window.findChild<QDoubleSpinBox*>("ns number"), "7"); }, { "--ns" } },
    { "a typed", [&] { Type(window.findChild<QDoubleSpinBox*>("a number"), "0.5"); },
      { "--translucency" } },
    { "peels", [&] { Type(window.findChild<QSpinBox*>("peels"), "3"); }, { "--peels" } },
    { "Ia", [&] { Type(window.findChild<QDoubleSpinBox*>("Ia green"), "0.4"); }, { "--ambient" } },
    { "attenuation", [&] { Type(window.findChild<QDoubleSpinBox*>("attenuation c2"), "0.01"); },
      { "--attenuation" } },
    { "attenuation all zero",
      [&]
      {
        // Refused: the numbers go back to the scene's, which the next one changes.
        Type(window.findChild<QDoubleSpinBox*>("attenuation c2"), "0");
        Type(window.findChild<QDoubleSpinBox*>("attenuation c0"), "0");
        EXPECT_EQ(window.findChild<QDoubleSpinBox*>("attenuation c0")->value(), 1);
        EXPECT_EQ(inspector.GetState().Scene.Attenuation, (Vec3{ 1, 0, 0 }));
        Type(window.findChild<QDoubleSpinBox*>("attenuation c1"), "0.5");
      },
      { "--attenuation" } },
    { "shadows", [&] { window.findChild<QCheckBox*>("shadows")->click(); }, { "--shadows" } },
    { "shadow map size", [&] { Type(window.findChild<QSpinBox*>("shadow map size"), "512"); },
      { "--shadow-map-size" } },
    { "fog", [&] { QTest::keyClick(find("fog"), Qt::Key_Down); }, { "--fog" } },
    { "fog end", [&] { Type(window.findChild<QDoubleSpinBox*>("fog end"), "1e6"); }, { "--fog" } },
    { "fog end not beyond start",
      [&]
      {
        // Refused as --fog refuses it: the number goes back.
        const Fog before = inspector.GetState().Scene.Fogging;
        ASSERT_EQ(before.Mode, FogMode::Linear);
        Type(window.findChild<QDoubleSpinBox*>("fog end"), "-5");
        EXPECT_EQ(inspector.GetState().Scene.Fogging, before);
        EXPECT_EQ(window.findChild<QDoubleSpinBox*>("fog end")->value(), before.End);
        Type(window.findChild<QDoubleSpinBox*>("fog start"), "1");
      },
      { "--fog" } },
    { "wireframe", [&] { QTest::keyClick(find("representation"), Qt::Key_Down); },
      { "--representation" } },
    { "line width", [&] { Type(window.findChild<QSpinBox*>("representation pixels"), "4"); },
      { "--line-width" } },
    { "points", [&] { QTest::keyClick(find("representation"), Qt::Key_Down); },
      { "--representation" } },
    { "point size",
      [&]
      {
        Type(window.findChild<QSpinBox*>("representation pixels"), "7");
        EXPECT_EQ(inspector.GetState().Scene.LineWidth, 4) << "the lines' width kept";
      },
      { "--point-size" } },
    { "surface",
      [&]
      {
        QTest::keyClick(find("representation"), Qt::Key_Up);
        QTest::keyClick(find("representation"), Qt::Key_Up);
        EXPECT_FALSE(window.findChild<QSpinBox*>("representation pixels")->isEnabled());
      },
      { "--representation" } },
    { "lights", [&] { QTest::keyClick(find("lights"), Qt::Key_Down); }, { "--light" } },
    { "add spot", [&] { static_cast<QPushButton*>(find("add spot"))->click(); }, { "--light" } },
    { "light position", [&] { Type(window.findChild<QDoubleSpinBox*>("light position x"), "1.5"); },
      { "--light" } },
    { "light direction",
      [&] { Type(window.findChild<QDoubleSpinBox*>("light direction y"), "-2"); }, { "--light" } },
    { "light colour", [&] { Type(window.findChild<QDoubleSpinBox*>("light color red"), "0.5"); },
      { "--light" } },
    { "cone angle", [&] { Type(window.findChild<QDoubleSpinBox*>("cone angle"), "20"); },
      { "--light" } },
    { "exponent", [&] { Type(window.findChild<QDoubleSpinBox*>("exponent"), "3"); },
      { "--light" } },
    { "add point", [&] { static_cast<QPushButton*>(find("add point"))->click(); }, { "--light" } },
    { "remove", [&] { static_cast<QPushButton*>(find("remove light"))->click(); }, { "--light" } },
    { "specular", [&] { checkBox("specular")->click(); }, { "--ks" } },
    { "normals", [&] { QTest::keyClick(find("normals"), Qt::Key_Down); },
      { "--normals", "--weighting" } },
    { "feature angle", [&] { Type(window.findChild<QDoubleSpinBox*>("feature angle"), "30"); },
      { "--feature-angle" } },
    { "edges", [&] { checkBox("edges")->click(); }, { "--edges" } },
    { "glyphs", [&] { checkBox("normal glyphs")->click(); }, { "--normal-glyphs" } },
  };
  for (const Case& c : cases)
  {
    const auto before = Settings(inspector);
    c.Do();
    const std::set<std::string> changed = Changed(before, Settings(inspector));
    EXPECT_FALSE(changed.empty()) << c.What << " changed nothing";
    for (const std::string& option : changed)
    {
      EXPECT_TRUE(c.Changes.count(option)) << c.What << " changed " << option;
    }
  }

  // The light list after those edits: one spot light, as edited.
  const std::vector<Light>& lights = inspector.GetState().Scene.Lights;
  ASSERT_EQ(lights.size(), 1u);
  EXPECT_EQ(lights[0].Kind, LightKind::Spot);
  EXPECT_EQ(lights[0].Position[0], 1.5);
  EXPECT_EQ(lights[0].Direction[1], -2);
  EXPECT_EQ(lights[0].Color[0], 0.5);
  EXPECT_EQ(lights[0].HalfAngleDeg, 20);
  EXPECT_EQ(lights[0].Exponent, 3);
  EXPECT_EQ(inspector.GetState().Lights, LightMode::Given);

  // The selected spot light's handle in the 3D view, dragged 30 pixels
  // right by the interactor's own events: the light moves, keeps its
  // direction, and its highlight moves.
  // A wide spot a third of the way to the camera, shining at the mesh: a
  // highlight the drag moves.
  const std::array<const char*, 3> axes{ "x", "y", "z" };
  const std::array<const char*, 3> position{ "1.3", "0.5", "-0.7" };
  const std::array<const char*, 3> direction{ "-1.3", "-0.5", "0.7" };
  for (int i = 0; i < 3; ++i)
  {
    Type(window.findChild<QDoubleSpinBox*>(QString("light position ") + axes[i]), position[i]);
    Type(window.findChild<QDoubleSpinBox*>(QString("light direction ") + axes[i]), direction[i]);
  }
  Type(window.findChild<QDoubleSpinBox*>("cone angle"), "60");
  Type(window.findChild<QDoubleSpinBox*>("exponent"), "0");
  for (const char* channel : { "ks red", "ks green", "ks blue" })
  {
    Type(window.findChild<QDoubleSpinBox*>(channel), "1");
  }
  vtkRenderWindow* view = inspector.GetWindow();
  vtkRenderer* panel = nullptr;
  view->GetRenderers()->InitTraversal();
  while (vtkRenderer* r = view->GetRenderers()->GetNextItem())
  {
    panel = !panel && r->GetInteractive() && r->GetLayer() == 0 ? r : panel;
  }
  ASSERT_NE(panel, nullptr);
  panel->SetWorldPoint(1.3, 0.5, -0.7, 1);
  panel->WorldToDisplay();
  const double* at = panel->GetDisplayPoint();
  vtkRenderWindowInteractor* mouse = view->GetInteractor();
  const Light before = inspector.GetState().Scene.Lights[0];
  const TempDir pictures;
  const std::array<double, 2> highlightBefore = Highlight(inspector, pictures);
  view->Render(); // the handle drawn, where the press picks it

  mouse->SetEventInformation(static_cast<int>(at[0]), static_cast<int>(at[1]));
  mouse->InvokeEvent(vtkCommand::MouseMoveEvent); // over the handle first, as a hand would
  mouse->InvokeEvent(vtkCommand::LeftButtonPressEvent);
  mouse->SetEventInformation(static_cast<int>(at[0]) + 30, static_cast<int>(at[1]));
  mouse->InvokeEvent(vtkCommand::MouseMoveEvent);
  mouse->InvokeEvent(vtkCommand::LeftButtonReleaseEvent);
  const Light after = inspector.GetState().Scene.Lights[0];
  EXPECT_NE(after.Position, before.Position) << "the drag moved the light";
  EXPECT_EQ(after.Direction, before.Direction);
  const std::array<double, 2> highlightAfter = Highlight(inspector, pictures);
  EXPECT_GT(
    std::hypot(highlightAfter[0] - highlightBefore[0], highlightAfter[1] - highlightBefore[1]), 1)
    << "the highlight moved with the light: from (" << highlightBefore[0] << ", "
    << highlightBefore[1] << ") to (" << highlightAfter[0] << ", " << highlightAfter[1] << ")";

  // Keys: the controls follow.
  auto* rule = static_cast<QComboBox*>(find("rule"));
  auto* material = static_cast<QComboBox*>(find("material"));
  inspector.OnKey("1");
  EXPECT_EQ(rule->currentText().toStdString(), "flat");
  inspector.OnKey("m");
  EXPECT_EQ(material->currentText().toStdString(), inspector.GetState().Scene.MaterialName)
    << "m: a row of the table again, the custom coefficients gone";
  const bool specular = checkBox("specular")->isChecked();
  inspector.OnKey("s");
  EXPECT_NE(checkBox("specular")->isChecked(), specular);
  auto* ns = window.findChild<QDoubleSpinBox*>("ns number");
  const double shininess = ns->value();
  inspector.OnKey("+");
  EXPECT_NEAR(ns->value(), shininess * 1.5, 1e-3);

  // Closing the window (what a window manager's close button asks for)
  // ends the event loop with 0.
  QTimer::singleShot(0, &window, [&window] { window.close(); });
  QTimer::singleShot(10000, application.get(), [] { QCoreApplication::exit(1); }); // still open
  EXPECT_EQ(application->exec(), 0);
}

// The material controls are the overrides of a mesh's own materials:
// choosing a row of the table, even the default's, replaces every part's
// material as --material does, and the render command says so.
TEST(Controls, ChoosingTheDefaultsRowStillReplacesEveryPartsMaterial)
{
  const ViewOptions options = SpotView(Shading::Phong);
  Inspector inspector(options, "shadelab view");
  ASSERT_EQ(inspector.Load(), 0);
  const auto application = MakeApplication();
  InspectorWindow window(inspector);
  ASSERT_TRUE(window.Open(options.Scene.Size));
  EXPECT_EQ(Settings(inspector).count("--material"), 0u) << "the file's materials, untouched";
  auto* material = window.findChild<QComboBox*>("material");
  ASSERT_NE(material, nullptr);
  ASSERT_EQ(material->currentText().toStdString(), "chrome");
  emit material->activated(material->currentIndex());
  EXPECT_TRUE(inspector.GetState().Scene.MaterialGiven);
  EXPECT_EQ(Settings(inspector)["--material"], "chrome;");
}

namespace
{
// The control panel's check box whose text starts with `name`, or null.
QCheckBox* ToggleNamed(const QWidget& window, const QString& name)
{
  QCheckBox* toggle = nullptr;
  for (QCheckBox* box : window.findChildren<QCheckBox*>())
  {
    toggle = box->text().startsWith(name) ? box : toggle;
  }
  return toggle;
}
}

// An environment is one of the terms: its toggle, shown where the scene has
// one, takes it out of the scene the view shows (its render command), and
// nothing else, and puts it back. That the code and picture follow the
// scene is the render tests' (test_environment_oracle.cxx).
TEST(Controls, TheEnvironmentsToggleTakesItsTermOutAndBack)
{
  TempDir dir;
  WriteImage8(dir / "sky.png", 2, 1, { 200, 180, 40, 20, 60, 220 });
  ViewOptions options = SpotView(Shading::Phong);
  options.Scene.Environment = (dir / "sky.png").string();
  Inspector inspector(options, "shadelab view");
  ASSERT_EQ(inspector.Load(), 0);
  const auto application = MakeApplication();
  InspectorWindow window(inspector);
  ASSERT_TRUE(window.Open(options.Scene.Size));
  QCheckBox* toggle = ToggleNamed(window, "environment");
  ASSERT_NE(toggle, nullptr);
  const auto with = Settings(inspector);
  EXPECT_EQ(with.at("--environment"), (dir / "sky.png").string() + ";");
  toggle->click();
  EXPECT_EQ(Changed(with, Settings(inspector)), std::set<std::string>{ "--environment" });
  EXPECT_TRUE(inspector.ShownScene().Environment.empty());
  toggle->click();
  EXPECT_EQ(Settings(inspector), with);
}

// A normal map, or a bump map, has its toggle and its scale in the Terms
// group where the scene has one: the toggle takes --normal-map (--bump-map)
// out of the scene the view shows and puts it back, the scale changes its
// SCALE and nothing else.
TEST(Controls, TheNormalMapsToggleAndScaleChangeOnlyIt)
{
  TempDir dir;
  WriteText(dir / "square.off",
    "STOFF\n4 2 0\n-1 -1 0 0 0\n1 -1 0 1 0\n1 1 0 1 1\n-1 1 0 0 1\n3 0 1 2\n3 0 2 3\n");
  WriteImage8(dir / "n.png", 2, 1, { 200, 110, 220, 128, 128, 255 });
  WriteImage8(dir / "h.png", 2, 1, { 10, 10, 10, 200, 200, 200 });
  const auto application = MakeApplication();
  for (const bool bump : { false, true })
  {
    const std::string name = bump ? "bump map" : "normal map";
    const std::string option = bump ? "--bump-map" : "--normal-map";
    const std::string image = (dir / (bump ? "h.png" : "n.png")).string();
    SCOPED_TRACE(name);
    ViewOptions options = SpotView(Shading::Phong);
    options.Scene.Mesh = (dir / "square.off").string();
    (bump ? options.Scene.BumpMap : options.Scene.NormalMap) = ScaledImage{ image, 1 };
    Inspector inspector(options, "shadelab view");
    ASSERT_EQ(inspector.Load(), 0);
    InspectorWindow window(inspector);
    ASSERT_TRUE(window.Open(options.Scene.Size));
    QCheckBox* toggle = ToggleNamed(window, QString::fromStdString(name));
    ASSERT_NE(toggle, nullptr);
    auto* scale = window.findChild<QDoubleSpinBox*>(QString::fromStdString(name + " scale"));
    ASSERT_NE(scale, nullptr);
    const auto with = Settings(inspector);
    EXPECT_EQ(with.at(option), image + ";");
    toggle->click();
    // Off: --normal-map none (no map, nor the file's), in the bump map's place too.
    const auto off = Settings(inspector);
    const std::set<std::string> changed = bump
      ? std::set<std::string>{ "--bump-map", "--normal-map" }
      : std::set<std::string>{ "--normal-map" };
    EXPECT_EQ(Changed(with, off), changed);
    EXPECT_EQ(off.at("--normal-map"), "none;");
    EXPECT_FALSE(inspector.ShownScene().Relief());
    toggle->click();
    EXPECT_EQ(Settings(inspector), with);
    Type(scale, "0.5");
    const auto scaled = Settings(inspector);
    EXPECT_EQ(Changed(with, scaled), std::set<std::string>{ option });
    EXPECT_EQ(scaled.at(option), image + ":0.5;");
  }
}

// A mesh file's own normal map has the toggle too (its parts' scales are
// their own: no scale box); off, the view draws --normal-map none.
TEST(Controls, TheFilesNormalMapHasItsToggle)
{
  TempDir dir;
  WriteText(dir / "square.obj",
    "mtllib square.mtl\nusemtl m\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\n"
    "vt 1 1\nvt 0 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
  WriteText(dir / "square.mtl", "newmtl m\nKd 0.5 0.5 0.5\nnorm n.png\n");
  WriteImage8(dir / "n.png", 2, 1, { 200, 110, 220, 128, 128, 255 });
  ViewOptions options = SpotView(Shading::Phong);
  options.Scene.Mesh = (dir / "square.obj").string();
  Inspector inspector(options, "shadelab view");
  ASSERT_EQ(inspector.Load(), 0);
  const auto application = MakeApplication();
  InspectorWindow window(inspector);
  ASSERT_TRUE(window.Open(options.Scene.Size));
  QCheckBox* toggle = ToggleNamed(window, "normal map");
  ASSERT_NE(toggle, nullptr);
  EXPECT_EQ(window.findChild<QDoubleSpinBox*>("normal map scale"), nullptr);
  const auto with = Settings(inspector);
  toggle->click();
  EXPECT_EQ(Changed(with, Settings(inspector)), std::set<std::string>{ "--normal-map" });
  EXPECT_TRUE(inspector.ShownScene().NoNormalMaps());
  toggle->click();
  EXPECT_EQ(Settings(inspector), with);
}
