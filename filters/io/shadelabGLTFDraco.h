/**
 * @brief   KHR_draco_mesh_compression: primitives decoded with Draco
 *
 * A primitive with this extension keeps its geometry in one bufferView as a
 * Draco mesh; its accessors say only what the decoded data are (count,
 * type, componentType) and have no bufferView of their own. Each such
 * triangle primitive is decoded once, as the document loads, and its
 * accessors are filled from the Draco mesh: an attribute from the Draco
 * attribute of the unique id that the extension gives its name, converted
 * to the accessor's type; the indices from the mesh's faces. Counts must
 * match the accessors', indices lie below the point count and fit their
 * type, and float values are finite. Afterwards an accessor reads as if
 * its bytes had been in the file (document.DecodedAccessors).
 */
#ifndef shadelabGLTFDraco_h
#define shadelabGLTFDraco_h

#include "shadelabGLTFDocument.h"

namespace shadelab::gltf
{
/** Decodes every Draco-compressed triangle primitive into document.DecodedAccessors. */
void DecodeDracoPrimitives(Document& document);
}

#endif
