/**
 * @class   shadelab::LegacyVTKScanner
 * @brief   the tokens and value arrays of a legacy .vtk file
 *
 * A TextScanner that also reads what the sections of a legacy VTK file are
 * made of: keywords across lines, section names, counts, vtkDataWriter's
 * type names, and arrays of values in ASCII or big-endian binary (which
 * starts on the line after its section's). A count that the whole file
 * could not hold is refused before anything is read or allocated for it.
 */
#ifndef shadelabLegacyVTKScanner_h
#define shadelabLegacyVTKScanner_h

#include "shadelabMeshReadError.h"
#include "shadelabScalarType.h"
#include "shadelabTextScanner.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace shadelab
{
class LegacyVTKScanner : public TextScanner
{
public:
  explicit LegacyVTKScanner(const std::string& bytes)
    : TextScanner(bytes)
    , Bytes(bytes)
  {
  }

  /** Whether arrays are binary (from the file's ASCII or BINARY line). */
  void SetBinary(bool binary) { this->Binary = binary; }
  bool GetBinary() const { return this->Binary; }

  /** The next token, across lines: a keyword, or a value of ASCII data. */
  std::string_view Word();

  /** The name after `section` on its line; fails if there is none. */
  std::string_view Name(const std::string& section);

  /** A count on the current line; fails if negative. */
  std::uint64_t Count(const char* what);

  /** A data type name on the current line, in any case. */
  ScalarType Type();

  /** Fails if `count` items of valuesEach values of `type` cannot fit the file. */
  void CheckFits(const std::string& section, std::uint64_t count, const char* noun,
    std::uint64_t valuesEach, ScalarType type) const;

  /**
   * Ends `section`'s line and reads count * valuesEach values of `type`,
   * handing each to store(index, value). Throws "truncated: SECTION
   * declares N NOUN but the file ends after M".
   */
  template <class Store>
  void ReadValues(const std::string& section, std::uint64_t count, const char* noun,
    std::uint64_t valuesEach, ScalarType type, Store&& store);

  /**
   * Reads and drops `section`'s count * valuesEach values, counted as values
   * in its messages (a FIELD array of 10^9 components in 3 tuples declares
   * 3 * 10^9 values).
   */
  void Skip(
    const std::string& section, std::uint64_t count, std::uint64_t valuesEach, ScalarType type)
  {
    const std::uint64_t values =
      valuesEach != 0 && count > UINT64_MAX / valuesEach ? UINT64_MAX : count * valuesEach;
    this->ReadValues(section, values, "values", 1, type, [](std::uint64_t, double) {});
  }

  /** Skips METADATA: it runs to the next blank line. */
  void SkipMetadata();

private:
  const std::string& Bytes;
  bool Binary = false;
};

template <class Store>
void LegacyVTKScanner::ReadValues(const std::string& section, std::uint64_t count, const char* noun,
  std::uint64_t valuesEach, ScalarType type, Store&& store)
{
  this->ExpectLineEnd(("the " + section + " line").c_str());
  this->CheckFits(section, count, noun, valuesEach, type);
  const auto truncated = [&](std::uint64_t values)
  {
    throw MeshReadError("truncated: " + section + " declares " + std::to_string(count) + " " +
        noun + " but the file ends after " + std::to_string(values / valuesEach),
      vtkErrorCode::PrematureEndOfFileError);
  };
  const std::uint64_t values = count * valuesEach;
  if (this->Binary)
  {
    const std::size_t start = this->GetNextLineOffset();
    const std::size_t size = SizeOf(type);
    if (values > (this->Bytes.size() - start) / size)
    {
      truncated((this->Bytes.size() - start) / size);
    }
    const auto* data = reinterpret_cast<const unsigned char*>(this->Bytes.data()) + start;
    for (std::uint64_t i = 0; i < values; ++i)
    {
      store(i, LoadScalar(data + i * size, type, true)); // big-endian, always
    }
    this->JumpTo(start + values * size);
    return;
  }
  for (std::uint64_t i = 0; i < values; ++i)
  {
    const std::string_view token = this->Word();
    if (token.empty())
    {
      truncated(i);
    }
    double value = 0;
    long long integer = 0;
    const bool ok = IsInteger(type) ? ParseNumber(token, integer) : ParseNumber(token, value);
    if (!ok)
    {
      this->Fail("malformed value " + Quote(token) + " in " + section);
    }
    store(i, IsInteger(type) ? static_cast<double>(integer) : value);
  }
}
}

#endif
