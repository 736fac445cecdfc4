// `shadelab view` in a real window (the desktop inspector): what it shows,
// and what each key and the mouse change (harness: viewer.h).
#include "desktop/view_keys.h"
#include "viewer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

using namespace shadelab_test;
using namespace std::chrono_literals;

TEST(View, TheWindowShowsWhatRenderRenders)
{
  Viewer viewer({});
  ASSERT_TRUE(viewer.HasWindow()) << "no window titled '" << viewer.Title << "'; "
                                  << viewer.Stderr();
  const Image shown = viewer.Screenshot();
  ASSERT_EQ(shown.Width, W);
  ASSERT_EQ(shown.Height, H);
  TempDir dir;
  const RunResult render =
    RunShadelab({ "render", TestMesh("teapot.obj").string(), "-o", (dir / "r.png").string(),
      "--size", std::to_string(W) + "x" + std::to_string(H), "--camera-position", "5,5,9" });
  ASSERT_EQ(render.ExitCode, 0) << render.Stderr;
  const Image rendered = ReadImage(dir / "r.png");
  // The same shaders on the same Mesa (llvmpipe through GLX here, through
  // OSMesa there): the same pixels but for rounding, at most 1 step.
  const Change change = Compare(shown, rendered, 1);
  EXPECT_LE(change.Largest, 1);
  EXPECT_GT(CountCovered(shown), static_cast<size_t>(W * H / 10)) << "the mesh is there";
}

// The window decodes a texture's image too (through the image writer it
// starts) and shows it as render does.
TEST(View, ATextureShowsAsRenderRendersIt)
{
  TempDir dir;
  WriteText(dir / "square.off",
    "STNOFF\n4 2 0\n-1 -1 0 0 0 1 0 0\n1 -1 0 0 0 1 2 0\n1 1 0 0 0 1 2 2\n"
    "-1 1 0 0 0 1 0 2\n3 0 1 2\n3 0 2 3\n");
  std::vector<unsigned char> checker;
  for (int i = 0; i < 16; ++i)
  {
    const bool light = (i % 4 + i / 4) % 2;
    checker.insert(checker.end(),
      { static_cast<unsigned char>(light ? 240 : 200), static_cast<unsigned char>(light ? 240 : 30),
        static_cast<unsigned char>(light ? 240 : 20) });
  }
  WriteImage8(dir / "checker.png", 4, 4, checker);
  const std::vector<std::string> texture{ "--texture", (dir / "checker.png").string(),
    "--texture-filter", "nearest" };
  Viewer viewer(
    texture, std::to_string(W) + "x" + std::to_string(H), RLIM_INFINITY, dir / "square.off");
  ASSERT_TRUE(viewer.HasWindow()) << viewer.Stderr();
  const Image shown = viewer.Screenshot();
  std::vector<std::string> args{ "render", (dir / "square.off").string(), "-o",
    (dir / "r.png").string(), "--size", std::to_string(W) + "x" + std::to_string(H),
    "--camera-position", "5,5,9" };
  args.insert(args.end(), texture.begin(), texture.end());
  const RunResult render = RunShadelab(args);
  ASSERT_EQ(render.ExitCode, 0) << render.Stderr;
  // As above: the same shaders on the same Mesa, at most 1 step of
  // rounding; a texture missing or upside down differs by 200 steps.
  const Change change = Compare(shown, ReadImage(dir / "r.png"), 1);
  EXPECT_LE(change.Largest, 1);
  EXPECT_GT(CountCovered(shown), static_cast<size_t>(W * H / 20)) << "the square is there";
}

