#include "scene/camera.h"

#include <vtkCamera.h>
#include <vtkMath.h>

#include <algorithm>
#include <cmath>

namespace shadelab
{
const char* const CameraHelp =
  "Camera: positions and directions are in the mesh's world coordinates. Given options are "
  "used as they are; missing ones are fitted to the mesh, as VTK's ResetCamera does: the focal "
  "point defaults to the centre of the mesh's bounding box; the position to the focal point "
  "plus +Z times the distance at which the mesh's bounding sphere (half the box diagonal, "
  "grown to enclose the mesh around a given focal point) fills the narrower of the two view "
  "angles; the view-up to +Y, or, for a camera looking straight along Y, to -Z looking "
  "down and +Z looking up. Orthographic: "
  "--parallel-scale is half the view height in world units, fitted to the same sphere when "
  "not given. The near and far planes always enclose the mesh.";

namespace
{
double Distance(const double a[3], const double b[3])
{
  return std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
}
}

std::string ApplyCamera(
  const SceneOptions& o, const double bounds[6], double aspect, vtkCamera* camera)
{
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double corner[3] = { bounds[1], bounds[3], bounds[5] };
  double radius = Distance(centre, corner);
  if (radius == 0)
  {
    radius = 0.5; // a single point, as ResetCamera does
  }

  double focal[3] = { centre[0], centre[1], centre[2] };
  if (o.CameraFocalPoint)
  {
    std::copy(o.CameraFocalPoint->begin(), o.CameraFocalPoint->end(), focal);
    radius += Distance(focal, centre);
  }

  // The narrower of the vertical and horizontal view angles must hold the sphere.
  const double halfAngle = vtkMath::RadiansFromDegrees(o.ViewAngle) / 2;
  const double narrowHalfAngle = aspect >= 1 ? halfAngle : std::atan(std::tan(halfAngle) * aspect);

  double position[3] = { 0, 0, 0 };
  if (o.CameraPosition)
  {
    std::copy(o.CameraPosition->begin(), o.CameraPosition->end(), position);
  }
  else
  {
    const double distance = radius / std::sin(narrowHalfAngle);
    position[0] = focal[0];
    position[1] = focal[1];
    position[2] = focal[2] + distance;
  }
  double direction[3] = { focal[0] - position[0], focal[1] - position[1], focal[2] - position[2] };
  if (vtkMath::Normalize(direction) == 0)
  {
    return "the camera position is the focal point";
  }

  double up[3] = { 0, 1, 0 };
  if (o.CameraViewUp)
  {
    std::copy(o.CameraViewUp->begin(), o.CameraViewUp->end(), up);
  }
  double side[3];
  vtkMath::Cross(direction, up, side);
  if (vtkMath::Norm(side) < 1e-9 * vtkMath::Norm(up))
  {
    if (o.CameraViewUp)
    {
      return "--camera-view-up is parallel to the view direction";
    }
    up[0] = 0;
    up[1] = 0;
    up[2] = direction[1] > 0 ? 1 : -1;
  }

  camera->SetFocalPoint(focal);
  camera->SetPosition(position);
  camera->SetViewUp(up);
  camera->OrthogonalizeViewUp();
  camera->SetViewAngle(o.ViewAngle);
  camera->SetParallelProjection(o.Orthographic);
  camera->SetParallelScale(o.ParallelScale.value_or(aspect >= 1 ? radius : radius / aspect));
  return {};
}
}
