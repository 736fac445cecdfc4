// The oracle's texture lookup (shadelabTexture.h) against OpenGL's
// definitions worked by hand on a 2 x 1 image: texel centres at
// (i + 0.5)/width, each wrap mode, nearest and bilinear; and glTF's enums.
#include "shadelabTexture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace shadelab;

namespace
{
// Two texels in a row: red-ish 0.2 at i = 0, 0.6 at i = 1 (every channel
// the same but scaled, so the channels stay apart).
TextureMap TwoTexels(TextureWrap wrap, TextureFilter filter)
{
  auto image = std::make_shared<TextureImage>();
  image->Width = 2;
  image->Height = 1;
  image->Pixels = { 0.2f, 0.4f, 0.8f, 0.6f, 0.3f, 0.1f };
  TextureMap map;
  map.Image = image;
  map.WrapS = map.WrapT = wrap;
  map.Filter = filter;
  return map;
}

double Red(const TextureMap& map, double s)
{
  return SampleTexture(map, s, 0.5)[0];
}
}

TEST(TextureLookup, NearestPicksTheTexelTheCoordinateFallsIn)
{
  const TextureMap map = TwoTexels(TextureWrap::Repeat, TextureFilter::Nearest);
  EXPECT_FLOAT_EQ(Red(map, 0.1), 0.2f);
  EXPECT_FLOAT_EQ(Red(map, 0.49), 0.2f);
  EXPECT_FLOAT_EQ(Red(map, 0.5), 0.6f);
  const Rgb texel = SampleTexture(map, 0.75, 0.5);
  EXPECT_FLOAT_EQ(texel[1], 0.3f);
  EXPECT_FLOAT_EQ(texel[2], 0.1f);
}

TEST(TextureLookup, BilinearMixesTheTexelCentresAround)
{
  const TextureMap map = TwoTexels(TextureWrap::Clamp, TextureFilter::Bilinear);
  // Centres at s = 0.25 and 0.75: exactly there, the texel; halfway, the mean.
  EXPECT_NEAR(Red(map, 0.25), 0.2, 1e-7);
  EXPECT_NEAR(Red(map, 0.75), 0.6, 1e-7);
  EXPECT_NEAR(Red(map, 0.5), 0.4, 1e-7);
  EXPECT_NEAR(Red(map, 0.375), 0.3, 1e-7);
  // Clamped: below the first centre only the first texel.
  EXPECT_NEAR(Red(map, 0.1), 0.2, 1e-7);
  EXPECT_NEAR(Red(map, -3), 0.2, 1e-7);
  EXPECT_NEAR(Red(map, 7), 0.6, 1e-7);
}

TEST(TextureLookup, RepeatWrapsAroundTheEdge)
{
  const TextureMap map = TwoTexels(TextureWrap::Repeat, TextureFilter::Bilinear);
  // At s = 0 the neighbours are texel 1 (wrapped, u = -0.5) and texel 0.
  EXPECT_NEAR(Red(map, 0), 0.4, 1e-7);
  EXPECT_NEAR(Red(map, 0.125), 0.3, 1e-7);
  EXPECT_NEAR(Red(map, 1.125), 0.3, 1e-7);
  EXPECT_NEAR(Red(map, -0.875), 0.3, 1e-7);
  EXPECT_NEAR(Red(map, 1e6 + 0.125), 0.3, 1e-7);
}

TEST(TextureLookup, MirrorReflectsEveryOtherRepeat)
{
  const TextureMap nearest = TwoTexels(TextureWrap::Mirror, TextureFilter::Nearest);
  // [0, 1) as it is, [1, 2) reversed, [-1, 0) reversed.
  EXPECT_FLOAT_EQ(Red(nearest, 0.1), 0.2f);
  EXPECT_FLOAT_EQ(Red(nearest, 1.1), 0.6f);
  EXPECT_FLOAT_EQ(Red(nearest, 1.9), 0.2f);
  EXPECT_FLOAT_EQ(Red(nearest, -0.1), 0.2f);
  EXPECT_FLOAT_EQ(Red(nearest, -0.9), 0.6f);
  EXPECT_FLOAT_EQ(Red(nearest, 2.1), 0.2f);
  const TextureMap bilinear = TwoTexels(TextureWrap::Mirror, TextureFilter::Bilinear);
  // At the edge s = 1 the mirrored neighbour is texel 1 itself.
  EXPECT_NEAR(Red(bilinear, 1), 0.6, 1e-7);
  EXPECT_NEAR(Red(bilinear, 0), 0.2, 1e-7);
}

TEST(TextureLookup, NonFiniteCoordinatesSampleTexelZero)
{
  const TextureMap map = TwoTexels(TextureWrap::Repeat, TextureFilter::Nearest);
  EXPECT_FLOAT_EQ(Red(map, std::nan("")), 0.2f);
  EXPECT_FLOAT_EQ(Red(map, HUGE_VAL), 0.2f);
}

TEST(TextureLookup, GltfEnumsMapToTheirModesAndMipmapsToTheirBase)
{
  EXPECT_EQ(WrapFromGL(10497), TextureWrap::Repeat);
  EXPECT_EQ(WrapFromGL(33071), TextureWrap::Clamp);
  EXPECT_EQ(WrapFromGL(33648), TextureWrap::Mirror);
  EXPECT_EQ(WrapFromGL(9729), std::nullopt);
  EXPECT_EQ(FilterFromGL(9728), TextureFilter::Nearest);
  EXPECT_EQ(FilterFromGL(9729), TextureFilter::Bilinear);
  EXPECT_EQ(FilterFromGL(9984), TextureFilter::Nearest);
  EXPECT_EQ(FilterFromGL(9985), TextureFilter::Bilinear);
  EXPECT_EQ(FilterFromGL(9986), TextureFilter::Nearest);
  EXPECT_EQ(FilterFromGL(9987), TextureFilter::Bilinear);
  EXPECT_EQ(FilterFromGL(10497), std::nullopt);
}
