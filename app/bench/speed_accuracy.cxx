#include "bench/speed_accuracy.h"

#include "core/output_file.h"
#include "shadelabVec3.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>
#include <unordered_set>
#include <utility>

namespace shadelab
{
namespace
{
// Pixels covered by both pictures and farther than `band` from any pixel
// that is not.
std::vector<unsigned char> ComparedPixels(const FloatImage& rendered, const ExactImage& exact)
{
  const int w = exact.Width, h = exact.Height;
  std::vector<unsigned char> both(exact.Covered.size());
  for (std::size_t p = 0; p < both.size(); ++p)
  {
    both[p] = exact.Covered[p] && rendered.Rgba[4 * p + 3] > 0.5f;
  }
  // Erosion by a (2 band + 1)^2 square, as two one-dimensional passes.
  auto erode = [&](const std::vector<unsigned char>& in, int dx, int dy)
  {
    std::vector<unsigned char> out(in.size(), 0);
    for (int j = 0; j < h; ++j)
    {
      for (int i = 0; i < w; ++i)
      {
        bool keep = true;
        for (int k = -SilhouetteBand; k <= SilhouetteBand && keep; ++k)
        {
          const int x = i + k * dx, y = j + k * dy;
          keep = x >= 0 && y >= 0 && x < w && y < h && in[static_cast<std::size_t>(y) * w + x];
        }
        out[static_cast<std::size_t>(j) * w + i] = keep;
      }
    }
    return out;
  };
  return erode(erode(both, 1, 0), 0, 1);
}

std::string Short(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

const char* const Columns[] = { "surface", "shading", "weighting", "triangles", "width", "height",
  "ms_per_frame", "rmse", "max_error", "psnr", "normals_ms", "compile_ms", "edge_angle_deg",
  "pixels" };

// Each column's text, in Columns' order; numbers with enough digits to read back.
std::vector<std::string> Fields(const SpeedAccuracyRow& r)
{
  auto number = [](double v)
  {
    std::ostringstream s;
    s.precision(9);
    s << v;
    return s.str();
  };
  return { r.Surface, r.Shading, r.Weighting, std::to_string(r.Triangles), std::to_string(r.Width),
    std::to_string(r.Height), number(r.MsPerFrame), number(r.Rmse), number(r.MaxError),
    number(r.Psnr), number(r.NormalsMs), number(r.CompileMs), number(r.EdgeAngle),
    std::to_string(r.Pixels) };
}
}

std::vector<std::string> CheckSpeedAccuracyOrder(const std::vector<SpeedAccuracyRow>& rows)
{
  std::vector<std::string> exceptions;
  // (surface, width, height) -> triangles -> "rule/weighting" -> rmse
  std::map<std::tuple<std::string, int, int>, std::map<long long, std::map<std::string, double>>>
    all;
  std::set<std::string> weightings;
  for (const SpeedAccuracyRow& r : rows)
  {
    all[{ r.Surface, r.Width, r.Height }][r.Triangles][r.Shading + "/" + r.Weighting] = r.Rmse;
    if (r.Weighting != "face")
    {
      weightings.insert(r.Weighting);
    }
  }
  for (const auto& [key, levels] : all)
  {
    const std::string where = std::get<0>(key) + " " + std::to_string(std::get<1>(key)) + "x" +
      std::to_string(std::get<2>(key));
    std::map<std::string, double> previous;
    for (const auto& [triangles, errors] : levels)
    {
      const std::string at = where + " at " + std::to_string(triangles) + " triangles";
      for (const auto& [candidate, rmse] : errors)
      {
        const auto before = previous.find(candidate);
        if (before != previous.end() && !(rmse < before->second))
        {
          exceptions.push_back(at + ": " + candidate + " RMSE " + Short(rmse) +
            " is not below the coarser level's " + Short(before->second));
        }
        previous[candidate] = rmse;
      }
      for (const std::string& w : weightings)
      {
        const auto flat = errors.find("flat/face");
        const auto gouraud = errors.find("gouraud/" + w);
        const auto phong = errors.find("phong/" + w);
        if (flat == errors.end() || gouraud == errors.end() || phong == errors.end())
        {
          continue;
        }
        if (!(phong->second < gouraud->second && gouraud->second < flat->second))
        {
          exceptions.push_back(at + ", " + w + " weighting: phong " + Short(phong->second) +
            ", gouraud " + Short(gouraud->second) + ", flat " + Short(flat->second) +
            " are not in the order phong < gouraud < flat");
        }
      }
    }
  }
  return exceptions;
}

std::string TriangleCountText(double n)
{
  char text[32];
  if (n >= 1e6)
  {
    std::snprintf(text, sizeof text, "%.1fM", n / 1e6);
  }
  else if (n >= 1e4)
  {
    std::snprintf(text, sizeof text, "%.0fk", n / 1e3);
  }
  else
  {
    std::snprintf(text, sizeof text, "%.0f", n);
  }
  return text;
}

AccuracyMetrics CompareWithExact(const FloatImage& rendered, const ExactImage& exact)
{
  AccuracyMetrics m;
  const std::vector<unsigned char> compared = ComparedPixels(rendered, exact);
  double sum = 0;
  for (std::size_t p = 0; p < compared.size(); ++p)
  {
    if (!compared[p])
    {
      continue;
    }
    ++m.Pixels;
    for (int k = 0; k < 3; ++k)
    {
      const double e =
        std::abs(static_cast<double>(rendered.Rgba[4 * p + k]) - exact.Rgb[3 * p + k]);
      sum += e * e;
      // NaN must not hide behind max(): it makes the error NaN.
      m.MaxError = std::isnan(e) ? e : std::max(m.MaxError, e);
    }
  }
  const double mse = m.Pixels ? sum / (3.0 * m.Pixels) : 0;
  m.Rmse = std::sqrt(mse);
  m.Psnr = mse > 0 ? -10 * std::log10(mse) : INFINITY;
  return m;
}

double MeanEdgeNormalAngle(vtkPolyData* mesh)
{
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  if (!normals)
  {
    return 0;
  }
  std::unordered_set<std::uint64_t> edges;
  double sum = 0;
  auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    cells->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = std::min(ids[k], ids[(k + 1) % n]),
                      b = std::max(ids[k], ids[(k + 1) % n]);
      if (!edges.insert((static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b))
             .second)
      {
        continue;
      }
      Vec3 na, nb;
      normals->GetTuple(a, na.data());
      normals->GetTuple(b, nb.data());
      // atan2 of |a x b| and a.b: exact for small angles, unlike acos.
      sum += std::atan2(length(cross(na, nb)), dot(na, nb));
    }
  }
  return edges.empty() ? 0 : sum / edges.size() * 180 / 3.14159265358979323846;
}

