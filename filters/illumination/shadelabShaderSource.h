// The lecture's equation and shading rules as GLSL, generated for what a
// scene needs and nothing more (doc/design.md, "The shading rules"): the number
// and kinds of lights compiled in, no specular code when ks is zero, lighting
// in the vertex stage for Gouraud, in the fragment stage for Phong, and for
// flat in the fragment stage with one triangle's inputs (its provoking
// vertex's position, its face normal by gl_PrimitiveID). The code goes into
// VTK 9.1's polydata shaders as replacements of their tags; each GLSL
// function mirrors the function of the same name in
// shadelabShadingOracle.cxx.
#ifndef shadelabShaderSource_h
#define shadelabShaderSource_h

#include "shadelabFog.h"
#include "shadelabIllumination.h"
#include "shadelabRepresentation.h"

#include <algorithm>
#include <string>
#include <vector>

namespace shadelab
{
/** What decides the shader code (uniform values do not). */
struct ShaderFeatures
{
  Shading Rule = Shading::Phong;
  Reflection Model = Reflection::BlinnPhong;
  std::vector<LightKind> Lights;
  bool Specular = true; // false when ks is zero: no specular code at all
  // How the specular term is written: stable (1 - cos without cancellation,
  // its power by a falloff that holds up to ns = 1e6) or the lecture's
  // expressions as written, pow(max(N.H, 0), ns), for reading beside the slide.
  SpecularForm Form = SpecularForm::Stable;
  // A point or spot light falls off with distance (Attenuated): every such
  // light's Il is divided by C0 + C1*d + C2*d^2 from its uniform
  // (1, 0, 0 for those that do not, which divides exactly by 1).
  bool Attenuation = false;
  // Fog over the fragment's colour, whatever the rule: its mode's factor
  // from the fragment's depth -vertexVC.z, and the fog's colour and
  // numbers as uniforms (shadelabFog.h).
  FogMode Fog = FogMode::None;
  // Towards a transparent background (no fog colour): the factor takes
  // the fragment's alpha down instead of mixing its colour, and the
  // translucent step composites it.
  bool FogTowardsTransparent = false;
  // The surface is translucent (a < 1): the fragment's alpha is VTK's
  // opacity (the actor's property's, the material's a) rather than 1, for
  // the translucent step to composite (vtkShadelabPeelingPass).
  bool Translucent = false;
  // What is drawn: the surface, or its edges or points, whose normal is
  // turned towards the viewer (they have no facing) and, under phong, fall
  // back to ka*Ia rather than to a face normal (ShadeElementFragment).
  Representation Drawn = Representation::Surface;
  // kd per vertex, from the mesh's colours (VertexKdAttributeName): the
  // vertex that lights uses its own (gouraud; flat's provoking vertex), phong
  // and none interpolate it to the fragment.
  bool VertexKd = false;
  // kd and/or ka times a texel of the texture (TextureSamplerName) at the
  // fragment's texture coordinates (TextureCoordinateAttributeName), under
  // every rule: phong lights with the products; flat and gouraud light
  // their vertices with the factors, pass the diffuse and specular sums
  // apart, and the fragment multiplies ka*Ia and the diffuse sum by its
  // texel (shadelabTriangleFragment.h says why that is the equation).
  bool KdTexture = false;
  bool KaTexture = false;
  // ks = shadelabKsFactor + shadelabKsScale * (texel - 1) (SurfaceTexture),
  // only with Specular: phong lights with it; flat and gouraud light their
  // vertices with ks = 1 and the fragment multiplies the specular sum by it.
  bool KsTexture = false;
  // The baseline that per-scene generation is measured against: one program
  // with every light kind, specular, and both reflection models, chosen by
  // uniforms at run time, for up to AllFeaturesMaxLights lights.
  // It has no texture code.
  bool AllFeatures = false;
  // Lines are drawn over the surface (edges, normal glyphs): the surface's
  // depth goes back by VTK's polygon offset for polygons, twice the depth's
  // slope in the pixel and two units of 0.000016, so that a line lying on
  // it wins the depth test (VTK's own offset needs its global coincident
  // mode, which would change every scene's code).
  bool BehindLines = false;
  // Per light (empty: none), whether it casts shadows: the light adds its
  // terms only where its shadow map says nothing lies nearer to it
  // (shadelabShadowLit, vtkShadelabShadowMaps), tested at the point the
  // rule lights (per fragment, per vertex, at the provoking vertex). Point
  // and spot lights read a cube map, directional ones an orthographic map.
  std::vector<bool> Shadows;
  // An environment map (EnvironmentSamplerName, EnvironmentFrameName):
  // the equation adds ks * E(R) where the rule lights (shadelabEnvironment.h),
  // only with Specular (ks zero reflects nothing) and a rule that lights.
  bool Environment = false;
  // A normal map (NormalMapSamplerName, NormalScaleName) in the frame of the
  // vertices' tangents (TangentAttributeName) at the texture coordinates:
  // the normal is perturbed where the rule takes it (phong per fragment,
  // gouraud per vertex, flat at the provoking vertex), on a lit surface.
  bool NormalMap = false;
  // The normal map is a height (bump) map: its vector comes from the
  // height's differences one texel apart (shadelabNormalMap.h).
  bool BumpMap = false;

