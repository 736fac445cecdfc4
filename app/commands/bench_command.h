// `shadelab bench [--out DIR] [--quick]`: the speed-accuracy trade measured
// against an analytic ground truth. Tessellations of a sphere and
// a torus, from about 100 to about 2M triangles, rendered through the
// OSMesa backend with each shading rule and normal weighting, against the
// exact picture of the same surface (shadelabExactImage.h).
#ifndef shadelab_bench_command_h
#define shadelab_bench_command_h

#include "bench/speed_accuracy.h"

#include <string>

namespace CLI
{
class App;
}

namespace shadelab
{
struct BenchOptions
{
  std::string Out = "speed-accuracy";
  bool Quick = false; // CI's version: four levels, one size, the default weighting
  int Frames = 5;     // timed frames after the first
  bool Quiet = false;
};

CLI::App* AddBenchCommand(CLI::App& program, BenchOptions& options);

/** Runs it; returns the exit code. */
int RunBench(const BenchOptions& options, const std::string& commandLine);
}

#endif
