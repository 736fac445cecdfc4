#include "shadelabTexture.h"

#include <algorithm>
#include <cmath>

namespace shadelab
{
namespace
{
// OpenGL 4.6, 8.14.2: the texel index i (any integer) brought into [0, size).
int Wrap(long long i, int size, TextureWrap wrap)
{
  switch (wrap)
  {
    case TextureWrap::Repeat:
      return static_cast<int>(((i % size) + size) % size);
    case TextureWrap::Clamp:
      return static_cast<int>(i < 0 ? 0 : (i >= size ? size - 1 : i));
    case TextureWrap::Mirror:
    {
      // (size - 1) - mirror((i mod 2size) - size), mirror(a) = a >= 0 ? a : -(1 + a)
      const long long a = ((i % (2LL * size)) + 2LL * size) % (2LL * size) - size;
      return static_cast<int>(size - 1 - (a >= 0 ? a : -(1 + a)));
    }
  }
  return 0;
}

// The texel coordinate u = s*size, brought near the image without changing
// the texels it picks: every wrap mode repeats every 2*size texels (fmod is
// exact), clamp is the same anywhere beyond the edges. So the floor below
// stays exact and fits an integer; a non-finite coordinate samples texel 0
// (OpenGL leaves it undefined).
double TexelCoordinate(double s, int size, TextureWrap wrap)
{
  const double u = s * size;
  if (!std::isfinite(u))
  {
    return 0;
  }
  switch (wrap)
  {
    case TextureWrap::Clamp:
      return std::clamp(u, -1.0, size + 1.0);
    case TextureWrap::Repeat:
    case TextureWrap::Mirror:
      return std::fmod(u, 2.0 * size);
  }
  return 0;
}
}

Rgb TextureImage::Texel(int i, int j) const
{
  const float* p = this->Pixels.data() + 3 * (static_cast<size_t>(j) * this->Width + i);
  return { p[0], p[1], p[2] };
}

Rgb SurfaceTexture::TexelKs(const Rgb& ks, const Rgb& texel) const
{
  Rgb result = ks;
  for (int c = 0; this->Ks && c < 3; ++c)
  {
    result[c] += this->KsScale[c] * (texel[c] - 1);
  }
  return result;
}

Rgb SampleTexture(const TextureMap& map, double s, double t)
{
  const TextureImage& image = *map.Image;
  const double u = TexelCoordinate(s, image.Width, map.WrapS),
               v = TexelCoordinate(t, image.Height, map.WrapT);
  switch (map.Filter)
  {
    case TextureFilter::Nearest:
      return image.Texel(Wrap(static_cast<long long>(std::floor(u)), image.Width, map.WrapS),
        Wrap(static_cast<long long>(std::floor(v)), image.Height, map.WrapT));
    case TextureFilter::Bilinear:
      break;
  }
  // GL_LINEAR: the four texels whose centres surround (u, v).
  const double x = u - 0.5, y = v - 0.5;
  const long long i0 = static_cast<long long>(std::floor(x)),
                  j0 = static_cast<long long>(std::floor(y));
  const double a = x - i0, b = y - j0;
  const int i[2] = { Wrap(i0, image.Width, map.WrapS), Wrap(i0 + 1, image.Width, map.WrapS) };
  const int j[2] = { Wrap(j0, image.Height, map.WrapT), Wrap(j0 + 1, image.Height, map.WrapT) };
  Rgb value{};
  for (int c = 0; c < 3; ++c)
  {
    value[c] = (1 - a) * (1 - b) * image.Texel(i[0], j[0])[c] +
      a * (1 - b) * image.Texel(i[1], j[0])[c] + (1 - a) * b * image.Texel(i[0], j[1])[c] +
      a * b * image.Texel(i[1], j[1])[c];
  }
  return value;
}

std::optional<TextureWrap> WrapFromGL(int value)
{
  switch (value)
  {
    case 10497:
      return TextureWrap::Repeat;
    case 33071:
      return TextureWrap::Clamp;
    case 33648:
      return TextureWrap::Mirror;
    default:
      return std::nullopt;
  }
}

std::optional<TextureFilter> FilterFromGL(int value)
{
  switch (value)
  {
    case 9728: // NEAREST
    case 9984: // NEAREST_MIPMAP_NEAREST
    case 9986: // NEAREST_MIPMAP_LINEAR
      return TextureFilter::Nearest;
    case 9729: // LINEAR
    case 9985: // LINEAR_MIPMAP_NEAREST
    case 9987: // LINEAR_MIPMAP_LINEAR
      return TextureFilter::Bilinear;
    default:
      return std::nullopt;
  }
}
}
