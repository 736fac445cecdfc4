#include "commands/bench_command.h"

#include "bench/speed_accuracy_chart.h"
#include "bench/speed_accuracy_run.h"
#include "bench/speed_accuracy_summary.h"
#include "core/errors.h"
#include "core/milliseconds.h"
#include "core/output_file.h"
#include "core/output_path.h"
#include "core/progress_bar.h"
#include "image/image_writer_process.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace shadelab
{
CLI::App* AddBenchCommand(CLI::App& program, BenchOptions& o)
{
  CLI::App* bench = program.add_subcommand("bench",
    "Measure speed against accuracy: tessellated sphere and torus under each shading rule "
    "against their exact pictures; writes speed_accuracy.{csv,json,png,md} into DIR");
  bench->add_option("--out", o.Out, "Folder for the results (made if missing)")
    ->option_text("DIR")
    ->capture_default_str();
  bench->add_flag("--quick", o.Quick,
    "Four levels (80 to 7680 triangles), 640x480, angle weighting: under a minute");
  bench->add_option("--frames", o.Frames, "Timed frames per measurement, after the first")
    ->check(CLI::Range(1, 1000))
    ->capture_default_str();
  bench->add_flag("-q,--quiet", o.Quiet, "No warnings and no progress bar");
  return bench;
}

namespace
{
// The output folder, made and checked; 0 or the exit code.
int PrepareFolder(const std::string& out, const std::string& csv)
{
  std::error_code error;
  std::filesystem::create_directories(out, error);
  if (error)
  {
    return ReportError(out, "cannot make the folder: " + error.message());
  }
  if (std::string problem = CheckWritableFolder(csv); !problem.empty())
  {
    return ReportError(out, problem);
  }
  return 0;
}

// Each output is tried and each failure reported: one that fits may follow
// one that does not. 0 or the exit code.
int WriteResults(const BenchOptions& o, const std::vector<SpeedAccuracyRow>& rows,
  const ChartImage& chart, ImageWriterProcess& writer, const std::string& commandLine,
  double seconds)
{
  const std::filesystem::path out(o.Out);
  const std::string csv = (out / "speed_accuracy.csv").string();
  const std::string json = (out / "speed_accuracy.json").string();
  const std::string md = (out / "speed_accuracy.md").string();
  const std::string png = (out / "speed_accuracy.png").string();
  int status = 0;
  for (const auto& [path, problem] : { std::pair{ csv, WriteSpeedAccuracyCsv(csv, rows) },
         std::pair{ json, WriteSpeedAccuracyJson(json, rows) },
         std::pair{ md, WriteFile(md, SpeedAccuracySummary(rows, commandLine, seconds)) },
         std::pair{ png,
           writer.Write(png, chart.Image, PixelType::UInt8,
             { { "ImageDescription", "shadelab bench: RMSE against ms/frame" } }) } })
  {
    if (!problem.empty())
    {
      status = ReportError(path, problem);
    }
  }
  return status;
}
}

int RunBench(const BenchOptions& o, const std::string& commandLine)
{
  const std::string csv = (std::filesystem::path(o.Out) / "speed_accuracy.csv").string();
  if (const int status = PrepareFolder(o.Out, csv); status != 0)
  {
    return status;
  }
  ImageWriterProcess writer;
  // Compilation is measured, so Mesa's shader cache must not answer for it.
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  const auto start = Clock::now();

  const SpeedAccuracyPlan plan = MakeSpeedAccuracyPlan(o.Quick, o.Frames);
  ProgressBar progress(SpeedAccuracyRowCount(plan), o.Quiet);
  std::vector<SpeedAccuracyRow> rows;
  if (const auto failure = MeasureSpeedAccuracy(plan, progress, rows))
  {
    return ReportError(failure->Input, failure->Problem);
  }
  progress.Show(static_cast<long long>(rows.size()), "chart");
  const ChartImage chart = DrawSpeedAccuracyChart(rows);
  progress.Finish();
  if (!chart.Error.empty())
  {
    return ReportError("chart", chart.Error);
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (const int status = WriteResults(o, rows, chart, writer, commandLine, seconds); status != 0)
  {
    return status;
  }
  std::printf("%s: %zu measurements in %.0f s; speed_accuracy.{csv,json,png,md}\n", o.Out.c_str(),
    rows.size(), seconds);
  return 0;
}
}
