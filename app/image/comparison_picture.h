// The comparison picture: rendered panels side by side, a label
// strip above each, and for a difference panel its heat map and colour bar
// with the scale. Pixels only: the panels come from whichever backend
// rendered them, the text from VTK's FreeType tools, no OpenGL.
#ifndef shadelab_comparison_picture_h
#define shadelab_comparison_picture_h

#include "core/options.h"
#include "image/image_pixels.h"

#include <optional>
#include <string>
#include <vector>

namespace shadelab
{
/** |A - B| per pixel as a heat map. */
struct Difference
{
  FloatImage Heat;         // black at 0 through red and yellow to white at Largest
  double Largest = 0;      // the largest difference, the colour bar's top
  double Mean = 0;         // over all pixels
  long long Differing = 0; // pixels whose difference is not 0
};

/**
 * The difference of what 8-bit pictures of a and b show: per pixel the
 * largest over R, G, B of |clamp(a) - clamp(b)|, intensities clamped to
 * [0, 1]. a and b have one size.
 */
Difference CompareImages(const FloatImage& a, const FloatImage& b);

/** The heat map's colour for t in [0, 1]. */
Rgb HeatColour(double t);

struct ComparisonCell
{
  const FloatImage* Image = nullptr; // every cell's picture has one size
  std::string Label;
};

/** Where things are in a comparison picture, in pixels from the top left. */
struct ComparisonLayout
{
  int Columns = 1;
  int Rows = 1;
  int PanelWidth = 0;
  int PanelHeight = 0;
  int Width = 0;
  int Height = 0;
  /** The top-left corner of cell i's picture (its label strip is above it). */
  int PanelX(int cell) const;
  int PanelY(int cell) const;
};

/** Label strip height, gap between cells and colour-bar strip height, in pixels. */
constexpr int LabelStripHeight = 28;
constexpr int CellGap = 2;
constexpr int ColourBarStripHeight = 44;

/**
 * The layout of `count` panels of width x height in `columns` columns, or
 * when that is 0, one row up to four panels, else a near-square grid.
 */
ComparisonLayout LayOut(int count, int width, int height, int columns, bool colourBar);

/**
 * The picture: cells as LayOut places them, each label in its strip, and,
 * when `difference` is given, a colour bar from 0 to difference->Largest
 * beneath the cell `differenceCell`.
 */
FloatImage ComposeComparison(const std::vector<ComparisonCell>& cells, int columns = 0,
  const Difference* difference = nullptr, int differenceCell = -1);
}

#endif
