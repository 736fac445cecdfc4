// Rendering shots: one from the command line, or a scene file's
// many in one process. Each mesh is read (and its normals computed) once,
// each picture size gets one OpenGL context whose compiled shader programs
// serve every shot of that size, and one image-writer process writes all
// pictures. A shot that fails is reported and the others still run.
#ifndef shadelab_batch_h
#define shadelab_batch_h

#include "scene/scene_file.h"

#include <string>
#include <vector>

namespace shadelab
{
struct BatchOptions
{
  std::string DumpShaders; // a folder, or empty (one shot only)
  bool Verbose = false;    // each phase's time
  bool Quiet = false;      // no progress bar
  int ShardIndex = 0;      // render the shots whose index mod ShardCount is ShardIndex
  int ShardCount = 1;
  bool SkipExisting = false; // a shot whose output exists is done (outputs appear whole, by rename)
};

/**
 * Renders shots (this shard's), writing each to its Output through a
 * temporary name. Returns ExitFailure when one was not, each failure
 * reported as one line on stderr. SIGINT or SIGTERM stops it between shots:
 * the pictures being written are finished, it says how far it got, and
 * returns 128 + the signal's number. When every one was written it does not
 * return: the process ends with 0, without teardown (exit_without_teardown.h;
 * in the sanitizer build it returns 0).
 */
int RenderShots(
  const std::vector<Shot>& shots, const BatchOptions& options, const std::string& commandLine);
}

#endif