// Copy command (key y) and Save scene (key j): the printed `shadelab
// render` command, and the scene file, rendered headless make the picture
// the window shows after the camera turned and the rule, reflection,
// material, lights, a term and the normals changed.
TEST(View, CopyCommandAndSaveSceneMakeThePictureTheViewShows)
{
  Viewer viewer({});
  ASSERT_TRUE(viewer.HasWindow()) << viewer.Stderr();
  viewer.Drag(W / 2, H / 2, 60, false);
  viewer.Keys({ "2", "b", "m", "l", "s", "w" });
  const Image shown = viewer.Screenshot();
  viewer.Keys({ "y" });
  std::string command = viewer.Await("shadelab: render command: ");
  ASSERT_EQ(command.rfind("shadelab render ", 0), 0u) << command;
  for (const char* option : { "--shading gouraud", "--reflection phong", "--material copper",
         "--ks 0,0,0", "--light directional:", "--weighting max", "--camera-position " })
  {
    EXPECT_NE(command.find(option), std::string::npos) << option << " in " << command;
  }
  TempDir dir;
  command.replace(0, std::string("shadelab").size(), SHADELAB_BINARY);
  ASSERT_EQ(shadelab_test::Run("cd " + dir.path().string() + " && " + command), 0) << command;
  const Image rendered = ReadImage(dir / "teapot.png");
  // As in TheWindowShowsWhatRenderRenders: the same shaders on the same
  // Mesa, at most 1 step of rounding apart.
  const Change change = Compare(shown, rendered, 1);
  EXPECT_LE(change.Largest, 1) << command;
  EXPECT_GT(CountCovered(shown), static_cast<size_t>(W * H / 10)) << "the mesh is there";

  viewer.Keys({ "j" });
  const std::string scene = viewer.Await("shadelab: scene file ");
  ASSERT_FALSE(scene.empty()) << viewer.Stderr();
  TempDir sceneDir;
  // Its output, teapot.png, goes into the current folder.
  ASSERT_EQ(shadelab_test::Run("cd " + sceneDir.path().string() + " && " + SHADELAB_BINARY +
              " render --scene " + scene),
    0)
    << Slurp(scene);
  EXPECT_LE(Compare(shown, ReadImage(sceneDir / "teapot.png"), 1).Largest, 1) << Slurp(scene);
}

TEST(View, RuleKeysSwitchTheRule)
{
  Viewer viewer({});
  ASSERT_TRUE(viewer.HasWindow()) << viewer.Stderr();
  const Image phong = viewer.Screenshot();
  viewer.Keys({ "1" });
  const Image flat = viewer.Screenshot();
  viewer.Keys({ "2" });
  const Image gouraud = viewer.Screenshot();
  viewer.Keys({ "3" });
  const Image phongAgain = viewer.Screenshot();
  viewer.Keys({ "0" });
  const Image none = viewer.Screenshot();
  ASSERT_EQ(none.Width, W);
  EXPECT_GT(Compare(phong, flat).Pixels, 1000) << "flat's facets";
  EXPECT_GT(Compare(phong, gouraud).Pixels, 100) << "gouraud's highlights";
  EXPECT_EQ(Compare(phong, phongAgain, 0).Pixels, 0) << "3 brings phong back exactly";
  EXPECT_GT(Compare(phong, none).Pixels, 1000) << "none: one colour, unlit";
}

TEST(View, TermKeysTurnTheIlluminationOff)
{
  Viewer viewer({});
  ASSERT_TRUE(viewer.HasWindow()) << viewer.Stderr();
  const Image lit = viewer.Screenshot();
  viewer.Keys({ "s" });
  const Image noSpecular = viewer.Screenshot();
  viewer.Keys({ "a", "d" });
  const Image dark = viewer.Screenshot();
  ASSERT_EQ(dark.Width, W);
  EXPECT_GT(Compare(lit, noSpecular).Pixels, 100) << "the highlights go";
  float brightest = 0;
  for (int y = 0; y < H - HudHeight; ++y)
  {
    for (int x = 0; x < W * 3; ++x)
    {
      brightest = std::max(brightest, dark.Pixels[static_cast<size_t>(y) * W * 3 + x]);
    }
  }
  EXPECT_EQ(brightest, 0) << "no term left: the mesh is black on black";
}

TEST(View, MaterialReflectionLightAndShininessKeysChangeThePicture)
{
  Viewer viewer({});
  ASSERT_TRUE(viewer.HasWindow()) << viewer.Stderr();
  Image before = viewer.Screenshot();
  for (const std::string key : { "m", "M", "b", "l", "plus", "minus", "w" })
  {
    viewer.Keys({ key });
    const Image after = viewer.Screenshot();
    ASSERT_EQ(after.Width, W) << key;
    // M undoes m: the picture is chrome's again, which differs from the
    // one before it (brass).
    EXPECT_GT(Compare(before, after).Pixels, 20) << "key " << key;
    before = after;
  }
}

