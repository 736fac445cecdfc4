/**
 * @class   vtkShadelabAssimpReader
 * @brief   reads the formats shadelab has no reader of its own for, through assimp
 *
 * FBX, COLLADA, 3DS, X, 3MF, AMF, AC3D, DXF, LWO, MD2, MD5, Ogre, X3D,
 * Blender and the rest of GetExtensions(), through Debian's assimp 5.2
 * (Assimp::Importer::ReadFile) with Triangulate, JoinIdenticalVertices,
 * SortByPType, ValidateDataStructure and PreTransformVertices: the nodes'
 * transforms are applied, and the meshes of one material merged.
 * FindInvalidData is off: it would quietly drop a channel with a NaN in it,
 * which shadelab refuses instead (see below). Points and lines are dropped
 * (shadelab draws triangles); a file without triangles is "no triangles",
 * as for the other readers.
 *
 * Every file assimp opens goes through shadelab::OpenChecked: the mesh file
 * is read first (so a folder, a FIFO or a file too big for the memory is
 * the error the other readers give), and a file it names (a material
 * library, an Ogre .material, an external texture) must resolve inside the
 * mesh file's folder unless AllowOutsideReferences; one that does not is not
 * opened (assimp reads on as if it were missing) and is a warning. assimp's
 * failure (GetErrorString(), its first line, trimmed) is the one error.
 * assimp logs through its DefaultLogger, which is its NullLogger unless a
 * program creates one; shadelab never does, so its warnings (its own
 * repairs) are not reported.
 *
 * assimp runs in a child process (shadelabIsolatedRead.h): its COLLADA and
 * DirectX parsers crash on some malformed files, and a crash is then the
 * one error "assimp crashed reading it (SIGSEGV)" rather than the end of the
 * program. The child reads and converts (below); the mesh comes back as
 * bytes (shadelabAssimpMeshBytes.h). What its bundled parsers print
 * themselves (OpenDDL's, for OpenGEX) goes to the child's /dev/null.
 *
 * What assimp hands back is checked as strictly as the own readers check a
 * file: counts that the memory can take, faces of 3 indices in range,
 * finite coordinates, normals, texture coordinates and colours
 * (shadelabAssimpScene.h). The first set of vertex colours is the point
 * data Colors, as the own readers give it (white for a mesh without among
 * meshes with).
 *
 * Each assimp mesh (after the merge: each material) is a part (cell data
 * "Part") with its material (shadelabPartMaterials.h): COLOR_AMBIENT as ka,
 * COLOR_DIFFUSE as kd, COLOR_SPECULAR times SHININESS_STRENGTH (where given)
 * as ks, SHININESS as ns, its name, and the first DIFFUSE texture as the kd
 * and ka texture on texture coordinates channel 0: a file beside the mesh, or
 * an embedded image's encoded bytes ("*N", or FBX's by name).
 */
#ifndef vtkShadelabAssimpReader_h
#define vtkShadelabAssimpReader_h

#include "shadelab_filtersModule.h" // the export macro

#include "vtkShadelabFileReader.h"

class SHADELAB_FILTERS_EXPORT vtkShadelabAssimpReader : public vtkShadelabFileReader
{
public:
  static vtkShadelabAssimpReader* New();
  vtkTypeMacro(vtkShadelabAssimpReader, vtkShadelabFileReader);

  /**
   * The extensions that vtkShadelabMeshReader gives this reader, lower case,
   * space-separated: assimp 5.2's importers' (Importer::GetExtensionList)
   * but those shadelab reads itself (.obj .ply .stl .off .gltf .glb). Written
   * out rather than asked of assimp at run time, so that which reader takes
   * a file is the same wherever shadelab runs; a test holds it to assimp's
   * list. ".mesh.xml" (Ogre) is ".xml".
   */
  static const char* GetExtensions();

protected:
  vtkShadelabAssimpReader() = default;
  ~vtkShadelabAssimpReader() override = default;

  void ReadMesh(const char* fileName, vtkPolyData* triangles) override;

private:
  vtkShadelabAssimpReader(const vtkShadelabAssimpReader&) = delete;
  void operator=(const vtkShadelabAssimpReader&) = delete;
};

#endif