  bool Textured() const
  {
    return this->KdTexture || this->KaTexture || (this->KsTexture && this->Specular);
  }
  /**
   * The code looks a texel up (and reads the texture coordinates): a
   * texture for kd, or for ka or ks under a rule that lights; never AllFeatures.
   */
  bool ReadsTexel() const
  {
    return !this->AllFeatures && (this->Rule == Shading::None ? this->KdTexture : this->Textured());
  }
  /**
   * Phong's shadow tests take the bias's slope from the fragment's face
   * (shadelabFaceN), as the maps hold faces: at a terminator the
   * interpolated normal leans towards the light while the face turns away.
   */
  bool SlopesByFace() const
  {
    return this->Rule == Shading::Phong && this->Drawn == Representation::Surface &&
      this->CastsShadows();
  }
  /** The environment's term is compiled in. */
  bool Reflects() const
  {
    return this->Environment && this->Specular && !this->AllFeatures && this->Rule != Shading::None;
  }
  /** The normal map's code is compiled in: a lit rule drawing the surface. */
  bool MapsNormals() const
  {
    return this->NormalMap && !this->AllFeatures && this->Drawn == Representation::Surface &&
      this->Rule != Shading::None;
  }
  /** A light casts shadows. */
  bool CastsShadows() const
  {
    return std::find(this->Shadows.begin(), this->Shadows.end(), true) != this->Shadows.end();
  }
  bool operator==(const ShaderFeatures& other) const;
};

/** One replacement: in the vertex or fragment shader, Tag becomes Code. */
struct ShaderReplacement
{
  bool Vertex = false;
  std::string Tag;
  std::string Code;
};

/** Replacements applied before VTK's own substitutions (replaceFirst). */
std::vector<ShaderReplacement> GenerateShaderReplacements(const ShaderFeatures& features);

constexpr int AllFeaturesMaxLights = 8;
/**
 * The buffer texture of face normals that flat shading reads, one RGB float
 * texel a triangle by gl_PrimitiveID (filled by vtkShadelabShading).
 */
extern const char* const FaceNormalSamplerName;
/** The vertex attribute (RGBA, alpha unused) that VertexKd reads. */
extern const char* const VertexKdAttributeName;
/** The vertex attribute (s, t) and the sampler that KdTexture and KaTexture read. */
extern const char* const TextureCoordinateAttributeName;
extern const char* const TextureSamplerName;
/**
 * Light i's shadow: its map's sampler, the matrix from view coordinates to
 * the map's, and its bias (shadelabShadowMaps.h), each name followed by i.
 */
extern const char* const ShadowMapSamplerName;
extern const char* const ShadowFrameName;
extern const char* const ShadowBiasName;
/**
 * The environment's sampler (equirectangular) and the rotation from view
 * coordinates to its frame (ShaderFeatures::Environment).
 */
extern const char* const EnvironmentSamplerName;
extern const char* const EnvironmentFrameName;
/**
 * The normal map's sampler and the scale of its x and y, and the vertex
 * attribute (x, y, z, handedness) of the tangents it is read in the frame of.
 */
extern const char* const NormalMapSamplerName;
extern const char* const NormalScaleName;
extern const char* const TangentAttributeName;
/**
 * The comment that ends each generated line computing a term of the
 * equation, followed by the terms' names, comma-separated ("ambient",
 * "diffuse", "specular"): `I += Il * term; // shadelab: diffuse, specular`.
 * The window's shader panel highlights those lines.
 */
extern const char* const TermMarker;
}

#endif
