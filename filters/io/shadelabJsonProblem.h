/**
 * @brief   nlohmann-json's parse errors as the part a user needs
 *
 * Scene files and glTF documents are parsed with nlohmann-json, whose
 * exceptions read "[json.exception.parse_error.101] parse error at line 3,
 * column 5: syntax error ..."; the line and column, or the message after the
 * exception's id, is what goes into the one-line error.
 */
#ifndef shadelabJsonProblem_h
#define shadelabJsonProblem_h

#include <nlohmann/json.hpp>

#include <string>

namespace shadelab
{
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
