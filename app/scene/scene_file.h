// Scene files: `shadelab render --scene FILE.json` takes every
// scene option, and many shots, from one JSON file. The format is
// data/scene.schema.json (`shadelab render --print-schema`, made from the
// table of settings); doc/user/scenes-and-batches.md shows it. Every value
// goes through the command line's own parsers, so a key means exactly what
// its option means.
#ifndef shadelab_scene_file_h
#define shadelab_scene_file_h

#include "core/options.h"

#include <string>
#include <vector>

namespace shadelab
{
/** One picture to render: everything the render command takes. */
struct Shot
{
  SceneOptions Scene;
  std::string Output;
  std::string Label;        // "scene.json shots[3]" for a scene file's shot, "" on the command line
  bool MakeFolders = false; // the output came from a template: its folders are made as needed
  bool Animation = false;   // Output holds every frame of Scene.Orbit (.gif, .mp4)
};

/**
 * A scene file whose one shot renders s into output: every setting that
 * decides the picture, numbers to the last bit (the inspector's Save
 * scene). s.Mesh as given: absolute, or relative to the file's folder.
 */
std::string WriteSceneText(const SceneOptions& s, const std::string& output);

/** The JSON Schema of scene files, as data/scene.schema.json holds it. */
std::string SceneSchema();

/**
 * Reads the shots of the scene file at path. outputTemplate, when not
 * empty, replaces every shot's "output". Mesh paths are relative to the
 * scene file's folder, outputs to the current folder. Returns "" or the
 * problem, starting with its JSON path: `shots[3].lights[0].kind: unknown
 * kind "laser"`.
 */
std::string ReadSceneFile(
  const std::string& path, const std::string& outputTemplate, std::vector<Shot>& shots);

/**
 * Fills an output name template for shot number index of count: {mesh}
 * (the mesh file's name without extension), {shading}, {reflection},
 * {material}, {weighting}, {size} (WxH), {index} (zero-padded to count's
 * digits), {name} (the shot's "name", else its index); "{{" and "}}" are
 * braces. Returns "" or the problem.
 */
std::string ExpandOutputTemplate(const std::string& pattern, const Shot& shot,
  const std::string& name, std::size_t index, std::size_t count, std::string& output);

/**
 * The shots that shot makes with the output template pattern, appended to
 * shots: one, its Output filled as ExpandOutputTemplate fills it; or, with
 * --orbit N, N (frame k's camera turned by 360*k/N degrees, OrbitFrame) when
 * pattern has {frame}, which numbers them zero-padded to N-1's digits; or
 * one Animation of every frame when it has not and ends in .gif or .mp4.
 * Returns "" or the problem.
 */
std::string ExpandShot(const std::string& pattern, const Shot& shot, const std::string& name,
  std::size_t index, std::size_t count, std::vector<Shot>& shots);
}

#endif