// Every key of the table (desktop/view_keys.h) is answered: from the start
// each changes the picture. Not here: p and q (their own tests), r (a
// camera that moved first: RResetsTheCamera), y and j
// (CopyCommandAndSaveSceneMakeThePictureTheViewShows), k (it arms the
// profile's drag: ProfileDock.ADragDrawsTheLineAndTheDockShowsTheViewsProfile). A term key turns
// its term back on after, lest the black mesh hide what the next key does.
TEST(View, EveryKeyOfTheTableChangesThePicture)
{
  const auto xdotoolName = [](std::string_view key) -> std::string {
    return key == "+" ? "plus" : key == "-" ? "minus" : std::string(key);
  };
  Viewer viewer({});
  ASSERT_TRUE(viewer.HasWindow()) << viewer.Stderr();
  Image before = viewer.Screenshot();
  for (const shadelab::ViewKey& row : shadelab::ViewKeys)
  {
    if (row.Action == shadelab::ViewAction::Screenshot ||
      row.Action == shadelab::ViewAction::CopyCommand ||
      row.Action == shadelab::ViewAction::SaveScene || row.Action == shadelab::ViewAction::Quit ||
      row.Action == shadelab::ViewAction::ResetCamera ||
      row.Action == shadelab::ViewAction::ProfileLine)
    {
      continue;
    }
    for (int which = 0; !shadelab::NthViewKey(row.Keys, which).empty(); ++which)
    {
      const std::string key = xdotoolName(shadelab::NthViewKey(row.Keys, which));
      viewer.Keys({ key });
      const Image after = viewer.Screenshot();
      ASSERT_EQ(after.Width, W) << key;
      EXPECT_GT(Compare(before, after).Pixels, 20) << "key " << key;
      before = after;
      if (row.Action == shadelab::ViewAction::Term)
      {
        viewer.Keys({ key });
        before = viewer.Screenshot();
      }
    }
  }
  viewer.Keys({ "equal" }); // + without shift
  EXPECT_GT(Compare(before, viewer.Screenshot()).Pixels, 20) << "key =";
}

TEST(View, HelpOverlayAppearsAndGoes)
{
  Viewer viewer({});
  ASSERT_TRUE(viewer.HasWindow()) << viewer.Stderr();
  const Image plain = viewer.Screenshot();
  viewer.Keys({ "h" });
  const Image help = viewer.Screenshot();
  viewer.Keys({ "h" });
  const Image again = viewer.Screenshot();
  ASSERT_EQ(again.Width, W);
  // The key list covers the middle of the window.
  EXPECT_GT(Compare(plain, help, 2, H / 4, H * 3 / 4, W / 4, W * 3 / 4).Pixels, W * H / 16);
  EXPECT_EQ(Compare(plain, again, 0).Pixels, 0);
}

TEST(View, EdgesGlyphsAndComparisonLayout)
{
  Viewer viewer({});
  ASSERT_TRUE(viewer.HasWindow()) << viewer.Stderr();
  const Image plain = viewer.Screenshot();
  viewer.Keys({ "e" });
  const Image edges = viewer.Screenshot();
  viewer.Keys({ "e", "n" });
  const Image glyphs = viewer.Screenshot();
  viewer.Keys({ "n", "c" });
  const Image compare = viewer.Screenshot();
  ASSERT_EQ(compare.Width, W);
  EXPECT_GT(Compare(plain, edges).Pixels, 1000);
  EXPECT_GT(Compare(plain, glyphs).Pixels, 1000);
  // Three panels, flat | gouraud | phong, under one camera: the left and
  // right thirds show the same silhouette with other shading.
  long long differ = 0, covered = 0;
  for (int y = 30; y < H - HudHeight; ++y)
  {
    for (int x = 0; x < W / 3; ++x)
    {
      const float* flat = &compare.Pixels[(static_cast<size_t>(y) * W + x) * 3];
      const float* phong = &compare.Pixels[(static_cast<size_t>(y) * W + x + 2 * W / 3) * 3];
      covered += (flat[0] + flat[1] + flat[2] > 0) && (phong[0] + phong[1] + phong[2] > 0);
      differ += std::fabs(flat[0] - phong[0]) > 2;
    }
  }
  EXPECT_GT(covered, 1000) << "the mesh in both panels";
  EXPECT_GT(differ, 200) << "flat's facets against phong";
}

