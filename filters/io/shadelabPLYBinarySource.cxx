#include "shadelabPLYBinarySource.h"

#include <algorithm>

namespace shadelab::ply
{
void BinarySource::SkipItems(const Element& element)
{
  const bool fixed = std::none_of(element.Properties.begin(), element.Properties.end(),
    [](const Property& property) { return property.IsList; });
  if (fixed)
  {
    std::uint64_t itemBytes = 0;
    for (const Property& property : element.Properties)
    {
      itemBytes += SizeOf(property.Type);
    }
    const std::uint64_t left = static_cast<std::uint64_t>(this->End - this->Position);
    if (element.Count * itemBytes > left) // no overflow: CheckCounts bounded the product
    {
      Truncated(element, left / itemBytes);
    }
    this->Position += element.Count * itemBytes;
    return;
  }
  double length = 0;
  for (std::uint64_t i = 0; i < element.Count; ++i)
  {
    for (const Property& property : element.Properties)
    {
      const bool ok = property.IsList
        ? this->Read(property.CountType, length) && FitsInt64(length) && length >= 0 &&
          this->Skip(property.Type, static_cast<std::uint64_t>(length))
        : this->Skip(property.Type, 1);
      if (!ok)
      {
        Truncated(element, i);
      }
    }
  }
}
}
