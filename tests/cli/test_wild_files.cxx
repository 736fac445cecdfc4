// Files from public sample collections (../shared/data/wild, beside the
// repository when it is there; MANIFEST.tsv names each one's source,
// licence, what it exercises and what shadelab must do with it): each
// renders (exit 0, a picture with something drawn), or is refused (exit 1,
// one line that names it, no picture), or either where the manifest says
// "refuse|render" (an extension shadelab may or may not read).
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

using namespace shadelab_test;

namespace
{
const std::filesystem::path Wild =
  std::filesystem::path(SHADELAB_SOURCE_DIR) / "../shared/data/wild";

struct WildFile
{
  std::string File;     // relative to Wild
  std::string Expected; // render, refuse, or refuse|render
};

// MANIFEST.tsv: a header, then file, source, path there, licence,
// exercises, expected; tab-separated.
std::vector<WildFile> ReadManifest()
{
  std::vector<WildFile> files;
  std::ifstream manifest(Wild / "MANIFEST.tsv");
  std::string line;
  std::getline(manifest, line); // the header
  while (std::getline(manifest, line))
  {
    std::vector<std::string> fields;
    std::istringstream columns(line);
    for (std::string field; std::getline(columns, field, '\t');)
    {
      fields.push_back(field);
    }
    if (fields.size() == 6)
    {
      files.push_back({ fields[0], fields[5] });
    }
    else
    {
      ADD_FAILURE() << "MANIFEST.tsv: not 6 fields: " << line;
    }
  }
  return files;
}
}

TEST(WildFiles, EachRendersOrIsRefusedAsItsManifestSays)
{
  if (!std::filesystem::is_regular_file(Wild / "MANIFEST.tsv"))
  {
    GTEST_SKIP() << Wild << " is not here (the shared test data beside the repository)";
  }
  const std::vector<WildFile> files = ReadManifest();
  ASSERT_GT(files.size(), 40u);
  TempDir dir;
  int rendered = 0, refused = 0;
  for (const WildFile& wild : files)
  {
    SCOPED_TRACE(wild.File + " (expected: " + wild.Expected + ")");
    ASSERT_TRUE(
      wild.Expected == "render" || wild.Expected == "refuse" || wild.Expected == "refuse|render");
    const std::string mesh = (Wild / wild.File).string();
    const std::filesystem::path picture = dir / (std::to_string(rendered + refused) + ".png");
    const RunResult run = RunShadelab(
      { "render", mesh, "-o", picture.string(), "--size", "96x72", "--view", "iso", "--quiet" });
    if (run.ExitCode == 0)
    {
      EXPECT_NE(wild.Expected, "refuse") << run.Stderr;
      const Image image = ReadImage(picture);
      ASSERT_EQ(image.Width, 96);
      EXPECT_GT(CountCovered(image), 0u) << "nothing drawn";
      ++rendered;
      continue;
    }
    EXPECT_EQ(run.ExitCode, 1) << run.Stderr;
    EXPECT_NE(wild.Expected, "render") << run.Stderr;
    EXPECT_EQ(run.Stderr.rfind("shadelab: error: " + mesh + ": ", 0), 0u) << run.Stderr;
    EXPECT_EQ(std::count(run.Stderr.begin(), run.Stderr.end(), '\n'), 1) << run.Stderr;
    EXPECT_FALSE(std::filesystem::exists(picture));
    ++refused;
  }
  std::cout << files.size() << " files: " << rendered << " rendered, " << refused << " refused\n";
}
