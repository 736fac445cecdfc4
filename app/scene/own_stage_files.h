// The stages of one's own that --vertex-shader and --fragment-shader name:
// read as checked files (regular, at most MaxShaderFileBytes), and the
// driver's compile and link errors turned into the lines of those files
// (`FILE:LINE`, the driver's message), as a compiler reports them.
#ifndef shadelab_own_stage_files_h
#define shadelab_own_stage_files_h

#include "core/errors.h"
#include "core/options.h"
#include "scene/scene.h"
#include "shadelabOwnStages.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadelab
{
constexpr std::uint64_t MaxShaderFileBytes = 1 << 20;

/** options' stage files, read into stages; on failure the file and why (else two ""). */
InputProblem ReadOwnStages(const SceneOptions& options, OwnStages& stages);

/** The files of the stages options give, as one name: "V.vert + F.frag", or the one given. */
std::string OwnStageFiles(const SceneOptions& options);

/**
 * The errors of the stages of one's own (those options name) that the
 * driver refused when scene was last drawn, one line each: the file and
 * the line where the driver gives one (Mesa's `0:LINE(COL): ...`,
 * NVIDIA's `0(LINE) : ...`), and the driver's message; none when they drew.
 */
std::vector<InputProblem> StageErrorLines(const SceneOptions& options, const BuiltScene& scene);
}

#endif
