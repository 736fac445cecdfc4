// `shadelab advise MESH --max-error E [--size WxH]`: what a scene requires.
// From the bench's measurements (speed_accuracy.csv: shadelab's
// own, compiled in, or a fresh `shadelab bench` run's), the cheapest shading
// rule that keeps the error under E for this mesh, and whether more
// triangles or a better rule is the better buy.
#ifndef shadelab_advise_command_h
#define shadelab_advise_command_h

#include "core/options.h"

#include <string>

namespace CLI
{
class App;
}

namespace shadelab
{
struct AdviseOptions
{
  std::string Mesh;
  double MaxError = 0; // RMSE, on the 0..1 intensity scale
  ImageSize Size{ 1920, 1080 };
  std::string Measurements; // a speed_accuracy.csv; empty: the one shadelab ships
  SceneOptions Scene;       // the settings advise takes: how normals are computed
};

CLI::App* AddAdviseCommand(CLI::App& program, AdviseOptions& options);

/** Runs it; returns the exit code. */
int RunAdvise(const AdviseOptions& options);
}

#endif
