/**
 * @brief   Wavefront MTL material libraries, as OBJ's `mtllib` names them
 *
 * ParseMtl reads `newmtl NAME` and each material's Ka, Kd, Ks (r [g b]: one
 * number is grey), Ns and d (Tr is 1 - d), the coefficients of the lecture's
 * equation, and its texture maps map_Kd and map_Ka: `map_Kd [options] FILE`,
 * and its normal map, norm or else bump / map_Bump.
 * Of the options, `-clamp on|off` is honoured (on: the image's edge
 * continues beyond it; off, the default: it repeats), and a normal map's
 * `-bm SCALE` (the scale of its x and y, or of a height map's heights);
 * the others that the
 * MTL specification defines (-blendu, -blendv, -cc, -mm, -o, -s, -t,
 * -texres, -bm, -boost, -imfchan) are skipped with their values and a
 * warning, since they would change the picture in ways not drawn here. FILE
 * is the rest of the statement (it may hold spaces), with '\' read as '/'
 * (files written on Windows); whether it exists is not checked. Every other
 * statement (illum, Ni, Ke, map_Ks, ...) and comments are skipped. A
 * coefficient the file does not give is 0 (d 1). It stops at the first
 * malformed or non-finite number, a negative Ns, a coefficient or map before
 * any newmtl, a map without a file name, an unknown option or one without
 * its value, with "line N: ..." in the message (MeshReadError).
 */
#ifndef shadelabMtlParser_h
#define shadelabMtlParser_h

#include "shadelabIllumination.h"

#include <string>
#include <string_view>
#include <vector>

namespace shadelab
{
/** A material's texture map as the MTL gives it. */
struct MtlMap
{
  std::string File;   // as the MTL names it, relative to the MTL's folder; "" for none
  bool Clamp = false; // -clamp on
  double Scale = 1;   // -bm, of a normal map (norm, bump, map_Bump)
};

struct MtlMaterial
{
  // Translucency is d, clamped to [0, 1]; without d, 1 - Tr, except that
  // Tr 1 is opaque: MeshLab and others write Tr for d, and a part drawn
  // invisible is never what such a file means.
  Material Coefficients;
  MtlMap KdMap; // map_Kd
  MtlMap KaMap; // map_Ka
  // norm, or else bump / map_Bump (FromBump): a tangent-space normal map,
  // unless a bump's image is grey (a height map).
  MtlMap NormalMap;
  bool NormalFromBump = false;
  bool OpacityGiven = false; // a d statement: Tr then changes nothing
};

struct MtlLibrary
{
  std::vector<MtlMaterial> Materials; // in the file's order
  std::vector<std::string> Warnings;  // "line N: ..." for each option skipped
};

/** The materials of an MTL file's text. */
MtlLibrary ParseMtl(std::string_view text);
}

#endif
