// libFuzzer target: the MTL parser (shadelabMtlParser) on any text. It may
// only answer or throw MeshReadError; what it answers must be finite, ns
// non-negative, a map's file named, with '/' for '\'.
#include "shadelabMeshReadError.h"
#include "shadelabMtlParser.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  try
  {
    const shadelab::MtlLibrary library =
      shadelab::ParseMtl(std::string_view(reinterpret_cast<const char*>(data), size));
    for (const shadelab::MtlMaterial& material : library.Materials)
    {
      const shadelab::Material& m = material.Coefficients;
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
      for (const shadelab::MtlMap* map : { &material.KdMap, &material.KaMap })
      {
        if (map->File.find('\\') != std::string::npos)
        {
          std::abort();
        }
      }
    }
  }
  catch (const shadelab::MeshReadError&)
  {
  }
  return 0;
}
