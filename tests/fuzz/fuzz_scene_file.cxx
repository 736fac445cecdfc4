// libFuzzer target: bytes as a scene file (`render --scene`),
// parsed by ReadSceneFile. A finding is a crash, a sanitizer report, an
// exception that escapes, or a file that parses but gives a shot without a
// mesh or an output.
#include "scene/scene_file.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
const std::string& InputPath()
{
  static const std::string path = "/tmp/shadelab-fuzz-" + std::to_string(getpid()) + ".json";
  return path;
}
}

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  std::atexit([] { std::remove(InputPath().c_str()); });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  FILE* file = std::fopen(InputPath().c_str(), "wb");
  if (!file || std::fwrite(data, 1, size, file) != size || std::fclose(file) != 0)
  {
    std::abort();
  }
  std::vector<shadelab::Shot> shots;
  if (shadelab::ReadSceneFile(InputPath(), "", shots).empty())
  {
    for (const shadelab::Shot& shot : shots)
    {
      if (shot.Scene.Mesh.empty() || shot.Output.empty())
      {
        std::abort();
      }
    }
  }
  return 0;
}
