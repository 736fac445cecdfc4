#include "bench/speed_accuracy_summary.h"

#include "core/report_text.h"

#include <map>
#include <set>
#include <sstream>
#include <thread>
#include <tuple>

namespace shadelab
{
namespace
{
// How the measurements were made and what the error is.
void WriteIntroduction(std::ostream& md, const std::string& commandLine, double seconds)
{
  md << "# Speed against accuracy\n\n"
     << "`" << commandLine << "`: " << FormatNumber("%.0f", seconds) << " s on " << CpuModel()
     << " (" << std::thread::hardware_concurrency() << " threads), OSMesa llvmpipe.\n\n"
     << "Error: |rendered - exact| of R, G, B over the object's pixels, less a " << SilhouetteBand
     << "-pixel band at the silhouette; exact = the lecture's equation at the ray's hit on the "
        "analytic surface with its exact normal, in double precision. Chrome, Blinn-Phong, one "
        "point light. ms/frame: median of the timed frames, read-back included.\n\n";
}

// A table per surface and size: each rule's error and speed at each level,
// angle weighting.
void WriteRuleTables(std::ostream& md, const std::vector<SpeedAccuracyRow>& rows)
{
  std::map<std::tuple<std::string, int, int>,
    std::map<long long, std::map<std::string, const SpeedAccuracyRow*>>>
    tables;
  for (const SpeedAccuracyRow& r : rows)
  {
    if (r.Weighting == "angle" || r.Weighting == "face")
    {
      tables[{ r.Surface, r.Width, r.Height }][r.Triangles][r.Shading] = &r;
    }
  }
  for (const auto& [key, levels] : tables)
  {
    md << "## " << std::get<0>(key) << ", " << std::get<1>(key) << "x" << std::get<2>(key)
       << "\n\n| triangles | edge angle | flat RMSE | gouraud RMSE | phong RMSE | flat ms | "
          "gouraud ms | phong ms | phong PSNR |\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& [triangles, byRule] : levels)
    {
      md << "| " << triangles << " | " << FormatNumber("%.2f", byRule.begin()->second->EdgeAngle)
         << " |";
      for (const Shading rule : LitRules)
      {
        const auto it = byRule.find(ToString(rule));
        md << " " << (it == byRule.end() ? "" : FormatNumber("%.2e", it->second->Rmse)) << " |";
      }
      for (const Shading rule : LitRules)
      {
        const auto it = byRule.find(ToString(rule));
        md << " " << (it == byRule.end() ? "" : FormatNumber("%.1f", it->second->MsPerFrame))
           << " |";
      }
      const auto phong = byRule.find("phong");
      md << " " << (phong == byRule.end() ? "" : FormatNumber("%.1f", phong->second->Psnr))
         << " |\n";
    }
    md << "\n";
  }
}

// The weightings' errors side by side at the last size, when more than one
// was measured.
void WriteWeightingTable(std::ostream& md, const std::vector<SpeedAccuracyRow>& rows)
{
  std::map<std::string, std::map<long long, std::map<std::string, double>>> weightings;
  std::set<std::string> weightingNames;
  for (const SpeedAccuracyRow& r : rows)
  {
    if (r.Weighting != "face" && r.Width == rows.back().Width)
    {
      weightings[r.Surface + " " + r.Shading][r.Triangles][r.Weighting] = r.Rmse;
      weightingNames.insert(r.Weighting);
    }
  }
  if (weightingNames.size() <= 1)
  {
    return;
  }
  md << "## Normal weightings (RMSE at " << rows.back().Width << "x" << rows.back().Height
     << ")\n\n| surface, rule | triangles |";
  for (const std::string& w : weightingNames)
  {
    md << " " << w << " |";
  }
  md << "\n|---|---:|";
  for (std::size_t k = 0; k < weightingNames.size(); ++k)
  {
    md << "---:|";
  }
  md << "\n";
  for (const auto& [name, levels] : weightings)
  {
    for (const auto& [triangles, byWeighting] : levels)
    {
      md << "| " << name << " | " << triangles << " |";
      for (const std::string& w : weightingNames)
      {
        const auto it = byWeighting.find(w);
        md << " " << (it == byWeighting.end() ? "" : FormatNumber("%.2e", it->second)) << " |";
      }
      md << "\n";
    }
  }
  md << "\n";
}

void WriteChecks(std::ostream& md, const std::vector<SpeedAccuracyRow>& rows)
{
  const std::vector<std::string> exceptions = CheckSpeedAccuracyOrder(rows);
  md << "## Checks\n\nError falls with tessellation for every rule, and phong < gouraud < flat "
        "at every level: "
     << (exceptions.empty() ? "yes, everywhere.\n" : "no:\n\n");
  for (const std::string& e : exceptions)
  {
    md << "- " << e << "\n";
  }
}
}

std::string SpeedAccuracySummary(
  const std::vector<SpeedAccuracyRow>& rows, const std::string& commandLine, double seconds)
{
  std::ostringstream md;
  WriteIntroduction(md, commandLine, seconds);
  WriteRuleTables(md, rows);
  WriteWeightingTable(md, rows);
  WriteChecks(md, rows);
  md << "\n![error against ms/frame](speed_accuracy.png)\n";
  return md.str();
}
}
