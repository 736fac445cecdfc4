/**
 * @class   shadelab::ply::AsciiSource
 * @brief   the values of an ASCII PLY body: one line per item
 *
 * The same interface as BinarySource, on the scanner that read the header.
 * Read and Skip throw on a missing or malformed value (with its line) and
 * otherwise return true; BeginItem is false when the text ends first.
 */
#ifndef shadelabPLYAsciiSource_h
#define shadelabPLYAsciiSource_h

#include "shadelabPLYHeader.h"

#include <cstdint>

namespace shadelab::ply
{
class AsciiSource
{
public:
  explicit AsciiSource(TextScanner& scanner)
    : Scanner(scanner)
  {
  }

  bool BeginItem() { return this->Scanner.NextLine(); }
  void EndItem() { this->Scanner.ExpectLineEnd("the values the header declares"); }

  bool Read(Scalar type, double& value)
  {
    value = IsInteger(type) ? static_cast<double>(this->Scanner.ReadInteger("integer value"))
                            : this->Scanner.ReadDouble("number");
    return true;
  }

  bool Skip(Scalar type, std::uint64_t count)
  {
    double value;
    for (std::uint64_t k = 0; k < count; ++k)
    {
      this->Read(type, value);
    }
    return true;
  }

  /** Skips a whole element: one line per item. */
  void SkipItems(const Element& element)
  {
    for (std::uint64_t i = 0; i < element.Count; ++i)
    {
      if (!this->Scanner.NextLine())
      {
        Truncated(element, i);
      }
    }
  }

private:
  TextScanner& Scanner;
};
}

#endif
