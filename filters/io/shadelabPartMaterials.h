/**
 * @brief   the parts' materials and textures as field data
 *
 * What the readers of files with materials (OBJ with its MTL, glTF) add to
 * their triangle mesh (shadelabTriangleMesh.h), by the names below: per part
 * (the cell data "Part" numbers the parts) its material's name, index and
 * coefficients and the textures its kd and ka use; per texture its image
 * (a file, or the encoded bytes of an image the mesh file holds) and how it
 * is sampled (glTF's sampler, with OpenGL's enum values).
 */
#ifndef shadelabPartMaterials_h
#define shadelabPartMaterials_h

#include "shadelabIllumination.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace shadelab
{
/** Field data, one per part: its material's name (string), "" without one. */
constexpr const char* PartMaterialsArrayName = "PartMaterials";
/** Field data, one per part: its material's index in the file (int), -1 without one. */
constexpr const char* PartMaterialIndicesArrayName = "PartMaterialIndices";
/**
 * Field data, one tuple per part: its material's ka, kd, ks (3 components)
 * and ns (1) (OBJ: from its MTL; glTF: mapped from metallic-roughness,
 * shadelabGLTFMaterial.h), double as parsed, so that the picture's metadata
 * gives the file's own numbers; zeros for a part whose index is -1.
 */
constexpr const char* PartKaArrayName = "PartKa";
constexpr const char* PartKdArrayName = "PartKd";
constexpr const char* PartKsArrayName = "PartKs";
constexpr const char* PartNsArrayName = "PartNs";
/** Field data, one per part: its opacity a (MTL d or 1 - Tr, glTF alpha), 1 without a material. */
constexpr const char* PartTranslucencyArrayName = "PartTranslucency";
/**
 * Field data, one per part (int): the texture that multiplies its kd, and
 * the one that multiplies its ka, as an index into the texture arrays
 * below; -1 for none. OBJ: the MTL's map_Kd and map_Ka; glTF: both are
 * baseColorTexture (its ka is its kd).
 */
constexpr const char* PartKdTextureArrayName = "PartKdTexture";
constexpr const char* PartKaTextureArrayName = "PartKaTexture";
/**
 * Field data, one per part: the texture of its ks (int, -1 for none) and the
 * part of ks that it multiplies (3 components, double as the others, zeros
 * without): ks at a texel T is Ks + PartKsTextureScale (T - 1). glTF:
 * baseColorTexture with m B, a metal's base colour (shadelabGLTFMaterial.h);
 * a dielectric (m = 0) and OBJ have none.
 */
constexpr const char* PartKsTextureArrayName = "PartKsTexture";
constexpr const char* PartKsTextureScaleArrayName = "PartKsTextureScale";
/**
 * Field data, one per part: its tangent-space normal map (int, -1 for none)
 * and the scale of the map's x and y (double, 1 without). OBJ: the MTL's
 * norm, or bump / map_Bump (-bm the scale), whose image a grey one shows
 * to be a height map instead; glTF: normalTexture with its scale.
 */
constexpr const char* PartNormalTextureArrayName = "PartNormalTexture";
constexpr const char* PartNormalScaleArrayName = "PartNormalScale";
/**
 * Field data, one per part (int): 1 where its normal map came from a bump
 * statement (OBJ's bump or map_Bump, which may name a height map), else 0.
 */
constexpr const char* PartNormalFromBumpArrayName = "PartNormalFromBump";
/**
 * Field data, one per texture (string): its image file's path, resolved
 * against the folder of the file that names it (the MTL, the glTF), or ""
 * for an image that the mesh file holds (a GLB's bufferView, a data URI).
 * Whether the file exists is not checked here: the renderer reports it.
 */
constexpr const char* TextureSourcesArrayName = "TextureSources";
/**
 * Field data, "TextureBytes<i>" for each texture i whose source is "": the
 * image file's encoded bytes (unsigned char), as the mesh file holds them.
 */
constexpr const char* TextureBytesArrayPrefix = "TextureBytes";
/**
 * Field data, one per texture (int): wrap in s and t, magnification and
 * minification filters, as glTF's samplers give them (OpenGL's values).
 */
constexpr const char* TextureWrapSArrayName = "TextureWrapS";
constexpr const char* TextureWrapTArrayName = "TextureWrapT";
constexpr const char* TextureMagFilterArrayName = "TextureMagFilter";
constexpr const char* TextureMinFilterArrayName = "TextureMinFilter";

/** OpenGL's (and glTF's) values for wrap and filter. */
namespace gl
{
constexpr int Nearest = 9728;
constexpr int Linear = 9729;
constexpr int Repeat = 10497;
constexpr int ClampToEdge = 33071;
constexpr int MirroredRepeat = 33648;
}

/** A part's material as its file names and defines it. */
struct PartMaterial
{
  std::string Name;      // "" without one
  int Index = -1;        // in the file; -1 without one, or where the file does not define it
  Material Coefficients; // where Index >= 0
  int KdTexture = -1;    // index into the mesh's textures, -1 for none
  int KaTexture = -1;
  int KsTexture = -1;
  Rgb KsTextureScale{};        // the part of ks that KsTexture multiplies
  int NormalTexture = -1;      // its normal map, -1 for none
  double NormalScale = 1;      // the scale of the normal map's x and y
  bool NormalFromBump = false; // named by OBJ's bump or map_Bump
};

/** A texture: an image and how it is sampled. */
struct Texture
{
  std::string Source;               // the image file's path; "" when embedded
  std::vector<unsigned char> Bytes; // the encoded image, where embedded
  int WrapS = gl::Repeat;
  int WrapT = gl::Repeat;
  int MagFilter = gl::Linear;
  int MinFilter = gl::Linear;
};

/**
 * The index of `texture` in `textures`, appended unless an equal one (same
 * source, bytes and sampling) is there already: a mesh's textures are the
 * distinct ones that its parts use, in the order of first use.
 */
int AddTexture(std::vector<Texture>& textures, Texture texture);

/**
 * Adds the parts' materials to `triangles` as field data: PartMaterials,
 * PartMaterialIndices, PartKa, PartKd, PartKs, PartNs (zeros where the
 * index is -1), PartKdTexture, PartKaTexture, PartKsTexture and
 * PartKsTextureScale.
 */
void AddPartMaterials(const std::vector<PartMaterial>& parts, vtkPolyData* triangles);

/**
 * Adds the textures to `triangles` as field data: TextureSources,
 * TextureBytes<i> for the embedded ones, TextureWrapS, TextureWrapT,
 * TextureMagFilter and TextureMinFilter; nothing without textures.
 */
void AddTextures(const std::vector<Texture>& textures, vtkPolyData* triangles);

/**
 * The textures that AddTextures added to mesh, read back from its field
 * data: none without TextureSources; OpenGL's defaults (repeat, linear)
 * where a sampler array is missing or short.
 */
std::vector<Texture> MeshTextures(vtkPolyData* mesh);
}

#endif
