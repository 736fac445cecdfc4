// Flat shading's face normals in OpenGL: a buffer texture that the fragment
// stage reads by gl_PrimitiveID.
#ifndef shadelabFaceNormalTexture_h
#define shadelabFaceNormalTexture_h

#include "shadelabRepresentation.h"

#include <vtkOpenGLBufferObject.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>

#include <string>

class vtkOpenGLRenderWindow;
class vtkPolyData;

namespace shadelab
{
struct FaceNormalTexture
{
  vtkSmartPointer<vtkOpenGLBufferObject> Buffer;
  vtkSmartPointer<vtkTextureObject> Texture; // over Buffer, one RGB float texel a triangle
};

/**
 * mesh's face normals (ComputeFaceNormals) uploaded into a buffer texture
 * of window's context, which must be current: one a triangle, or drawn as
 * edges or points, one an element, its owner's (DrawnElements). Returns "" and sets
 * `uploaded`, or the problem: cells other than triangles (gl_PrimitiveID
 * counts the triangles of one draw of the polys, so cell t must be triangle
 * t), or more triangles than OpenGL's buffer textures hold.
 */
std::string UploadFaceNormals(vtkPolyData* mesh, Representation drawn,
  vtkOpenGLRenderWindow* window, FaceNormalTexture& uploaded);
}

#endif
