// How glibc's allocator serves a long process's large blocks.
#ifndef shadelab_heap_policy_h
#define shadelab_heap_policy_h

#include <cstddef>

namespace shadelab
{
/**
 * Serves blocks of up to `bytes` from the heap, and keeps up to 1 GiB of
 * freed heap rather than giving it back, so that a block freed and asked
 * for again (a batch's next picture) reuses pages already faulted in. Larger
 * blocks (a large mesh's arrays) stay mapped on their own and go back to
 * the system when freed. A setting glibc refused would leave its default:
 * slower, no different, so nothing is reported (glibc 2.36 takes any
 * positive int).
 */
void KeepBlocksInHeapUpTo(std::size_t bytes);
}

#endif