std::string WriteSpeedAccuracyCsv(
  const std::string& path, const std::vector<SpeedAccuracyRow>& rows)
{
  std::string text;
  for (const char* column : Columns)
  {
    text += std::string(text.empty() ? "" : ",") + column;
  }
  text += "\n";
  for (const SpeedAccuracyRow& row : rows)
  {
    const std::vector<std::string> fields = Fields(row);
    for (std::size_t k = 0; k < fields.size(); ++k)
    {
      text += (k ? "," : "") + fields[k];
    }
    text += "\n";
  }
  return WriteFile(path, text);
}

std::string WriteSpeedAccuracyJson(
  const std::string& path, const std::vector<SpeedAccuracyRow>& rows)
{
  nlohmann::json all = nlohmann::json::array();
  for (const SpeedAccuracyRow& r : rows)
  {
    all.push_back({ { "surface", r.Surface }, { "shading", r.Shading },
      { "weighting", r.Weighting }, { "triangles", r.Triangles }, { "width", r.Width },
      { "height", r.Height }, { "ms_per_frame", r.MsPerFrame }, { "rmse", r.Rmse },
      { "max_error", r.MaxError }, { "psnr", r.Psnr }, { "normals_ms", r.NormalsMs },
      { "compile_ms", r.CompileMs }, { "edge_angle_deg", r.EdgeAngle }, { "pixels", r.Pixels } });
  }
  return WriteFile(path, all.dump(1) + "\n");
}

std::string ReadSpeedAccuracyCsv(const std::string& path, std::vector<SpeedAccuracyRow>& rows)
{
  std::ifstream in(path);
  if (!in)
  {
    return "cannot read the measurements";
  }
  return ParseSpeedAccuracyCsv(in, rows);
}

std::string ParseSpeedAccuracyCsv(std::istream& in, std::vector<SpeedAccuracyRow>& rows)
{
  auto split = [](const std::string& line)
  {
    std::vector<std::string> fields;
    std::istringstream s(line);
    for (std::string field; std::getline(s, field, ',');)
    {
      fields.push_back(field);
    }
    return fields;
  };
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split(line);
  std::map<std::string, std::size_t> at;
  for (const char* column : Columns)
  {
    const auto found = std::find(header.begin(), header.end(), column);
    if (found == header.end())
    {
      return std::string("not speed_accuracy.csv: no column \"") + column + "\"";
    }
    at[column] = static_cast<std::size_t>(found - header.begin());
  }
  rows.clear();
  for (int number = 2; std::getline(in, line); ++number)
  {
    if (line.empty())
    {
      continue;
    }
    const std::vector<std::string> f = split(line);
    if (f.size() != header.size())
    {
      return "line " + std::to_string(number) + ": " + std::to_string(f.size()) + " fields, not " +
        std::to_string(header.size());
    }
    SpeedAccuracyRow r;
    try
    {
      r.Surface = f[at["surface"]];
      r.Shading = f[at["shading"]];
      r.Weighting = f[at["weighting"]];
      r.Triangles = std::stoll(f[at["triangles"]]);
      r.Width = std::stoi(f[at["width"]]);
      r.Height = std::stoi(f[at["height"]]);
      r.MsPerFrame = std::stod(f[at["ms_per_frame"]]);
      r.Rmse = std::stod(f[at["rmse"]]);
      r.MaxError = std::stod(f[at["max_error"]]);
      r.Psnr = std::stod(f[at["psnr"]]);
      r.NormalsMs = std::stod(f[at["normals_ms"]]);
      r.CompileMs = std::stod(f[at["compile_ms"]]);
      r.EdgeAngle = std::stod(f[at["edge_angle_deg"]]);
      r.Pixels = std::stoll(f[at["pixels"]]);
    }
    catch (const std::exception&)
    {
      return "line " + std::to_string(number) + ": a number is not a number";
    }
    rows.push_back(r);
  }
  return {};
}
}
