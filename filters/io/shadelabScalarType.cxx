#include "shadelabScalarType.h"

#include <cstdint>
#include <limits>

namespace shadelab
{
std::size_t SizeOf(ScalarType type)
{
  switch (type)
  {
    case ScalarType::Int8:
    case ScalarType::UInt8:
      return 1;
    case ScalarType::Int16:
    case ScalarType::UInt16:
      return 2;
    case ScalarType::Int32:
    case ScalarType::UInt32:
    case ScalarType::Float32:
      return 4;
    case ScalarType::Int64:
    case ScalarType::UInt64:
    case ScalarType::Float64:
      break;
  }
  return 8;
}

bool IsInteger(ScalarType type)
{
  return type != ScalarType::Float32 && type != ScalarType::Float64;
}

double LargestValue(ScalarType type)
{
  switch (type)
  {
    case ScalarType::Int8:
      return std::numeric_limits<std::int8_t>::max();
    case ScalarType::UInt8:
      return std::numeric_limits<std::uint8_t>::max();
    case ScalarType::Int16:
      return std::numeric_limits<std::int16_t>::max();
    case ScalarType::UInt16:
      return std::numeric_limits<std::uint16_t>::max();
    case ScalarType::Int32:
      return std::numeric_limits<std::int32_t>::max();
    case ScalarType::UInt32:
      return std::numeric_limits<std::uint32_t>::max();
    case ScalarType::Int64:
      return static_cast<double>(std::numeric_limits<std::int64_t>::max());
    case ScalarType::UInt64:
      return static_cast<double>(std::numeric_limits<std::uint64_t>::max());
    case ScalarType::Float32:
    case ScalarType::Float64:
      break;
  }
  return 1;
}

double LoadScalar(const unsigned char* bytes, ScalarType type, bool bigEndian)
{
  switch (type)
  {
    case ScalarType::Int8:
      return LoadValue<std::int8_t>(bytes, bigEndian);
    case ScalarType::UInt8:
      return LoadValue<std::uint8_t>(bytes, bigEndian);
    case ScalarType::Int16:
      return LoadValue<std::int16_t>(bytes, bigEndian);
    case ScalarType::UInt16:
      return LoadValue<std::uint16_t>(bytes, bigEndian);
    case ScalarType::Int32:
      return LoadValue<std::int32_t>(bytes, bigEndian);
    case ScalarType::UInt32:
      return LoadValue<std::uint32_t>(bytes, bigEndian);
    case ScalarType::Int64:
      return LoadValue<std::int64_t>(bytes, bigEndian);
    case ScalarType::UInt64:
      return LoadValue<std::uint64_t>(bytes, bigEndian);
    case ScalarType::Float32:
      return LoadValue<float>(bytes, bigEndian);
    case ScalarType::Float64:
      break;
  }
  return LoadValue<double>(bytes, bigEndian);
}
}
