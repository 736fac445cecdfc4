// The stages of one's own that --vertex-shader and --fragment-shader name:
// read as checked files (regular, at most MaxShaderFileBytes), and the
// driver's compile and link errors turned into the lines of those files
// (`FILE:LINE`, the driver's message), as a compiler reports them.
#ifndef shadelab_own_stage_files_h
#define shadelab_own_stage_files_h

#include "core/errors.h"
#include "core/options.h"
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
 * errors (of the stages options name) one line each: the file and the
 * line where the driver gives one (Mesa's `0:LINE(COL): ...`, NVIDIA's
 * `0(LINE) : ...`), and the driver's message.
 */
std::vector<InputProblem> StageErrorLines(
  const SceneOptions& options, const std::vector<StageError>& errors);
}

#endif
