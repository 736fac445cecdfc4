// The window on the screen it opens on, in process (an Xvfb of the test's
// own, viewer.cxx, of $SHADELAB_TEST_SCREEN's size, with the window manager
// $SHADELAB_TEST_WINDOW_MANAGER or none; ctest runs it at 1366x768 and
// 1920x1080, each with openbox and without): without --size the whole
// window, frame and docks, lies on the screen, its 3D view in the default
// size's shape; a given --size larger than the screen is kept, with one
// warning; the controls are in front at start.
#include "desktop/inspector_window.h"
#include "in_process.h"
#include "viewer.h"

#include <QApplication>
#include <QDockWidget>
#include <QGuiApplication>
#include <QScreen>

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>

using namespace shadelab;
using namespace shadelab_test;

namespace
{
ViewOptions SpotView()
{
  ViewOptions options;
  options.Scene.Mesh = TestMesh("teapot.obj").string();
  return options;
}

std::string Text(const QRect& r)
{
  return std::to_string(r.width()) + "x" + std::to_string(r.height()) + " at " +
    std::to_string(r.x()) + "," + std::to_string(r.y());
}

// Whether `dock` shows: open, and not behind another dock's tab.
bool Shows(QDockWidget* dock)
{
  return dock && dock->isVisible() && !dock->visibleRegion().isEmpty();
}

QDockWidget* Dock(InspectorWindow& window, const char* title)
{
  for (QDockWidget* dock : window.findChildren<QDockWidget*>())
  {
    if (dock->windowTitle() == title)
    {
      return dock;
    }
  }
  return nullptr;
}
}

// The default 1024x768 view with its docks is wider than a laptop's screen
// (the window was 2031 pixels wide, its docks off a 1920 one).
TEST(WindowFits, WithoutASizeTheWholeWindowIsOnTheScreen)
{
  const ViewOptions options = SpotView();
  Inspector inspector(options, "shadelab view");
  ASSERT_EQ(inspector.Load(), 0);
  const auto application = MakeApplication();
  InspectorWindow window(inspector);
  ASSERT_TRUE(window.Open(options.Scene.Size, false));
  const QRect screen = window.screen()->availableGeometry();
  EXPECT_TRUE(screen.contains(window.frameGeometry()))
    << "window " << Text(window.frameGeometry()) << ", screen " << Text(screen);
  const QSize view = window.centralWidget()->size();
  EXPECT_LE(view.width(), 1024);
  // The same shape within a pixel's rounding, so the fitted camera frames alike.
  EXPECT_NEAR(static_cast<double>(view.width()) / view.height(), 1024.0 / 768,
    2.0 / std::min(view.width(), view.height()));
  EXPECT_TRUE(Shows(Dock(window, "Controls"))) << "the controls are not in front at start";
  EXPECT_FALSE(Shows(Dock(window, "Shader")));
  EXPECT_FALSE(Shows(Dock(window, "Probe")));
}

TEST(WindowFits, AGivenSizeIsKeptWithOneWarning)
{
  ViewOptions options = SpotView();
  const auto application = MakeApplication();
  const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
  options.Scene.Size = { screen.width() + 100, screen.height() };
  Inspector inspector(options, "shadelab view");
  ASSERT_EQ(inspector.Load(), 0);
  InspectorWindow window(inspector);
  testing::internal::CaptureStderr();
  ASSERT_TRUE(window.Open(options.Scene.Size, true));
  const std::string warnings = testing::internal::GetCapturedStderr();
  EXPECT_EQ(
    window.centralWidget()->size(), QSize(options.Scene.Size.Width, options.Scene.Size.Height));
  EXPECT_EQ(
    warnings.rfind("shadelab: warning: view: --size " + std::to_string(options.Scene.Size.Width) +
        "x" + std::to_string(options.Scene.Size.Height) + " with the controls needs ",
      0),
    0u)
    << warnings;
  EXPECT_EQ(std::count(warnings.begin(), warnings.end(), '\n'), 1) << warnings;
}
