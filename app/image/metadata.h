// What a picture carries about how it was made, so that it can be made again:
// the command line, shading, material, lights, camera and shadelab version.
#ifndef shadelab_metadata_h
#define shadelab_metadata_h

#include "core/options.h"

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

class vtkCamera;
class vtkPolyData;

namespace shadelab
{
/**
 * argv as one shell-quoted line, without the options that choose which of a
 * batch's shots run or what is printed (--shard, --skip-existing, --quiet,
 * --verbose): a picture is the same file whichever shard, rerun or single
 * process made it.
 */
std::string QuoteCommandLine(int argc, const char* const* argv);

/**
 * The image attributes: "Software" and "ImageDescription" (JSON of every
 * parameter, the camera as rendered, where kd came from in `mesh`, the mesh
 * as read, its parts with the materials they were drawn with; `shot`, when given, names the scene
 * file and shot it comes from; `panels`, a comparison's panel labels). No time stamps: the same
 * scene gives the same bytes.
 */
std::vector<std::pair<std::string, std::string>> DescribePicture(const std::string& commandLine,
  const SceneOptions& options, vtkCamera* camera, vtkPolyData* mesh, const std::string& shot = "",
  const std::vector<std::string>& panels = {});

/** A light as the description writes it: kind, position, direction, color, a spot's cone. */
nlohmann::ordered_json DescribeLight(const Light& light);

/** A material as the description writes it: name, ka, kd, ks, ns. */
nlohmann::ordered_json DescribeMaterial(const Material& material);
}

#endif
