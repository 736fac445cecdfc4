#include "scene/own_stage_files.h"

#include "shadelabCheckedFile.h"
#include "shadelabMeshReadError.h"
#include "vtkShadelabPolyDataMapper.h"

#include <vtkActor.h>

#include <regex>
#include <sstream>

namespace shadelab
{
InputProblem ReadOwnStages(const SceneOptions& options, OwnStages& stages)
{
  const std::pair<const std::string*, std::string*> files[] = {
    { &options.VertexShader, &stages.Vertex }, { &options.FragmentShader, &stages.Fragment }
  };
  for (const auto& [path, text] : files)
  {
    text->clear();
    if (path->empty())
    {
      continue;
    }
    try
    {
      *text = OpenChecked(*path, MaxShaderFileBytes).ReadAll();
    }
    catch (const MeshReadError& e)
    {
      return { *path, e.what() };
    }
    if (text->empty())
    {
      return { *path, "is empty: a stage is complete GLSL, as --dump-shaders writes it" };
    }
  }
  return {};
}

std::string OwnStageFiles(const SceneOptions& options)
{
  if (options.VertexShader.empty() || options.FragmentShader.empty())
  {
    return options.VertexShader + options.FragmentShader;
  }
  return options.VertexShader + " + " + options.FragmentShader;
}

namespace
{
// Every part draws the same stages: the first that failed says why.
std::vector<StageError> StageErrors(const BuiltScene& scene)
{
  for (const DrawnParts& drawn : scene.Drawn)
  {
    if (auto* mapper = vtkShadelabPolyDataMapper::SafeDownCast(drawn.Actor->GetMapper());
        mapper && !mapper->GetOwnStageErrors().empty())
    {
      return mapper->GetOwnStageErrors();
    }
  }
  return {};
}
}

std::vector<StageErrorLine> LocateStageErrors(const BuiltScene& scene)
{
  // Mesa: "0:12(5): error: ...", NVIDIA: "0(12) : error C0000: ...".
  static const std::regex located(R"(^\s*\d+(?::(\d+)\(\d+\)|\((\d+)\))\s*:\s*(.*)$)");
  std::vector<StageErrorLine> lines;
  for (const StageError& error : StageErrors(scene))
  {
    const std::size_t before = lines.size();
    std::istringstream log(error.Log);
    std::string line;
    while (std::getline(log, line))
    {
      std::smatch m;
      if (std::regex_match(line, m, located))
      {
        lines.push_back({ error.Where, std::stoi(m[1].matched ? m[1].str() : m[2].str()), m[3] });
      }
      else if (line.find_first_not_of(" \t\r") != std::string::npos)
      {
        lines.push_back(
          { error.Where, 0, error.Where == StageError::Stage::Link ? "linking: " + line : line });
      }
    }
    if (lines.size() == before)
    {
      lines.push_back({ error.Where, 0, "the driver rejected it and said nothing more" });
    }
  }
  return lines;
}

std::vector<InputProblem> StageErrorLines(const SceneOptions& options, const BuiltScene& scene)
{
  const std::string both = OwnStageFiles(options);
  std::vector<InputProblem> lines;
  for (const StageErrorLine& error : LocateStageErrors(scene))
  {
    const std::string& own = error.Where == StageError::Stage::Vertex ? options.VertexShader
      : error.Where == StageError::Stage::Fragment                    ? options.FragmentShader
                                                                      : both;
    const std::string file = own.empty()
      ? std::string(error.Where == StageError::Stage::Vertex ? "the generated vertex stage"
                                                             : "the generated fragment stage")
      : own;
    lines.push_back({ error.Line ? file + ":" + std::to_string(error.Line) : file, error.Message });
  }
  return lines;
}
}
