#include "scene/mesh_arguments.h"

#include "core/output_path.h"
#include "vtkShadelabMeshReader.h"

#include <glob.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace shadelab
{
namespace
{
bool IsGlob(const std::string& argument)
{
  return argument.find_first_of("*?[") != std::string::npos;
}

bool IsMeshFile(const std::filesystem::path& path)
{
  const std::string ext = LowerExtension(path.string());
  std::istringstream known(vtkShadelabMeshReader::GetKnownExtensions());
  for (std::string k; known >> k;)
  {
    if (!ext.empty() && ext == k)
    {
      return true;
    }
  }
  return false;
}

std::vector<std::string> MeshesIn(const std::string& folder)
{
  std::vector<std::string> meshes;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error))
  {
    if (entry.is_regular_file(error) && IsMeshFile(entry.path()))
    {
      meshes.push_back(entry.path().string());
    }
  }
  std::sort(meshes.begin(), meshes.end());
  return meshes;
}

std::vector<std::string> Matches(const std::string& pattern)
{
  std::vector<std::string> matches;
  glob_t found = {};
  if (glob(pattern.c_str(), 0, nullptr, &found) == 0)
  {
    matches.assign(found.gl_pathv, found.gl_pathv + found.gl_pathc);
  }
  globfree(&found);
  return matches; // glob sorts them
}
}

bool IsOneMeshFile(const std::vector<std::string>& arguments)
{
  std::error_code error;
  return arguments.size() == 1 && !IsGlob(arguments[0]) &&
    !std::filesystem::is_directory(arguments[0], error);
}

std::string ExpandMeshArguments(
  const std::vector<std::string>& arguments, std::vector<std::string>& meshes)
{
  meshes.clear();
  for (const std::string& argument : arguments)
  {
    std::error_code error;
    if (std::filesystem::is_directory(argument, error))
    {
      const std::vector<std::string> in = MeshesIn(argument);
      if (in.empty())
      {
        return argument +
          ": no mesh files in the folder (known: " + vtkShadelabMeshReader::GetKnownExtensions() +
          ")";
      }
      meshes.insert(meshes.end(), in.begin(), in.end());
    }
    else if (IsGlob(argument))
    {
      const std::vector<std::string> matched = Matches(argument);
      if (matched.empty())
      {
        return argument + ": matches no file";
      }
      meshes.insert(meshes.end(), matched.begin(), matched.end());
    }
    else
    {
      meshes.push_back(argument);
    }
  }
  return {};
}
}
