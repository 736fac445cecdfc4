// shadelab-bench-png PICTURE.png...: the cost of PNG's zlib level and row
// filter (scripts/bench-png; doc/benchmarks-log.md, "PNG encoding"). Each picture's
// pixels are encoded into memory through OpenImageIO at each level and
// filter, the median time of ROUNDS and the size printed as a markdown
// table, and each encoding decoded again from memory (as textures are) to
// check that its pixels are the picture's: PNG is lossless, whatever the
// level and filter.
#include "core/milliseconds.h"
#include "image/texture_decoding.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <png.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace shadelab;

namespace
{
constexpr int Rounds = 11;

struct Filter
{
  const char* Name;
  int Flags; // OpenImageIO's "png:filter": libpng's PNG_FILTER_* flags; 0 for libpng's own choice
};

std::vector<unsigned char> Pixels(OIIO::ImageInput& in)
{
  const OIIO::ImageSpec& spec = in.spec();
  std::vector<unsigned char> pixels(spec.image_bytes());
  if (!in.read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, pixels.data()))
  {
    pixels.clear();
  }
  return pixels;
}

// The picture encoded at level with filter; its median time over Rounds in ms.
std::vector<unsigned char> Encode(const OIIO::ImageSpec& spec,
  const std::vector<unsigned char>& pixels, int level, const Filter& filter, double& ms)
{
  std::vector<double> times;
  std::vector<unsigned char> encoded;
  for (int round = 0; round < Rounds; ++round)
  {
    encoded.clear();
    OIIO::Filesystem::IOVecOutput memory(encoded);
    OIIO::ImageSpec out(spec.width, spec.height, spec.nchannels, OIIO::TypeDesc::UINT8);
    out.attribute("png:compressionLevel", level);
    if (filter.Flags != 0)
    {
      out.attribute("png:filter", filter.Flags);
    }
    const Clock::time_point start = Clock::now();
    auto writer = OIIO::ImageOutput::create("picture.png", &memory);
    if (!writer || !writer->open("picture.png", out) ||
      !writer->write_image(OIIO::TypeDesc::UINT8, pixels.data()) || !writer->close())
    {
      std::fprintf(stderr, "shadelab-bench-png: cannot encode\n");
      std::exit(1);
    }
    times.push_back(Milliseconds(start));
  }
  std::nth_element(times.begin(), times.begin() + Rounds / 2, times.end());
  ms = times[Rounds / 2];
  return encoded;
}

// The picture decoded (a file, or an encoding's bytes) as a texture is: RGB
// floats, each 8-bit value to a float of its own (k / 255), so two 8-bit
// RGB pictures decode alike only if their pixels are equal.
TextureImage Decoded(DecodeRequest request, const char* what)
{
  TextureImage image;
  if (const std::string problem = DecodeTexture(request, image); !problem.empty())
  {
    std::fprintf(stderr, "shadelab-bench-png: %s: %s\n", what, problem.c_str());
    std::exit(1);
  }
  return image;
}
}

int main(int argc, char** argv)
{
  const Filter filters[] = { { "adaptive (libpng's default)", 0 }, { "none", PNG_FILTER_NONE },
    { "sub", PNG_FILTER_SUB }, { "up", PNG_FILTER_UP } };
  for (int i = 1; i < argc; ++i)
  {
    auto in = OIIO::ImageInput::open(argv[i]);
    if (!in)
    {
      std::fprintf(stderr, "shadelab-bench-png: cannot read %s\n", argv[i]);
      return 1;
    }
    const OIIO::ImageSpec spec = in->spec();
    const std::vector<unsigned char> pixels = Pixels(*in);
    const std::vector<float> picture = Decoded({ argv[i], {} }, argv[i]).Pixels;
    std::printf("\n%s (%dx%d, %d channels), median of %d:\n\n", argv[i], spec.width, spec.height,
      spec.nchannels, Rounds);
    std::printf("| zlib level | filter | ms | bytes |\n|---:|---|---:|---:|\n");
    for (int level : { 1, 2, 3, 4, 6 })
    {
      for (const Filter& filter : filters)
      {
        double ms = 0;
        const std::vector<unsigned char> encoded = Encode(spec, pixels, level, filter, ms);
        if (Decoded({ "", encoded }, "an encoding").Pixels != picture)
        {
          std::fprintf(
            stderr, "shadelab-bench-png: level %d, filter %s changed pixels\n", level, filter.Name);
          return 1;
        }
        std::printf("| %d | %s | %.1f | %zu |\n", level, filter.Name, ms, encoded.size());
      }
    }
  }
  return 0;
}
