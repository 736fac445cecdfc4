// The table of settings held to itself, setting by setting, so that a new
// setting is covered without a test of its own: a value other than the
// default, given on the command line, written by Save scene, read back and
// given back by Copy command, is the same to the last bit; the schema takes
// the written file and refuses a value of the wrong type under its key.
#include "scene/scene_file.h"
#include "settings/command_line.h"
#include "settings/setting_kinds.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using namespace shadelab;
using nlohmann::json;

namespace
{
std::filesystem::path Folder()
{
  return std::filesystem::temp_directory_path() / ("shadelab-settings-" + std::to_string(getpid()));
}

std::string ReadText(const std::filesystem::path& path)
{
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The value under a key "a" or "a.b" of a shot, or null.
const json* Find(const json& shot, const std::string& key)
{
  const auto dot = key.find('.');
  const std::string top = key.substr(0, dot);
  if (!shot.contains(top))
  {
    return nullptr;
  }
  if (dot == std::string::npos)
  {
    return &shot[top];
  }
  const json& inner = shot[top];
  return inner.is_object() && inner.contains(key.substr(dot + 1)) ? &inner[key.substr(dot + 1)]
                                                                  : nullptr;
}

// The name a test calls a setting by.
std::string NameOf(const Setting& s)
{
  return s.Option.empty() ? s.Key : s.Option;
}
}

TEST(SettingsTable, EverySettingRoundTripsThroughTheCommandLineAndASceneFile)
{
  const auto folder = Folder();
  std::filesystem::create_directories(folder);
  std::map<std::string, bool> expectedValid; // a file the schema checks -> whether it is valid
  int tested = 0;
  for (const Setting& s : Settings())
  {
    if (!s.Sample)
    {
      EXPECT_TRUE(s.Option.empty() && !s.Write) << s.Key << ": a setting with no sample";
      continue;
    }
    ++tested;
    SCOPED_TRACE(NameOf(s));
    SceneOptions given;
    given.Mesh = (folder / "mesh.obj").string();
    s.Sample(given);

    // The command line: its words, parsed, give them again.
    const std::vector<std::string> words = SceneArguments(given);
    if (!s.Option.empty())
    {
      EXPECT_NE(std::find(words.begin(), words.end(), s.Option), words.end())
        << "the sample is not given back: it is the default";
    }
    SceneOptions parsed;
    parsed.Mesh = given.Mesh;
    ApplySceneArguments(parsed, words);
    EXPECT_EQ(SceneArguments(parsed), words);
    // Bit for bit: JSON writes every double exactly.
    const std::string output = parsed.Orbit ? "out.gif" : "out.png";
    EXPECT_EQ(WriteSceneText(parsed, output), WriteSceneText(given, output));

    // Save scene, read back: the same words, the same file.
    const std::string text = WriteSceneText(parsed, output);
    const auto file = folder / (std::to_string(tested) + ".json");
    std::ofstream(file) << text;
    std::vector<Shot> shots;
    ASSERT_EQ(ReadSceneFile(file.string(), "", shots), "") << text;
    ASSERT_EQ(shots.size(), 1u);
    const json written = json::parse(text);
    if (s.Key.empty())
    {
      // The command line's only (the user's trust): never in a file.
      SceneOptions plain;
      plain.Mesh = given.Mesh;
      EXPECT_EQ(text, WriteSceneText(plain, output));
      continue;
    }
    EXPECT_EQ(SceneArguments(shots[0].Scene), words) << text;
    EXPECT_EQ(WriteSceneText(shots[0].Scene, output), text);
    const json* value = Find(written, s.Key);
    ASSERT_NE(value, nullptr) << s.Key << " is not written:\n" << text;
    expectedValid[file.string()] = true;

    // The same file with a value of the wrong type under the key: refused
    // by the reader and by the schema.
    json wrong = written;
    const auto dot = s.Key.find('.');
    json& at =
      dot == std::string::npos ? wrong[s.Key] : wrong[s.Key.substr(0, dot)][s.Key.substr(dot + 1)];
    at = value->is_string() ? json(7) : json("wrong");
    const auto wrongFile = folder / (std::to_string(tested) + "-wrong.json");
    std::ofstream(wrongFile) << wrong.dump(2);
    EXPECT_NE(ReadSceneFile(wrongFile.string(), "", shots), "") << wrong.dump();
    expectedValid[wrongFile.string()] = false;
  }
  EXPECT_GE(tested, 40); // the settings of the table when this test was written

  // The schema, as render --print-schema gives it, on every file.
  const auto schema = folder / "scene.schema.json";
  std::ofstream(schema) << SceneSchema();
  std::string command =
    "python3 " SHADELAB_SOURCE_DIR "/tests/unit/validate_json_schema.py " + schema.string();
  for (const auto& [file, valid] : expectedValid)
  {
    command += " " + file;
  }
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string out;
  char buffer[4096];
  while (std::size_t n = fread(buffer, 1, sizeof buffer, pipe))
  {
    out.append(buffer, n);
  }
  const int exit = WEXITSTATUS(pclose(pipe));
  if (exit == 3)
  {
    std::filesystem::remove_all(folder);
    GTEST_SKIP() << out;
  }
  ASSERT_EQ(exit, 0) << out;
  std::istringstream lines(out);
  std::string status, path;
  std::size_t checked = 0;
  while (lines >> status >> path)
  {
    std::string message;
    std::getline(lines, message);
    path = path.substr(0, path.find(':'));
    ASSERT_EQ(expectedValid.count(path), 1u) << status << " " << path;
    EXPECT_EQ(status == "valid", expectedValid[path]) << status << " " << path << message << "\n"
                                                      << ReadText(path);
    ++checked;
  }
  EXPECT_EQ(checked, expectedValid.size()) << out;
  std::filesystem::remove_all(folder);
}
