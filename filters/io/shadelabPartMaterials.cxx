#include "shadelabPartMaterials.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <initializer_list>
#include <string>

namespace shadelab
{
namespace
{
vtkSmartPointer<vtkIntArray> IntArray(const char* name, vtkIdType count)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(count);
  return array;
}

void AddArrays(vtkPolyData* triangles, std::initializer_list<vtkAbstractArray*> arrays)
{
  for (vtkAbstractArray* array : arrays)
  {
    triangles->GetFieldData()->AddArray(array);
  }
}
}

int AddTexture(std::vector<Texture>& textures, Texture texture)
{
  const auto same = [&](const Texture& t)
  {
    return t.Source == texture.Source && t.Bytes == texture.Bytes && t.WrapS == texture.WrapS &&
      t.WrapT == texture.WrapT && t.MagFilter == texture.MagFilter &&
      t.MinFilter == texture.MinFilter;
  };
  const auto found = std::find_if(textures.begin(), textures.end(), same);
  if (found != textures.end())
  {
    return static_cast<int>(found - textures.begin());
  }
  textures.push_back(std::move(texture));
  return static_cast<int>(textures.size() - 1);
}

void AddPartMaterials(const std::vector<PartMaterial>& parts, vtkPolyData* triangles)
{
  const auto count = static_cast<vtkIdType>(parts.size());
  vtkNew<vtkStringArray> names;
  names->SetName(PartMaterialsArrayName);
  names->SetNumberOfValues(count);
  auto indices = IntArray(PartMaterialIndicesArrayName, count);
  auto kdTextures = IntArray(PartKdTextureArrayName, count);
  auto kaTextures = IntArray(PartKaTextureArrayName, count);
  auto ksTextures = IntArray(PartKsTextureArrayName, count);
  auto normalTextures = IntArray(PartNormalTextureArrayName, count);
  auto fromBump = IntArray(PartNormalFromBumpArrayName, count);
  const auto coefficients = [count](const char* name, int components)
  {
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(name);
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(count);
    array->Fill(0);
    return array;
  };
  auto ka = coefficients(PartKaArrayName, 3);
  auto kd = coefficients(PartKdArrayName, 3);
  auto ks = coefficients(PartKsArrayName, 3);
  auto ns = coefficients(PartNsArrayName, 1);
  auto translucency = coefficients(PartTranslucencyArrayName, 1);
  translucency->Fill(1);
  auto ksScales = coefficients(PartKsTextureScaleArrayName, 3);
  auto normalScales = coefficients(PartNormalScaleArrayName, 1);
  for (vtkIdType part = 0; part < count; ++part)
  {
    const PartMaterial& p = parts[part];
    names->SetValue(part, p.Name);
    indices->SetValue(part, p.Index);
    kdTextures->SetValue(part, p.KdTexture);
    kaTextures->SetValue(part, p.KaTexture);
    ksTextures->SetValue(part, p.KsTexture);
    ksScales->SetTuple(part, p.KsTextureScale.data());
    normalTextures->SetValue(part, p.NormalTexture);
    normalScales->SetTuple(part, &p.NormalScale);
    fromBump->SetValue(part, p.NormalFromBump);
    if (p.Index >= 0)
    {
      ka->SetTuple(part, p.Coefficients.Ka.data());
      kd->SetTuple(part, p.Coefficients.Kd.data());
      ks->SetTuple(part, p.Coefficients.Ks.data());
      ns->SetTuple(part, &p.Coefficients.Ns);
      translucency->SetTuple(part, &p.Coefficients.Translucency);
    }
  }
  AddArrays(triangles,
    { names, indices, ka, kd, ks, ns, translucency, kdTextures, kaTextures, ksTextures, ksScales,
      normalTextures, normalScales, fromBump });
}

void AddTextures(const std::vector<Texture>& textures, vtkPolyData* triangles)
{
  if (textures.empty())
  {
    return;
  }
  const auto count = static_cast<vtkIdType>(textures.size());
  vtkNew<vtkStringArray> sources;
  sources->SetName(TextureSourcesArrayName);
  sources->SetNumberOfValues(count);
  auto wrapS = IntArray(TextureWrapSArrayName, count);
  auto wrapT = IntArray(TextureWrapTArrayName, count);
  auto magFilter = IntArray(TextureMagFilterArrayName, count);
  auto minFilter = IntArray(TextureMinFilterArrayName, count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    const Texture& texture = textures[i];
    sources->SetValue(i, texture.Source);
    wrapS->SetValue(i, texture.WrapS);
    wrapT->SetValue(i, texture.WrapT);
    magFilter->SetValue(i, texture.MagFilter);
    minFilter->SetValue(i, texture.MinFilter);
    if (texture.Source.empty())
    {
      vtkNew<vtkUnsignedCharArray> bytes;
      bytes->SetName((TextureBytesArrayPrefix + std::to_string(i)).c_str());
      bytes->SetNumberOfValues(static_cast<vtkIdType>(texture.Bytes.size()));
      std::copy(texture.Bytes.begin(), texture.Bytes.end(), bytes->GetPointer(0));
      AddArrays(triangles, { bytes });
    }
  }
  AddArrays(triangles, { sources, wrapS, wrapT, magFilter, minFilter });
}

std::vector<Texture> MeshTextures(vtkPolyData* mesh)
{
  vtkFieldData* field = mesh->GetFieldData();
  auto* sources = vtkStringArray::SafeDownCast(field->GetAbstractArray(TextureSourcesArrayName));
  std::vector<Texture> textures(sources ? sources->GetNumberOfValues() : 0);
  const auto sampler = [field](const char* name, vtkIdType i, int fallback)
  {
    auto* values = vtkIntArray::SafeDownCast(field->GetArray(name));
    return values && i < values->GetNumberOfValues() ? values->GetValue(i) : fallback;
  };
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(textures.size()); ++i)
  {
    Texture& texture = textures[i];
    texture.Source = sources->GetValue(i);
    texture.WrapS = sampler(TextureWrapSArrayName, i, gl::Repeat);
    texture.WrapT = sampler(TextureWrapTArrayName, i, gl::Repeat);
    texture.MagFilter = sampler(TextureMagFilterArrayName, i, gl::Linear);
    texture.MinFilter = sampler(TextureMinFilterArrayName, i, gl::Linear);
    const std::string bytesName = TextureBytesArrayPrefix + std::to_string(i);
    if (auto* bytes = vtkUnsignedCharArray::SafeDownCast(field->GetArray(bytesName.c_str())))
    {
      texture.Bytes.assign(bytes->GetPointer(0), bytes->GetPointer(0) + bytes->GetNumberOfValues());
    }
  }
  return textures;
}
}
