#include "probe/probe_json.h"

#include "image/image_pixels.h"
#include "image/metadata.h"

namespace shadelab
{
namespace
{
using nlohmann::ordered_json;

// A light as the scene gives it and its terms at the point.
const char* SourceKind(const RayTracer::Source& s)
{
  switch (s.What)
  {
    case RayTracer::Source::Surface:
      return s.Bounce > 0 ? "reflected" : s.Through > 0 ? "transmitted" : "surface";
    case RayTracer::Source::Background:
      return "background";
    case RayTracer::Source::Fog:
      return "fog";
  }
  return "";
}

ordered_json LightJson(const PixelProbe& p, std::size_t l, const LightTerms& t)
{
  const Light& light = p.Lights[l];
  const Reflection model = p.Model;
  ordered_json j = DescribeLight(light);
  j["L"] = t.L;
  if (Attenuated(light))
  {
    // The light's C0, C1, C2 as the picture's metadata names them
    // "attenuation"; here that name is the factor they give at P.
    j["attenuation_coefficients"] = j["attenuation"];
    j.erase("attenuation");
    j["distance"] = t.Distance;
    j["attenuation"] = t.Attenuation;
  }
  if (GeometryOf(light.Kind).Cone)
  {
    j["cos_angle"] = t.SpotCos;
    j["in_cone"] = t.Reaches;
    j["spot_factor"] = t.SpotFactor;
  }
  j["Il"] = t.Il;
  j["n_dot_l"] = t.NdotL;
  if (CastsShadows(light))
  {
    j["shadowed"] = t.Shadowed;
    if (l < p.Shadows.size() && p.Shadows[l].MapRead && p.Shadows[l].Rays > 0)
    {
      j["shadow_map_agrees"] = p.Shadows[l].MapDisagrees == 0;
    }
  }
  j["lit"] = t.Lit;
  j["diffuse"] = t.DiffuseTerm;
  j[UsesHalfVector(model) ? "H" : "R"] = t.HR;
  j["base"] = t.Base;
  j["power"] = t.Power;
  j["specular"] = t.SpecularTerm;
  return j;
}

// The equation at a point: N, V, ka*Ia and each light's terms.
void AddTerms(ordered_json& j, const PixelProbe& p, const IlluminationTerms& t)
{
  j["normal"] = t.N;
  j["view"] = t.V;
  j["ambient"] = t.Ambient;
  ordered_json lights = ordered_json::array();
  for (std::size_t l = 0; l < t.Lights.size(); ++l)
  {
    lights.push_back(LightJson(p, l, t.Lights[l]));
  }
  j["lights"] = lights;
  if (t.Environment)
  {
    const EnvironmentTerm& e = *t.Environment;
    j["environment"] = { { "R", e.R }, { "direction", e.Direction }, { "texcoord", e.TexCoord },
      { "texel", e.Texel }, { "term", e.Term } };
  }
}

// A normal or bump map's perturbation (under "normal_map" or "bump_map"):
// the normal before it, the tangent frame, where the map was read and what it held (a
// height map's heights there and one texel along s and t), and the normal
// that lit.
void AddMapping(ordered_json& j, const NormalMapping& m)
{
  ordered_json& mapped = j[m.Height ? "bump_map" : "normal_map"];
  mapped = { { "normal", m.N }, { "tangent", m.T }, { "bitangent", m.B },
    { "texcoord", m.TexCoord }, { "texel", m.Texel } };
  if (m.Height)
  {
    mapped["heights"] = m.Heights;
  }
  mapped["tangent_space"] = m.TangentSpace;
  mapped["perturbed"] = m.Perturbed;
}

ordered_json VertexJson(const PixelProbe& p, int k)
{
  ordered_json v;
  v["index"] = p.Corners[k];
  v["weight"] = p.Fragment.Weights[k];
  v["position"] = p.Fragment.Positions[k];
  if (p.HasNormals)
  {
    v["mesh_normal"] = p.Fragment.Normals[k];
  }
  if (p.Fragment.VertexKd)
  {
    v["kd"] = (*p.Fragment.VertexKd)[k];
  }
  if (p.Rule == Shading::Gouraud)
  {
    const IlluminationTerms& t = p.Shaded.Vertices[k];
    v["color"] = t.Total();
    if (const auto& m = p.Shaded.VerticesMapped[k])
    {
      AddMapping(v, *m);
    }
    AddTerms(v, p, t);
  }
  return v;
}
}

ordered_json ProbeJson(const PixelProbe& p)
{
  ordered_json j;
  j["pixel"] = { p.At.X, p.At.Y };
  j["size"] = { p.Size.Width, p.Size.Height };
  j["hit"] = p.Hit;
  j["shading"] = ToString(p.Rule);
  j["reflection"] = ToString(p.Model);
  if (p.Form != SpecularForm::Stable)
  {
    j["specular_form"] = ToString(p.Form);
  }
  j["rendered"] = p.Rendered;
  j["stored"] = { static_cast<int>(Quantised(p.Rendered[0], 255)),
    static_cast<int>(Quantised(p.Rendered[1], 255)),
    static_cast<int>(Quantised(p.Rendered[2], 255)) };
  j["edge_distance"] = p.EdgeDistance;
  if (!p.Hit)
  {
    j["background"] = p.Background;
    if (p.Behind)
    {
      j["background_environment"] = { { "direction", p.Behind->R },
        { "environment_direction", p.Behind->Direction }, { "texcoord", p.Behind->TexCoord },
        { "texel", p.Behind->Texel } };
    }
    return j;
  }
  j["oracle"] = OracleOf(p);
  if (p.Traced)
  {
    // Where the ray-traced sample's light comes from: these adds sum to the
    // oracle; the rest explains the nearest surface's own light.
    auto sources = nlohmann::ordered_json::array();
    for (const RayTracer::Source& s : p.Sources)
    {
      ordered_json source = { { "kind", SourceKind(s) }, { "bounce", s.Bounce },
        { "through", s.Through } };
      if (s.What != RayTracer::Source::Background)
      {
        source["point"] = s.Point;
        source["distance"] = s.Distance;
      }
      if (s.What == RayTracer::Source::Surface)
      {
        source["triangle"] = s.Triangle;
        source["a"] = s.Opacity;
        auto shadowed = nlohmann::ordered_json::array();
        for (const LightTerms& l : s.Local.Terms.Lights)
        {
          shadowed.push_back(l.Shadowed);
        }
        source["shadowed"] = shadowed;
      }
      source["color"] = s.Color;
      source["weight"] = s.Weight;
      source["adds"] = s.Adds;
      sources.push_back(source);
    }
    j["raytrace"] = { { "reflections", p.Reflections }, { "sources", sources },
      { "coverage", p.Traced->Alpha } };
  }
  if (p.Composited)
  {
    // Nearest first, down to the first opaque one; the rest of this
    // explains the nearest, whose own colour is layers[0].color.
    auto layers = nlohmann::ordered_json::array();
    for (const PixelProbe::Layer& l : p.Layers)
    {
      layers.push_back(
        { { "triangle", l.Triangle }, { "part", l.Part }, { "front_facing", l.Front },
          { "depth", l.Depth }, { "a", l.Opacity }, { "color", l.Color }, { "adds", l.Adds } });
    }
    j["layers"] = layers;
    j["coverage"] = p.Composited->Alpha;
    if (p.Peels > 0)
    {
      j["peels"] = p.Peels;
    }
  }
  if (p.Fogged)
  {
    // oracle = factor*before + (1 - factor)*color.
    j["fog"] = { { "mode", ToString(p.Fogged->Mode) }, { "depth", p.Fogged->Depth },
      { "factor", p.Fogged->Factor }, { "color", p.Fogged->Color },
      { "before", p.Fogged->Before } };
    if (p.Fogged->Transparent)
    {
      j["fog"]["color"] = "transparent"; // the colour stays, a becomes factor*a (layers)
    }
  }
  j["triangle"] = p.Triangle;
  if (p.Element)
  {
    // The edge or point drawn here; triangle is the one that owns it.
    j["element"] = { { "representation", ToString(p.Drawn) }, { "index", p.Element->Index },
      { "points", p.Element->Points }, { "pixels", p.Element->Pixels } };
  }
  else
  {
    j["front_facing"] = p.Fragment.Front;
  }
  j["part"] = p.Part;
  j["part_name"] = p.PartName;
  j["material"] = DescribeMaterial(p.Surface);
  j["material_from"] = ToString(p.Source);
  // The kd that lit the pixel and where it came from (material or vertex
  // colours), times the texel where a texture is looked up.
  j["kd"] = p.Shaded.Kd;
  j["kd_from"] = p.VertexKd ? "vertex colors" : p.Textured ? "texture" : "material";
  if (p.Shaded.Texel)
  {
    j["texture_coordinates"] = *p.Shaded.TexCoord;
    j["texel"] = *p.Shaded.Texel;
    j["ks"] = *p.Shaded.Ks; // the texel's where it is ks's (a glTF metal's), else the material's
  }
  j["ia"] = p.Ia;
  switch (p.Rule)
  {
    case Shading::None:
      j["position"] = p.Shaded.Point;
      j["unlit"] = p.Fogged ? p.Fogged->Before : p.Shaded.Color;
      break;
    case Shading::Flat:
    case Shading::Gouraud:
    case Shading::Raytrace: // its hits are lit as phong lights a fragment
    case Shading::Phong:
      j["position"] = p.Shaded.Terms.P;
      AddTerms(j, p, p.Shaded.Terms);
      break;
  }
  if (p.Shaded.Mapped) // phong's at the fragment, flat's at the provoking vertex
  {
    AddMapping(j, *p.Shaded.Mapped);
  }
  if (p.Rule == Shading::Flat)
  {
    j["provoking_vertex"] = p.Corners[2];
    j["face_normal"] = p.Shaded.FaceNormal;
  }
  ordered_json vertices = ordered_json::array();
  for (int k = 0; k < 3; ++k)
  {
    vertices.push_back(VertexJson(p, k));
  }
  j["vertices"] = vertices;
  return j;
}
}
