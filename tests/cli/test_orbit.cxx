// --orbit N: N frames turning the camera once about the up axis, into a
// {frame} template, an animated GIF or an MP4 (through ffmpeg). Frame k is
// exactly the picture --azimuth 360*k/N gives; the GIF and the MP4 hold every
// frame in order; with --fit tight every frame holds the whole mesh at one
// size; mistakes are one-line errors that leave nothing behind.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <thread>

using namespace shadelab_test;

namespace
{
const std::vector<std::string> Small{ "--size", "64x48", "--material", "gold" };

RunResult Render(
  const std::vector<std::string>& args, const std::vector<std::string>& environment = {})
{
  std::vector<std::string> words{ "render" };
  words.insert(words.end(), args.begin(), args.end());
  words.insert(words.end(), Small.begin(), Small.end());
  return RunShadelab(words, environment);
}

// The mean over pixels and RGB of |a - b|, in 8-bit steps (a GIF reads back
// as RGBA).
double MeanDifference(const Image& a, const Image& b)
{
  double sum = 0;
  const std::size_t pixels = static_cast<std::size_t>(a.Width) * a.Height;
  for (std::size_t i = 0; i < pixels; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      sum += std::fabs(a.Pixels[i * a.Channels + c] - b.Pixels[i * b.Channels + c]);
    }
  }
  return sum / static_cast<double>(3 * pixels);
}

bool OnPath(const std::string& program)
{
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

// Every line a command printed.
std::string Output(const std::string& command)
{
  std::string text;
  if (FILE* pipe = popen(command.c_str(), "r"))
  {
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe))
    {
      text += buffer;
    }
    pclose(pipe);
  }
  return text;
}
}

