// `shadelab normals MESH -o OUT.(ply|vtp|obj) [--weighting W]
// [--feature-angle DEG] [--orient]`: the mesh with its computed normals.
#ifndef shadelab_normals_command_h
#define shadelab_normals_command_h

#include "core/options.h"

#include <string>

namespace CLI
{
class App;
}

namespace shadelab
{
struct NormalsOptions
{
  std::string Mesh;
  std::string Output;
  SceneOptions Scene; // the settings normals takes: how normals are computed, trust
  bool Quiet = false; // no warnings
};

/** Declares the normals command and its options on the program. */
CLI::App* AddNormalsCommand(CLI::App& program, NormalsOptions& options);

/** Runs it; returns the exit code. */
int RunNormals(const NormalsOptions& options);
}

#endif
