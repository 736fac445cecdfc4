// One setting of a picture (--edge-width, "edge_width") and everything that
// shadelab makes of it: its option on each command that takes it, its
// scene-file key read and written, the words Copy command gives back, its
// JSON Schema and its entry in the option reference. The table of them is
// settings_table.cxx; ARCHITECTURE.md says how the pieces fit.
#ifndef shadelab_setting_h
#define shadelab_setting_h

#include "core/options.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace CLI
{
class App;
class Option;
}

namespace shadelab
{
/** The commands whose command lines take settings. */
enum class Command
{
  Render,
  Compare,
  View,
  Probe,
  Normals,
  Advise,
  CheckShader,
  Profile
};

template <>
struct NameTable<Command>
{
  static constexpr std::array<std::pair<Command, const char*>, 8> Entries{
    { { Command::Render, "render" }, { Command::Compare, "compare" }, { Command::View, "view" },
      { Command::Probe, "probe" }, { Command::Normals, "normals" }, { Command::Advise, "advise" },
      { Command::CheckShader, "check-shader" }, { Command::Profile, "profile" } }
  };
};

/** A set of commands, one bit each. */
using CommandSet = unsigned;

constexpr CommandSet Of(Command c)
{
  return 1u << static_cast<unsigned>(c);
}

/** The commands that make or explain a picture of a scene. */
constexpr CommandSet PictureCommands = Of(Command::Render) | Of(Command::Compare) |
  Of(Command::View) | Of(Command::Probe) | Of(Command::CheckShader) | Of(Command::Profile);

struct Setting
{
  std::string Option;    // "--edge-width"; "" where only scene files have it
  std::string Key;       // "edge_width", "camera.view_angle"; "" on the command line only
  std::string ValueName; // the help's "W"; "" for a flag
  std::string Help;      // the default appended, where it has one
  std::string Default;   // as the reference shows it; "" where none
  CommandSet Commands = 0;
  bool Always = false; // given back (Copy command, Save scene) even when it is the default

  /** The option on command, setting o's value; null without an option. */
  std::function<CLI::Option*(CLI::App& command, SceneOptions& o)> Declare;
  /** The words that give o's value, appended to words; none for the default. */
  std::function<void(const SceneOptions& o, std::vector<std::string>& words)> Arguments;
  /**
   * The key's value (at JSON path `path`) onto o, files relative to
   * folder; throws scene_file::SceneError. Null where another setting's
   * key reads it (--ka's is "material"'s).
   */
  std::function<void(const nlohmann::json& value, const std::string& path,
    const std::filesystem::path& folder, SceneOptions& o)>
    Read;
  /** o's value under Key in shot (nested keys in their object); nothing for the default. */
  std::function<void(const SceneOptions& o, nlohmann::ordered_json& shot)> Write;
  /** The key's JSON Schema, its description the help. Null where Read is. */
  std::function<nlohmann::ordered_json()> Schema;
  /** Sets a value other than the default on o (the table's round-trip test). */
  std::function<void(SceneOptions& o)> Sample;
  /** Read after every other key: it depends on them (the material on --texture). */
  bool ReadLast = false;
};

/** Every setting, in the order of the help, the scene files' keys and the reference. */
const std::vector<Setting>& Settings();
}

#endif
