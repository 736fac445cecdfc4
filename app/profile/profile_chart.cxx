#include "profile/profile_chart.h"

#include "headless/headless_renderer.h"

#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkContext2D.h>
#include <vtkContextActor.h>
#include <vtkContextItem.h>
#include <vtkContextScene.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkImageItem.h>
#include <vtkObjectFactory.h>
#include <vtkPen.h>
#include <vtkPlotLine.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace shadelab
{
namespace
{
// The triangles' edges that the line crosses, as grey verticals over each
// chart's plot (between the samples on either side), the inset's caption
// and the picture's title. vtkChartXY has no such marks; this item, painted after the
// charts, maps samples to pixels through their axes.
class EdgeMarks : public vtkContextItem
{
public:
  static EdgeMarks* New();
  vtkTypeMacro(EdgeMarks, vtkContextItem);

  std::vector<vtkChartXY*> Charts;
  std::vector<double> Edges; // in samples
  float CaptionAt[2] = {};
  std::string Caption;
  float TitleAt[2] = {};
  std::string Title;
  // Beside the charts, not over their curves: each mode's colour, then the
  // oracle's dashes.
  struct Entry
  {
    std::string Label;
    std::array<unsigned char, 3> Colour;
    bool Dashed;
  };
  std::vector<Entry> Legend;
  float LegendAt[2] = {};

  bool Paint(vtkContext2D* painter) override
  {
    painter->GetPen()->SetColor(190, 190, 190);
    painter->GetPen()->SetWidth(1);
    for (vtkChartXY* chart : this->Charts)
    {
      vtkAxis* x = chart->GetAxis(vtkAxis::BOTTOM);
      vtkAxis* y = chart->GetAxis(vtkAxis::LEFT);
      const float a = x->GetPoint1()[0], b = x->GetPoint2()[0];
      for (double edge : this->Edges)
      {
        const float at = static_cast<float>(
          a + (edge - x->GetMinimum()) / (x->GetMaximum() - x->GetMinimum()) * (b - a));
        painter->DrawLine(at, y->GetPoint1()[1], at, y->GetPoint2()[1]);
      }
    }
    painter->GetTextProp()->SetFontSize(14);
    painter->GetTextProp()->SetColor(0.2, 0.2, 0.2);
    painter->GetTextProp()->SetJustificationToLeft();
    painter->GetTextProp()->SetVerticalJustificationToTop();
    painter->DrawString(this->CaptionAt[0], this->CaptionAt[1], this->Caption.c_str());
    painter->GetTextProp()->SetVerticalJustificationToCentered();
    float y = this->LegendAt[1];
    for (const Entry& entry : this->Legend)
    {
      painter->GetPen()->SetColor(entry.Colour[0], entry.Colour[1], entry.Colour[2]);
      painter->GetPen()->SetWidth(entry.Dashed ? 1.5f : 2.5f);
      painter->GetPen()->SetLineType(entry.Dashed ? vtkPen::DASH_LINE : vtkPen::SOLID_LINE);
      painter->DrawLine(this->LegendAt[0], y, this->LegendAt[0] + 36, y);
      painter->DrawString(this->LegendAt[0] + 44, y, entry.Label.c_str());
      y -= 22;
    }
    painter->GetTextProp()->SetVerticalJustificationToTop();
    painter->GetTextProp()->SetFontSize(18);
    painter->GetTextProp()->SetJustificationToCentered();
    painter->DrawString(this->TitleAt[0], this->TitleAt[1], this->Title.c_str());
    return true;
  }
};
vtkStandardNewMacro(EdgeMarks);

enum class Quantity
{
  Luminance,
  First,
  Second
};

const std::vector<double>& Of(const ProfileCurve& curve, Quantity q)
{
  return q == Quantity::Luminance ? curve.Luminance
    : q == Quantity::First        ? curve.First
                                  : curve.Second;
}

// A curve's line on chart: off the mesh (NaN, or a luminance there) it
// breaks; the oracle dashed and black.
void AddCurve(vtkChartXY* chart, const ProfileCurve& curve, Quantity q,
  const std::vector<vtkIdType>& triangles, bool oracle)
{
  auto table = vtkSmartPointer<vtkTable>::New();
  auto sample = vtkSmartPointer<vtkDoubleArray>::New();
  sample->SetName("sample");
  auto value = vtkSmartPointer<vtkDoubleArray>::New();
  value->SetName(curve.Label.c_str());
  const std::vector<double>& values = Of(curve, q);
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    sample->InsertNextValue(static_cast<double>(i));
    value->InsertNextValue(
      triangles[i] >= 0 ? values[i] : std::numeric_limits<double>::quiet_NaN());
  }
  table->AddColumn(sample);
  table->AddColumn(value);
  auto* line = vtkPlotLine::SafeDownCast(chart->AddPlot(vtkChart::LINE));
  line->SetInputData(table, 0, 1);
  if (oracle)
  {
    line->SetColor(0, 0, 0, 255);
    line->SetWidth(1.5);
    line->GetPen()->SetLineType(vtkPen::DASH_LINE);
  }
  else
  {
    const auto c = RuleColour(curve.Label);
    line->SetColor(c[0], c[1], c[2], 255);
    line->SetWidth(2.0);
  }
}

// The range of q over the curves on the mesh, a little wider; [-1, 1]
// where there is none.
std::pair<double, double> Range(const LineProfile& profile, Quantity q)
{
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const auto take = [&](const ProfileCurve& curve)
  {
    const std::vector<double>& values = Of(curve, q);
    for (std::size_t i = 0; i < values.size(); ++i)
    {
      if (profile.Triangles[i] >= 0 && std::isfinite(values[i]))
      {
        lo = std::min(lo, values[i]);
        hi = std::max(hi, values[i]);
      }
    }
  };
  for (const ProfileCurve& curve : profile.Curves)
  {
    take(curve);
  }
  take(profile.Oracle);
  if (!(lo <= hi))
  {
    return { -1, 1 };
  }
  const double pad = std::max(0.05 * (hi - lo), 1e-6);
  return { q == Quantity::Luminance ? std::min(0.0, lo) : lo - pad, hi + pad };
}

vtkSmartPointer<vtkChartXY> MakeChart(
  const LineProfile& profile, Quantity q, const std::string& title, const vtkRectf& place)
{
  auto chart = vtkSmartPointer<vtkChartXY>::New();
  chart->SetAutoSize(false);
  chart->SetSize(place);
  chart->SetTitle(title);
  chart->GetTitleProperties()->SetFontSize(16);
  for (const ProfileCurve& curve : profile.Curves)
  {
    AddCurve(chart, curve, q, profile.Triangles, false);
  }
  AddCurve(chart, profile.Oracle, q, profile.Triangles, true);
  vtkAxis* x = chart->GetAxis(vtkAxis::BOTTOM);
  x->SetBehavior(vtkAxis::FIXED);
  x->SetRange(0, std::max<double>(1, static_cast<double>(profile.Samples.size()) - 1));
  x->SetTitle(q == Quantity::Second ? "sample along the line (a pixel each)" : "");
  vtkAxis* y = chart->GetAxis(vtkAxis::LEFT);
  const auto [lo, hi] = Range(profile, q);
  y->SetBehavior(vtkAxis::FIXED);
  y->SetRange(lo, hi);
  for (vtkAxis* axis : { x, y })
  {
    axis->GetTitleProperties()->SetFontSize(14);
    axis->GetLabelProperties()->SetFontSize(13);
  }
  return chart;
}

// The picture with the profile's samples drawn over it in yellow, shrunk
// (nearest pixel) to fit `room` pixels wide and high; RGBA, bottom row first.
vtkSmartPointer<vtkImageData> Inset(const FloatImage& picture, const LineProfile& profile, int room)
{
  const double scale =
    std::min(1.0, static_cast<double>(room) / std::max(picture.Width, picture.Height));
  const int w = std::max(1, static_cast<int>(picture.Width * scale));
  const int h = std::max(1, static_cast<int>(picture.Height * scale));
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int y = 0; y < h; ++y) // from the bottom, as both are stored
  {
    for (int x = 0; x < w; ++x)
    {
      const int sx = std::min(picture.Width - 1, static_cast<int>(x / scale));
      const int sy = std::min(picture.Height - 1, static_cast<int>(y / scale));
      const float* p =
        picture.Rgba.data() + (static_cast<std::size_t>(sy) * picture.Width + sx) * 4;
      unsigned char* o = out + (static_cast<std::size_t>(y) * w + x) * 4;
      for (int c = 0; c < 3; ++c)
      {
        o[c] = static_cast<unsigned char>(std::lround(std::clamp(p[c], 0.0f, 1.0f) * 255));
      }
      o[3] = 255;
    }
  }
  for (const Pixel& s : profile.Samples)
  {
    const int x = std::min(w - 1, static_cast<int>(s.X * scale));
    const int y = std::min(h - 1, static_cast<int>((picture.Height - 1 - s.Y) * scale));
    unsigned char* o = out + (static_cast<std::size_t>(y) * w + x) * 4;
    o[0] = 255;
    o[1] = 220;
    o[2] = 0;
  }
  return image;
}
}

