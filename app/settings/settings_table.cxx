// The table of settings: each setting once, with its option, its scene-file
// key, its kind (which says its type, range or choices), its help and the
// commands that take it. The command lines, the scene files' reader and
// writer, Copy command, the JSON Schema and the option reference all come
// from it. The order is the help's and the scene files' keys'.
//
// A plain setting is one Plain entry and the code that uses its value.
#include "settings/setting_kinds.h"
#include "settings/special_settings.h"
#include "vtkShadelabMeshNormals.h"

namespace shadelab
{
namespace
{
using namespace settings;

// The member of a SceneOptions that a setting keeps its value in, as a
// function pointer: Plain is then compiled once per kind and value type,
// not once per setting (a lambda's type each time): 32 s of compiling, not 45.
#define SHADELAB_FIELD(member)                                                                     \
  +[](SceneOptions & o) -> auto&                                                                   \
  {                                                                                                \
    return o.member;                                                                               \
  }

// The commands that draw with a rule's shaders (probe explains the generated ones).
constexpr CommandSet StageCommands = Of(Command::Render) | Of(Command::Compare) |
  Of(Command::View) | Of(Command::CheckShader) | Of(Command::Profile);
constexpr CommandSet ComputedNormals = PictureCommands | Of(Command::Normals) | Of(Command::Advise);

std::vector<Setting> MakeSettings()
{
  const Triple point{ Triple::Point }, direction{ Triple::Direction }, colour{ Triple::Colour };
  return {
    TextKey("name", "The shot's name, for {name} in output"),
    Plain({ "", "mesh", "", MeshFileHelp(), 0, "", true }, File{}, SHADELAB_FIELD(Mesh)),
    TextKey("output",
      "Image file; a template of {mesh} {shading} {reflection} {material} {weighting} {size} "
      "{index} {name}, and {frame} with orbit; {{ and }} are braces"),
    Plain({ "--shading", "shading", "", "Shading rule" }, Choice<Shading>{ "shading" },
      SHADELAB_FIELD(ShadingRule)),
    Plain({ "--reflection", "reflection", "", "Specular term" }, Choice<Reflection>{ "reflection" },
      SHADELAB_FIELD(ReflectionModel)),
    MaterialSetting(),
    ReadByParent(
      Plain({ "--ka", "material.ka", "R,G,B", "Ambient coefficients, overriding the material" },
        colour, SHADELAB_FIELD(Ka))),
    ReadByParent(Plain(
      { "--kd", "material.kd", "R,G,B", "Diffuse coefficients" }, colour, SHADELAB_FIELD(Kd))),
    ReadByParent(Plain(
      { "--ks", "material.ks", "R,G,B", "Specular coefficients" }, colour, SHADELAB_FIELD(Ks))),
    ReadByParent(Plain({ "--ns", "material.ns", "X", "Specular exponent" }, Number::NonNegative(),
      SHADELAB_FIELD(Ns))),
    Plain({ "--translucency", "translucency", "A",
            "Opacity a of every part, overriding its material's (MTL d, glTF alpha; 1 in the "
            "lecture's table): a surface's colour I goes over what lies behind it as a*I + "
            "(1-a)*behind, in exact depth order, every surface included",
            PictureCommands, "the material's" },
      ClosedRange{ 0, 1 }, SHADELAB_FIELD(Translucency)),
    Plain({ "--peels", "peels", "N",
            "Translucency: composite at most the N nearest layers at each pixel (depth "
            "peeling), for speed; the farther ones are left out",
            PictureCommands, "0: every layer" },
      Integer{ 0, MaxPeels }, SHADELAB_FIELD(Peels)),
    Plain({ "--texture", "texture", "IMAGE",
            "An image (any format OpenImageIO reads; its stored values, as display colours) whose "
            "texel "
            "at the mesh's texture coordinates is kd and ka, looked up per fragment under every "
            "rule (times --kd and --ka when given)" },
      File{}, SHADELAB_FIELD(Texture)),
    Plain({ "--texture-wrap", "texture_wrap", "",
            "The texture beyond [0, 1]: repeat, clamp to the edge texels, or mirror" },
      Choice<TextureWrap>{ "texture wrap" }, SHADELAB_FIELD(TextureWrapping)),
    Plain({ "--texture-filter", "texture_filter", "",
            "Texel lookup: bilinear between the four nearest texel centres, or the nearest "
            "texel; no mipmaps" },
      Choice<TextureFilter>{ "texture filter" }, SHADELAB_FIELD(TextureFiltering)),
    Plain({ "--environment", "environment", "IMAGE",
            "An equirectangular image of the surroundings (its stored values; its top row "
            "straight up along --environment-up, its middle column ahead of the front view): the "
            "surface adds "
            "ks E(R), E the image seen along R, the view vector reflected about the normal, where "
            "the rule lights; looked up with --texture-filter" },
      File{}, SHADELAB_FIELD(Environment)),
    Plain({ "--environment-up", "environment_up", "",
            "The world axis the environment's top row lies along", PictureCommands, "--up's" },
      Choice<UpAxis>{ "up axis" }, SHADELAB_FIELD(EnvironmentUp)),
    Plain({ "--normal-map", "normal_map", "IMAGE[:SCALE]",
            "A tangent-space normal map (its stored values as data: RGB in [0, 1] is the "
            "direction 2 RGB - 1 along the tangent, bitangent and normal, its x and y times "
            "SCALE, default 1, as glTF's normalTexture) at the mesh's texture coordinates: it "
            "takes the normal's place where the rule takes the normal (per fragment, per vertex, "
            "at the provoking vertex); looked up with --texture-wrap and --texture-filter; "
            "none: no normal map at all, not even the mesh file's own" },
      ScaledFile{}, SHADELAB_FIELD(NormalMap)),
    Plain({ "--bump-map", "bump_map", "IMAGE[:SCALE]",
            "A height (bump) map, grey, its stored values as data, at the mesh's texture "
            "coordinates: the normal tilts by the height's differences one texel apart along s "
            "and t (Blinn's bump, in the tangent frame), SCALE (default 1) the height of white "
            "above black in texels' widths; in --normal-map's place, where the rule takes the "
            "normal; looked up with --texture-wrap and --texture-filter" },
      ScaledFile{}, SHADELAB_FIELD(BumpMap)),
    Plain({ "--specular-form", "specular_form", "",
            "How the shaders write the specular term: stable, 1 - cos without cancellation and a "
            "power that holds up to ns = 1e6; literal, the lecture's pow(max(N.H, 0), ns) as "
            "written, which float rounds into bands at high ns" },
      Choice<SpecularForm>{ "specular form" }, SHADELAB_FIELD(Form)),
    Plain({ "--vertex-shader", "vertex_shader", "FILE",
            "The vertex stage's complete GLSL, as --dump-shaders writes it, possibly edited: it "
            "replaces the generated stage of the rule (compare: the panels of --shading's rule); "
            "the uniforms and attributes stay the generated program's",
            StageCommands, "the generated stage" },
      File{}, SHADELAB_FIELD(VertexShader)),
    Plain({ "--fragment-shader", "fragment_shader", "FILE",
            "The fragment stage's complete GLSL, as --vertex-shader's", StageCommands,
            "the generated stage" },
      File{}, SHADELAB_FIELD(FragmentShader)),
    Plain({ "--ambient", "ambient", "R,G,B", "Ambient light Ia" }, colour, SHADELAB_FIELD(Ambient)),
    LightsSetting(),
    Plain({ "--attenuation", "attenuation", "C0,C1,C2",
            "Point and spot lights fall off with the distance d from them in world units: Il / "
            "(C0 + C1*d + C2*d^2), for each light without attenuation of its own (--light's "
            "@C0,C1,C2, a scene file light's \"attenuation\")",
            PictureCommands, "1,0,0: none" },
      Triple{ Triple::Attenuation }, SHADELAB_FIELD(Attenuation)),
    Plain({ "--shadows", "shadows", "",
            "Every light casts hard shadows, unless it says otherwise (--light's +no-shadows, "
            "a scene file light's \"shadows\"): where the mesh lies between a light and a point, "
            "the light adds neither diffuse nor specular there; tested where the rule lights "
            "(per fragment, per vertex, per triangle) against shadow maps" },
      Flag{}, SHADELAB_FIELD(Shadows)),
    Plain({ "--shadow-map-size", "shadow_map_size", "N",
            "Shadows: each shadow map's side in texels (a point or spot light's cube map has six "
            "such faces, a directional light's map one); larger is sharper and slower",
            PictureCommands, "2048" },
      Integer{ 1, MaxShadowMapSize }, SHADELAB_FIELD(ShadowMapSize)),
    Plain({ "--reflections", "reflections", "N",
            "--shading raytrace: how many mirror reflections a ray follows (each weighted by the "
            "surface's ks); 0 shows none",
            PictureCommands, "2" },
      Integer{ 0, MaxReflections }, SHADELAB_FIELD(Reflections)),
    Plain({ "--fog", "fog", "MODE",
            "Fog over the surface, per fragment under every rule, d the depth along the view "
            "direction from the camera: linear:START,END (f = (END-d)/(END-START) clamped to [0, "
            "1]), exp:DENSITY (f = exp(-DENSITY*d)) or exp2:DENSITY (f = exp(-(DENSITY*d)^2)), "
            "each with :R,G,B for its colour (default the background's; a transparent background "
            "needs one); the colour C becomes f*C + (1-f)*FOG" },
      FogSpec{}, SHADELAB_FIELD(Fogging)),
    Plain({ "--representation", "representation", "",
            "Draw the surface, or its edges (wireframe) or its points, each once, lit by the same "
            "rule and equation with the normal turned towards the viewer; flat lights an edge "
            "or a point with the normal of the first triangle that has it" },
      Choice<Representation>{ "representation" }, SHADELAB_FIELD(Drawn)),
    Plain({ "--line-width", "line_width", "W", "Wireframe: the edges' width in whole pixels" },
      Integer{ 1, MaxLineWidth }, SHADELAB_FIELD(LineWidth)),
    Plain({ "--point-size", "point_size", "S", "Points: the squares' side in whole pixels" },
      Integer{ 1, MaxPointSize }, SHADELAB_FIELD(PointSize)),
    Plain({ "--camera-position", "camera.position", "X,Y,Z", "Camera position" }, point,
      SHADELAB_FIELD(CameraPosition)),
    Plain({ "--camera-focal-point", "camera.focal_point", "X,Y,Z", "Point the camera looks at" },
      point, SHADELAB_FIELD(CameraFocalPoint)),
    Plain({ "--camera-view-up", "camera.view_up", "X,Y,Z", "Up direction", PictureCommands,
            "--up's axis" },
      direction, SHADELAB_FIELD(CameraViewUp)),
    Plain({ "--view-angle", "camera.view_angle", "DEG",
            "Perspective camera's vertical view angle in degrees" },
      Number{ 0, 180, true, true, "degrees" }, SHADELAB_FIELD(ViewAngle)),
    Plain(
      { "--orthographic", "camera.orthographic", "", "Parallel projection instead of perspective" },
      Flag{}, SHADELAB_FIELD(Orthographic)),
    Plain({ "--parallel-scale", "camera.parallel_scale", "S",
            "Orthographic: half the view height in world units" },
      Number::Positive(), SHADELAB_FIELD(ParallelScale)),
    Plain({ "--view", "camera.view", "",
            "Where the fitted camera looks from: for up +Y front looks along -Z, for up +Z along "
            "+Y; iso from front, right and above" },
      Choice<ViewPreset>{ "view" }, SHADELAB_FIELD(View)),
    Plain({ "--azimuth", "camera.azimuth", "DEG",
            "Turn the camera by DEG about the up axis (--camera-view-up when given, else --up's) "
            "through the focal point" },
      Number{}, SHADELAB_FIELD(Azimuth)),
    Plain({ "--elevation", "camera.elevation", "DEG",
            "Then by DEG up about the horizontal through the focal point" },
      Number{}, SHADELAB_FIELD(Elevation)),
    Plain({ "--zoom", "camera.zoom", "F",
            "Magnify by F: the view angle (orthographic: the parallel scale) divided by F" },
      Number::Positive(), SHADELAB_FIELD(Zoom)),
    Plain({ "--fit", "camera.fit", "",
            "How the missing camera settings are fitted: sphere, the bounding sphere fills the "
            "view (VTK's ResetCamera); tight, the mesh's projection fills the picture" },
      Choice<FitMode>{ "fit" }, SHADELAB_FIELD(Fit)),
    Plain({ "--size", "size", "WxH", "Image size in pixels", PictureCommands, "", true }, Size{},
      SHADELAB_FIELD(Size)),
    BackgroundSetting(),
    Plain({ "--normals", "normals", "",
            "auto: the file's normals if it has them, else computed; file: the file's normals, "
            "an error where it has none; compute: always computed" },
      Choice<NormalsMode>{ "normals" }, SHADELAB_FIELD(Normals)),
    Plain({ "--weighting", "weighting", "", "Vertex-normal weighting when normals are computed",
            ComputedNormals },
      NameChoice{ Names<vtkShadelabMeshNormals::Weightings>(), "weighting" },
      SHADELAB_FIELD(Computed.Weighting)),
    Plain({ "--feature-angle", "feature_angle", "DEG",
            "Computed normals: split vertices where faces meet at more than DEG degrees",
            ComputedNormals, "no splitting" },
      ClosedRange{ 0, 180 }, SHADELAB_FIELD(Computed.FeatureAngle)),
    Plain({ "--orient", "orient", "",
            "Computed normals: make the faces' orientation consistent first", ComputedNormals },
      Flag{}, SHADELAB_FIELD(Computed.Orient)),
    Plain({ "--pixel-type", "pixel_type", "",
            "auto: float for .exr .hdr .pfm (unclamped), 8-bit otherwise", Of(Command::Render) },
      Choice<PixelType>{ "pixel type" }, SHADELAB_FIELD(Pixels)),
    Plain({ "--ssaa", "ssaa", "N",
            "Anti-aliasing: N x N samples per pixel, averaged in float before quantising; "
            "exactly the box average of the picture rendered N times as large",
            Of(Command::Render) | Of(Command::Compare) | Of(Command::Probe) },
      Integer{ 1, MaxSupersampling }, SHADELAB_FIELD(Supersampling)),
    Plain({ "--up", "up", "", "The world axis up on the screen when the camera is fitted" },
      Choice<UpAxis>{ "up axis" }, SHADELAB_FIELD(Up)),
    Plain({ "--edges", "edges", "", "The triangles' edges over the shading" }, Flag{},
      SHADELAB_FIELD(Edges)),
    Plain(
      { "--edge-color", "edge_color", "R,G,B", "Their colour" }, colour, SHADELAB_FIELD(EdgeColor)),
    Plain({ "--edge-width", "edge_width", "W", "Their width in pixels" },
      Number{ 0, 16, true, false, "pixels" }, SHADELAB_FIELD(EdgeWidth)),
    Plain({ "--normal-glyphs", "normal_glyphs", "",
            "A line along each vertex normal (those gouraud and phong use)" },
      Flag{}, SHADELAB_FIELD(NormalGlyphs)),
    Plain({ "--orbit", "orbit", "N",
            "N frames turning the camera once about the up axis through the focal point (frame "
            "k at --azimuth plus 360*k/N degrees): into a -o template with {frame}, or one .gif "
            "or .mp4 (through the ffmpeg program)",
            Of(Command::Render), "none: one picture" },
      Integer{ 1, MaxOrbitFrames }, SHADELAB_FIELD(Orbit)),
    Plain({ "--fps", "fps", "F", "An --orbit animation's frames a second; a .gif's at most 50",
            Of(Command::Render) },
      Number{ 0, MaxFramesPerSecond, true, false, "frames a second" },
      SHADELAB_FIELD(FramesPerSecond)),
    // The user's trust, from the command line only: a scene file cannot give
    // itself this.
    Plain({ "--allow-outside-references", "", "",
            "Read the files that the mesh names (MTL libraries, texture maps, glTF buffers and "
            "images) also where they lie outside the mesh's folder: for meshes you trust",
            PictureCommands | Of(Command::Normals), "refused" },
      Flag{}, SHADELAB_FIELD(AllowOutsideReferences)),
  };
}
#undef SHADELAB_FIELD
}

const std::vector<Setting>& Settings()
{
  static const std::vector<Setting> settings = MakeSettings();
  return settings;
}
}
