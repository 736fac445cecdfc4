// libFuzzer target: the MTL parser (shadelabMtlParser) on any text. It may
// only answer or throw MeshReadError; what it answers must be finite, ns
// non-negative.
#include "shadelabMeshReadError.h"
#include "shadelabMtlParser.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  try
  {
    for (const shadelab::Material& m :
      shadelab::ParseMtl(std::string_view(reinterpret_cast<const char*>(data), size)))
    {
      for (const shadelab::Rgb* c : { &m.Ka, &m.Kd, &m.Ks })
      {
        for (double v : *c)
        {
          if (!std::isfinite(v))
          {
            std::abort();
          }
        }
      }
      if (!(m.Ns >= 0) || !std::isfinite(m.Ns) || !std::isfinite(m.Translucency))
      {
        std::abort();
      }
    }
  }
  catch (const shadelab::MeshReadError&)
  {
  }
  return 0;
}
