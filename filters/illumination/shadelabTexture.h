// Texture maps for the lecture's kd, ka and ks (doc/design.md, "Command line"): an
// image of RGB (display values, as stored), how it wraps and filters, and its lookup as OpenGL
// defines it (texel centres at (i + 0.5)/size, GL_REPEAT, GL_CLAMP_TO_EDGE
// and GL_MIRRORED_REPEAT, GL_NEAREST and GL_LINEAR without mipmaps), in
// double: what the oracle multiplies kd and ka by (and ks, SurfaceTexture),
// and what the shaders are given as a float texture with the same sampler
// settings.
#ifndef shadelabTexture_h
#define shadelabTexture_h

#include "shadelabIllumination.h"

#include <memory>
#include <optional>
#include <vector>

namespace shadelab
{
enum class TextureWrap
{
  Repeat,
  Clamp,
  Mirror
};

template <>
struct NameTable<TextureWrap>
{
  static constexpr std::array<std::pair<TextureWrap, const char*>, 3> Entries{
    { { TextureWrap::Repeat, "repeat" }, { TextureWrap::Clamp, "clamp" },
      { TextureWrap::Mirror, "mirror" } }
  };
};

/**
 * One filter for magnification and minification, without mipmaps: a
 * texture seen smaller than its texels aliases rather than blurs (glTF's
 * mipmap filters map to their base, see FilterFromGL).
 */
enum class TextureFilter
{
  Bilinear,
  Nearest
};

template <>
struct NameTable<TextureFilter>
{
  static constexpr std::array<std::pair<TextureFilter, const char*>, 2> Entries{
    { { TextureFilter::Bilinear, "bilinear" }, { TextureFilter::Nearest, "nearest" } }
  };
};

/**
 * Decoded pixels: RGB floats as the file stores them (display values), row 0 at t = 0
 * (the image's bottom row: OBJ's and OpenGL's origin is bottom-left).
 */
struct TextureImage
{
  int Width = 0;
  int Height = 0;
  std::vector<float> Pixels; // RGB, 3 per texel, row by row from the bottom

  Rgb Texel(int i, int j) const;
};

/** An image with its sampler settings. */
struct TextureMap
{
  std::shared_ptr<const TextureImage> Image;
  TextureWrap WrapS = TextureWrap::Repeat;
  TextureWrap WrapT = TextureWrap::Repeat;
  TextureFilter Filter = TextureFilter::Bilinear;
};

/**
 * What a surface's texture map stands for: kd, ka or both are factor x
 * texel; ks, where Ks is set, is ks + KsScale x (texel - 1), the part
 * KsScale of ks times the texel (a glTF metal's m B of its ks,
 * doc/user/formats-and-materials.md, "Materials from glTF").
 */
struct SurfaceTexture
{
  TextureMap Map;
  bool Kd = false;
  bool Ka = false;
  bool Ks = false;
  Rgb KsScale{};

  /** Whether it changes anything: an image for kd, ka or ks. */
  bool Used() const { return this->Map.Image && (this->Kd || this->Ka || this->Ks); }
  /** ks at a texel: ks + KsScale (texel - 1) where the texture is ks's, else ks. */
  Rgb TexelKs(const Rgb& ks, const Rgb& texel) const;
};

/** The map's value at texture coordinates (s, t), as OpenGL samples it. */
Rgb SampleTexture(const TextureMap& map, double s, double t);

/**
 * glTF's (OpenGL's) wrap enum: 10497 REPEAT, 33071 CLAMP_TO_EDGE, 33648
 * MIRRORED_REPEAT; nothing for another value.
 */
std::optional<TextureWrap> WrapFromGL(int value);

/**
 * glTF's (OpenGL's) filter enum: 9728 NEAREST and 9729 LINEAR, and the
 * mipmap filters by their base (9984 and 9986 nearest, 9985 and 9987
 * bilinear); nothing for another value.
 */
std::optional<TextureFilter> FilterFromGL(int value);
}

#endif