TEST(Orbit, FrameKIsTheAzimuthTurnedBy360KOverN)
{
  TempDir dir;
  const std::string teapot = TestMesh("teapot.obj").string();
  const RunResult r =
    Render({ teapot, "-o", (dir / "frames" / "{frame}.png").string(), "--orbit", "12" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  std::vector<std::string> names;
  for (int k = 0; k < 12; ++k)
  {
    names.push_back((k < 10 ? "0" : "") + std::to_string(k) + ".png");
  }
  EXPECT_EQ(FilesIn(dir / "frames"), names) << "numbered to the width of 11";
  std::vector<Image> frames;
  for (const std::string& name : names)
  {
    frames.push_back(ReadImage(dir / "frames" / name));
  }
  for (std::size_t k = 0; k < frames.size(); ++k)
  {
    EXPECT_NE(frames[k].Pixels, frames[(k + 1) % frames.size()].Pixels) << "frames " << k;
  }
  // Frame 0 is the plain picture, the last one step (30 degrees) before it.
  ASSERT_EQ(Render({ teapot, "-o", (dir / "plain.png").string() }).ExitCode, 0);
  EXPECT_EQ(frames.front().Pixels, ReadImage(dir / "plain.png").Pixels);
  ASSERT_EQ(Render({ teapot, "-o", (dir / "330.png").string(), "--azimuth", "330" }).ExitCode, 0);
  EXPECT_EQ(frames.back().Pixels, ReadImage(dir / "330.png").Pixels);
  // Ten frames number 0 to 9, with a given azimuth added.
  ASSERT_EQ(Render({ teapot, "-o", (dir / "ten" / "f{frame}.png").string(), "--orbit", "10",
                     "--azimuth", "5" })
              .ExitCode,
    0);
  EXPECT_EQ(FilesIn(dir / "ten").size(), 10u);
  ASSERT_EQ(Render({ teapot, "-o", (dir / "77.png").string(), "--azimuth", "77" }).ExitCode, 0);
  EXPECT_EQ(ReadImage(dir / "ten" / "f2.png").Pixels, ReadImage(dir / "77.png").Pixels);
}

TEST(Orbit, AGifHoldsEveryFrameInOrder)
{
  TempDir dir;
  const std::string teapot = TestMesh("teapot.obj").string();
  ASSERT_EQ(Render({ teapot, "-o", (dir / "{frame}.png").string(), "--orbit", "6" }).ExitCode, 0);
  const RunResult r =
    Render({ teapot, "-o", (dir / "spin.gif").string(), "--orbit", "6", "--fps", "20" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  const std::vector<Image> gif = ReadSubimages(dir / "spin.gif");
  ASSERT_EQ(gif.size(), 6u);
  for (std::size_t k = 0; k < gif.size(); ++k)
  {
    SCOPED_TRACE("frame " + std::to_string(k));
    ASSERT_EQ(gif[k].Width, 64);
    ASSERT_EQ(gif[k].Height, 48);
    // GIF holds 256 colours, dithered: each frame is near its PNG (a mean
    // of 0.24 to 0.28 steps here, the dither's noise on the mesh's quarter
    // of the pixels; the background is exact) and nearer to it than to any
    // other frame.
    const Image png = ReadImage(dir / (std::to_string(k) + ".png"));
    const double own = MeanDifference(gif[k], png);
    EXPECT_LT(own, 1);
    for (std::size_t other = 0; other < gif.size(); ++other)
    {
      if (other != k)
      {
        EXPECT_LT(own, MeanDifference(gif[k], ReadImage(dir / (std::to_string(other) + ".png"))));
      }
    }
  }
  // 20 frames a second: 5 hundredths of a second each.
  auto in = OIIO::ImageInput::open((dir / "spin.gif").string());
  ASSERT_TRUE(in);
  const int* rate = static_cast<const int*>(in->spec().find_attribute("FramesPerSecond")->data());
  EXPECT_EQ(static_cast<double>(rate[0]) / rate[1], 20);
}

TEST(Orbit, AnMp4HoldsEveryFrame)
{
  if (!OnPath("ffmpeg") || !OnPath("ffprobe"))
  {
    GTEST_SKIP() << "ffmpeg and ffprobe are not installed (Debian: apt-get install ffmpeg)";
  }
  TempDir dir;
  const RunResult r =
    Render({ TestMesh("teapot.obj").string(), "-o", (dir / "spin.mp4").string(), "--orbit", "9" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  EXPECT_EQ(Output("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                   "stream=nb_read_frames,width,height,r_frame_rate -of csv=p=0 '" +
              (dir / "spin.mp4").string() + "'"),
    "64,48,25/1,9\n");
  EXPECT_EQ(dir.Files(), std::vector<std::string>{ "spin.mp4" });
}

TEST(Orbit, WithoutFfmpegAnMp4IsRefusedBeforeAnythingRenders)
{
  TempDir dir, empty;
  WriteText(dir / "scene.json",
    R"({ "mesh": ")" + TestMesh("teapot.obj").string() + R"(", "size": [64, 48],
         "shots": [ { "output": ")" +
      (dir / "still.png").string() + R"(" },
                    { "output": ")" +
      (dir / "spin.mp4").string() + R"(", "orbit": 4 } ] })");
  const RunResult r = RunShadelab(
    { "render", "--scene", (dir / "scene.json").string() }, { "PATH=" + empty.path().string() });
  EXPECT_EQ(r.ExitCode, 1);
  EXPECT_EQ(r.Stderr,
    "shadelab: error: " + (dir / "spin.mp4").string() +
      ": writing .mp4 needs the ffmpeg program, which is not on PATH (Debian: apt-get install "
      "ffmpeg)\n");
  EXPECT_EQ(dir.Files(), std::vector<std::string>{ "scene.json" }) << "not even the still";
}

TEST(Orbit, AFailingFfmpegLeavesNothing)
{
  TempDir dir, programs;
  // An ffmpeg that reads every frame and fails at the end, and one that
  // fails at once.
  for (const auto& [name, script] :
    { std::pair{ "late", "cat >/dev/null; echo 'late: encoder broke' >&2; exit 3" },
      std::pair{ "early", "echo 'early: no such encoder' >&2; exit 1" } })
  {
    SCOPED_TRACE(name);
    std::filesystem::create_directories(programs / name);
    WriteText(programs / name / "ffmpeg", std::string("#!/bin/sh\n") + script + "\n");
    std::filesystem::permissions(programs / name / "ffmpeg", std::filesystem::perms::owner_all);
    const RunResult r =
      Render({ TestMesh("teapot.obj").string(), "-o", (dir / "spin.mp4").string(), "--orbit", "5" },
        { "PATH=" + (programs / name).string() + ":/usr/bin:/bin" });
    EXPECT_EQ(r.ExitCode, 1);
    EXPECT_EQ(
      r.Stderr.rfind(
        "shadelab: error: " + (dir / "spin.mp4").string() + ": ffmpeg failed (exit status ", 0),
      0u)
      << r.Stderr;
    EXPECT_NE(r.Stderr.find(std::string(name) + ": "), std::string::npos) << r.Stderr;
    EXPECT_EQ(std::count(r.Stderr.begin(), r.Stderr.end(), '\n'), 1) << r.Stderr;
    EXPECT_TRUE(dir.Files().empty()) << "no video, no temporary";
  }
}

TEST(Orbit, AnAnimationCutShortIsNotWritten)
{
  for (const std::string format : { ".gif", ".mp4" })
  {
    SCOPED_TRACE(format);
    if (format == ".mp4" && !OnPath("ffmpeg"))
    {
      continue; // AnMp4HoldsEveryFrame says it is skipped
    }
    TempDir dir, logs;
    const std::string out = (dir / ("spin" + format)).string();
    const int pid = StartShadelab({ "render", TestMesh("teapot.obj").string(), "-o", out, "--orbit",
                                    "1000", "--size", "320x240", "-v" },
      logs / "stdout", logs / "stderr");
    ASSERT_GT(pid, 0);
    // -v prints a line per frame: stop it a few frames in.
    const auto start = std::chrono::steady_clock::now();
    std::string said;
    while (std::count(said.begin(), said.end(), '\n') < 3 ||
      said.find("shadelab: frame") == std::string::npos)
    {
      ASSERT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(60));
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      std::ifstream err(logs / "stderr");
      said.assign(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
    }
    kill(pid, SIGINT);
    EXPECT_EQ(WaitShadelab(pid), 128 + SIGINT);
    std::ifstream err(logs / "stderr");
    said.assign(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
    EXPECT_NE(
      said.find("shadelab: error: " + out + ": interrupted before its last frame: not written\n"),
      std::string::npos)
      << said;
    EXPECT_NE(said.find("after 1 of 1 shots: 0 written, 0 skipped, 1 failed"), std::string::npos)
      << said;
    EXPECT_TRUE(dir.Files().empty()) << "no animation, no temporary";
  }
}

TEST(Orbit, ManyMeshesAndSceneFilesNumberTheirFrames)
{
  TempDir dir;
  ASSERT_EQ(Render({ TestMesh("teapot.obj").string(), TestMesh("torus.obj").string(), "-o",
                     (dir / "{mesh}" / "{frame}.png").string(), "--orbit", "3" })
              .ExitCode,
    0);
  EXPECT_EQ(FilesIn(dir / "teapot"), (std::vector<std::string>{ "0.png", "1.png", "2.png" }));
  EXPECT_EQ(FilesIn(dir / "torus"), (std::vector<std::string>{ "0.png", "1.png", "2.png" }));
  WriteText(dir / "scene.json",
    R"({ "mesh": ")" + TestMesh("teapot.obj").string() + R"(", "size": [64, 48], "orbit": 2,
         "output": ")" +
      (dir / "scene" / "{name}-{frame}.png").string() + R"(",
         "shots": [ { "name": "a" }, { "name": "b", "fps": 10, "output": ")" +
      (dir / "scene" / "b.gif").string() + R"(" } ] })");
  const RunResult r = RunShadelab({ "render", "--scene", (dir / "scene.json").string() });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  EXPECT_EQ(FilesIn(dir / "scene"), (std::vector<std::string>{ "a-0.png", "a-1.png", "b.gif" }));
  EXPECT_EQ(ReadSubimages(dir / "scene" / "b.gif").size(), 2u);
}

TEST(Orbit, TightFitHoldsEveryFrameAtOneSize)
{
  TempDir dir;
  const TestShape box = Box({ 1, 2, 4 });
  WriteText(dir / "box.obj", box.Obj());
  for (const bool orthographic : { false, true })
  {
    SCOPED_TRACE(orthographic ? "orthographic" : "perspective");
    const std::string folder = orthographic ? "ortho" : "persp";
    std::vector<std::string> args{ (dir / "box.obj").string(), "-o",
      (dir / folder / "{frame}.png").string(), "--orbit", "8", "--view", "iso", "--fit", "tight",
      "--azimuth", "10" };
    if (orthographic)
    {
      args.push_back("--orthographic");
    }
    ASSERT_EQ(Render(args).ExitCode, 0);
    const RecordedCamera first = CameraOf(ReadImage(dir / folder / "0.png"));
    const auto distance = [](const RecordedCamera& c)
    {
      const double dx = c.Position[0] - c.Focal[0], dy = c.Position[1] - c.Focal[1],
                   dz = c.Position[2] - c.Focal[2];
      return std::sqrt(dx * dx + dy * dy + dz * dz);
    };
    double widest = 0; // of the frames' projections, as a share of the picture's side
    for (int k = 0; k < 8; ++k)
    {
      SCOPED_TRACE("frame " + std::to_string(k));
      const Image frame = ReadImage(dir / folder / (std::to_string(k) + ".png"));
      const RecordedCamera c = CameraOf(frame);
      // One turn's centre and one size for all frames (up to rounding).
      for (int i = 0; i < 3; ++i)
      {
        EXPECT_NEAR(c.Focal[i], first.Focal[i], 1e-12);
      }
      EXPECT_NEAR(distance(c), distance(first), 1e-12 * distance(first));
      EXPECT_NEAR(c.ParallelScale, first.ParallelScale, 1e-12 * first.ParallelScale);
      // The whole box in every frame (a millionth of a pixel is rounding).
      const Extents e = Project(c, box.Vertices, 64, 48);
      EXPECT_GE(e.Left, -1e-6);
      EXPECT_LE(e.Right, 64 + 1e-6);
      EXPECT_GE(e.Top, -1e-6);
      EXPECT_LE(e.Bottom, 48 + 1e-6);
      widest = std::max({ widest, (32 - e.Left) / 32, (e.Right - 32) / 32, (24 - e.Top) / 24,
        (e.Bottom - 24) / 24 });
    }
    // and no larger than that: some frame reaches a border exactly.
    EXPECT_NEAR(widest, 1, 1e-9);
  }
}

TEST(Orbit, MistakesAreOneLineErrors)
{
  TempDir dir;
  const std::string teapot = TestMesh("teapot.obj").string(), png = (dir / "a.png").string();
  const std::vector<std::tuple<std::vector<std::string>, int, std::string>> cases{
    { { teapot, "-o", png, "--orbit", "0" }, 2, "--orbit" },
    { { teapot, "-o", png, "--orbit", "-3" }, 2, "--orbit" },
    { { teapot, "-o", png, "--orbit", "x" }, 2, "--orbit" },
    { { teapot, "-o", png, "--orbit", "2.5" }, 2, "--orbit" },
    { { teapot, "-o", png, "--orbit", "4000" }, 2, "--orbit" },
    { { teapot, "-o", png, "--orbit", "3" }, 2,
      "shadelab: error: --output: \"" + png +
        "\" has no {frame} (a picture per frame of --orbit) nor the extension .gif or .mp4 (one "
        "animation of them all)\n" },
    { { teapot, "-o", png, "--fps", "10" }, 2, "--fps" },
    { { teapot, "-o", (dir / "a.gif").string(), "--orbit", "3", "--fps", "0" }, 2, "--fps" },
    { { teapot, "-o", (dir / "a.gif").string(), "--orbit", "3", "--fps", "60" }, 1,
      "--fps at most 50" },
    { { teapot, TestMesh("torus.obj").string(), "-o", (dir / "{mesh}-{frame}.png").string() }, 2,
      "{frame} numbers --orbit's frames" },
    { { teapot, "-o", (dir / "odd.mp4").string(), "--orbit", "2", "--size", "65x48" }, 1,
      "needs an even width and height, not 65x48" },
    { { teapot, "-o", (dir / "clear.mp4").string(), "--orbit", "2", "--size", "64x48",
        "--background", "transparent" },
      1, "cannot store transparency" },
  };
  for (const auto& [args, status, says] : cases)
  {
    std::vector<std::string> words{ "render" };
    words.insert(words.end(), args.begin(), args.end());
    const RunResult r = RunShadelab(words);
    SCOPED_TRACE(r.Stderr);
    EXPECT_EQ(r.ExitCode, status);
    EXPECT_EQ(std::count(r.Stderr.begin(), r.Stderr.end(), '\n'), 1);
    EXPECT_NE(r.Stderr.find(says), std::string::npos);
  }
  EXPECT_TRUE(dir.Files().empty());
}
