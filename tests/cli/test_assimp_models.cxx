// Files from the wild: every one of Debian's assimp-testmodels (about 600
// files in some 50 formats, /usr/share/assimp/models) in one batch, which
// must neither crash, nor hang, nor take more than 2 GB: each file renders
// or is refused in one line that names it (or a file beside it that it
// names, such as a texture). Prints the counts per format and the pictures
// that cover no pixel; SHADELAB_ASSIMP_MODELS_KEEP=FOLDER keeps the
// pictures there, named by the model (for a contact sheet).
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <thread>

using namespace shadelab_test;

namespace
{
const std::filesystem::path Models = "/usr/share/assimp/models";

// JSON's string syntax for a path (the models' names are plain ASCII).
std::string JsonString(const std::string& text)
{
  std::string quoted = "\"";
  for (char c : text)
  {
    quoted += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
  }
  return quoted + "\"";
}
}

TEST(AssimpModels, EachRendersOrIsRefusedInOneLine)
{
  if (!std::filesystem::is_directory(Models))
  {
    GTEST_SKIP() << Models << " is missing (Debian's assimp-testmodels; scripts/setup installs it)";
  }
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(Models))
  {
    if (entry.is_regular_file())
    {
      files.push_back(entry.path().string());
    }
  }
  ASSERT_GT(files.size(), 100u);
  TempDir dir;
  std::ostringstream scene;
  scene
    << R"({ "output": ")" << (dir / "{name}.png").string()
    << R"(", "size": [64, 48], "background": "transparent", "camera": { "view": "iso" }, "shots": [)";
  for (std::size_t i = 0; i < files.size(); ++i)
  {
    scene << (i ? "," : "") << R"({ "name": "m)" << i << R"(", "mesh": )" << JsonString(files[i])
          << " }";
  }
  scene << "] }";
  WriteText(dir / "scene.json", scene.str());

  const int pid = StartShadelab(
    { "render", "--scene", (dir / "scene.json").string(), "--quiet" }, dir / "out", dir / "err");
  ASSERT_GT(pid, 0);
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0)
  {
    if (std::chrono::steady_clock::now() - start > std::chrono::minutes(10))
    {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      FAIL() << "no end after 10 minutes: a hang";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_TRUE(WIFEXITED(status)) << "died of signal " << WTERMSIG(status);
  EXPECT_LE(WEXITSTATUS(status), 1);
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  EXPECT_LT(usage.ru_maxrss, 2L << 20) << "KiB at the peak: more than 2 GB";

  // Each line an error naming one of the files, or the batch's summary.
  std::istringstream err(Slurp(dir / "err"));
  std::set<std::string> refused;
  std::size_t summaries = 0;
  for (std::string line; std::getline(err, line);)
  {
    // "shadelab: error: scene.json shots[7]: FILE: PROBLEM", then the
    // summary "shadelab: 540 of 595 shots failed".
    if (line.rfind("shadelab: ", 0) == 0 && line.find(" shots failed") != std::string::npos)
    {
      ++summaries;
      continue;
    }
    if (line.rfind("shadelab: error: ", 0) != 0)
    {
      ADD_FAILURE() << "not an error line: " << line;
      continue;
    }
    // The shot's model, or a file it names beside it (a missing texture).
    const auto shot = line.find(" shots[");
    const std::size_t index =
      shot == std::string::npos ? files.size() : std::stoul(line.substr(shot + 7));
    const auto named = files.begin() + std::min(index, files.size());
    const std::string folder =
      std::filesystem::path(files[std::min(index, files.size() - 1)]).parent_path().string();
    if (named == files.end() || line.find("]: " + folder + "/") == std::string::npos)
    {
      ADD_FAILURE() << "names no model: " << line;
      continue;
    }
    EXPECT_TRUE(refused.insert(*named).second) << "refused twice: " << line;
  }
  EXPECT_LE(summaries, 1u);
  // Every other file was drawn.
  const char* keep = std::getenv("SHADELAB_ASSIMP_MODELS_KEEP");
  std::map<std::string, std::array<int, 2>> counts; // extension: drawn, refused
  std::size_t pictures = 0;
  for (std::size_t i = 0; i < files.size(); ++i)
  {
    const auto picture = dir / ("m" + std::to_string(i) + ".png");
    const bool drawn = std::filesystem::exists(picture);
    pictures += drawn;
    EXPECT_TRUE(drawn || refused.count(files[i])) << files[i] << ": neither drawn nor refused";
    std::string extension = std::filesystem::path(files[i]).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
      [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    ++counts[extension][drawn ? 0 : 1];
    if (drawn && CountCovered(ReadImage(picture)) == 0)
    {
      std::cout << "drawn, no pixel covered: " << files[i] << "\n";
    }
    if (drawn && keep)
    {
      std::string name = std::filesystem::relative(files[i], Models).string();
      std::replace(name.begin(), name.end(), '/', '_');
      std::filesystem::copy_file(picture, std::filesystem::path(keep) / (name + ".png"),
        std::filesystem::copy_options::overwrite_existing);
    }
  }
  EXPECT_EQ(pictures + refused.size(), files.size());
  std::cout << "format\tdrawn\trefused\n";
  for (const auto& [extension, count] : counts)
  {
    std::cout << (extension.empty() ? "(none)" : extension) << "\t" << count[0] << "\t" << count[1]
              << "\n";
  }
  std::cout << files.size() << " files: " << pictures << " drawn, " << refused.size()
            << " refused in one line\n";
}
