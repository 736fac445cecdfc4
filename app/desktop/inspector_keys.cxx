// The inspector's keys: each key of the table (desktop/view_keys.h) to its
// row's action.
#include "desktop/inspector.h"

#include "scene/scene.h"
#include "vtkShadelabMeshNormals.h"

#include <algorithm>

namespace shadelab
{
namespace
{
const std::vector<std::string> Weightings = Names<vtkShadelabMeshNormals::Weightings>();

// The table's name of a key that arrives under another: the window names
// Esc "Escape", and = is + without shift on a US keyboard.
std::string TableName(const std::string& key)
{
  if (key == "Escape")
  {
    return "Esc";
  }
  return key == "=" ? "+" : key;
}
}

bool Inspector::OnKey(const std::string& key)
{
  const ViewKeyPress press = FindViewKey(TableName(key));
  if (press.Row)
  {
    this->Do(press.Row->Action, press.Which);
  }
  return press.Row;
}

void Inspector::Do(ViewAction action, int which)
{
  if (this->Act(action, which))
  {
    this->Show(action == ViewAction::Compare); // a new grid: the panels' aspect
  }
}

// Does `action`, `which` the key's place in its row; whether the picture is
// to be drawn again.
bool Inspector::Act(ViewAction action, int which)
{
  SceneOptions& s = this->State.Scene;
  switch (action)
  {
    case ViewAction::Shading:
      s.ShadingRule = static_cast<Shading>(which); // the row is in Shading's order
      return true;
    case ViewAction::Reflection:
      s.ReflectionModel = NextOf(s.ReflectionModel);
      return true;
    case ViewAction::Material:
      this->StepMaterial(which == 0 ? 1 : -1);
      return true;
    case ViewAction::Lights:
      this->NextLights();
      return true;
    case ViewAction::Shininess:
    {
      const double ns = s.EffectiveMaterial().Ns;
      s.Ns = which == 1 ? ns / 1.5 : std::max(1.0, ns * 1.5);
      return true;
    }
    case ViewAction::Term:
    {
      bool& term = which == 0 ? this->State.Ambient
        : which == 1          ? this->State.Diffuse
                              : this->State.Specular;
      term = !term;
      return true;
    }
    case ViewAction::Weighting:
      this->NextWeighting();
      return true;
    case ViewAction::Glyphs:
      this->State.Glyphs = !this->State.Glyphs;
      return true;
    case ViewAction::Edges:
      this->State.Edges = !this->State.Edges;
      return true;
    case ViewAction::Compare:
      this->State.Compare = !this->State.Compare;
      return true;
    case ViewAction::ResetCamera:
      this->ResetCamera();
      return true;
    case ViewAction::Screenshot:
      this->Screenshot();
      return false;
    case ViewAction::CopyCommand:
      this->CopyCommand();
      return false;
    case ViewAction::SaveScene:
      this->SaveScene(NumberedName(this->Options.Scene.Mesh, ".json"));
      return false;
    case ViewAction::ProfileLine:
      this->ArmProfileLine();
      return false;
    case ViewAction::Help:
      this->State.Help = !this->State.Help;
      return true;
    case ViewAction::Quit:
      if (this->Quit)
      {
        this->Quit();
      }
      return false;
  }
  return false;
}

// The lecture's material `step` places along its table, round.
void Inspector::StepMaterial(int step)
{
  SceneOptions& s = this->State.Scene;
  const auto& materials = LectureMaterials();
  const auto current = std::find_if(materials.begin(), materials.end(),
    [&s](const Material& m) { return m.Name == s.MaterialName; });
  const int n = static_cast<int>(materials.size());
  const int index = current == materials.end() ? -1 : static_cast<int>(current - materials.begin());
  s.MaterialName = materials[(index + step + n) % n].Name;
  s.MaterialGiven = true; // every part's material, as --material replaces it
  s.Ka.reset();           // the command line's coefficients were for its material
  s.Kd.reset();
  s.Ks.reset();
  s.Ns.reset();
}

// LightMode's cycle; the light list only when it has any.
void Inspector::NextLights()
{
  const bool given = !this->State.Scene.Lights.empty();
  const int next = static_cast<int>(this->State.Lights) + 1;
  this->State.Lights = static_cast<LightMode>(next > static_cast<int>(LightMode::Spot)
      ? (given ? 0 : static_cast<int>(LightMode::PointAtCamera))
      : next);
}

// The cycle: the file's normals (when it has them), then each weighting.
void Inspector::NextWeighting()
{
  SceneOptions& s = this->State.Scene;
  const bool fromFile = s.Normals != NormalsMode::Compute && this->FileNormals;
  const auto at = std::find(Weightings.begin(), Weightings.end(), s.Computed.Weighting);
  if (fromFile)
  {
    s.Normals = NormalsMode::Compute;
    s.Computed.Weighting = Weightings.front();
  }
  else if (at == Weightings.end() || at + 1 == Weightings.end())
  {
    s.Computed.Weighting = Weightings.front();
    s.Normals = this->FileNormals ? NormalsMode::Auto : NormalsMode::Compute;
  }
  else
  {
    s.Computed.Weighting = *(at + 1);
  }
}
}
