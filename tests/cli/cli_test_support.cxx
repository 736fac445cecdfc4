#include "cli_test_support.h"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>

extern char** environ;

namespace shadelab_test
{
namespace
{
std::string Quote(const std::string& s)
{
  std::string q = "'";
  for (char c : s)
  {
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return q + "'";
}

Point3 Minus(const Point3& a, const Point3& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

double Dot(const Point3& a, const Point3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Point3 Cross(const Point3& a, const Point3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

Point3 Unit(const Point3& v)
{
  const double n = std::sqrt(Dot(v, v));
  return { v[0] / n, v[1] / n, v[2] / n };
}

}

std::string Slurp(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> VerbosePhases(const std::string& text, const std::string& program)
{
  const std::regex line(program + R"(: (\w+) ([0-9.]+) ms, peak ([0-9]+) MiB)");
  std::vector<std::string> phases;
  long lastPeak = 0;
  std::istringstream lines(text);
  for (std::string one; std::getline(lines, one);)
  {
    std::smatch m;
    if (!std::regex_match(one, m, line))
    {
      continue;
    }
    phases.push_back(m[1]);
    const long peak = std::stol(m[3]);
    EXPECT_GE(peak, lastPeak) << one;
    EXPECT_GT(peak, 0) << one;
    lastPeak = peak;
  }
  return phases;
}

RunResult RunShadelab(
  const std::vector<std::string>& args, const std::vector<std::string>& environment)
{
  return RunProgram(SHADELAB_BINARY, args, environment);
}

RunResult RunProgram(const std::filesystem::path& program, const std::vector<std::string>& args,
  const std::vector<std::string>& environment)
{
  TempDir capture;
  // A run that hangs (the fault the hostile-input tests guard against) is
  // ended after ten minutes, exit status 124, rather than holding the suite
  // until CI's own limit; no test's run comes near it.
  std::string command = "timeout -k 10 600 env -u DISPLAY";
  for (const std::string& setting : environment)
  {
    command += " " + Quote(setting);
  }
  command += " " + Quote(program.string());
  for (const std::string& a : args)
  {
    command += " " + Quote(a);
  }
  command += " >" + Quote((capture / "out").string()) + " 2>" + Quote((capture / "err").string()) +
    " </dev/null";
  const int status = std::system(command.c_str());
  RunResult r;
  r.ExitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.Stdout = Slurp(capture / "out");
  r.Stderr = Slurp(capture / "err");
  return r;
}

int StartShadelab(const std::vector<std::string>& args, const std::filesystem::path& stdoutFile,
  const std::filesystem::path& stderrFile)
{
  std::vector<std::string> words{ SHADELAB_BINARY };
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words)
  {
    argv.push_back(w.data());
  }
  argv.push_back(nullptr);
  std::vector<char*> envp; // ours, less DISPLAY
  for (char** e = environ; *e; ++e)
  {
    if (std::string(*e).rfind("DISPLAY=", 0) != 0)
    {
      envp.push_back(*e);
    }
  }
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(
    &actions, STDOUT_FILENO, stdoutFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(
    &actions, STDERR_FILENO, stderrFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int error = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  return error == 0 ? pid : -1;
}

int WaitShadelab(int pid)
{
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
  {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TempDir::TempDir()
{
  std::random_device random;
  this->Path = std::filesystem::temp_directory_path() /
    ("shadelab-test-" + std::to_string(getpid()) + "-" + std::to_string(random()));
  std::filesystem::create_directories(this->Path);
}

TempDir::~TempDir()
{
  std::error_code ignored;
  std::filesystem::remove_all(this->Path, ignored);
}

std::vector<std::string> FilesIn(const std::filesystem::path& folder)
{
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
  {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> TempDir::Files() const
{
  return FilesIn(this->Path);
}

namespace
{
// The subimage `in` is at, as an Image.
Image ReadCurrent(OIIO::ImageInput& in, int subimage)
{
  Image image;
  const OIIO::ImageSpec& spec = in.spec();
  image.Width = spec.width;
  image.Height = spec.height;
  image.Channels = spec.nchannels;
  image.Format = spec.format.c_str();
  image.Description = spec.get_string_attribute("ImageDescription");
  image.Pixels.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  const bool eightBit = spec.format == OIIO::TypeDesc::UINT8;
  in.read_image(subimage, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.Pixels.data());
  if (eightBit)
  {
    for (float& v : image.Pixels)
    {
      v = std::round(v * 255.0f);
    }
  }
  return image;
}
}

void WriteImage(const std::filesystem::path& path, int width, int height,
  const std::vector<float>& rgb, const std::string& type)
{
  // A failure shows as the test's picture missing: shadelab names the file.
  auto out = OIIO::ImageOutput::create(path.string());
  if (out && out->open(path.string(), OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc(type))))
  {
    out->write_image(OIIO::TypeDesc::FLOAT, rgb.data());
    out->close();
  }
}

void WriteImage8(
  const std::filesystem::path& path, int width, int height, const std::vector<unsigned char>& rgb)
{
  std::vector<float> values;
  for (unsigned char v : rgb)
  {
    values.push_back(v / 255.0f);
  }
  WriteImage(path, width, height, values, "uint8");
}

Image ReadImage(const std::filesystem::path& path)
{
  auto in = OIIO::ImageInput::open(path.string());
  if (!in)
  {
    (void)OIIO::geterror();
    return {};
  }
  return ReadCurrent(*in, 0);
}

std::vector<Image> ReadSubimages(const std::filesystem::path& path)
{
  std::vector<Image> images;
  auto in = OIIO::ImageInput::open(path.string());
  if (!in)
  {
    (void)OIIO::geterror();
    return images;
  }
  for (int k = 0; in->seek_subimage(k, 0); ++k)
  {
    images.push_back(ReadCurrent(*in, k));
  }
  return images;
}

size_t CountCovered(const Image& image)
{
  size_t covered = 0;
  for (size_t i = 0; i < image.Pixels.size(); i += image.Channels)
  {
    covered += image.Channels == 4
      ? image.Pixels[i + 3] > 0
      : image.Pixels[i] + image.Pixels[i + 1] + image.Pixels[i + 2] > 0;
  }
  return covered;
}

Silhouette MeasureSilhouette(const Image& image)
{
  Silhouette s;
  s.Left = image.Width;
  s.Top = image.Height;
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      const std::size_t i = (static_cast<std::size_t>(y) * image.Width + x) * image.Channels;
      if (image.Pixels[i] + image.Pixels[i + 1] + image.Pixels[i + 2] > 0)
      {
        s.Left = std::min(s.Left, x);
        s.Right = std::max(s.Right, x);
        s.Top = std::min(s.Top, y);
        s.Bottom = std::max(s.Bottom, y);
      }
    }
  }
  s.Width = s.Right - s.Left + 1;
  s.Height = s.Bottom - s.Top + 1;
  return s;
}

std::string TestShape::Obj() const
{
  std::ostringstream obj;
  obj.precision(17);
  for (const Point3& v : this->Vertices)
  {
    obj << "v " << v[0] << " " << v[1] << " " << v[2] << "\n";
  }
  return obj.str() + this->Faces;
}

TestShape Box(const Point3& sides)
{
  TestShape box;
  for (int i = 0; i < 8; ++i)
  {
    box.Vertices.push_back({ (i & 1 ? 0.5 : -0.5) * sides[0], (i & 2 ? 0.5 : -0.5) * sides[1],
      (i & 4 ? 0.5 : -0.5) * sides[2] });
  }
  // Quads (triangulated by the reader), each wound outwards.
  box.Faces = "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  return box;
}

RecordedCamera CameraOf(const Image& image)
{
  const auto j = nlohmann::json::parse(image.Description).at("camera");
  RecordedCamera c;
  c.Position = j.at("position").get<Point3>();
  c.Focal = j.at("focal_point").get<Point3>();
  c.Up = j.at("view_up").get<Point3>();
  c.Orthographic = j.at("projection") == "orthographic";
  c.ViewAngle = c.Orthographic ? 0 : j.at("view_angle_deg").get<double>();
  c.ParallelScale = c.Orthographic ? j.at("parallel_scale").get<double>() : 0;
  return c;
}

Extents Project(const RecordedCamera& c, const std::vector<Point3>& vertices, int width, int height)
{
  const Point3 forward = Unit(Minus(c.Focal, c.Position));
  const Point3 right = Unit(Cross(forward, c.Up));
  const Point3 up = Cross(right, forward);
  Extents e;
  for (const Point3& p : vertices)
  {
    const Point3 v = Minus(p, c.Position);
    const double halfHeight =
      c.Orthographic ? c.ParallelScale : Dot(v, forward) * std::tan(c.ViewAngle * M_PI / 360);
    const double x = (Dot(v, right) / (halfHeight * width / height) + 1) / 2 * width;
    const double y = (1 - Dot(v, up) / halfHeight) / 2 * height;
    e.Left = std::min(e.Left, x);
    e.Right = std::max(e.Right, x);
    e.Top = std::min(e.Top, y);
    e.Bottom = std::max(e.Bottom, y);
  }
  return e;
}

std::filesystem::path TestMesh(const std::string& name)
{
  return std::filesystem::path(SHADELAB_TEST_MESHES) / name;
}

std::filesystem::path DebianModel(const std::string& path)
{
  return std::filesystem::path(SHADELAB_DEBIAN_MODELS) / path;
}

std::filesystem::path MetalBoxTextured(const std::filesystem::path& dir, bool binary)
{
  const auto metal = [](nlohmann::json document)
  {
    document.at("materials").at(0).at("pbrMetallicRoughness")["metallicFactor"] = 1;
    return document.dump();
  };
  if (!binary)
  {
    for (const char* file : { "BoxTextured0.bin", "CesiumLogoFlat.png" })
    {
      std::filesystem::copy_file(DebianModel(std::string("glTF2/BoxTextured-glTF/") + file),
        dir / file, std::filesystem::copy_options::overwrite_existing);
    }
    WriteText(dir / "metal.gltf",
      metal(nlohmann::json::parse(Slurp(DebianModel("glTF2/BoxTextured-glTF/BoxTextured.gltf")))));
    return dir / "metal.gltf";
  }
  // The JSON chunk rewritten: 12 bytes of header (magic, version, length),
  // the JSON chunk (length, type, text padded with spaces to 4 bytes), the
  // BIN chunk as it was.
  const std::string glb = Slurp(DebianModel("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"));
  std::uint32_t jsonLength = 0;
  std::memcpy(&jsonLength, glb.data() + 12, 4);
  std::string text = metal(nlohmann::json::parse(glb.substr(20, jsonLength)));
  text.append((4 - text.size() % 4) % 4, ' ');
  const std::string rest = glb.substr(20 + jsonLength);
  const std::uint32_t header[5] = { 0x46546C67, 2,
    static_cast<std::uint32_t>(20 + text.size() + rest.size()),
    static_cast<std::uint32_t>(text.size()), 0x4E4F534A };
  WriteText(dir / "metal.glb",
    std::string(reinterpret_cast<const char*>(header), sizeof header) + text + rest);
  return dir / "metal.glb";
}

void WriteText(const std::filesystem::path& path, const std::string& text)
{
  std::ofstream(path, std::ios::binary) << text;
}

void WriteRgbTriangle(const std::filesystem::path& path)
{
  WriteText(path,
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "-1 -1 0 255 0 0\n1 -1 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n");
}
}
