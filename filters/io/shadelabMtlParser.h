/**
 * @brief   Wavefront MTL material libraries, as OBJ's `mtllib` names them
 *
 * ParseMtl reads `newmtl NAME` and each material's Ka, Kd, Ks (r [g b]: one
 * number is grey), Ns and d (Tr is 1 - d), the coefficients of the lecture's
 * equation; every other statement (illum, Ni, Ke, map_*, ...) and comments
 * are skipped. A coefficient the file does not give is 0 (d 1). It stops at
 * the first malformed or non-finite number, a negative Ns, or a coefficient
 * before any newmtl, with "line N: ..." in the message (MeshReadError).
 */
#ifndef shadelabMtlParser_h
#define shadelabMtlParser_h

#include "shadelabIllumination.h"

#include <string_view>
#include <vector>

namespace shadelab
{
/** The materials of an MTL file's text, in the file's order (Translucency is d). */
std::vector<Material> ParseMtl(std::string_view text);
}

#endif
