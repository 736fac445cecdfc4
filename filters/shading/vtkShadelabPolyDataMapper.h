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
 */
#ifndef vtkShadelabPolyDataMapper_h
#define vtkShadelabPolyDataMapper_h

#include <vtkOpenGLPolyDataMapper.h>

class vtkShadelabPolyDataMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkShadelabPolyDataMapper* New();
  vtkTypeMacro(vtkShadelabPolyDataMapper, vtkOpenGLPolyDataMapper);

protected:
  vtkShadelabPolyDataMapper() = default;
  ~vtkShadelabPolyDataMapper() override = default;

  void BuildIBO(vtkRenderer* renderer, vtkActor* actor, vtkPolyData* mesh) override;

private:
  vtkShadelabPolyDataMapper(const vtkShadelabPolyDataMapper&) = delete;
  void operator=(const vtkShadelabPolyDataMapper&) = delete;
};

#endif
