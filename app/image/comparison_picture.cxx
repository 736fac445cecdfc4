#include "image/comparison_picture.h"

#include <vtkFreeTypeTools.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkStdString.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace shadelab
{
namespace
{
constexpr Rgb StripColour{ 0.12, 0.12, 0.12 };
constexpr Rgb GapColour{ 0.35, 0.35, 0.35 };
constexpr Rgb TextColour{ 0.92, 0.92, 0.92 };
constexpr int FontSize = 16;

// Pixel access from the top left, on a bottom-row-first picture.
float* At(FloatImage& image, int x, int yFromTop)
{
  return image.Rgba.data() +
    4 * (static_cast<size_t>(image.Height - 1 - yFromTop) * image.Width + x);
}

void Fill(FloatImage& image, int x0, int y0, int w, int h, const Rgb& colour)
{
  for (int y = std::max(0, y0); y < std::min(image.Height, y0 + h); ++y)
  {
    for (int x = std::max(0, x0); x < std::min(image.Width, x0 + w); ++x)
    {
      float* p = At(image, x, y);
      std::copy(colour.begin(), colour.end(), p);
      p[3] = 1;
    }
  }
}

enum class Align
{
  Left,
  Centre,
  Right
};

// Draws text with its vertical middle at yMiddle (from the top) and its
// left end, middle or right end at x, cut off at `right`.
void DrawText(FloatImage& image, const std::string& text, int x, int yMiddle,
  Align align = Align::Left, int right = std::numeric_limits<int>::max())
{
  vtkNew<vtkTextProperty> style;
  style->SetFontFamilyToArial();
  style->SetFontSize(FontSize);
  style->SetColor(TextColour[0], TextColour[1], TextColour[2]);
  vtkNew<vtkImageData> rendered;
  int size[2] = { 0, 0 };
  if (text.empty() ||
    !vtkFreeTypeTools::GetInstance()->RenderString(style, vtkStdString(text), 72, rendered, size))
  {
    return;
  }
  int extent[6];
  rendered->GetExtent(extent);
  const int left = align == Align::Left ? x
    : align == Align::Centre            ? x - size[0] / 2
                                        : x - size[0];
  const int top = yMiddle - size[1] / 2;
  for (int j = 0; j < size[1] && j <= extent[3] - extent[2]; ++j)
  {
    for (int i = 0; i < size[0] && i <= extent[1] - extent[0]; ++i)
    {
      const int px = left + i;
      const int py = top + (size[1] - 1 - j); // the text image is bottom row first
      if (px < 0 || py < 0 || px >= std::min(image.Width, right) || py >= image.Height)
      {
        continue;
      }
      const auto* src = static_cast<const unsigned char*>(
        rendered->GetScalarPointer(extent[0] + i, extent[2] + j, 0));
      const float alpha = src[3] / 255.0f;
      float* dst = At(image, px, py);
      for (int c = 0; c < 3; ++c)
      {
        dst[c] = dst[c] * (1 - alpha) + (src[c] / 255.0f) * alpha;
      }
    }
  }
}

std::string Number(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}
}

Difference CompareImages(const FloatImage& a, const FloatImage& b)
{
  Difference d;
  d.Heat.Width = a.Width;
  d.Heat.Height = a.Height;
  const size_t n = static_cast<size_t>(a.Width) * a.Height;
  std::vector<double> value(n);
  const auto clamp = [](float v) { return v > 0 ? (v < 1 ? v : 1.0f) : 0.0f; }; // NaN: 0
  double sum = 0;
  for (size_t i = 0; i < n; ++i)
  {
    double largest = 0;
    for (int c = 0; c < 3; ++c)
    {
      largest = std::max(largest,
        static_cast<double>(std::fabs(clamp(a.Rgba[4 * i + c]) - clamp(b.Rgba[4 * i + c]))));
    }
    value[i] = largest;
    sum += largest;
    d.Largest = std::max(d.Largest, largest);
    d.Differing += largest > 0;
  }
  d.Mean = n ? sum / n : 0;
  d.Heat.Rgba.resize(4 * n);
  for (size_t i = 0; i < n; ++i)
  {
    const Rgb colour = HeatColour(d.Largest > 0 ? value[i] / d.Largest : 0);
    std::copy(colour.begin(), colour.end(), d.Heat.Rgba.begin() + 4 * i);
    d.Heat.Rgba[4 * i + 3] = 1;
  }
  return d;
}

Rgb HeatColour(double t)
{
  // Black, red, yellow, white: brightness rises with the difference, so the
  // map reads in grey too.
  t = std::clamp(t, 0.0, 1.0);
  return { std::min(1.0, 3 * t), std::clamp(3 * t - 1, 0.0, 1.0), std::clamp(3 * t - 2, 0.0, 1.0) };
}

int ComparisonLayout::PanelX(int cell) const
{
  return CellGap + (cell % this->Columns) * (this->PanelWidth + CellGap);
}

int ComparisonLayout::PanelY(int cell) const
{
  return (cell / this->Columns) * (LabelStripHeight + this->PanelHeight + CellGap) +
    LabelStripHeight;
}

ComparisonLayout LayOut(int count, int width, int height, int columns, bool colourBar)
{
  ComparisonLayout l;
  l.Columns = columns > 0 ? columns
    : count <= 4          ? std::max(count, 1)
                          : static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  l.Rows = (std::max(count, 1) + l.Columns - 1) / l.Columns;
  l.PanelWidth = width;
  l.PanelHeight = height;
  l.Width = l.Columns * (width + CellGap) + CellGap;
  l.Height =
    l.Rows * (LabelStripHeight + height + CellGap) + (colourBar ? ColourBarStripHeight : 0);
  return l;
}

FloatImage ComposeComparison(const std::vector<ComparisonCell>& cells, int columns,
  const Difference* difference, int differenceCell)
{
  const FloatImage& first = *cells.at(0).Image;
  const ComparisonLayout l = LayOut(
    static_cast<int>(cells.size()), first.Width, first.Height, columns, difference != nullptr);
  FloatImage out;
  out.Width = l.Width;
  out.Height = l.Height;
  out.Rgba.assign(static_cast<size_t>(out.Width) * out.Height * 4, 0.0f);
  Fill(out, 0, 0, out.Width, out.Height, GapColour);
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    const int cell = static_cast<int>(i);
    const int x0 = l.PanelX(cell);
    const int y0 = l.PanelY(cell);
    Fill(out, x0, y0 - LabelStripHeight, l.PanelWidth, LabelStripHeight, StripColour);
    DrawText(
      out, cells[i].Label, x0 + 8, y0 - LabelStripHeight / 2, Align::Left, x0 + l.PanelWidth - 4);
    const FloatImage& panel = *cells[i].Image;
    for (int y = 0; y < l.PanelHeight; ++y)
    {
      const float* src =
        panel.Rgba.data() + static_cast<size_t>(panel.Height - 1 - y) * panel.Width * 4;
      std::copy(src, src + 4 * static_cast<size_t>(panel.Width), At(out, x0, y0 + y));
    }
  }
  if (difference)
  {
    // The colour bar beneath the difference cell: 0 at its left, the
    // largest difference at its right, and the middle marked.
    const int x0 = l.PanelX(differenceCell) + 8;
    const int width = l.PanelWidth - 16;
    const int top = l.Height - ColourBarStripHeight + 6;
    Fill(out, 0, l.Height - ColourBarStripHeight, out.Width, ColourBarStripHeight, StripColour);
    for (int x = 0; x < width; ++x)
    {
      Fill(out, x0 + x, top, 1, 12, HeatColour(width > 1 ? x / (width - 1.0) : 0));
    }
    const int textMiddle = top + 12 + 12;
    DrawText(out, "0", x0, textMiddle);
    DrawText(out, Number(difference->Largest / 2), x0 + width / 2, textMiddle, Align::Centre);
    DrawText(out, Number(difference->Largest), x0 + width, textMiddle, Align::Right);
  }
  return out;
}
}
