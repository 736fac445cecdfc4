// One table of names per enum. The command line's choices, the scene files'
// parser, the window's cycles, the help texts and ToString all read it, so
// that adding a value (a weighting, a light kind) is one edit.
//
// A table is a specialisation of NameTable with a static constexpr array
// Entries of {value, name} pairs, in the order help texts and cycles use.
#ifndef shadelabNames_h
#define shadelabNames_h

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace shadelab
{
template <typename Enum>
struct NameTable; // specialised beside each enum

/** value's name in its table; "?" for a value the table lacks. */
template <typename Enum, typename = decltype(NameTable<Enum>::Entries)>
const char* ToString(Enum value)
{
  for (const auto& [entry, name] : NameTable<Enum>::Entries)
  {
    if (entry == value)
    {
      return name;
    }
  }
  return "?";
}

/** The value called name, if any. */
template <typename Enum>
std::optional<Enum> FromName(std::string_view name)
{
  for (const auto& [entry, entryName] : NameTable<Enum>::Entries)
  {
    if (name == entryName)
    {
      return entry;
    }
  }
  return std::nullopt;
}

/** Every name, in the table's order. */
template <typename Enum>
std::vector<std::string> Names()
{
  std::vector<std::string> names;
  for (const auto& entry : NameTable<Enum>::Entries)
  {
    names.emplace_back(entry.second);
  }
  return names;
}

/** Every value by its name, as CLI11's transformers take them. */
template <typename Enum>
std::map<std::string, Enum> NamedValues()
{
  std::map<std::string, Enum> values;
  for (const auto& [entry, name] : NameTable<Enum>::Entries)
  {
    values.emplace(name, entry);
  }
  return values;
}

/** The value after value in its table, the first after the last (the window's cycles). */
template <typename Enum>
Enum NextOf(Enum value)
{
  const auto& entries = NameTable<Enum>::Entries;
  for (std::size_t i = 0; i < entries.size(); ++i)
  {
    if (entries[i].first == value)
    {
      return entries[(i + 1) % entries.size()].first;
    }
  }
  return entries[0].first;
}

/**
 * The names joined by separator, the last two by `last` when given:
 * "none|flat|gouraud|phong", "point, directional or spot".
 */
template <typename Enum>
std::string JoinedNames(const char* separator, const char* last = nullptr)
{
  const std::vector<std::string> names = Names<Enum>();
  std::string joined;
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    joined += (i == 0 ? "" : last && i + 1 == names.size() ? last : separator) + names[i];
  }
  return joined;
}
}

#endif
