/**
 * @brief   EXT_meshopt_compression: bufferViews decoded with meshoptimizer
 *
 * A bufferView with this extension holds no bytes of its own: its data are
 * compressed elsewhere (the extension's buffer, byteOffset and byteLength)
 * as `count` elements of `byteStride` bytes, in one of meshoptimizer's
 * three bitstreams (mode ATTRIBUTES, TRIANGLES or INDICES), optionally
 * filtered (OCTAHEDRAL, QUATERNION, EXPONENTIAL). Each is decoded once, as
 * the document loads, with everything the extension's spec requires checked
 * first (meshoptimizer asserts on the rest): afterwards ViewBytes() gives
 * its decoded bytes like any other view's. The buffer that such a view
 * names is a placeholder whose bytes are never loaded.
 */
#ifndef shadelabGLTFMeshopt_h
#define shadelabGLTFMeshopt_h

#include "shadelabGLTFDocument.h"

#include <string>

namespace shadelab::gltf
{
/**
 * Whether `buffer` (`where`) is a placeholder: marked as the extension's
 * fallback, or without data (`hasData`: no uri, not the GLB's BIN chunk) in
 * a document that uses the extension.
 */
bool IsPlaceholder(const Json& root, const Json& buffer, bool hasData, const std::string& where);

/** Decodes every compressed bufferView into document.DecodedViews. */
void DecodeMeshoptViews(Document& document);
}

#endif
