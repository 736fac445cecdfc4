#include "settings/option_reference.h"

#include "settings/scene_keys.h"
#include "settings/setting.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <sstream>

namespace shadelab
{
namespace
{
using nlohmann::ordered_json;

std::string Bound(const ordered_json& v)
{
  std::ostringstream text;
  text << v.get<double>();
  return text.str();
}

// What a key's JSON Schema takes, in words.
std::string Describe(const ordered_json& schema)
{
  if (schema.contains("enum"))
  {
    std::string names;
    for (const auto& name : schema["enum"])
    {
      names += (names.empty() ? "" : ", ") + name.dump();
    }
    return "one of " + names;
  }
  if (schema.contains("oneOf"))
  {
    std::string either;
    for (const auto& alternative : schema["oneOf"])
    {
      either += (either.empty() ? "" : ", or ") + Describe(alternative);
    }
    return either;
  }
  if (schema.contains("const"))
  {
    return schema["const"].dump();
  }
  if (schema.contains("$ref"))
  {
    const std::string ref = schema["$ref"];
    return ref == "#/$defs/color"    ? "[r, g, b], none negative"
      : ref == "#/$defs/attenuation" ? "[c0, c1, c2], none negative, not all zero"
                                     : "[x, y, z]";
  }
  const std::string type = schema.value("type", "");
  if (type == "number" || type == "integer")
  {
    std::string text = type == "number" ? "a number" : "a whole number";
    const bool low = schema.contains("minimum") || schema.contains("exclusiveMinimum");
    const bool high = schema.contains("maximum") || schema.contains("exclusiveMaximum");
    const char* open = schema.contains("exclusiveMinimum") ? "(" : "[";
    const char* close = schema.contains("exclusiveMaximum") ? ")" : "]";
    const auto& min = schema.contains("minimum") ? schema["minimum"] : schema["exclusiveMinimum"];
    const auto& max = schema.contains("maximum") ? schema["maximum"] : schema["exclusiveMaximum"];
    if (low && high)
    {
      text += std::string(" in ") + open + Bound(min) + ", " + Bound(max) + close;
    }
    else if (low)
    {
      text += std::string(schema.contains("minimum") ? " >= " : " > ") + Bound(min);
    }
    return text;
  }
  if (type == "boolean")
  {
    return "true or false";
  }
  if (type == "string")
  {
    return "a string";
  }
  if (type == "object")
  {
    std::string keys;
    for (const auto& item : schema["properties"].items())
    {
      keys += (keys.empty() ? "" : ", ") + item.key();
    }
    return "an object of " + keys;
  }
  if (type == "array" && schema["items"].value("type", "") == "object")
  {
    return "an array of " + Describe(schema["items"]);
  }
  if (type == "array")
  {
    return "[width, height], whole numbers in [" + Bound(schema["items"]["minimum"]) + ", " +
      Bound(schema["items"]["maximum"]) + "]";
  }
  return type;
}

// "-o, --output", "MESH": an option's names.
std::string Names(const CLI::Option& option)
{
  if (option.get_positional())
  {
    return option.get_name(true);
  }
  std::string names = option.get_name(false, true);
  for (std::size_t comma = names.find(','); comma != std::string::npos;
       comma = names.find(',', comma + 2))
  {
    names.insert(comma + 1, " ");
  }
  return names;
}

// "--edge-width W", "-o, --output OUT", "MESH": as the help shows an option.
std::string Synopsis(const CLI::Option& option)
{
  const std::string& value = option.get_option_text();
  return Names(option) + (value.empty() || option.get_positional() ? "" : " " + value);
}

const Setting* SettingOf(const CLI::Option& option)
{
  const auto& all = Settings();
  const auto s = std::find_if(all.begin(), all.end(),
    [&option](const Setting& s) { return !s.Option.empty() && option.check_name(s.Option); });
  return s == all.end() ? nullptr : &*s;
}

std::vector<CLI::App*> Commands(CLI::App& program)
{
  // Not the hidden ones (print-reference itself).
  return program.get_subcommands([](CLI::App* c) { return !c->get_group().empty(); });
}

void AddSetting(std::ostringstream& out, const Setting& s, CLI::App& program)
{
  out << "### " << (s.Option.empty() ? s.Key + " (scene files)" : s.Option) << "\n\n";
  std::string commands;
  std::string others; // descriptions a command gives the option instead
  const CLI::Option* first = nullptr;
  for (CLI::App* command : Commands(program))
  {
    const CLI::Option* option = s.Option.empty() ? nullptr : command->get_option_no_throw(s.Option);
    if (!option)
    {
      continue;
    }
    first = first ? first : option;
    commands += (commands.empty() ? "" : ", ") + command->get_name();
    if (option->get_description() != s.Help)
    {
      others += "- In `" + command->get_name() + "`: " + option->get_description() + "\n";
    }
  }
  if (first)
  {
    out << "`" << Synopsis(*first) << "`\n\n";
  }
  out << s.Help << "\n\n";
  if (!commands.empty())
  {
    out << "- Commands: " << commands << "\n";
  }
  if (s.Schema)
  {
    out << "- Scene file: `" << s.Key << "`, " << Describe(s.Schema()) << "\n";
  }
  else if (!s.Key.empty())
  {
    out << "- Scene file: in `" << s.Key.substr(0, s.Key.find('.')) << "`, as `"
        << s.Key.substr(s.Key.find('.') + 1) << "`\n";
  }
  else
  {
    out << "- Scene file: none (the command line only)\n";
  }
  out << others << "\n";
}
}

std::string OptionReference(CLI::App& program)
{
  std::ostringstream out;
  out << "# Option reference\n\n"
      << "<!-- Made by `shadelab print-reference` from the table of settings "
         "(app/settings/settings_table.cxx) and the commands' own options; the build checks "
         "it. Remake it with `cmake --build build --target regenerate`. -->\n\n"
      << "Every option of every command, as its `--help` gives it. The settings come first: "
         "they decide a picture, and most are also keys of scene files "
         "([scenes and batches](scenes-and-batches.md)). Then each command's own options.\n\n"
      << "## Settings\n\n";
  for (const Setting& s : Settings())
  {
    AddSetting(out, s, program);
  }
  for (CLI::App* command : Commands(program))
  {
    out << "## " << command->get_name() << "\n\n" << command->get_description() << "\n\n";
    for (const CLI::Option* option : command->get_options())
    {
      if (SettingOf(*option) || option->get_name() == "--help")
      {
        continue;
      }
      out << "### " << command->get_name() << " " << Names(*option) << "\n\n"
          << "`" << Synopsis(*option) << "`\n\n"
          << option->get_description() << "\n\n";
    }
  }
  std::string text = out.str();
  text.pop_back(); // one newline at the end
  return text;
}
}
