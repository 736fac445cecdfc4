#include "shadelabNormalMap.h"

#include "shadelabVec3.h"

namespace shadelab
{
namespace
{
// The shaders' shadelabTinyLength: below it a vector has no direction.
constexpr double TinyLength = 1e-20;
}

bool IsGrey(const TextureImage& image)
{
  for (std::size_t i = 0; i + 2 < image.Pixels.size(); i += 3)
  {
    if (image.Pixels[i] != image.Pixels[i + 1] || image.Pixels[i] != image.Pixels[i + 2])
    {
      return false;
    }
  }
  return true;
}

NormalMapping MapNormal(
  const NormalMap& map, const Vec3& N, const Tangent& tangent, const std::array<double, 2>& st)
{
  NormalMapping m;
  m.N = N;
  m.TexCoord = st;
  m.Texel = SampleTexture(map.Map, st[0], st[1]);
  m.Height = map.Height;
  if (map.Height)
  {
    m.Heights = { m.Texel[0], SampleTexture(map.Map, st[0] + 1.0 / map.Map.Image->Width, st[1])[0],
      SampleTexture(map.Map, st[0], st[1] + 1.0 / map.Map.Image->Height)[0] };
    m.TangentSpace = { -map.Scale * (m.Heights[1] - m.Heights[0]),
      -map.Scale * (m.Heights[2] - m.Heights[0]), 1 };
  }
  else
  {
    m.TangentSpace = { map.Scale * (2 * m.Texel[0] - 1), map.Scale * (2 * m.Texel[1] - 1),
      2 * m.Texel[2] - 1 };
  }
  m.Perturbed = N;
  const Vec3 t{ tangent[0], tangent[1], tangent[2] };
  const Vec3 along = t - dot(N, t) * N;
  const double tLength = length(along);
  if (!(tLength > TinyLength))
  {
    return m;
  }
  m.T = (1 / tLength) * along;
  m.B = tangent[3] * cross(N, m.T);
  const Vec3 sum = m.TangentSpace[0] * m.T + m.TangentSpace[1] * m.B + m.TangentSpace[2] * N;
  const double len = length(sum);
  if (len > TinyLength)
  {
    m.Perturbed = (1 / len) * sum;
  }
  return m;
}
}