ChartImage DrawProfileChart(const LineProfile& profile, const FloatImage& picture,
  const std::string& title, int width, int height)
{
  ChartImage result;
  HeadlessRenderer renderer;
  if (std::string error = renderer.Start(width, height); !error.empty())
  {
    result.Error = error;
    return result;
  }
  renderer.GetRenderer()->SetBackground(1, 1, 1);
  auto actor = vtkSmartPointer<vtkContextActor>::New();
  vtkContextScene* scene = actor->GetScene();
  // Three charts stacked on the left, the inset in a column on the right.
  const int room = std::min(width / 4, height / 2);
  const float chartsWidth = static_cast<float>(width - room - 40);
  const float top = static_cast<float>(height) - 40; // the title's line above
  const float each = top / 3;
  const char* titles[] = { "luminance (Rec. 709) along the line", "first difference: L[i+1] - L[i]",
    "second difference: L[i+1] - 2 L[i] + L[i-1]" };
  const char* names[] = { "L", "first difference", "second difference" };
  auto marks = vtkSmartPointer<EdgeMarks>::New();
  for (int k = 0; k < 3; ++k)
  {
    const vtkRectf place(0, top - each * static_cast<float>(k + 1), chartsWidth, each);
    auto chart = MakeChart(profile, static_cast<Quantity>(k), titles[k], place);
    chart->GetAxis(vtkAxis::LEFT)->SetTitle(names[k]);
    scene->AddItem(chart);
    marks->Charts.push_back(chart);
  }
  for (std::size_t i : EdgeCrossings(profile))
  {
    marks->Edges.push_back(static_cast<double>(i) + 0.5);
  }
  auto inset = vtkSmartPointer<vtkImageItem>::New();
  vtkSmartPointer<vtkImageData> image = Inset(picture, profile, room);
  const int* size = image->GetDimensions();
  const float insetX = chartsWidth + 20, insetY = top - 40 - static_cast<float>(size[1]);
  inset->SetImage(image);
  inset->SetPosition(insetX, insetY);
  scene->AddItem(inset);
  marks->CaptionAt[0] = insetX;
  marks->CaptionAt[1] = insetY - 8;
  const Pixel& from = profile.Samples.front();
  const Pixel& to = profile.Samples.back();
  marks->Caption = "the line (yellow): " + std::to_string(from.X) + "," + std::to_string(from.Y) +
    " to " + std::to_string(to.X) + "," + std::to_string(to.Y) + "\n" +
    std::to_string(profile.Samples.size()) + " samples; grey verticals:\nthe triangles' " +
    "edges it crosses";
  for (const ProfileCurve& curve : profile.Curves)
  {
    marks->Legend.push_back({ curve.Label, RuleColour(curve.Label), false });
  }
  marks->Legend.push_back({ "the oracle's phong", { 0, 0, 0 }, true });
  marks->LegendAt[0] = insetX;
  marks->LegendAt[1] = insetY - 90;
  scene->AddItem(marks);
  marks->Title = title;
  marks->TitleAt[0] = static_cast<float>(width) / 2;
  marks->TitleAt[1] = static_cast<float>(height) - 10;
  renderer.GetRenderer()->AddActor(actor);
  result.Image = renderer.Render();
  return result;
}
}
