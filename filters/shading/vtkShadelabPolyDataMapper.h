/**
 * @class   vtkShadelabPolyDataMapper
 * @brief   VTK's OpenGL polydata mapper without the CPU copy of its vertex buffers
 *
 * VTK 9.1 packs each vertex attribute into a CPU array, uploads it, and then
 * empties the array with resize(0), which keeps its memory: 12 bytes a point
 * for the points and as much again for the normals, kept while the index
 * buffer is built (the frame's memory peak on a large mesh) and for the
 * mapper's life. This mapper releases that memory before building the index
 * buffer. It draws exactly as vtkOpenGLPolyDataMapper does: the packed
 * arrays are rebuilt from the data arrays at every upload.
 *
 * It also builds a surface's triangle index buffer itself
 * (shadelabTriangleIndexBuffer: the same indices, without VTK's copy of
 * each cell), where the surface is only polygons drawn without edges or
 * vertices; VTK builds every other case. Drawn as a wireframe or as points,
 * those polygons' edges or points are drawn as VTK draws them (an edge once
 * for each triangle that has it), or with EachElementOnce each once
 * (DrawnElements), as shadelab's shading needs.
 *
 * And it draws with stages of one's own where it is given them
 * (SetOwnStages: the hands-on's edited shaders).
 */
#ifndef vtkShadelabPolyDataMapper_h
#define vtkShadelabPolyDataMapper_h

#include "shadelab_filtersModule.h" // the export macro

#include "shadelabOwnStages.h" // the stages of one's own

#include <vtkOpenGLPolyDataMapper.h>

#include <vector>

class SHADELAB_FILTERS_EXPORT vtkShadelabPolyDataMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkShadelabPolyDataMapper* New();
  vtkTypeMacro(vtkShadelabPolyDataMapper, vtkOpenGLPolyDataMapper);

  /**
   * Drawn as a wireframe or as points, each edge or point once, in
   * DrawnElements' order, so that gl_PrimitiveID counts them (flat's face
   * normals per element). Default off: VTK's own index buffers.
   */
  vtkSetMacro(EachElementOnce, bool);
  vtkGetMacro(EachElementOnce, bool);

  /**
   * Stages of one's own: complete GLSL (as `--dump-shaders` writes it) that
   * replaces the generated vertex and/or fragment stage once every
   * replacement and render pass has made its own (an empty one: the
   * generated stage). They are compiled and linked when the program is
   * built; where that fails the generated stages draw instead and
   * GetOwnStageErrors says why. Default none.
   */
  VTK_WRAPEXCLUDE void SetOwnStages(const shadelab::OwnStages& stages);
  VTK_WRAPEXCLUDE const shadelab::OwnStages& GetOwnStages() const { return this->Own; }
  /** The errors of the own stages when the program was last built; none when they draw. */
  VTK_WRAPEXCLUDE const std::vector<shadelab::StageError>& GetOwnStageErrors() const
  {
    return this->OwnErrors;
  }

protected:
  vtkShadelabPolyDataMapper() = default;
  ~vtkShadelabPolyDataMapper() override = default;

  void BuildIBO(vtkRenderer* renderer, vtkActor* actor, vtkPolyData* mesh) override;
  void BuildShaders(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* renderer, vtkActor* actor) override;

private:
  // The index buffers of a surface of polygons alone; false where VTK's
  // BuildIBO must make them.
  bool BuildSurfaceIBO(vtkActor* actor, vtkPolyData* mesh);

  // The modification time of the polys that BuildSurfaceIBO last built the
  // buffers from; 0 once VTK's BuildIBO has built them.
  vtkMTimeType SurfacePolysTime = 0;
  int SurfaceRepresentation = -1; // the representation (VTK_SURFACE, ...) they were built for
  bool EachElementOnce = false;
  shadelab::OwnStages Own;
  std::vector<shadelab::StageError> OwnErrors;

  vtkShadelabPolyDataMapper(const vtkShadelabPolyDataMapper&) = delete;
  void operator=(const vtkShadelabPolyDataMapper&) = delete;
};

#endif
