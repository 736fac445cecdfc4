// libFuzzer target: the command line's value parsers (colours, points,
// lights, sizes, numbers, shards, comparison modes and --diff, pixels). The
// first byte picks the parser, the rest is the text. They may only answer or
// throw std::invalid_argument; what they accept must be in range.
#include "core/options.h"
#include "scene/comparison_panels.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace
{
void Finite(const std::array<double, 3>& v)
{
  if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
  {
    std::abort();
  }
}
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size == 0)
  {
    return 0;
  }
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try
  {
    switch (data[0] % 8)
    {
      case 0:
      {
        const shadelab::Rgb c = shadelab::ParseRgb(text);
        Finite(c);
        if (c[0] < 0 || c[1] < 0 || c[2] < 0)
        {
          std::abort();
        }
        break;
      }
      case 1:
        Finite(shadelab::ParseVec3(text));
        break;
      case 2:
      {
        const shadelab::Light l = shadelab::ParseLight(text);
        Finite(l.Position);
        Finite(l.Direction);
        Finite(l.Color);
        if (l.Kind != shadelab::LightKind::Point && l.Direction == shadelab::Vec3{ 0, 0, 0 })
        {
          std::abort();
        }
        if (l.Kind == shadelab::LightKind::Spot && !(l.HalfAngleDeg > 0 && l.HalfAngleDeg <= 90))
        {
          std::abort();
        }
        break;
      }
      case 3:
      {
        const shadelab::ImageSize s = shadelab::ParseSize(text);
        if (s.Width < 1 || s.Height < 1 || s.Width > shadelab::MaxImageSide ||
          s.Height > shadelab::MaxImageSide ||
          static_cast<long long>(s.Width) * s.Height > shadelab::MaxImagePixels)
        {
          std::abort();
        }
        break;
      }
      case 4:
        if (!std::isfinite(shadelab::ParseNumber(text)))
        {
          std::abort();
        }
        break;
      case 6:
      {
        // "MODES" or "MODES|DIFF": every panel a mode's, the difference's two in range.
        shadelab::ComparisonOptions o;
        const auto bar = text.find('|');
        o.Modes = text.substr(0, bar);
        o.Difference = bar == std::string::npos ? "" : text.substr(bar + 1);
        o.Components = data[0] & 0x80;
        const shadelab::Comparison c = shadelab::PlanComparison(o, shadelab::SceneOptions{});
        const int n = static_cast<int>(c.Panels.size());
        if (c.Modes.empty() || n != static_cast<int>(c.Modes.size()) * (o.Components ? 4 : 1) ||
          (!o.Difference.empty() &&
            (c.DifferenceA < 0 || c.DifferenceA >= n || c.DifferenceB < 0 || c.DifferenceB >= n)))
        {
          std::abort();
        }
        break;
      }
      case 7:
      {
        const shadelab::Pixel p = shadelab::ParsePixel(text);
        if (p.X < 0 || p.Y < 0)
        {
          std::abort();
        }
        break;
      }
      default:
      {
        const auto [index, count] = shadelab::ParseShard(text);
        if (index < 0 || count < 1 || index >= count)
        {
          std::abort();
        }
      }
    }
  }
  catch (const std::invalid_argument&)
  {
  }
  return 0;
}
