/**
 * @brief   the scalar types that binary mesh files store
 *
 * Binary PLY and legacy VTK files declare each value's type by name and
 * store it in a stated byte order; both readers decode through this.
 */
#ifndef shadelabScalarType_h
#define shadelabScalarType_h

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace shadelab
{
enum class ScalarType
{
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Int64,
  UInt64,
  Float32,
  Float64
};

std::size_t SizeOf(ScalarType type);

bool IsInteger(ScalarType type);

/** An integer type's largest value (a colour stored as one is that fraction of it); 1 for floats.
 */
double LargestValue(ScalarType type);

/** Whether this machine stores numbers big-endian (a binary file states its own order). */
inline bool HostIsBigEndian()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 0;
}

/** The sizeof(T) bytes at `bytes`, stored in the given byte order, as a T. */
template <typename T>
T LoadValue(const unsigned char* bytes, bool bigEndian)
{
  unsigned char ordered[sizeof(T)];
  std::memcpy(ordered, bytes, sizeof ordered);
  if (bigEndian != HostIsBigEndian())
  {
    std::reverse(ordered, ordered + sizeof ordered);
  }
  T value;
  std::memcpy(&value, ordered, sizeof value);
  return value;
}

/** The SizeOf(type) bytes at `bytes`, in the given byte order, as a double. */
double LoadScalar(const unsigned char* bytes, ScalarType type, bool bigEndian);

/**
 * Binary mesh files' scalars are read as doubles; a count or an index
 * converts to an integer only where int64 holds it (a uint64 can say 1.8e19,
 * and the cast of a double beyond the range, or of NaN, is undefined).
 */
inline bool FitsInt64(double value)
{
  return value >= -0x1p63 && value < 0x1p63;
}
}

#endif
