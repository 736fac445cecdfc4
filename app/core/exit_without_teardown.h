// The end of a command whose every output is on disk: the process leaves
// without freeing what it holds. Tearing down VTK's contexts and scenes,
// OSMesa and the image writer's pipe takes a 1080p screenshot about 30 ms
// (doc/benchmarks-log.md, "One 1080p screenshot"), and the kernel frees it all anyway.
#ifndef shadelab_exit_without_teardown_h
#define shadelab_exit_without_teardown_h

namespace shadelab
{
/**
 * Flushes standard output and error and ends the process with status, without
 * destructors or atexit handlers. Call it only once nothing is left to do:
 * every file written and answered for. In the sanitizer build it only
 * returns status, so that the command returns to main and LeakSanitizer,
 * which checks at a normal exit, still sees the whole run.
 */
int ExitWithoutTeardown(int status);
}

#endif
