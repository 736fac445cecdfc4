#include "core/options.h"

#include "vtkShadelabMeshReader.h"

namespace shadelab
{
Material SceneOptions::EffectiveMaterial() const
{
  const Material* base = FindLectureMaterial(this->MaterialName);
  return this->Overridden(base ? *base : Material{ this->MaterialName });
}

Material SceneOptions::Overridden(Material m) const
{
  // --texture is every part's kd and ka: their factors become 1.
  const bool textured = !this->Texture.empty();
  m.Ka = this->Ka.value_or(textured ? Rgb{ 1, 1, 1 } : m.Ka);
  m.Kd = this->Kd.value_or(textured ? Rgb{ 1, 1, 1 } : m.Kd);
  m.Ks = this->Ks.value_or(m.Ks);
  m.Ns = this->Ns.value_or(m.Ns);
  m.Translucency = this->Translucency.value_or(m.Translucency);
  return m;
}

std::vector<std::string> LectureMaterialNames()
{
  std::vector<std::string> names;
  for (const Material& m : LectureMaterials())
  {
    names.push_back(m.Name);
  }
  return names;
}

std::string MeshFileHelp()
{
  return std::string("Mesh file: ") + vtkShadelabMeshReader::GetKnownExtensions();
}
}
