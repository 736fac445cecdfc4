#include "shadelabGLTFTexture.h"

#include <algorithm>

#include <cmath>
#include <initializer_list>

namespace shadelab::gltf
{
namespace
{
// object[key], one of `allowed`; `fallback` where absent.
int Enum(const Json& object, const char* key, const std::string& where,
  std::initializer_list<int> allowed, int fallback)
{
  const std::uint64_t value = Unsigned(object, key, where, fallback);
  for (const int v : allowed)
  {
    if (static_cast<std::uint64_t>(v) == value)
    {
      return v;
    }
  }
  Fail(where + "." + key + " is " + std::to_string(value) + ", which glTF does not define");
}

void ReadSampler(const Json& root, const Json& texture, const std::string& where, Texture& out)
{
  if (!texture.contains("sampler"))
  {
    return;
  }
  const std::uint64_t index = Unsigned(texture, "sampler", where);
  const Json& sampler = Item(root, "samplers", index, where);
  const std::string name = "sampler " + std::to_string(index);
  const std::initializer_list<int> wraps = { gl::ClampToEdge, gl::MirroredRepeat, gl::Repeat };
  out.WrapS = Enum(sampler, "wrapS", name, wraps, gl::Repeat);
  out.WrapT = Enum(sampler, "wrapT", name, wraps, gl::Repeat);
  out.MagFilter = Enum(sampler, "magFilter", name, { gl::Nearest, gl::Linear }, gl::Linear);
  // NEAREST, LINEAR and the four mipmap filters, 9984 .. 9987.
  out.MinFilter = Enum(
    sampler, "minFilter", name, { gl::Nearest, gl::Linear, 9984, 9985, 9986, 9987 }, gl::Linear);
}

// textureInfo's KHR_texture_transform (of `where`): its map, and the
// texCoord it overrides the textureInfo's with.
UvTransform ReadTransform(const Json& info, const std::string& where, std::uint64_t& set)
{
  UvTransform map;
  if (!info.contains("extensions") || !info["extensions"].is_object() ||
    !info["extensions"].contains("KHR_texture_transform"))
  {
    return map;
  }
  const Json& extension = info["extensions"]["KHR_texture_transform"];
  const std::string at = where + " KHR_texture_transform";
  if (!extension.is_object())
  {
    Fail(at + " is not an object");
  }
  const std::vector<double> offset = Numbers(extension, "offset", at, 2, { 0, 0 });
  const std::vector<double> scale = Numbers(extension, "scale", at, 2, { 1, 1 });
  const double rotation = Number(extension, "rotation", at, 0);
  set = Unsigned(extension, "texCoord", at, static_cast<long long>(set));
  // Translation * rotation * scale, as the extension defines them, its
  // rotation (counter-clockwise, with v running down the image) the rows
  // (cos, sin) and (-sin, cos): Khronos' TextureTransformTest points its
  // arrows at "Correct" so, and at "Error" with the rotation reversed.
  const double c = std::cos(rotation), s = std::sin(rotation);
  map.U[0] = c * scale[0];
  map.U[1] = s * scale[1];
  map.U[2] = offset[0];
  map.V[0] = -s * scale[0];
  map.V[1] = c * scale[1];
  map.V[2] = offset[1];
  return map;
}
}

void MapTextureCoordinates(const UvTransform& map, float* st, std::size_t count)
{
  for (float* p = st; p < st + 2 * count; p += 2)
  {
    const double u = p[0], v = 1.0 - p[1];
    p[0] = static_cast<float>(map.U[0] * u + map.U[1] * v + map.U[2]);
    p[1] = static_cast<float>(1.0 - (map.V[0] * u + map.V[1] * v + map.V[2]));
  }
}

namespace
{
// The texture of textureInfo `info` (named `at`), as BaseColorTexture says.
int InfoTexture(const Document& document, const Json& info, const std::string& at,
  std::vector<Texture>& textures, std::string& warning, UvTransform& transform)
{
  if (!info.is_object())
  {
    Fail(at + " is not an object");
  }
  const std::uint64_t index = Unsigned(info, "index", at);
  const Json& texture = Item(document.Root, "textures", index, at);
  const std::string name = "texture " + std::to_string(index);
  std::uint64_t set = Unsigned(info, "texCoord", at, 0);
  transform = ReadTransform(info, at, set);
  if (set != 0)
  {
    warning = at + " uses TEXCOORD_" + std::to_string(set) +
      ", but only TEXCOORD_0 is read: it is not drawn";
    return -1;
  }
  if (!texture.contains("source"))
  {
    warning = name + " has no source (its image comes from an extension): it is not drawn";
    return -1;
  }
  const std::uint64_t source = Unsigned(texture, "source", name);
  Item(document.Root, "images", source, name);
  const Image& image = document.Images[source];
  Texture result;
  result.Source = image.Path;
  result.Bytes.assign(image.Bytes.begin(), image.Bytes.end());
  ReadSampler(document.Root, texture, name, result);
  return AddTexture(textures, std::move(result));
}

bool operator==(const UvTransform& a, const UvTransform& b)
{
  return std::equal(a.U, a.U + 3, b.U) && std::equal(a.V, a.V + 3, b.V);
}
}

int BaseColorTexture(const Document& document, const Json& material, const std::string& where,
  std::vector<Texture>& textures, std::string& warning, UvTransform& transform)
{
  if (!material.contains("pbrMetallicRoughness") ||
    !material["pbrMetallicRoughness"].contains("baseColorTexture"))
  {
    return -1;
  }
  return InfoTexture(document, material["pbrMetallicRoughness"]["baseColorTexture"],
    where + " baseColorTexture", textures, warning, transform);
}

int NormalTexture(const Document& document, const Json& material, const std::string& where,
  std::vector<Texture>& textures, std::string& warning, UvTransform& transform, bool mapped,
  double& scale)
{
  if (!material.contains("normalTexture"))
  {
    return -1;
  }
  const std::string at = where + " normalTexture";
  const Json& info = material["normalTexture"];
  UvTransform own;
  const int texture = InfoTexture(document, info, at, textures, warning, own);
  scale = Number(info, "scale", at, 1);
  if (texture >= 0 && mapped && !(own == transform))
  {
    warning = at +
      " maps the texture coordinates otherwise than baseColorTexture "
      "(KHR_texture_transform): it is not drawn";
    return -1;
  }
  transform = own;
  return texture;
}
}
