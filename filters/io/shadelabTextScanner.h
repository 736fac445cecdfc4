/**
 * @class   shadelab::TextScanner
 * @brief   lines and whitespace-separated tokens of a text held in memory
 *
 * The tokenizer that the OBJ, ASCII PLY and ASCII STL parsers share. Numbers
 * are parsed with std::from_chars: no locale, no copies, and a token must be
 * exactly one number ("1.5x" is malformed, not 1.5). Blank lines are skipped
 * but still counted, so that messages name the line a user's editor shows.
 * With a comment character (OFF's '#'), the text from it to the line's end
 * is blank too. A UTF-8 byte order mark at the start is skipped.
 */
#ifndef shadelabTextScanner_h
#define shadelabTextScanner_h

#include <cstddef>
#include <string>
#include <string_view>

namespace shadelab
{
/** Parses all of `token` as one number; false if it is anything else. */
bool ParseNumber(std::string_view token, double& value);
bool ParseNumber(std::string_view token, long long& value);

/** `token` in single quotes for a message, shortened and with unprintable bytes as '?'. */
std::string Quote(std::string_view token);

/** `text` in lower or upper case (keywords that files may write in any case). */
std::string ToLower(std::string_view text);
std::string ToUpper(std::string_view text);

class TextScanner
{
public:
  explicit TextScanner(std::string_view text, char comment = '\0')
    : Text(text)
    , Comment(comment)
  {
    // A UTF-8 byte order mark (Windows editors write one) is no token: the
    // first line would otherwise start with an unknown keyword.
    if (this->Text.substr(0, 3) == "\xEF\xBB\xBF")
    {
      this->Text.remove_prefix(3);
    }
  }

  /** Moves to the next line that is not blank; false at the end of the text. */
  bool NextLine();

  /** The next token of the current line; empty when the line has no more. */
  std::string_view NextToken();

  /**
   * The next token as a number. Throws "line N: missing WHAT" or
   * "line N: malformed WHAT 'token'".
   */
  double ReadDouble(const char* what);
  long long ReadInteger(const char* what);

  /** Throws "line N: unexpected 'token' after WHAT" if the line goes on. */
  void ExpectLineEnd(const char* what);

  /** Throws MeshReadError("line N: " + message). */
  [[noreturn]] void Fail(const std::string& message) const;

  std::size_t GetLineNumber() const { return this->LineNumber; }

  /** Where the line after the current one starts (binary data follows a header line). */
  std::size_t GetNextLineOffset() const { return this->NextLineStart; }

  /**
   * Ends the current line and goes on at `offset` (past binary data),
   * counting the line breaks it passes.
   */
  void JumpTo(std::size_t offset);

private:
  bool AtComment() const { return this->Comment && this->Text[this->Position] == this->Comment; }

  std::string_view Text;
  char Comment;
  std::size_t NextLineStart = 0;
  std::size_t Position = 0; // within the current line
  std::size_t LineEnd = 0;
  std::size_t LineNumber = 0;
};
}

#endif
