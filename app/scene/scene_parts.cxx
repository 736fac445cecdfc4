#include "scene/scene_parts.h"

#include "scene/camera.h"

#include "shadelabPartMaterials.h"
#include "shadelabTriangleMesh.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>

namespace shadelab
{
namespace
{
// Part p's coefficients from the field array `name`, of N components (zeros where it has none).
template <std::size_t N>
std::array<double, N> FieldTuple(vtkFieldData* field, const char* name, vtkIdType p)
{
  std::array<double, N> values{};
  vtkDataArray* array = field->GetArray(name);
  if (array && p < array->GetNumberOfTuples() &&
    array->GetNumberOfComponents() == static_cast<int>(N))
  {
    array->GetTuple(p, values.data());
  }
  return values;
}

int FieldInt(vtkFieldData* field, const char* name, vtkIdType p)
{
  auto* array = vtkIntArray::SafeDownCast(field->GetArray(name));
  return array && p < array->GetNumberOfValues() ? array->GetValue(p) : -1;
}

// The file's textures of a part: indices into the mesh's textures, -1 for none.
struct FileTextures
{
  int Kd = -1;
  int Ka = -1;
  int Ks = -1;
  Rgb KsScale{};
  int Normal = -1; // its normal map
  double NormalScale = 1;
  bool NormalFromBump = false;
};

// The part's texture: --texture's on every part (kd and ka), else the file's
// kd, ka and ks textures of a part with its own material, less those that
// --kd, --ka and --ks drop.
void SetTexture(const SceneOptions& options, const std::vector<Texture>& textures,
  const SceneImages& images, const FileTextures& fileTextures, ScenePart& part)
{
  SurfaceTexture& t = part.Texture;
  if (!options.Texture.empty())
  {
    t.Map.Image = images.Option;
    t.Map.WrapS = t.Map.WrapT = options.TextureWrapping;
    t.Map.Filter = options.TextureFiltering;
    t.Kd = t.Ka = true;
    part.ImageName = options.Texture;
    return;
  }
  const int count = static_cast<int>(textures.size());
  const int kd = options.Kd || fileTextures.Kd >= count ? -1 : fileTextures.Kd;
  const int ka = options.Ka || fileTextures.Ka >= count ? -1 : fileTextures.Ka;
  const int ks = options.Ks || fileTextures.Ks >= count ? -1 : fileTextures.Ks;
  const int drawn = kd >= 0 ? kd : ka >= 0 ? ka : ks;
  if (drawn < 0)
  {
    return;
  }
  const Texture& file = textures[drawn];
  t.Map.Image = drawn < static_cast<int>(images.File.size()) ? images.File[drawn] : nullptr;
  t.Map.WrapS = WrapFromGL(file.WrapS).value_or(TextureWrap::Repeat);
  t.Map.WrapT = WrapFromGL(file.WrapT).value_or(TextureWrap::Repeat);
  // One filter without mipmaps (shadelabTexture.h): the magnification one,
  // since a close view shows it and minification aliases either way.
  t.Map.Filter = FilterFromGL(file.MagFilter).value_or(TextureFilter::Bilinear);
  t.Kd = kd == drawn;
  t.Ka = ka == drawn;
  t.Ks = ks == drawn;
  t.KsScale = t.Ks ? fileTextures.KsScale : Rgb{};
  part.FileTexture = drawn;
  part.ImageName = FileTextureName(options, textures, drawn);
}

// The part's normal map: --normal-map's or --bump-map's on every part, else
// the file's of a part with its own material, a height map where it came
// from a bump statement and its image is grey.
void SetNormalMap(const SceneOptions& options, const std::vector<Texture>& textures,
  const SceneImages& images, const FileTextures& fileTextures, ScenePart& part)
{
  if (const auto& given = options.Relief())
  {
    part.Relief = NormalMap{ { images.NormalMap, options.TextureWrapping, options.TextureWrapping,
                               options.TextureFiltering },
      given->Scale, options.BumpMap.has_value() };
    return;
  }
  const int n = options.NoNormalMaps() ? -1 : fileTextures.Normal;
  if (n < 0 || n >= static_cast<int>(textures.size()))
  {
    return;
  }
  const Texture& file = textures[n];
  const auto image = n < static_cast<int>(images.File.size()) ? images.File[n] : nullptr;
  part.Relief = NormalMap{ { image, WrapFromGL(file.WrapS).value_or(TextureWrap::Repeat),
                             WrapFromGL(file.WrapT).value_or(TextureWrap::Repeat),
                             FilterFromGL(file.MagFilter).value_or(TextureFilter::Bilinear) },
    fileTextures.NormalScale, image && fileTextures.NormalFromBump && IsGrey(*image) };
  part.FileNormalTexture = n;
  part.FileBump = fileTextures.NormalFromBump;
}
}

std::string FileTextureName(
  const SceneOptions& options, const std::vector<Texture>& textures, int index)
{
  const Texture& file = textures[index];
  return file.Source.empty() ? options.Mesh + " (texture " + std::to_string(index) + ")"
                             : file.Source;
}

std::vector<int> PartOfCells(vtkPolyData* mesh)
{
  std::vector<int> parts(mesh->GetNumberOfCells(), 0);
  if (vtkDataArray* part = mesh->GetCellData()->GetArray(PartArrayName))
  {
    for (vtkIdType c = 0; c < mesh->GetNumberOfCells() && c < part->GetNumberOfTuples(); ++c)
    {
      parts[c] = std::max(0, static_cast<int>(part->GetComponent(c, 0)));
    }
  }
  return parts;
}

std::vector<ScenePart> SceneParts(
  const SceneOptions& options, vtkPolyData* mesh, const SceneImages& images)
{
  const std::vector<int> cells = PartOfCells(mesh);
  vtkFieldData* field = mesh->GetFieldData();
  auto* names = vtkStringArray::SafeDownCast(field->GetAbstractArray(PartMaterialsArrayName));
  auto* indices = vtkIntArray::SafeDownCast(field->GetArray(PartMaterialIndicesArrayName));
  // Every part the field data names, and any a triangle is of beyond them.
  int count = names ? static_cast<int>(names->GetNumberOfValues()) : 1;
  for (int p : cells)
  {
    count = std::max(count, p + 1);
  }
  const std::pair<const char*, bool> overrides[] = { { "ka", options.Ka.has_value() },
    { "kd", options.Kd.has_value() }, { "ks", options.Ks.has_value() },
    { "ns", options.Ns.has_value() } };
  // A file's textures need its texture coordinates: without them none is drawn.
  const std::vector<Texture> textures = mesh->GetPointData()->GetArray(TextureCoordinatesArrayName)
    ? MeshTextures(mesh)
    : std::vector<Texture>{};
  std::vector<ScenePart> parts(count);
  for (int p = 0; p < count; ++p)
  {
    ScenePart& part = parts[p];
    part.Index = p;
    part.Name = names && p < names->GetNumberOfValues() ? names->GetValue(p) : "";
    const bool own = indices && p < indices->GetNumberOfValues() && indices->GetValue(p) >= 0;
    if (own && !options.MaterialGiven)
    {
      Material file{ part.Name };
      file.Ka = FieldTuple<3>(field, PartKaArrayName, p);
      file.Kd = FieldTuple<3>(field, PartKdArrayName, p);
      file.Ks = FieldTuple<3>(field, PartKsArrayName, p);
      file.Ns = FieldTuple<1>(field, PartNsArrayName, p)[0];
      if (field->GetArray(PartTranslucencyArrayName))
      {
        file.Translucency = FieldTuple<1>(field, PartTranslucencyArrayName, p)[0];
      }
      part.Surface = options.Overridden(file);
      part.Source = MaterialSource::File;
    }
    else
    {
      part.Surface = options.EffectiveMaterial();
      part.Source = options.MaterialGiven ? MaterialSource::Option : MaterialSource::Default;
    }
    for (const auto& [name, given] : overrides)
    {
      if (given)
      {
        part.Overridden.push_back(name);
      }
    }
    FileTextures fileTextures;
    if (own && !options.MaterialGiven)
    {
      fileTextures = { FieldInt(field, PartKdTextureArrayName, p),
        FieldInt(field, PartKaTextureArrayName, p), FieldInt(field, PartKsTextureArrayName, p),
        FieldTuple<3>(field, PartKsTextureScaleArrayName, p),
        FieldInt(field, PartNormalTextureArrayName, p),
        field->GetArray(PartNormalScaleArrayName)
          ? FieldTuple<1>(field, PartNormalScaleArrayName, p)[0]
          : 1.0,
        FieldInt(field, PartNormalFromBumpArrayName, p) > 0 };
    }
    SetTexture(options, textures, images, fileTextures, part);
    SetNormalMap(options, textures, images, fileTextures, part);
    if (part.Overridden.size() == std::size(overrides))
    {
      part.Source = MaterialSource::Option; // nothing of the file's or the default's is left
    }
  }
  for (int p : cells)
  {
    ++parts[p].Triangles;
  }
  return parts;
}

bool AnyTranslucent(const std::vector<ScenePart>& parts)
{
  return std::any_of(parts.begin(), parts.end(),
    [](const ScenePart& part) { return part.Triangles > 0 && part.Surface.Translucency < 1; });
}

vtkSmartPointer<vtkPolyData> TrianglesOfParts(vtkPolyData* mesh, const std::vector<int>& parts)
{
  const std::vector<int> cells = PartOfCells(mesh);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  vtkCellArray* all = mesh->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  vtkIdType cell = mesh->GetNumberOfVerts() + mesh->GetNumberOfLines(); // polys come after these
  for (all->InitTraversal(); all->GetNextCell(n, ids); ++cell)
  {
    if (std::binary_search(parts.begin(), parts.end(), cells[cell]))
    {
      polys->InsertNextCell(n, ids);
    }
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->SetPoints(mesh->GetPoints());
  result->GetPointData()->ShallowCopy(mesh->GetPointData());
  result->SetPolys(polys);
  return result;
}

std::optional<EnvironmentMap> SceneEnvironment(
  const SceneOptions& options, const SceneImages& images)
{
  if (!images.Environment)
  {
    return std::nullopt;
  }
  EnvironmentMap e;
  e.Map.Image = images.Environment;
  e.Map.WrapS = TextureWrap::Repeat; // the longitude goes round
  e.Map.WrapT = TextureWrap::Clamp;  // the latitude ends at the poles
  e.Map.Filter = options.TextureFiltering;
  const UpFrame axes = FrameOf(options.EnvironmentUp.value_or(options.Up));
  for (int j = 0; j < 3; ++j)
  {
    e.Frame[0][j] = axes.Right[j];
    e.Frame[1][j] = axes.Up[j];
    e.Frame[2][j] = axes.Front[j];
  }
  return e;
}
}
