#include "scene/camera.h"

#include "scene/camera_fit.h"

#include <vtkCamera.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkTransform.h>

#include <algorithm>
#include <cmath>

namespace shadelab
{
const char* const CameraHelp =
  "Camera: positions and directions are in the mesh's world coordinates. Given options are "
  "used as they are; missing ones are fitted to the mesh, as VTK's ResetCamera does: the focal "
  "point defaults to the centre of the mesh's bounding box; the position to the focal point "
  "plus, in the direction --view and --up name (by default front, +Y up: +Z), the distance at "
  "which the mesh's bounding sphere (half the box diagonal, grown to enclose the mesh around a "
  "given focal point) fills the narrower of the two view angles; the view-up to --up's axis, "
  "or, for a camera looking straight along it (top, bottom), to the front's direction: away "
  "from it looking down, towards it looking up. --azimuth (about the up axis: the view-up "
  "given, else --up's) and --elevation then turn the camera, given or fitted, about its focal "
  "point. Orthographic: --parallel-scale is half the view height in world units, fitted to "
  "the same sphere when not given. --fit tight then fits what was not given to the mesh's "
  "points instead, for the direction the camera now has: the distance (orthographic: the "
  "parallel scale) at which the points' projection spans the picture exactly, without margin, "
  "on the axis that limits it, and the focal point moved in the view plane to centre it (with "
  "--orbit it stays the turn's centre, and the fit holds every frame). --zoom then magnifies. "
  "The near and far planes always enclose the mesh.";

namespace
{
double Distance(const double a[3], const double b[3])
{
  return std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
}
}

UpFrame FrameOf(UpAxis axis)
{
  UpFrame f;
  switch (axis)
  {
    case UpAxis::PlusX:
      f = { { 1, 0, 0 }, { 0, 0, 1 }, {} };
      break;
    case UpAxis::MinusX:
      f = { { -1, 0, 0 }, { 0, 0, 1 }, {} };
      break;
    case UpAxis::PlusY:
      f = { { 0, 1, 0 }, { 0, 0, 1 }, {} };
      break;
    case UpAxis::MinusY:
      f = { { 0, -1, 0 }, { 0, 0, -1 }, {} };
      break;
    case UpAxis::PlusZ:
      f = { { 0, 0, 1 }, { 0, -1, 0 }, {} };
      break;
    case UpAxis::MinusZ:
      f = { { 0, 0, -1 }, { 0, 1, 0 }, {} };
      break;
  }
  vtkMath::Cross(f.Up.data(), f.Front.data(), f.Right.data());
  return f;
}

namespace
{
Vec3 Scaled(const Vec3& v, double s)
{
  return { s * v[0], s * v[1], s * v[2] };
}

// Where a fitted camera sits, as a unit direction from the focal point, and
// its view-up: --view about the frame. From above the front is at the bottom
// of the picture, from below at the top.
void Preset(ViewPreset view, const UpFrame& f, Vec3& eye, Vec3& up)
{
  up = f.Up;
  switch (view)
  {
    case ViewPreset::Front:
      eye = f.Front;
      break;
    case ViewPreset::Back:
      eye = Scaled(f.Front, -1);
      break;
    case ViewPreset::Right:
      eye = f.Right;
      break;
    case ViewPreset::Left:
      eye = Scaled(f.Right, -1);
      break;
    case ViewPreset::Top:
      eye = f.Up;
      up = Scaled(f.Front, -1);
      break;
    case ViewPreset::Bottom:
      eye = Scaled(f.Up, -1);
      up = f.Front;
      break;
    case ViewPreset::Iso:
      eye = { f.Front[0] + f.Right[0] + f.Up[0], f.Front[1] + f.Right[1] + f.Up[1],
        f.Front[2] + f.Right[2] + f.Up[2] };
      vtkMath::Normalize(eye.data());
      break;
  }
}

// Turns the camera, its position and view-up, by degrees about axis
// through the focal point.
void Turn(vtkCamera* camera, const Vec3& axis, double degrees)
{
  const double* focal = camera->GetFocalPoint();
  vtkNew<vtkTransform> turn;
  turn->Translate(focal[0], focal[1], focal[2]);
  turn->RotateWXYZ(degrees, axis.data());
  turn->Translate(-focal[0], -focal[1], -focal[2]);
  double position[3], up[3];
  turn->TransformPoint(camera->GetPosition(), position);
  turn->TransformVector(camera->GetViewUp(), up);
  camera->SetPosition(position);
  camera->SetViewUp(up);
}
}

SceneOptions OrbitFrame(const SceneOptions& options, int k)
{
  SceneOptions frame = options;
  frame.Azimuth += 360.0 * k / options.Orbit;
  return frame;
}

std::string ApplyCamera(const SceneOptions& o, vtkPoints* points, double aspect, vtkCamera* camera)
{
  double bounds[6];
  points->GetBounds(bounds);
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

  const UpFrame frame = FrameOf(o.Up);
  Vec3 eye, presetUp;
  Preset(o.View, frame, eye, presetUp);
  double position[3] = { 0, 0, 0 };
  if (o.CameraPosition)
  {
    std::copy(o.CameraPosition->begin(), o.CameraPosition->end(), position);
    presetUp = frame.Up;
  }
  else
  {
    const double distance = radius / std::sin(narrowHalfAngle);
    for (int i = 0; i < 3; ++i)
    {
      position[i] = focal[i] + distance * eye[i];
    }
  }
  double direction[3] = { focal[0] - position[0], focal[1] - position[1], focal[2] - position[2] };
  if (vtkMath::Normalize(direction) == 0)
  {
    return "the camera position is the focal point";
  }

  double up[3] = { presetUp[0], presetUp[1], presetUp[2] };
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
    // A given position straight above or below: as the top and bottom views.
    const double sign = vtkMath::Dot(direction, frame.Up.data()) > 0 ? 1 : -1;
    for (int i = 0; i < 3; ++i)
    {
      up[i] = sign * frame.Front[i];
    }
  }

  camera->SetFocalPoint(focal);
  camera->SetPosition(position);
  camera->SetViewUp(up);
  camera->OrthogonalizeViewUp();
  camera->SetViewAngle(o.ViewAngle);
  camera->SetParallelProjection(o.Orthographic);
  camera->SetParallelScale(o.ParallelScale.value_or(aspect >= 1 ? radius : radius / aspect));
  // Turns, the tight fit and magnification after everything else, given
  // cameras too; none by default, so that a default camera is exactly as set
  // above. The azimuth (and an orbit) turns about the up axis: the given
  // view-up, else --up's axis, so that from the top the picture spins.
  const Vec3 axis = o.CameraViewUp.value_or(frame.Up);
  if (o.Azimuth != 0)
  {
    Turn(camera, axis, o.Azimuth);
  }
  if (o.Elevation != 0)
  {
    camera->Elevation(o.Elevation);
    camera->OrthogonalizeViewUp();
  }
  if (o.Fit == FitMode::Tight)
  {
    FitTight(o, points, aspect, axis, camera);
  }
  if (o.Zoom != 1)
  {
    camera->Zoom(o.Zoom);
  }
  return {};
}
}
