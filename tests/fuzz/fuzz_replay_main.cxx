// The fuzz targets without libFuzzer: runs LLVMFuzzerTestOneInput once on
// every file of the folders (or files) given, so that the seed corpora and
// the regression inputs of past findings run in every build's test suite
// (ctest), with whatever sanitizers that build has.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) __attribute__((weak));

int main(int argc, char** argv)
{
  if (LLVMFuzzerInitialize)
  {
    LLVMFuzzerInitialize(&argc, &argv);
  }
  std::vector<std::filesystem::path> inputs;
  for (int i = 1; i < argc; ++i)
  {
    const std::filesystem::path path(argv[i]);
    if (std::filesystem::is_directory(path))
    {
      for (const auto& entry : std::filesystem::directory_iterator(path))
      {
        inputs.push_back(entry.path());
      }
    }
    else if (std::filesystem::exists(path))
    {
      inputs.push_back(path);
    }
  }
  for (const auto& input : inputs)
  {
    std::ifstream in(input, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("%zu inputs ran\n", inputs.size());
  return inputs.empty() ? 1 : 0;
}
