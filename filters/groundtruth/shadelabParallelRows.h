// A picture's rows over every core: the oracle's pictures (the exact
// image, the ray tracer, the environment behind a scene) cost per pixel,
// unevenly, and each row is independent of the others.
#ifndef shadelabParallelRows_h
#define shadelabParallelRows_h

#include <functional>

namespace shadelab
{
/**
 * Calls row(y) once for each y in [first, last), on as many threads as the
 * machine has cores, each taking the next row left when it is done.
 */
void ForEachRow(int first, int last, const std::function<void(int)>& row);
}

#endif
