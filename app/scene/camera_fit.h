// --fit tight: the camera moved so that the mesh's points, not their
// bounding sphere, fill the picture. The view direction stays; what the
// options leave free is solved for exactly from the points' projections.
#ifndef shadelab_camera_fit_h
#define shadelab_camera_fit_h

#include "core/options.h"

class vtkCamera;
class vtkPoints;

namespace shadelab
{
/**
 * Refits camera, which already looks in its final direction, to points in a
 * picture of the given aspect (width/height). What is free moves: the focal
 * point in the view plane unless a focal point or position was given (or
 * the picture is an --orbit frame: then it stays the turn's centre); the
 * distance (perspective) unless a position was given; the parallel scale
 * (orthographic) unless given. The result: on the limiting axis the extreme
 * points project exactly onto the picture's two borders, on the other the
 * projection is centred (for an --orbit of N frames: over every frame's
 * view, the camera turned about `axis` through the focal point by 360*k/N
 * degrees). Without margin. A camera with nothing free, or points without
 * extent on the screen, is left as it is.
 */
void FitTight(const SceneOptions& options, vtkPoints* points, double aspect, const Vec3& axis,
  vtkCamera* camera);
}

#endif
