/**
 * @class   shadelab::ply::BinarySource
 * @brief   the values of a binary PLY body, in either byte order
 *
 * One of the two sources that the PLY reader's ReadElement takes (the other
 * is AsciiSource): BeginItem and EndItem frame an element's item, Read
 * gives the next value as a double, Skip passes values over, and SkipItems
 * a whole element. Read and Skip return false when the file ends first.
 */
#ifndef shadelabPLYBinarySource_h
#define shadelabPLYBinarySource_h

#include "shadelabPLYHeader.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace shadelab::ply
{
class BinarySource
{
public:
  BinarySource(std::string_view body, bool bigEndian)
    : Position(reinterpret_cast<const unsigned char*>(body.data()))
    , End(Position + body.size())
    , BigEndian(bigEndian)
  {
  }

  bool BeginItem() { return true; }
  void EndItem() {}

  bool Read(Scalar type, double& value)
  {
    const std::size_t size = SizeOf(type);
    if (static_cast<std::size_t>(this->End - this->Position) < size)
    {
      return false;
    }
    value = LoadScalar(this->Position, type, this->BigEndian);
    this->Position += size;
    return true;
  }

  bool Skip(Scalar type, std::uint64_t count)
  {
    const std::uint64_t left = static_cast<std::uint64_t>(this->End - this->Position);
    if (count > left / SizeOf(type))
    {
      return false;
    }
    this->Position += count * SizeOf(type);
    return true;
  }

  /** Skips a whole element by its sizes: in one step when it has no lists. */
  void SkipItems(const Element& element);

  /** The body from the next value on. */
  std::string_view Rest() const
  {
    return { reinterpret_cast<const char*>(this->Position),
      static_cast<std::size_t>(this->End - this->Position) };
  }

private:
  const unsigned char* Position;
  const unsigned char* End;
  bool BigEndian;
};
}

#endif
