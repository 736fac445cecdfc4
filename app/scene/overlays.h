// Lines over the shading, unlit: the triangles' edges and the vertex
// normals as glyphs. The window toggles them (keys e and n); render draws
// them with --edges and --normal-glyphs.
#ifndef shadelab_overlays_h
#define shadelab_overlays_h

#include "core/options.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace shadelab
{
class MeshCache;

/** mesh's triangle edges as lines of colour and width (pixels). */
vtkSmartPointer<vtkActor> MakeEdges(vtkPolyData* mesh, const Rgb& colour, double width);

/**
 * A line along each vertex normal of mesh (which has point normals), about
 * twice the vertices' spacing long, so that neighbours' glyphs barely
 * overlap; bounds are the mesh's, which sets the scale.
 */
vtkSmartPointer<vtkActor> MakeNormalGlyphs(vtkPolyData* mesh, const double bounds[6]);

/** The vertex normals that gouraud and phong use for options' mesh, whatever its rule. */
vtkPolyData* LitMesh(const SceneOptions& options, MeshCache& meshes);

/**
 * The edges and glyphs that options ask for over `shown` (the mesh as
 * drawn), in renderer while this lives.
 */
class SceneOverlays
{
public:
  SceneOverlays(
    const SceneOptions& options, vtkPolyData* shown, MeshCache& meshes, vtkRenderer* renderer);
  ~SceneOverlays();

private:
  SceneOverlays(const SceneOverlays&) = delete;
  void operator=(const SceneOverlays&) = delete;

  vtkRenderer* Renderer;
  vtkSmartPointer<vtkActor> Edges, Glyphs;
};
}

#endif
