/**
 * @brief   a glTF accessor's values, read with every range checked
 *
 * An accessor says where typed elements lie in a buffer view, which lies in
 * a buffer. Before anything is allocated for them, its count, component
 * type, element type, offsets and stride are checked against the view and
 * the view against its buffer. An accessor without a bufferView is zeros;
 * a sparse one's elements replace the base's (or the zeros) at its indices,
 * which must increase and stay below the count, as glTF requires. What a
 * use allows (a mesh attribute's element and component types, an index's
 * unsigned integers) is checked too, with KHR_mesh_quantization's integer
 * types where the document uses it. Integers become floats as glTF says: a
 * normalized one c / 255, c / 65535, max(c / 127, -1) or max(c / 32767, -1),
 * any other as it is. An accessor that a Draco-compressed primitive fills
 * reads its decoded bytes (shadelabGLTFDraco.h).
 */
#ifndef shadelabGLTFAccessor_h
#define shadelabGLTFAccessor_h

#include "shadelabGLTFDocument.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadelab::gltf
{
/** The integers besides FLOAT that KHR_mesh_quantization allows an attribute. */
enum class Quantization
{
  None,
  SignedNormalized, // normalized BYTE and SHORT (NORMAL, TANGENT)
  Integers // BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT, normalized or not (POSITION, TEXCOORD)
};

/** What a use of an accessor allows. */
struct AccessorUse
{
  const char* Name;        // for messages: "POSITION", "indices"
  int MinComponents;       // SCALAR 1, VEC2 2, VEC3 3, VEC4 4
  int MaxComponents;       // COLOR_0 takes VEC3 and VEC4
  bool NormalizedIntegers; // also normalized UNSIGNED_BYTE and UNSIGNED_SHORT (TEXCOORD, COLOR)
  bool Indices = false;    // SCALAR UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT instead
  Quantization Quantized = Quantization::None; // where the document uses KHR_mesh_quantization
};

/** A primitive's indices. */
inline const AccessorUse IndicesUse = { "indices", 1, 1, false, true };

/** Float values of an accessor. */
struct FloatValues
{
  std::vector<float> Values; // Count * Components
  std::uint64_t Count = 0;
  int Components = 0;
};

/**
 * The element count of accessor `index` for `use` (of `where`, for
 * messages), with everything checked that reading it checks.
 */
std::uint64_t CountOf(
  const Document& document, std::uint64_t index, const AccessorUse& use, const std::string& where);

/** Accessor `index` for `use` (of `where`, for messages), as floats. */
FloatValues ReadFloats(
  const Document& document, std::uint64_t index, const AccessorUse& use, const std::string& where);

/** Accessor `index` as vertex indices: SCALAR UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT. */
std::vector<std::uint32_t> ReadIndices(
  const Document& document, std::uint64_t index, const std::string& where);
}

#endif
