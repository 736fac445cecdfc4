#include "scene/scene_cache.h"

#include "scene/own_stage_files.h"

#include "shadelabPartMaterials.h"
#include "shadelabTriangleMesh.h"
#include "vtkShadelabShading.h"

#include <vtkActor.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <algorithm>

namespace shadelab
{
SceneCache::Shown SceneCache::Show(const SceneOptions& options, vtkRenderer* renderer,
  const std::vector<Light>* lights, const OwnStages* given)
{
  Shown shown;
  const LoadedMesh& loaded = this->Meshes->Get(options);
  if (!loaded.Mesh)
  {
    shown.Input = options.Mesh;
    shown.Error = loaded.Error;
    return shown;
  }
  shown.Mesh = &loaded;
  SceneImages images;
  // The image `name` decoded (from `bytes` where the file embeds it), or
  // nothing with shown's error set.
  const auto decoded = [this, &shown](
                         const std::string& name, const std::vector<std::uint8_t>& bytes)
  {
    const LoadedTexture& image = this->Meshes->GetTexture(name, bytes);
    if (!image.Image)
    {
      shown.Input = name;
      shown.Error = image.Error;
    }
    return image.Image;
  };
  if (!options.Texture.empty())
  {
    images.Option = decoded(options.Texture, {});
    if (!images.Option)
    {
      return shown;
    }
    if (!loaded.Mesh->GetPointData()->GetArray(TextureCoordinatesArrayName))
    {
      shown.Input = options.Mesh;
      shown.Error = "--texture needs texture coordinates, and the mesh has none";
      return shown;
    }
  }
  if (options.NormalMap && !options.NoNormalMaps() && options.BumpMap)
  {
    shown.Input = "--bump-map";
    shown.Error = "takes the normal map's place, and --normal-map is given too: give one";
    return shown;
  }
  if (const auto& relief = options.Relief())
  {
    const std::string option = options.BumpMap ? "--bump-map" : "--normal-map";
    images.NormalMap = decoded(relief->Image, {});
    if (!images.NormalMap)
    {
      return shown;
    }
    if (!loaded.Mesh->GetPointData()->GetArray(TextureCoordinatesArrayName))
    {
      shown.Input = options.Mesh;
      shown.Error = option + " needs texture coordinates, and the mesh has none";
      return shown;
    }
    if (IsGrey(*images.NormalMap) != options.BumpMap.has_value())
    {
      shown.Input = relief->Image;
      shown.Error = options.BumpMap
        ? "is not grey, so not a height map (a normal map's RGB goes to --normal-map)"
        : "is grey, a height map rather than a normal map (whose RGB is a direction; --bump-map "
          "reads heights)";
      return shown;
    }
  }
  if (options.EnvironmentBackground && options.Environment.empty())
  {
    shown.Input = "--background";
    shown.Error = "environment needs --environment, the image it shows";
    return shown;
  }
  if (!options.Environment.empty())
  {
    images.Environment = decoded(options.Environment, {});
    if (!images.Environment)
    {
      return shown;
    }
  }
  // The images of the file's textures that its parts draw, each decoded once.
  const std::vector<Texture> textures = MeshTextures(loaded.Mesh);
  images.File.resize(textures.size());
  for (const ScenePart& part : SceneParts(options, loaded.Mesh))
  {
    for (const int t : { part.FileTexture, part.FileNormalTexture })
    {
      if (t >= 0 && !images.File[t])
      {
        images.File[t] = decoded(FileTextureName(options, textures, t), textures[t].Bytes);
        if (!images.File[t])
        {
          return shown;
        }
      }
    }
  }
  OwnStages stages;
  if (given)
  {
    stages = *given;
  }
  else if (auto [input, error] = ReadOwnStages(options, stages); !error.empty())
  {
    shown.Input = input;
    shown.Error = error;
    return shown;
  }
  const Key key{ options.ShadingRule, loaded.Mesh.GetPointer() };
  const auto before = this->Scenes.find(key);
  const BuiltScene* reuse = before == this->Scenes.end() ? nullptr : &before->second;
  BuiltScene scene = lights
    ? BuildActor(options, *lights, loaded.Mesh, renderer, reuse, images, stages)
    : BuildScene(options, loaded.Mesh, renderer, reuse, images, stages);
  if (!scene.Error.empty())
  {
    shown.Input = "camera";
    shown.Error = scene.Error;
    return shown;
  }
  if (reuse)
  {
    // The actors of the scene before that this one did not take over (its
    // parts grouped otherwise by their materials) are drawn no more.
    for (const DrawnParts& old : reuse->Drawn)
    {
      if (std::none_of(scene.Drawn.begin(), scene.Drawn.end(),
            [&old](const DrawnParts& drawn) { return drawn.Actor == old.Actor; }))
      {
        renderer->RemoveActor(old.Actor);
        old.Actor->ReleaseGraphicsResources(renderer->GetRenderWindow());
      }
    }
  }
  BuiltScene& kept = this->Scenes[key] = scene;
  this->Current = key;
  for (auto& [other, built] : this->Scenes)
  {
    for (DrawnParts& drawn : built.Drawn)
    {
      drawn.Actor->SetVisibility(other == key);
    }
  }
  shown.Scene = &kept;
  return shown;
}

const BuiltScene* SceneCache::GetShown() const
{
  const auto shown = this->Scenes.find(this->Current);
  return shown == this->Scenes.end() ? nullptr : &shown->second;
}

void SceneCache::ForgetOtherMeshes(const vtkPolyData* keep, vtkRenderer* renderer)
{
  for (auto it = this->Scenes.begin(); it != this->Scenes.end();)
  {
    if (it->first.second != keep)
    {
      for (DrawnParts& drawn : it->second.Drawn)
      {
        renderer->RemoveActor(drawn.Actor);
        drawn.Actor->ReleaseGraphicsResources(renderer->GetRenderWindow());
      }
      it = this->Scenes.erase(it);
    }
    else
    {
      ++it;
    }
  }
}
}
