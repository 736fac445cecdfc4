/**
 * @brief   nlohmann-json for documents from anywhere: parsed within limits,
 *          its errors and values as the part a user needs
 *
 * Scene files and glTF documents are parsed with nlohmann-json, whose
 * exceptions read "[json.exception.parse_error.101] parse error at line 3,
 * column 5: syntax error ..."; the line and column, or the message after the
 * exception's id, is what goes into the one-line error. Its parser is
 * iterative but dumping and destroying a value recurse, so a document nested
 * 70,000 deep crashes the program after it was read: ParseWithin stops at
 * MaxJsonDepth instead. A value quoted in a message is cut short
 * (JsonExcerpt), and bytes that are not UTF-8 (a file's names can be Latin-1)
 * are written as U+FFFD where they would otherwise throw.
 */
#ifndef shadelabJsonProblem_h
#define shadelabJsonProblem_h

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace shadelab
{
/** Deeper than this, a JSON document is refused: glTF and scene files need a dozen. */
constexpr int MaxJsonDepth = 256;

/**
 * text parsed as Json, with comments where a scene file allows them; throws
 * nlohmann's parse error, or its out_of_range.406 "nested deeper than 256"
 * (JsonProblem reads both).
 */
template <typename Json = nlohmann::json>
Json ParseWithin(std::string_view text, bool comments = false)
{
  const typename Json::parser_callback_t depth = [](int level, typename Json::parse_event_t, Json&)
  {
    if (level > MaxJsonDepth)
    {
      throw Json::out_of_range::create(
        406, "nested deeper than " + std::to_string(MaxJsonDepth) + " levels", nullptr);
    }
    return true;
  };
  return Json::parse(text.begin(), text.end(), depth, true, comments);
}

/** value as JSON text, with bytes that are not UTF-8 written as U+FFFD. */
template <typename Json>
std::string JsonText(const Json& value, int indent = -1)
{
  return value.dump(indent, ' ', false, Json::error_handler_t::replace);
}

/**
 * value as JSON text for a message: invalid UTF-8 replaced, and cut to
 * about 60 characters ("[[[[[[...") so that a line stays a line.
 */
template <typename Json>
std::string JsonExcerpt(const Json& value)
{
  constexpr std::size_t Longest = 60;
  std::string text = JsonText(value);
  if (text.size() > Longest)
  {
    std::size_t cut = Longest;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80)
    {
      --cut; // not inside a UTF-8 sequence
    }
    text = text.substr(0, cut) + "...";
  }
  return text;
}

/**
 * "line 3, column 5: ..." for a syntax error; for others (a number too large
 * for a double: "number overflow parsing '7e999'", a finding of
 * fuzz_scene_file) the message after the exception's id.
 */
inline std::string JsonProblem(const nlohmann::json::exception& e)
{
  const std::string what = e.what();
  const auto at = what.find("at line ");
  const auto close = what.find("] ");
  return at != std::string::npos ? what.substr(at + 3)
    : close != std::string::npos ? what.substr(close + 2)
                                 : what;
}
}

#endif
