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

/** One line of the driver's log of a refused stage. */
struct StageErrorLine
{
  StageError::Stage Where = StageError::Stage::Link;
  int Line = 0; // in that stage's text, from 1; 0 where the driver gives none
  std::string Message;
};

/**
 * The driver's errors of the stages of one's own that it refused when
 * scene was last drawn, one per line of its log, with the stage's line
 * where the driver gives one (Mesa's `0:LINE(COL): ...`, NVIDIA's
 * `0(LINE) : ...`); none when they drew.
 */
std::vector<StageErrorLine> LocateStageErrors(const BuiltScene& scene);

/**
 * LocateStageErrors as a compiler reports them: `FILE:LINE` (the files
 * options name) and the driver's message.
 */
std::vector<InputProblem> StageErrorLines(const SceneOptions& options, const BuiltScene& scene);
}

#endif
