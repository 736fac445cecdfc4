#include "core/heap_policy.h"

#include <malloc.h>

#include <algorithm>
#include <climits>

namespace shadelab
{
void KeepBlocksInHeapUpTo(std::size_t bytes)
{
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(std::min<std::size_t>(bytes, INT_MAX)));
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
}
}
