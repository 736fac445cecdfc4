#include "bench/speed_accuracy_chart.h"

#include "headless/headless_renderer.h"

#include <vtkAutoInit.h>
#include <vtkAxis.h>
#include <vtkBrush.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContext2D.h>
#include <vtkContextActor.h>
#include <vtkContextItem.h>
#include <vtkContextScene.h>
#include <vtkDoubleArray.h>
#include <vtkObjectFactory.h>
#include <vtkPen.h>
#include <vtkPlotLine.h>
#include <vtkRenderer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

// The charts draw through OpenGL context devices and FreeType text.
VTK_MODULE_INIT(vtkRenderingContextOpenGL2);
VTK_MODULE_INIT(vtkRenderingFreeType);

namespace shadelab
{
namespace
{
struct PointLabel
{
  double X, Y;
  std::string Text;
};

// Text beside data points. vtkChartXY shows point labels only as tooltips,
// so this item, painted after the chart, maps data to pixels through the
// chart's axes itself.
class PointLabels : public vtkContextItem
{
public:
  static PointLabels* New();
  vtkTypeMacro(PointLabels, vtkContextItem);

  vtkChartXY* Chart = nullptr;
  std::vector<PointLabel> Labels;

  bool Paint(vtkContext2D* painter) override
  {
    vtkAxis* x = this->Chart->GetAxis(vtkAxis::BOTTOM);
    vtkAxis* y = this->Chart->GetAxis(vtkAxis::LEFT);
    auto toPixel = [](vtkAxis* axis, int k, double v)
    {
      const float a = axis->GetPoint1()[k], b = axis->GetPoint2()[k];
      return a +
        (std::log10(v) - axis->GetMinimum()) / (axis->GetMaximum() - axis->GetMinimum()) * (b - a);
    };
    painter->GetTextProp()->SetFontSize(13);
    painter->GetTextProp()->SetColor(0.25, 0.25, 0.25);
    painter->GetTextProp()->SetJustificationToLeft();
    painter->GetTextProp()->SetVerticalJustificationToBottom();
    for (const PointLabel& label : this->Labels)
    {
      painter->DrawString(static_cast<float>(toPixel(x, 0, label.X) + 5),
        static_cast<float>(toPixel(y, 1, label.Y) + 3), label.Text.c_str());
    }
    return true;
  }
};
vtkStandardNewMacro(PointLabels);

using Line = std::vector<const SpeedAccuracyRow*>;

// The largest picture measured, angle weighting (flat has none): one line
// per surface and rule, in order of triangles.
std::map<std::pair<std::string, std::string>, Line> Lines(
  const std::vector<SpeedAccuracyRow>& rows, int largest)
{
  std::map<std::pair<std::string, std::string>, Line> lines;
  for (const SpeedAccuracyRow& r : rows)
  {
    if (r.Width * r.Height == largest && (r.Weighting == "angle" || r.Weighting == "face"))
    {
      lines[{ r.Surface, r.Shading }].push_back(&r);
    }
  }
  for (auto& [key, points] : lines)
  {
    std::sort(points.begin(), points.end(),
      [](const SpeedAccuracyRow* a, const SpeedAccuracyRow* b)
      { return a->Triangles < b->Triangles; });
  }
  return lines;
}

// "WxH" of the largest picture measured.
std::string SizeText(const std::vector<SpeedAccuracyRow>& rows, int largest)
{
  for (const SpeedAccuracyRow& r : rows)
  {
    if (r.Width * r.Height == largest)
    {
      return std::to_string(r.Width) + "x" + std::to_string(r.Height);
    }
  }
  return std::string();
}

// The line of a surface (solid with circles for the sphere, dashed with
// squares otherwise) and rule (its colour), its points labelled with their
// triangles. Adds the points' values to msValues and rmseValues.
void AddLine(vtkChartXY* chart, PointLabels* labels, const std::pair<std::string, std::string>& key,
  const Line& points, std::vector<double>& msValues, std::vector<double>& rmseValues)
{
  auto table = vtkSmartPointer<vtkTable>::New();
  auto ms = vtkSmartPointer<vtkDoubleArray>::New();
  ms->SetName("ms per frame");
  auto rmse = vtkSmartPointer<vtkDoubleArray>::New();
  rmse->SetName((key.first + ", " + key.second).c_str());
  for (const SpeedAccuracyRow* p : points)
  {
    ms->InsertNextValue(std::log10(p->MsPerFrame));
    rmse->InsertNextValue(std::log10(p->Rmse));
    labels->Labels.push_back(
      { p->MsPerFrame, p->Rmse, TriangleCountText(static_cast<double>(p->Triangles)) });
    msValues.push_back(p->MsPerFrame);
    rmseValues.push_back(p->Rmse);
  }
  table->AddColumn(ms);
  table->AddColumn(rmse);
  auto* line = vtkPlotLine::SafeDownCast(chart->AddPlot(vtkChart::LINE));
  line->SetInputData(table, 0, 1);
  const auto c = RuleColour(key.second);
  line->SetColor(c[0], c[1], c[2], 255);
  line->SetWidth(2.5);
  line->SetMarkerStyle(key.first == "sphere" ? vtkPlotPoints::CIRCLE : vtkPlotPoints::SQUARE);
  line->SetMarkerSize(9);
  if (key.first != "sphere")
  {
    line->GetPen()->SetLineType(vtkPen::DASH_LINE);
  }
}

void SetTitleAndLegend(vtkChartXY* chart, const std::string& size)
{
  chart->SetTitle("shadelab: error against time per frame (" + size +
    ", angle-weighted normals; points: triangles)");
  chart->GetTitleProperties()->SetFontSize(20);
  chart->SetBorders(90, 70, 40, 50); // room for the axis titles and the chart's title
  chart->SetShowLegend(true);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
  chart->GetLegend()->GetLabelProperties()->SetFontSize(15);
}

// Log-log through log10 values on linear axes, labelled 1, 2, 5 per
// decade: VTK 9.1's log-scale axes leave vtkPlotLine's lines undrawn.
void SetLogAxis(vtkAxis* axis, const std::vector<double>& values)
{
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  const double low = std::log10(*lo) - 0.05, high = std::log10(*hi) + 0.05;
  auto positions = vtkSmartPointer<vtkDoubleArray>::New();
  auto labels = vtkSmartPointer<vtkStringArray>::New();
  for (int decade = static_cast<int>(std::floor(low)); decade <= std::ceil(high); ++decade)
  {
    for (double m : { 1.0, 2.0, 5.0 })
    {
      const double at = decade + std::log10(m);
      if (at >= low && at <= high)
      {
        char text[32];
        std::snprintf(text, sizeof text, "%g", m * std::pow(10.0, decade));
        positions->InsertNextValue(at);
        labels->InsertNextValue(text);
      }
    }
  }
  axis->SetBehavior(vtkAxis::FIXED);
  axis->SetRange(low, high);
  axis->SetCustomTickPositions(positions, labels);
  axis->GetTitleProperties()->SetFontSize(17);
  axis->GetLabelProperties()->SetFontSize(14);
}
}

ChartImage DrawSpeedAccuracyChart(const std::vector<SpeedAccuracyRow>& rows, int width, int height)
{
  ChartImage result;
  int largest = 0;
  for (const SpeedAccuracyRow& r : rows)
  {
    largest = std::max(largest, r.Width * r.Height);
  }
  HeadlessRenderer renderer;
  if (std::string error = renderer.Start(width, height); !error.empty())
  {
    result.Error = error;
    return result;
  }
  renderer.GetRenderer()->SetBackground(1, 1, 1);
  auto chart = vtkSmartPointer<vtkChartXY>::New();
  auto labels = vtkSmartPointer<PointLabels>::New();
  labels->Chart = chart;
  std::vector<double> msValues, rmseValues;
  for (const auto& [key, points] : Lines(rows, largest))
  {
    AddLine(chart, labels, key, points, msValues, rmseValues);
  }
  SetTitleAndLegend(chart, SizeText(rows, largest));
  if (msValues.empty())
  {
    result.Error = "no measurements to draw";
    return result;
  }
  SetLogAxis(chart->GetAxis(vtkAxis::BOTTOM), msValues);
  SetLogAxis(chart->GetAxis(vtkAxis::LEFT), rmseValues);
  chart->GetAxis(vtkAxis::BOTTOM)
    ->SetTitle("median ms per frame (OSMesa llvmpipe, read-back included)");
  chart->GetAxis(vtkAxis::LEFT)->SetTitle("RMSE against the exact picture");

  auto actor = vtkSmartPointer<vtkContextActor>::New();
  actor->GetScene()->AddItem(chart);
  actor->GetScene()->AddItem(labels);
  renderer.GetRenderer()->AddActor(actor);
  result.Image = renderer.Render();
  return result;
}
}
