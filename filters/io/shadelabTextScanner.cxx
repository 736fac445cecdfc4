#include "shadelabTextScanner.h"

#include "shadelabMeshReadError.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstring>

namespace shadelab
{
namespace
{
bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

template <typename T>
bool ParseWhole(std::string_view token, T& value)
{
  // from_chars takes no '+' sign, which some writers put before exponents'
  // mantissas ("+1.5e-3"); accept one, but not "+-1".
  if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+')
  {
    token.remove_prefix(1);
  }
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end;
}
}

bool ParseNumber(std::string_view token, double& value)
{
  return ParseWhole(token, value);
}

bool ParseNumber(std::string_view token, long long& value)
{
  return ParseWhole(token, value);
}

std::string Quote(std::string_view token)
{
  constexpr std::size_t maxLength = 24;
  std::string quoted = "'";
  for (std::size_t i = 0; i < token.size() && i < maxLength; ++i)
  {
    const char c = token[i];
    quoted += (c >= 0x20 && c < 0x7f) ? c : '?';
  }
  if (token.size() > maxLength)
  {
    quoted += "...";
  }
  return quoted + "'";
}

std::string ToLower(std::string_view text)
{
  std::string lower(text);
  for (char& c : lower)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return lower;
}

std::string ToUpper(std::string_view text)
{
  std::string upper(text);
  for (char& c : upper)
  {
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return upper;
}

bool TextScanner::NextLine()
{
  while (this->NextLineStart < this->Text.size())
  {
    const char* begin = this->Text.data() + this->NextLineStart;
    const void* newline = std::memchr(begin, '\n', this->Text.size() - this->NextLineStart);
    this->Position = this->NextLineStart;
    this->LineEnd = newline
      ? static_cast<std::size_t>(static_cast<const char*>(newline) - this->Text.data())
      : this->Text.size();
    this->NextLineStart = newline ? this->LineEnd + 1 : this->LineEnd;
    ++this->LineNumber;
    while (this->Position < this->LineEnd && IsSpace(this->Text[this->Position]))
    {
      ++this->Position;
    }
    if (this->Position < this->LineEnd && !this->AtComment())
    {
      return true;
    }
  }
  return false;
}

std::string_view TextScanner::NextToken()
{
  while (this->Position < this->LineEnd && IsSpace(this->Text[this->Position]))
  {
    ++this->Position;
  }
  if (this->Position < this->LineEnd && this->AtComment())
  {
    this->Position = this->LineEnd;
  }
  const std::size_t start = this->Position;
  while (
    this->Position < this->LineEnd && !IsSpace(this->Text[this->Position]) && !this->AtComment())
  {
    ++this->Position;
  }
  return this->Text.substr(start, this->Position - start);
}

double TextScanner::ReadDouble(const char* what)
{
  const std::string_view token = this->NextToken();
  double value = 0;
  if (token.empty())
  {
    this->Fail(std::string("missing ") + what);
  }
  if (!ParseNumber(token, value))
  {
    this->Fail(std::string("malformed ") + what + " " + Quote(token));
  }
  return value;
}

long long TextScanner::ReadInteger(const char* what)
{
  const std::string_view token = this->NextToken();
  long long value = 0;
  if (token.empty())
  {
    this->Fail(std::string("missing ") + what);
  }
  if (!ParseNumber(token, value))
  {
    this->Fail(std::string("malformed ") + what + " " + Quote(token));
  }
  return value;
}

void TextScanner::ExpectLineEnd(const char* what)
{
  const std::string_view token = this->NextToken();
  if (!token.empty())
  {
    this->Fail("unexpected " + Quote(token) + " after " + what);
  }
}

void TextScanner::JumpTo(std::size_t offset)
{
  offset = std::min(offset, this->Text.size());
  if (offset > this->NextLineStart)
  {
    this->LineNumber += static_cast<std::size_t>(
      std::count(this->Text.begin() + this->NextLineStart, this->Text.begin() + offset, '\n'));
  }
  this->NextLineStart = offset;
  this->Position = this->LineEnd;
}

void TextScanner::Fail(const std::string& message) const
{
  throw MeshReadError("line " + std::to_string(this->LineNumber) + ": " + message);
}
}
