#include "shadelabRepresentation.h"

#include "shadelabVec3.h"

#include <algorithm>
#include <cstdint>
#include <unordered_set>

namespace shadelab
{
using namespace vec3;

DrawnElements ElementsOf(Representation representation, const std::vector<unsigned int>& triangles)
{
  DrawnElements drawn;
  const std::size_t count = triangles.size() / 3;
  if (representation == Representation::Wireframe)
  {
    // A closed mesh has 3/2 edges a triangle.
    std::unordered_set<std::uint64_t> seen(count * 3 / 2 + 1);
    drawn.Corners.reserve(3 * count + 1);
    drawn.Owners.reserve(3 * count / 2 + 1);
    for (std::size_t t = 0; t < count; ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        const unsigned int a = triangles[3 * t + k], b = triangles[3 * t + (k + 1) % 3];
        const std::uint64_t key =
          (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
        if (a != b && seen.insert(key).second)
        {
          drawn.Corners.insert(drawn.Corners.end(), { a, b });
          drawn.Owners.push_back(static_cast<unsigned int>(t));
        }
      }
    }
  }
  else if (representation == Representation::Points)
  {
    const unsigned int most =
      triangles.empty() ? 0 : *std::max_element(triangles.begin(), triangles.end());
    std::vector<bool> seen(triangles.empty() ? 0 : std::size_t(most) + 1);
    for (std::size_t i = 0; i < triangles.size(); ++i)
    {
      if (!seen[triangles[i]])
      {
        seen[triangles[i]] = true;
        drawn.Corners.push_back(triangles[i]);
        drawn.Owners.push_back(static_cast<unsigned int>(i / 3));
      }
    }
  }
  return drawn;
}

ShadedFragment ShadeElementFragment(
  const IlluminationInputs& inputs, Shading rule, const TriangleFragment& f)
{
  IlluminationInputs in = inputs;
  in.NormalTexture.reset(); // a line or a point has no tangent plane to perturb in
  const auto towardsViewer = [&in](const Vec3& n, const Vec3& p)
  { return dot(n, in.Orthographic ? -in.ViewDirection : in.Eye - p) >= 0; };
  TriangleFragment turned = f;
  turned.Front = true;
  switch (rule)
  {
    case Shading::None:
      break;
    case Shading::Flat:
    {
      const std::array<Vec3, 3>& P = f.Positions;
      turned.Front = towardsViewer(cross(P[1] - P[0], P[2] - P[0]), P[2]);
      break;
    }
    case Shading::Gouraud:
      for (int k = 0; k < 3; ++k)
      {
        turned.Normals[k] =
          towardsViewer(f.Normals[k], f.Positions[k]) ? f.Normals[k] : -f.Normals[k];
      }
      break;
    case Shading::Raytrace: // its hits are lit as phong lights a fragment
    case Shading::Phong:
    {
      const std::array<double, 3>& w = f.Weights;
      const Vec3 n = w[0] * f.Normals[0] + w[1] * f.Normals[1] + w[2] * f.Normals[2];
      if (!UsableInterpolatedNormal(n))
      {
        // ka*Ia alone, the texel where it multiplies ka: gouraud's answer
        // for vertices of no normal.
        turned.Normals = {};
        ShadedFragment ambient = ShadeTriangleFragment(in, Shading::Gouraud, turned);
        ambient.FaceNormalFallback = false;
        return ambient;
      }
      turned.Front =
        towardsViewer(n, w[0] * f.Positions[0] + w[1] * f.Positions[1] + w[2] * f.Positions[2]);
      break;
    }
  }
  return ShadeTriangleFragment(in, rule, turned);
}
}
