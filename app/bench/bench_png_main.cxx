// shadelab-bench-png PICTURE.png...: the cost of PNG's zlib level and row
// filter (scripts/bench-png; BENCHMARKS.md, "PNG encoding"). Each picture's
// pixels are encoded into memory through OpenImageIO at each level and
// filter, the median time of ROUNDS and the size printed as a markdown
// table, and each encoding decoded again to check that its pixels are the
// picture's: PNG is lossless, whatever the level and filter.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

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
    const auto start = std::chrono::steady_clock::now();
    auto writer = OIIO::ImageOutput::create("picture.png", &memory);
    if (!writer || !writer->open("picture.png", out) ||
      !writer->write_image(OIIO::TypeDesc::UINT8, pixels.data()) || !writer->close())
    {
      std::fprintf(stderr, "shadelab-bench-png: cannot encode\n");
      std::exit(1);
    }
    times.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(times.begin(), times.begin() + Rounds / 2, times.end());
  ms = times[Rounds / 2];
  return encoded;
}

// The encoding's pixels, decoded again through a file (OpenImageIO's PNG
// reader takes a file).
std::vector<unsigned char> Decoded(const std::vector<unsigned char>& encoded)
{
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
    ("shadelab-bench-png-" + std::to_string(getpid()) + ".png");
  std::ofstream(path, std::ios::binary)
    .write(
      reinterpret_cast<const char*>(encoded.data()), static_cast<std::streamsize>(encoded.size()));
  auto in = OIIO::ImageInput::open(path.string());
  std::vector<unsigned char> pixels = in ? Pixels(*in) : std::vector<unsigned char>();
  in.reset();
  std::filesystem::remove(path);
  return pixels;
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
    std::printf("\n%s (%dx%d, %d channels), median of %d:\n\n", argv[i], spec.width, spec.height,
      spec.nchannels, Rounds);
    std::printf("| zlib level | filter | ms | bytes |\n|---:|---|---:|---:|\n");
    for (int level : { 1, 2, 3, 4, 6 })
    {
      for (const Filter& filter : filters)
      {
        double ms = 0;
        const std::vector<unsigned char> encoded = Encode(spec, pixels, level, filter, ms);
        if (Decoded(encoded) != pixels)
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
