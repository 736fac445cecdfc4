#include "shadelabMapSource.h"

namespace shadelab
{
// ShaderFeatures::Environment: E(R), the environment seen along R in view
// coordinates (the oracle's EnvironmentAt, shadelabEnvironment.cxx); no
// derivatives, so that a vertex stage and branches may look it up. GLSL
// leaves atan's precision to the driver (llvmpipe's is off by up to some
// 1e-4 radians, a thousandth of a texel of a small image, a visible 1e-4
// in the picture), so the angles come from shadelabAtan2, to float's
// precision on every driver: Cephes' atanf, its argument reduced to at most
// tan(pi/8), then its polynomial.
const char* const EnvironmentSource = R"glsl(uniform sampler2D shadelabEnvironment;
uniform mat3 shadelabEnvironmentFrame; // view coordinates to the environment's, its y up
float shadelabAtan2(float y, float x)
{
  float ax = abs(x);
  float ay = abs(y);
  float r = max(ax, ay) > 0.0 ? min(ax, ay) / max(ax, ay) : 0.0;
  float a = 0.0;
  if (r > 0.4142135623730950)
  {
    a = 0.7853981633974483;
    r = (r - 1.0) / (r + 1.0);
  }
  float z = r * r;
  a += (((0.0805374449538 * z - 0.138776856032) * z + 0.199777106478) * z - 0.333329491539) * z * r + r;
  a = ay > ax ? 1.5707963267948966 - a : a;
  a = x < 0.0 ? 3.1415926535897932 - a : a;
  return y < 0.0 ? -a : a;
}
vec3 shadelabEnvironmentAt(vec3 R)
{
  vec3 d = shadelabEnvironmentFrame * R;
  vec2 st = vec2(0.5 + shadelabAtan2(d.x, -d.z) * 0.15915494309189535, 0.5 + shadelabAtan2(d.y, length(d.xz)) * 0.3183098861837907);
  return textureLod(shadelabEnvironment, st, 0.0).rgb; // shadelab: environment
}
)glsl";

namespace
{
// ShaderFeatures::NormalMap: shadelabReliefVector(st), the map's vector
// along (T, B, N), a normal map's texel or a height map's differences (the
// height in r, one texel apart through the same sampler, so in its wrap and
// filter); textureLod, so that the vertex stage (gouraud) may read the map too.
const char* const NormalMapVectorSource = R"glsl(uniform sampler2D shadelabNormalMap;
uniform float shadelabNormalScale;
vec3 shadelabReliefVector(vec2 st)
{
  vec3 texel = textureLod(shadelabNormalMap, st, 0.0).rgb; // shadelab: normal map
  return vec3(shadelabNormalScale * (2.0 * texel.xy - 1.0), 2.0 * texel.z - 1.0);
}
)glsl";

const char* const BumpMapVectorSource =
  R"glsl(uniform sampler2D shadelabNormalMap; // the height map: r is the height
uniform float shadelabNormalScale;
vec3 shadelabReliefVector(vec2 st)
{
  vec2 texel = 1.0 / vec2(textureSize(shadelabNormalMap, 0));
  float h = textureLod(shadelabNormalMap, st, 0.0).r; // shadelab: bump map
  float dhs = textureLod(shadelabNormalMap, st + vec2(texel.x, 0.0), 0.0).r - h; // shadelab: bump map
  float dht = textureLod(shadelabNormalMap, st + vec2(0.0, texel.y), 0.0).r - h; // shadelab: bump map
  return vec3(-shadelabNormalScale * vec2(dhs, dht), 1.0);
}
)glsl";

// N perturbed by the vector in the frame of T (less its part along N) and
// w N x T, the oracle's MapNormal.
const char* const MapNormalSource = R"glsl(vec3 shadelabMapNormal(vec3 N, vec3 T, float w, vec2 st)
{
  vec3 m = shadelabReliefVector(st);
  vec3 t = T - dot(N, T) * N;
  float tLength = length(t);
  if (!(tLength > shadelabTinyLength))
  {
    return N;
  }
  t /= tLength;
  vec3 n = m.x * t + m.y * (w * cross(N, t)) + m.z * N; // shadelab: $
  float len = length(n);
  return len > shadelabTinyLength ? n / len : N;
}
)glsl";
}

std::string ReliefSource(bool height)
{
  std::string mapping = MapNormalSource;
  const std::size_t at = mapping.find('$');
  mapping.replace(at, 1, ReliefMark(height));
  return (height ? BumpMapVectorSource : NormalMapVectorSource) + mapping;
}

const char* ReliefMark(bool height)
{
  return height ? "bump map" : "normal map";
}
}
