// The camera of the contract: every given option used as it is, the missing
// ones fitted to the mesh the way VTK's ResetCamera does.
#ifndef shadelab_camera_h
#define shadelab_camera_h

#include "core/options.h"

#include <string>

class vtkCamera;
class vtkPoints;

namespace shadelab
{
/**
 * Sets camera from options for a mesh of the given points and an image of
 * the given aspect (width/height). Returns an error text for an impossible
 * camera (position at the focal point, view-up along the view direction),
 * else an empty string. The clipping range is left to the renderer.
 */
std::string ApplyCamera(
  const SceneOptions& options, vtkPoints* points, double aspect, vtkCamera* camera);

/**
 * Frame k of options' --orbit: its camera turned by 360*k/N degrees more,
 * which is exactly --azimuth with that much added.
 */
SceneOptions OrbitFrame(const SceneOptions& options, int k);

/**
 * The right-handed frame of an up axis: Up, Front (from the focal point
 * towards a camera that sees the front: +Z for up +Y, -Y for up +Z) and
 * Right = Up x Front, which is +X for every up axis but the X ones. A fitted
 * camera's and the environment's (Right, Up, Front its x, y, z).
 */
struct UpFrame
{
  Vec3 Up, Front, Right;
};
UpFrame FrameOf(UpAxis axis);

/** The conventions above, for --help. */
extern const char* const CameraHelp;
}

#endif
