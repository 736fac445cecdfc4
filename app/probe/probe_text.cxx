#include "probe/probe_text.h"

#include "core/report_text.h"
#include "image/image_pixels.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace shadelab
{
std::string ProbeNumber(double value)
{
  return FormatNumber("%.6g", value);
}

std::string ProbeTriple(const std::array<double, 3>& v)
{
  return "(" + ProbeNumber(v[0]) + ", " + ProbeNumber(v[1]) + ", " + ProbeNumber(v[2]) + ")";
}

namespace
{
// The text's lines: a quantity, then what it is in a column of its own.
class Lines
{
public:
  void Add(const std::string& indent, const std::string& quantity, const std::string& what = "")
  {
    std::string line = indent + quantity;
    if (!what.empty())
    {
      line.resize(std::max<std::size_t>(line.size() + 2, 44), ' ');
      line += what;
    }
    this->Text << line << "\n";
  }
  std::string Str() const { return this->Text.str(); }

private:
  std::ostringstream Text;
};

const char* SourceText(MaterialSource source)
{
  switch (source)
  {
    case MaterialSource::File:
      return "the material is the mesh file's";
    case MaterialSource::Option:
      return "the material is the options' (--material, or all of --ka --kd --ks --ns)";
    case MaterialSource::Default:
      return "no material of its own: the default, the options'";
  }
  return "";
}

std::string LightName(const Light& l, std::size_t index)
{
  const LightGeometry g = GeometryOf(l.Kind);
  std::string name = "light " + std::to_string(index + 1) + ": " + ToString(l.Kind);
  if (g.Position)
  {
    name += " at " + ProbeTriple(l.Position);
  }
  if (g.Direction)
  {
    name += " shining along " + ProbeTriple(l.Direction);
  }
  if (g.Cone)
  {
    name +=
      ", half-angle " + ProbeNumber(l.HalfAngleDeg) + " deg, exponent " + ProbeNumber(l.Exponent);
  }
  return name + ", colour " + ProbeTriple(l.Color);
}

// Ray traced: where the sample's light comes from, each surface its rays
// met with its own light and what that adds, summing to the oracle.
void AddSources(Lines& out, const PixelProbe& p)
{
  out.Add("", "where the ray-traced light comes from:",
    "up to " + std::to_string(p.Reflections) +
      " mirror reflections, each weighted by ks; (1 - a) through a translucent surface");
  for (const RayTracer::Source& s : p.Sources)
  {
    std::string what;
    switch (s.What)
    {
      case RayTracer::Source::Surface:
      {
        what = "triangle " + std::to_string(s.Triangle) + " at distance " +
          ProbeNumber(s.Distance) + ", its own I = " + ProbeTriple(s.Color);
        for (std::size_t l = 0; l < s.Local.Terms.Lights.size(); ++l)
        {
          if (s.Local.Terms.Lights[l].Shadowed)
          {
            what += ", light " + std::to_string(l + 1) + " in shadow";
          }
        }
        break;
      }
      case RayTracer::Source::Background:
        what = "the background " + ProbeTriple(s.Color) + ", met by nothing";
        break;
      case RayTracer::Source::Fog:
        what = "the fog's colour " + ProbeTriple(s.Color);
        break;
    }
    const std::string path =
      s.Bounce == 0 ? "the camera's ray" : "reflection " + std::to_string(s.Bounce);
    out.Add("  ",
      path + (s.Through > 0 ? ", through " + std::to_string(s.Through) : "") + ": " + what +
        ", times " + ProbeTriple(s.Weight) + " adds " + ProbeTriple(s.Adds));
  }
  out.Add("",
    "sum = " + ProbeTriple(p.Traced->Color) + ", coverage " + ProbeNumber(p.Traced->Alpha),
    "the oracle");
}

// Translucency: each surface under the pixel centre with its a and I, and
// their composite in depth order, the oracle.
void AddLayers(Lines& out, const PixelProbe& p)
{
  out.Add("", "layers under the pixel centre, nearest first:",
    "each composited as a*I + (1-a)*behind, from the farthest");
  for (std::size_t k = 0; k < p.Layers.size(); ++k)
  {
    const PixelProbe::Layer& l = p.Layers[k];
    out.Add("  ",
      std::to_string(k + 1) + ": triangle " + std::to_string(l.Triangle) + " (part " +
        std::to_string(l.Part) + (l.Front ? "" : ", back face") + ") at depth " +
        ProbeNumber(l.Depth) + ", a = " + ProbeNumber(l.Opacity) + ", I = " + ProbeTriple(l.Color) +
        ", adds " + ProbeTriple(l.Adds),
      l.Opacity >= 1 ? "opaque: what lies behind"
        : l.LeftOut  ? "beyond --peels: left out"
                     : "");
  }
  const Covered& c = *p.Composited;
  out.Add("", "composited = " + ProbeTriple(c.Color) + ", coverage " + ProbeNumber(c.Alpha),
    "the oracle");
}

// One light's terms: L, the spot's cone, N.L and the diffuse term, H or R,
// the base and its power, the specular term.
void AddLight(Lines& out, const std::string& indent, const PixelProbe& p, std::size_t index,
  const LightTerms& t)
{
  const Light& light = p.Lights[index];
  const bool blinn = UsesHalfVector(p.Model);
  const LightGeometry g = GeometryOf(light.Kind);
  out.Add(indent, LightName(light, index));
  const std::string in = indent + "  ";
  out.Add(in, "L = " + ProbeTriple(t.L),
    g.Position ? "normalize(light - P)" : "minus the direction it shines along");
  if (Attenuated(light))
  {
    const Vec3& c = *light.Attenuation;
    out.Add(in, "d = " + ProbeNumber(t.Distance), "|light - P|");
    out.Add(in, "attenuation = " + ProbeNumber(t.Attenuation),
      "1 / (" + ProbeNumber(c[0]) + " + " + ProbeNumber(c[1]) + "*d + " + ProbeNumber(c[2]) +
        "*d^2)");
  }
  if (g.Cone)
  {
    out.Add(in, "cos angle = " + ProbeNumber(t.SpotCos),
      t.Reaches ? "inside the cone (cos half-angle " +
          ProbeNumber(std::cos(light.HalfAngleDeg * 3.14159265358979323846 / 180)) + ")"
                : "outside the cone: no light");
    out.Add(in, "spot factor = " + ProbeNumber(t.SpotFactor), "(cos angle)^e, 1 for e = 0");
  }
  out.Add(in, "Il = " + ProbeTriple(t.Il),
    Attenuated(light) ? "the light's colour reaching P, times the attenuation"
                      : "the light's colour reaching P");
  out.Add(in, "N.L = " + ProbeNumber(t.NdotL),
    !t.Reaches      ? "the light does not reach P: no diffuse, no specular"
      : t.Lit       ? "> 0: lit"
      : t.Shadowed  ? "> 0, but in shadow: no diffuse, no specular"
      : t.NdotL > 0 ? "not above 1e-5, taken as 0: no diffuse, no specular"
                    : "<= 0: no diffuse, no specular");
  if (CastsShadows(light))
  {
    const PixelProbe::ShadowCheck check =
      index < p.Shadows.size() ? p.Shadows[index] : PixelProbe::ShadowCheck{};
    out.Add(in, std::string("shadowed = ") + (t.Shadowed ? "yes" : "no"),
      check.Rays == 0 ? "no shadow ray: the light adds nothing here anyway"
        : t.Shadowed  ? "the shadow ray towards the light meets the mesh"
                      : "the shadow ray reaches the light");
    if (check.MapRead && check.Rays > 0)
    {
      out.Add(in, std::string("shadow map ") + (check.MapDisagrees == 0 ? "agrees" : "disagrees"),
        check.MapDisagrees == 0
          ? "the picture's shadow map decides as the ray does"
          : "the picture's shadow map decides otherwise at " + std::to_string(check.MapDisagrees) +
            " of the " + std::to_string(check.Rays) + " points lit: the picture differs here");
    }
  }
  out.Add(in, "kd*Il*(N.L) = " + ProbeTriple(t.DiffuseTerm), ToString(Terms::Diffuse));
  const std::string base = blinn ? "N.H" : "V.R";
  out.Add(
    in, (blinn ? "H = " : "R = ") + ProbeTriple(t.HR), blinn ? "normalize(L + V)" : "2(N.L)N - L");
  const bool undefinedH = blinn && t.HR == Vec3{ 0, 0, 0 };
  out.Add(in, base + " = " + ProbeNumber(t.Base),
    t.Specular     ? "the specular base, > 0"
      : !t.Lit     ? "no specular where there is no diffuse"
      : undefinedH ? "H undefined (L = -V): no specular"
                   : "<= 0: no specular");
  out.Add(in, "(" + base + ")^ns = " + ProbeNumber(t.Power), "ns = " + ProbeNumber(p.Surface.Ns));
  out.Add(
    in, "ks*Il*(" + base + ")^ns = " + ProbeTriple(t.SpecularTerm), ToString(Terms::Specular));
}

// The equation at a point: N, V, ka*Ia, the lights.
void AddTerms(Lines& out, const std::string& indent, const PixelProbe& p,
  const IlluminationTerms& t, const std::string& whatN)
{
  out.Add(indent, "N = " + ProbeTriple(t.N), whatN);
  out.Add(indent, "V = " + ProbeTriple(t.V),
    p.Orthographic ? "towards the viewer: minus the view direction" : "normalize(eye - P)");
  out.Add(indent, "ka*Ia = " + ProbeTriple(t.Ambient), ToString(Terms::Ambient));
  for (std::size_t l = 0; l < t.Lights.size(); ++l)
  {
    AddLight(out, indent, p, l, t.Lights[l]);
  }
  if (t.Environment)
  {
    const EnvironmentTerm& e = *t.Environment;
    out.Add(indent, "environment");
    const std::string in = indent + "  ";
    out.Add(in, "R = " + ProbeTriple(e.R), "2(N.V)N - V, what the mirror direction sees");
    out.Add(in, "direction = " + ProbeTriple(e.Direction), "R in the environment's frame, y up");
    out.Add(in, "(s, t) = (" + ProbeNumber(e.TexCoord[0]) + ", " + ProbeNumber(e.TexCoord[1]) + ")",
      "(0.5 + atan2(x, -z)/2pi, 0.5 + asin(y)/pi)");
    out.Add(in, "E(R) = " + ProbeTriple(e.Texel), "the environment's texel there");
    out.Add(in, "ks*E(R) = " + ProbeTriple(e.Term), "environment");
  }
}

// A normal or bump map's perturbation of the normal the rule took (`where`).
void AddMapping(
  Lines& out, const std::string& indent, const NormalMapping& m, const std::string& where)
{
  const std::string in = indent + "  ";
  out.Add(indent, m.Height ? "bump map" : "normal map", where);
  out.Add(in, "N = " + ProbeTriple(m.N), "the normal the rule takes, unit, before the map");
  out.Add(in, "T = " + ProbeTriple(m.T), "the tangent (along s) made orthogonal to N");
  out.Add(in, "B = " + ProbeTriple(m.B), "w N x T, w the tangent's handedness");
  out.Add(in,
    "texel = " + ProbeTriple(m.Texel) + " at (s, t) = (" + ProbeNumber(m.TexCoord[0]) + ", " +
      ProbeNumber(m.TexCoord[1]) + ")",
    "the map there, as stored");
  if (m.Height)
  {
    out.Add(in,
      "h = " + ProbeNumber(m.Heights[0]) + ", h_s = " + ProbeNumber(m.Heights[1]) +
        ", h_t = " + ProbeNumber(m.Heights[2]),
      "the height (r) there, one texel along s, one along t");
    out.Add(
      in, "(x, y, z) = " + ProbeTriple(m.TangentSpace), "(-scale (h_s-h), -scale (h_t-h), 1)");
  }
  else
  {
    out.Add(in, "(x, y, z) = " + ProbeTriple(m.TangentSpace), "(scale (2r-1), scale (2g-1), 2b-1)");
  }
  out.Add(in, "N' = " + ProbeTriple(m.Perturbed), "normalize(x T + y B + z N): what lights");
}

std::string Point(vtkIdType id)
{
  return "point " + std::to_string(id);
}

// What phong lit with: the interpolated normal, unless it was too short.
std::string PhongNormal(const PixelProbe& p)
{
  if (p.Shaded.FaceNormalFallback)
  {
    return "the face normal, towards the viewer: w0*N0 + w1*N1 + w2*N2 is too short";
  }
  return std::string(p.Shaded.Mapped ? "N', normalize(w0*N0 + w1*N1 + w2*N2) perturbed by the map"
                                     : "normalize(w0*N0 + w1*N1 + w2*N2)") +
    (p.Fragment.Front ? "" : ", flipped: a back face");
}
}

std::string ProbeText(const PixelProbe& p)
{
  Lines out;
  const std::string pixel = "pixel (" + std::to_string(p.At.X) + ", " + std::to_string(p.At.Y) +
    ") of the " + std::to_string(p.Size.Width) + "x" + std::to_string(p.Size.Height) + " picture";
  const std::string rendered = "rendered = " + ProbeTriple(p.Rendered);
  const std::string stored = "stored = (" + ProbeNumber(Quantised(p.Rendered[0], 255)) + ", " +
    ProbeNumber(Quantised(p.Rendered[1], 255)) + ", " + ProbeNumber(Quantised(p.Rendered[2], 255)) +
    ")";
  if (!p.Hit)
  {
    out.Add("",
      pixel +
        (p.Drawn != Representation::Surface ? ": no edge or point drawn there, "
                                            : ": no triangle under its centre, the nearest edge ") +
        ProbeNumber(p.EdgeDistance) + " px away");
    if (p.Behind)
    {
      out.Add("", "background: the environment", "along the ray through the pixel's centre");
      out.Add("  ", "d = " + ProbeTriple(p.Behind->R), "the ray's direction, unit");
      out.Add(
        "  ", "(x, y, z) = " + ProbeTriple(p.Behind->Direction), "d in the environment's frame");
      out.Add("  ",
        "(s, t) = (" + ProbeNumber(p.Behind->TexCoord[0]) + ", " +
          ProbeNumber(p.Behind->TexCoord[1]) + ")",
        "(0.5 + atan2(x, -z)/2pi, 0.5 + asin(y)/pi)");
      out.Add("  ", "E(d) = " + ProbeTriple(p.Behind->Texel), "the environment's texel there");
    }
    out.Add("", "background = " + ProbeTriple(p.Background));
    out.Add("", rendered, p.RenderedFrom);
    out.Add("", stored, "round(255*clamp(rendered, 0, 1)), as 8-bit files store it");
    return out.Str();
  }
  const Material& m = p.Surface;
  const std::string corners = std::to_string(p.Corners[0]) + ", " + std::to_string(p.Corners[1]) +
    ", " + std::to_string(p.Corners[2]);
  if (p.Element)
  {
    const bool point = p.Drawn == Representation::Points;
    out.Add("",
      pixel + ": " +
        (point ? "point " + std::to_string(p.Element->Points[0])
               : "edge " + std::to_string(p.Element->Points[0]) + "-" +
              std::to_string(p.Element->Points[1])) +
        " of triangle " + std::to_string(p.Triangle) + " (turned: points " + corners + "), " +
        ProbeNumber(p.EdgeDistance) + " px from where its coverage may change",
      point ? "a square " + std::to_string(p.Element->Pixels) + " px on a side, lit at the point"
            : "a line " + std::to_string(p.Element->Pixels) +
          " px wide, at its step along the major axis; its normal turned towards the viewer");
  }
  else
  {
    out.Add("",
      pixel + ": triangle " + std::to_string(p.Triangle) + " (points " + corners + "), " +
        (p.Fragment.Front ? "front" : "back") + " face, " + ProbeNumber(p.EdgeDistance) +
        " px from an edge that may cover it");
  }
  out.Add("",
    std::string("shading ") + ToString(p.Rule) + ", reflection " +
      (UsesHalfVector(p.Model) ? "Blinn-Phong" : "Phong") +
      (p.Form == SpecularForm::Literal ? " written literally (pow of the clamped base)" : "") +
      "; material " + m.Name + ": ka " + ProbeTriple(m.Ka) + ", kd " + ProbeTriple(m.Kd) + ", ks " +
      ProbeTriple(m.Ks) + ", ns " + ProbeNumber(m.Ns) + "; Ia " + ProbeTriple(p.Ia));
  out.Add("", "part " + std::to_string(p.Part) + " \"" + p.PartName + "\"", SourceText(p.Source));
  if (p.VertexKd)
  {
    out.Add("", "kd = " + ProbeTriple(p.Shaded.Kd),
      p.Rule == Shading::Flat ? "the provoking vertex's colour, not the material's"
                              : "the vertex colours mixed by the weights, not the material's");
  }
  if (p.Shaded.Texel)
  {
    const auto& st = *p.Shaded.TexCoord;
    out.Add("",
      "texel = " + ProbeTriple(*p.Shaded.Texel) + " at (s, t) = (" + ProbeNumber(st[0]) + ", " +
        ProbeNumber(st[1]) + "); kd = " + ProbeTriple(p.Shaded.Kd) +
        "; ks = " + ProbeTriple(*p.Shaded.Ks),
      "kd and ka are the material's times the texel, looked up per fragment; ks too for a "
      "glTF metal (ks + m B (texel - 1))");
  }
  out.Add("", "weights = " + ProbeTriple(p.Fragment.Weights),
    "barycentric, perspective-correct, of the triangle's vertices");
  const IlluminationTerms& t = p.Shaded.Terms;
  std::string oracle =
    std::string("I = ka*Ia + sum of the lights' terms") + (t.Environment ? " + ks*E(R)" : "");
  switch (p.Rule)
  {
    case Shading::None:
      out.Add("", "P = " + ProbeTriple(p.Shaded.Point), "the surface point under the pixel centre");
      oracle = "I = kd, no illumination";
      break;
    case Shading::Flat:
      out.Add("", "P = P2 = " + ProbeTriple(t.P),
        "the provoking vertex: the triangle's last, " + Point(p.Corners[2]));
      if (p.Shaded.Mapped)
      {
        AddMapping(out, "", *p.Shaded.Mapped, "at the provoking vertex");
      }
      AddTerms(out, "", p, t,
        std::string(p.Shaded.Mapped ? "N', the face normal perturbed by the map"
                                    : "the face normal normalize((P1 - P0) x (P2 - P0))") +
          (p.Fragment.Front ? "" : ", flipped: a back face"));
      break;
    case Shading::Gouraud:
      out.Add("", "P = " + ProbeTriple(p.Shaded.Point), "the surface point under the pixel centre");
      for (int k = 0; k < 3; ++k)
      {
        const IlluminationTerms& v = p.Shaded.Vertices[k];
        out.Add("",
          "vertex " + std::to_string(k) + " (" + Point(p.Corners[k]) + "), weight " +
            ProbeNumber(p.Fragment.Weights[k]) + ": the equation there");
        out.Add("  ", "P" + std::to_string(k) + " = " + ProbeTriple(v.P));
        const auto& mapped = p.Shaded.VerticesMapped[k];
        if (mapped)
        {
          AddMapping(out, "  ", *mapped, "at the vertex");
        }
        AddTerms(out, "  ", p, v,
          std::string(
            mapped ? "N', its vertex normal perturbed by the map" : "its vertex normal, unit") +
            (p.Fragment.Front ? "" : ", flipped"));
        out.Add(
          "  ", "C" + std::to_string(k) + " = " + ProbeTriple(v.Total()), "the vertex's colour");
      }
      oracle = "I = w0*C0 + w1*C1 + w2*C2";
      break;
    case Shading::Raytrace: // its hits are lit as phong lights a fragment
    case Shading::Phong:
      out.Add("", "P = " + ProbeTriple(t.P), "the surface point under the pixel centre");
      if (p.Shaded.Mapped)
      {
        AddMapping(out, "", *p.Shaded.Mapped, "at the fragment, N the interpolated normal");
      }
      AddTerms(out, "", p, t, PhongNormal(p));
      break;
  }
  if (p.Fogged)
  {
    const FogAt& fog = *p.Fogged;
    out.Add("", oracle + " = " + ProbeTriple(fog.Before), "before the fog");
    out.Add("", "d = " + ProbeNumber(fog.Depth), "the depth along the view direction, for the fog");
    out.Add("", "f = " + ProbeNumber(fog.Factor),
      std::string("the ") + ToString(fog.Mode) + " fog's factor at d");
    if (fog.Transparent)
    {
      out.Add("", "I = " + ProbeTriple(p.Shaded.Color),
        "towards the transparent background the colour stays and a becomes f*a");
    }
    else
    {
      out.Add("", "f*I + (1-f)*" + ProbeTriple(fog.Color) + " = " + ProbeTriple(p.Shaded.Color),
        p.Composited ? "fogged" : "the oracle, fogged");
    }
  }
  else
  {
    out.Add("", oracle + " = " + ProbeTriple(p.Shaded.Color),
      p.Composited || p.Traced ? "the nearest surface's colour" : "the oracle");
  }
  if (p.Composited)
  {
    AddLayers(out, p);
  }
  if (p.Traced)
  {
    AddSources(out, p);
  }
  out.Add("", rendered, p.RenderedFrom);
  out.Add("", stored, "round(255*clamp(rendered, 0, 1)), as 8-bit files store it");
  return out.Str();
}

std::optional<Terms> ProbeTextTerm(const std::string& line)
{
  for (const Terms term : { Terms::Ambient, Terms::Diffuse, Terms::Specular })
  {
    // A term's line ends with its name (comparison_panels.h's ToString).
    const std::string note = std::string("  ") + ToString(term);
    if (line.size() >= note.size() &&
      line.compare(line.size() - note.size(), note.size(), note) == 0)
    {
      return term;
    }
  }
  return std::nullopt;
}
}
