// The stages of one's own in the window (the hands-on): the shader panel's
// edits drawn, refused with the driver's errors while the program that
// drew before keeps drawing, reverted to the generated stages, and saved
// through the one way files are written, so that Copy command and Save
// scene can name them.
#include "desktop/inspector.h"

#include "core/output_file.h"

#include <filesystem>
#include <iostream>

namespace shadelab
{
std::vector<StageErrorLine> Inspector::ApplyStages(const OwnStages& edits)
{
  const ViewState before = this->State;
  ViewState next = before;
  // The rule of the program the panel shows: the first panel's.
  const Shading rule = this->State.Compare && !this->Plan.Panels.empty()
    ? this->Plan.Panels.front().Scene.ShadingRule
    : this->State.Scene.ShadingRule;
  if (next.StagesRule != rule)
  {
    // One rule's stages at a time: another rule's are dropped with their files.
    next.Stages = {};
    next.Scene.VertexShader.clear();
    next.Scene.FragmentShader.clear();
    next.StagesRule = rule;
  }
  if (!edits.Vertex.empty())
  {
    next.Stages.Vertex = edits.Vertex;
  }
  if (!edits.Fragment.empty())
  {
    next.Stages.Fragment = edits.Fragment;
  }
  this->SetState(next); // drawn: the program is built and checked
  const BuiltScene* refusing = this->RefusingScene();
  if (!refusing)
  {
    return {};
  }
  std::vector<StageErrorLine> errors = LocateStageErrors(*refusing);
  this->SetState(before);
  return errors;
}

void Inspector::RevertStages()
{
  this->Saved = {};
  this->Edit(
    [](ViewState& s)
    {
      s.Stages = {};
      s.Scene.VertexShader.clear();
      s.Scene.FragmentShader.clear();
    });
}

bool Inspector::SaveStages()
{
  struct StageFile
  {
    const std::string& Text;
    std::string& Path;
    std::string& Saved;
    const char* Extension;
    const char* Name;
  };
  for (const StageFile& stage :
    { StageFile{ this->State.Stages.Vertex, this->State.Scene.VertexShader, this->Saved.Vertex,
        ".vert", "vertex" },
      StageFile{ this->State.Stages.Fragment, this->State.Scene.FragmentShader,
        this->Saved.Fragment, ".frag", "fragment" } })
  {
    if (stage.Text.empty() || (!stage.Path.empty() && stage.Text == stage.Saved))
    {
      continue;
    }
    const std::string path =
      stage.Path.empty() ? NumberedName(this->Options.Scene.Mesh, stage.Extension) : stage.Path;
    if (const std::string error = WriteFile(path, stage.Text); !error.empty())
    {
      ReportError(path, error);
      return false;
    }
    stage.Path = path;
    stage.Saved = stage.Text;
    std::cout << "shadelab: " << stage.Name << " stage " << std::filesystem::absolute(path).string()
              << std::endl;
  }
  return true;
}

SceneOptions Inspector::StageNames() const
{
  SceneOptions named = this->State.Scene;
  if (named.VertexShader.empty() && !this->State.Stages.Vertex.empty())
  {
    named.VertexShader = "the edited vertex stage";
  }
  if (named.FragmentShader.empty() && !this->State.Stages.Fragment.empty())
  {
    named.FragmentShader = "the edited fragment stage";
  }
  return named;
}
}
