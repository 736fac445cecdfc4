/**
 * @class   vtkShadelabGLTFReader
 * @brief   reads glTF 2.0 (.gltf with its buffers, or .glb) as one triangle mesh
 *
 * Every mesh primitive of the default scene (see shadelabGLTFScene.h), with
 * its node's world transform applied to positions (in double) and normals
 * (by the inverse transpose, renormalised), becomes part of one vtkPolyData.
 * TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN primitives give triangles (a
 * transform that mirrors, determinant < 0, turns them round, as glTF says,
 * so that their front stays in front); POINTS and LINES primitives are
 * skipped with a warning. NORMAL becomes "Normals" (when every primitive
 * has it; otherwise they are dropped with a warning), COLOR_0 the "Colors"
 * (a primitive without it is white, as glTF's base colour is then
 * unchanged), TEXCOORD_0 the "TextureCoordinates" (turned to VTK's origin at
 * the bottom-left: t = 1 - v; a primitive without them gets 0 0). Each
 * triangle's cell-data "Part" is the index of the primitive it comes from
 * (counting every drawn primitive of every node in the scene in order), and
 * the field data holds, per part, its material's name ("PartMaterials", a
 * string array; "" without a material), index into the document's
 * materials ("PartMaterialIndices", -1 without one), coefficients (the
 * lecture's, mapped as shadelabGLTFMaterial.h says) and baseColorTexture
 * as both its kd's and its ka's texture, with the textures' images and
 * samplers (shadelabGLTFTexture.h; the arrays of shadelabPartMaterials.h).
 * Quantized attributes (KHR_mesh_quantization) are read as glTF dequantizes
 * them, compressed ones (EXT_meshopt_compression, KHR_draco_mesh_compression)
 * as they decode (shadelabGLTFMeshopt.h, shadelabGLTFDraco.h).
 *
 * Strict, unlike VTK 9.1's vtkGLTFDocumentLoader, which (tried under
 * AddressSanitizer) crashes on a missing .bin, a buffer shorter than its
 * byteLength, an index accessor beyond its view or an offset beyond it,
 * aborts on an unknown componentType, overflows the stack on a node cycle,
 * and reads on past counts that lie, out-of-range indices and a bufferView
 * index that does not exist. Here each of these is a one-line error (see
 * shadelabGLTFDocument.h and shadelabGLTFAccessor.h), and so are indices
 * out of range, a TRIANGLES count that is not a multiple of 3, attributes of
 * different counts and accessors of a type glTF does not allow for their
 * attribute. Morph targets and skins are not applied (the rest pose is
 * read).
 *
 * Nodes that draw one mesh many times cost the file nothing, so the scene
 * is measured before it is built: it must fit in half the memory available,
 * and instancing may take it to at most 4Mi (4,194,304) triangles, or to as
 * many as its meshes hold counted once. Reading is linear in the scene's
 * triangles.
 */
#ifndef vtkShadelabGLTFReader_h
#define vtkShadelabGLTFReader_h

#include "shadelab_filtersModule.h" // the export macro

#include "vtkShadelabFileReader.h"

class SHADELAB_FILTERS_EXPORT vtkShadelabGLTFReader : public vtkShadelabFileReader
{
public:
  static vtkShadelabGLTFReader* New();
  vtkTypeMacro(vtkShadelabGLTFReader, vtkShadelabFileReader);

protected:
  vtkShadelabGLTFReader() = default;
  ~vtkShadelabGLTFReader() override = default;

  void ReadMesh(const char* fileName, vtkPolyData* triangles) override;

private:
  vtkShadelabGLTFReader(const vtkShadelabGLTFReader&) = delete;
  void operator=(const vtkShadelabGLTFReader&) = delete;
};

#endif