TEST(View, DragTimeRuleHoldsWhileTheMouseIsDown)
{
  Viewer viewer({ "--interactive-shading", "flat" });
  ASSERT_TRUE(viewer.HasWindow()) << viewer.Stderr();
  viewer.Drag(W / 2, H / 2, 40, true);
  const Image dragging = viewer.Screenshot();
  viewer.Release();
  std::this_thread::sleep_for(500ms);
  const Image released = viewer.Screenshot();
  viewer.Keys({ "1" });
  const Image flat = viewer.Screenshot();
  ASSERT_EQ(flat.Width, W);
  EXPECT_EQ(Compare(dragging, flat, 0).Pixels, 0) << "flat while dragging";
  EXPECT_GT(Compare(released, flat).Pixels, 1000) << "phong again on release";
}

TEST(View, RResetsTheCamera)
{
  Viewer viewer({});
  ASSERT_TRUE(viewer.HasWindow()) << viewer.Stderr();
  const Image start = viewer.Screenshot();
  viewer.Drag(W / 2, H / 2, 60, false);
  const Image turned = viewer.Screenshot();
  viewer.Keys({ "r" });
  const Image reset = viewer.Screenshot();
  ASSERT_EQ(reset.Width, W);
  EXPECT_GT(Compare(start, turned).Pixels, 1000) << "the drag turned the camera";
  EXPECT_EQ(Compare(start, reset, 0).Pixels, 0) << "r: the command line's camera again";
}

TEST(View, AScreenshotThatCannotBeWrittenIsReportedAndLeavesNothing)
{
  // 16 kB: stdout and stderr fit, a screenshot of the teapot does not.
  Viewer viewer({}, std::to_string(W) + "x" + std::to_string(H), 16384);
  ASSERT_TRUE(viewer.HasWindow()) << viewer.Stderr();
  viewer.Keys({ "p" });
  const std::string line =
    "shadelab: error: shadelab-teapot-001.png: cannot write: File too large\n";
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (
    viewer.Stderr().find(line) == std::string::npos && std::chrono::steady_clock::now() < deadline)
  {
    std::this_thread::sleep_for(50ms);
  }
  const std::string stderrText = viewer.Stderr();
  const auto first = stderrText.find(line);
  EXPECT_NE(first, std::string::npos) << stderrText;
  EXPECT_EQ(stderrText.find(line, first + 1), std::string::npos) << "reported once";
  std::vector<std::string> files = viewer.Files();
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{ "stderr", "stdout" }));
  viewer.Keys({ "q" });
  EXPECT_EQ(viewer.Wait(), 0) << "the window goes on after a failed screenshot\n"
                              << viewer.Stderr();
}

TEST(View, QAndEscapeQuitWithZero)
{
  for (const std::string key : { "q", "Escape" })
  {
    Viewer viewer({});
    ASSERT_TRUE(viewer.HasWindow()) << viewer.Stderr();
    viewer.Keys({ key });
    EXPECT_EQ(viewer.Wait(), 0) << key << ": " << viewer.Stderr();
  }
}

TEST(View, DifferencePanelInTheComparisonLayout)
{
  // 1200x400 in four cells of 300x400: the difference cell's picture
  // (label strip, 300x400 heat map, colour bar: 304x474) fits by height,
  // its heat map between 30 and 355 from the top, 900+30 to 1200-30 across.
  const auto hot = [](const Image& shot)
  {
    int count = 0;
    for (int y = 30; y < 355; ++y)
    {
      for (int x = 930; x < 1170; ++x)
      {
        const float* p = &shot.Pixels[(static_cast<size_t>(y) * shot.Width + x) * 3];
        count += p[0] > 60 && p[2] < 30; // red to yellow: the heat map's lower two thirds
      }
    }
    return count;
  };
  { // one window at a time: xdotool finds them by their common title
    Viewer same({ "--compare", "--modes", "phong,phong,flat", "--diff", "1,2" }, "1200x400");
    ASSERT_TRUE(same.HasWindow()) << same.Stderr();
    const Image identical = same.Screenshot();
    ASSERT_EQ(identical.Width, 1200);
    EXPECT_EQ(hot(identical), 0) << "phong against phong: all black";
  }
  Viewer other({ "--compare", "--modes", "phong,phong,flat", "--diff", "1,3" }, "1200x400");
  ASSERT_TRUE(other.HasWindow()) << other.Stderr();
  const Image differing = other.Screenshot();
  ASSERT_EQ(differing.Width, 1200);
  EXPECT_GT(hot(differing), 500) << "phong against flat";
}
