// Rendered pixels and the contract's rules for storing them, without
// OpenImageIO: shared by shadelab (which quantises 8-bit pictures before
// handing them to the writer, a quarter of the bytes) and the writer.
#ifndef shadelab_image_pixels_h
#define shadelab_image_pixels_h

#include "core/options.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadelab
{
/** A rendered picture: RGBA floats, unclamped, bottom row first. */
struct FloatImage
{
  int Width = 0;
  int Height = 0;
  std::vector<float> Rgba;
  bool Alpha = false; // files keep the alpha channel (--background transparent), else RGB
};

/**
 * A picture for an 8-bit file, quantised as Quantise does: top-down rows
 * of RGB, or RGBA with Alpha, as files store them.
 */
struct Image8
{
  int Width = 0;
  int Height = 0;
  std::vector<std::uint8_t> Pixels;
  bool Alpha = false;
};

/**
 * image with each n x n block of pixels averaged into one: the sum of its
 * samples in double, row by row, divided by n*n and rounded to float. What
 * --ssaa stores, and what its test computes from an n-times picture.
 */
FloatImage BoxAverage(const FloatImage& image, int n);

/** Pixel (x, y) of image, y from the top, as RGB. */
inline Rgb PixelRgb(const FloatImage& image, int x, int y)
{
  const float* p =
    image.Rgba.data() + (static_cast<size_t>(image.Height - 1 - y) * image.Width + x) * 4;
  return { p[0], p[1], p[2] };
}

/** The pixel type that Auto means for path: float for EXR, HDR and PFM, else 8-bit. */
PixelType ResolvePixelType(const std::string& path, PixelType requested);

/** The channels a file of image stores: RGBA with Alpha, else RGB. */
inline int Channels(const FloatImage& image)
{
  return image.Alpha ? 4 : 3;
}

/**
 * Bottom-up RGBA rows (width x height, as OpenGL reads them) as top-down
 * rows of C channels of type T, each value through convert; C a constant,
 * so the loop vectorises.
 */
template <int C, typename S, typename T, typename Convert>
void TopDownRows(const S* rgba, int width, int height, T* out, Convert convert)
{
  for (int y = 0; y < height; ++y)
  {
    const S* src = rgba + static_cast<size_t>(height - 1 - y) * width * 4;
    T* dst = out + static_cast<size_t>(y) * width * C;
    for (int x = 0; x < width; ++x)
    {
      for (int c = 0; c < C; ++c)
      {
        dst[C * x + c] = convert(src[4 * x + c]);
      }
    }
  }
}

/** Bottom-up RGBA as top-down RGB (or RGBA with alpha) of type T, each value through convert. */
template <typename T, typename S, typename Convert>
std::vector<T> ToTopDown(const S* rgba, int width, int height, bool alpha, Convert convert)
{
  std::vector<T> out(static_cast<size_t>(width) * height * (alpha ? 4 : 3));
  if (alpha)
  {
    TopDownRows<4>(rgba, width, height, out.data(), convert);
  }
  else
  {
    TopDownRows<3>(rgba, width, height, out.data(), convert);
  }
  return out;
}

/** The picture as top-down RGB (or RGBA) of type T, each value through convert. */
template <typename T, typename Convert>
std::vector<T> ToTopDown(const FloatImage& image, Convert convert)
{
  return ToTopDown<T>(image.Rgba.data(), image.Width, image.Height, image.Alpha, convert);
}

/** round(scale*clamp(v, 0, 1)): the contract's rule for integer files; NaN lands on 0. */
inline double Quantised(double v, double scale)
{
  const double clamped = v > 0 ? (v < 1 ? v : 1.0) : 0.0; // NaN compares false
  // At least 0.5, so truncating is flooring (and vectorises; scale <= 65535).
  return static_cast<int>(scale * clamped + 0.5);
}

/** The picture through Quantised, top-down as ToTopDown. */
template <typename T>
std::vector<T> Quantise(const FloatImage& image, double scale)
{
  return ToTopDown<T>(image, [scale](double v) { return static_cast<T>(Quantised(v, scale)); });
}

/** The picture for an 8-bit file: Quantise's bytes with its size and alpha. */
inline Image8 QuantiseToImage8(const FloatImage& image)
{
  return { image.Width, image.Height, Quantise<std::uint8_t>(image, 255), image.Alpha };
}
}

#endif
