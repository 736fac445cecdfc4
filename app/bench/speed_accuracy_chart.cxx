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
#include <cmath>
#include <map>
#include <tuple>

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
}

ChartImage DrawSpeedAccuracyChart(const std::vector<SpeedAccuracyRow>& rows, int width, int height)
{
  ChartImage result;
  // The largest picture measured, angle weighting (flat has none): one line
  // per surface and rule, in order of triangles.
  int largest = 0;
  for (const SpeedAccuracyRow& r : rows)
  {
    largest = std::max(largest, r.Width * r.Height);
  }
  std::map<std::pair<std::string, std::string>, std::vector<const SpeedAccuracyRow*>> lines;
  for (const SpeedAccuracyRow& r : rows)
  {
    if (r.Width * r.Height == largest && (r.Weighting == "angle" || r.Weighting == "face"))
    {
      lines[{ r.Surface, r.Shading }].push_back(&r);
    }
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
  const std::map<std::string, std::array<unsigned char, 3>> colors{ { "flat", { 214, 39, 40 } },
    { "gouraud", { 44, 160, 44 } }, { "phong", { 31, 119, 180 } } };
  std::vector<double> msValues, rmseValues;
  for (auto& [key, points] : lines)
  {
    std::sort(points.begin(), points.end(),
      [](const SpeedAccuracyRow* a, const SpeedAccuracyRow* b)
      { return a->Triangles < b->Triangles; });
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
    const auto& c = colors.count(key.second) ? colors.at(key.second) : colors.at("flat");
    line->SetColor(c[0], c[1], c[2], 255);
    line->SetWidth(2.5);
    line->SetMarkerStyle(key.first == "sphere" ? vtkPlotPoints::CIRCLE : vtkPlotPoints::SQUARE);
    line->SetMarkerSize(9);
    if (key.first != "sphere")
    {
      line->GetPen()->SetLineType(vtkPen::DASH_LINE);
    }
  }
  const std::string size = rows.empty() ? ""
                                        : [&]
  {
    for (const SpeedAccuracyRow& r : rows)
    {
      if (r.Width * r.Height == largest)
      {
        return std::to_string(r.Width) + "x" + std::to_string(r.Height);
      }
    }
    return std::string();
  }();
  chart->SetTitle("shadelab: error against time per frame (" + size +
    ", angle-weighted normals; points: triangles)");
  chart->GetTitleProperties()->SetFontSize(20);
  chart->SetBorders(90, 70, 40, 50); // room for the axis titles and the chart's title
  chart->SetShowLegend(true);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
  chart->GetLegend()->GetLabelProperties()->SetFontSize(15);
  if (msValues.empty())
  {
    result.Error = "no measurements to draw";
    return result;
  }
  // Log-log through log10 values on linear axes, labelled 1, 2, 5 per
  // decade: VTK 9.1's log-scale axes leave vtkPlotLine's lines undrawn.
  for (const auto& [a, values] :
    { std::make_pair(vtkAxis::BOTTOM, &msValues), std::make_pair(vtkAxis::LEFT, &rmseValues) })
  {
    vtkAxis* axis = chart->GetAxis(a);
    const auto [lo, hi] = std::minmax_element(values->begin(), values->end());
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
