// Scene files: what a valid file gives, each kind of invalid one
// with its message, output templates, and the schema held to the parser.
#include "scene/scene_file.h"
#include "settings/command_line.h"
#include "vtkShadelabMeshNormals.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

using namespace shadelab;

namespace
{
class SceneFile : public testing::Test
{
protected:
  void SetUp() override
  {
    this->Folder = std::filesystem::temp_directory_path() /
      ("shadelab-scene-" + std::to_string(getpid()) + "-" +
        testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(this->Folder / "meshes");
  }
  void TearDown() override { std::filesystem::remove_all(this->Folder); }

  // Reads text as a scene file; the problem, or "" with this->Shots filled.
  std::string Read(const std::string& text, const std::string& outputTemplate = "")
  {
    const auto path = this->Folder / "scene.json";
    std::ofstream(path) << text;
    return ReadSceneFile(path.string(), outputTemplate, this->Shots);
  }

  std::filesystem::path Folder;
  std::vector<Shot> Shots;
};
}

TEST_F(SceneFile, DefaultsAndShotsMerge)
{
  ASSERT_EQ(Read(R"({
    // comments are allowed
    "mesh": "meshes/spot.obj",
    "output": "out/{mesh}_{shading}_{material}_{index}.png",
    "size": [320, 240],
    "camera": { "position": [1, 2, 3], "view_angle": 40 },
    "lights": [ { "kind": "directional", "direction": [0, 0, -1] } ],
    "shots": [
      { "shading": "flat", "material": "gold" },
      { "material": { "base": "gold", "ns": 5 }, "camera": { "view_angle": 20 } },
      { "material": { "name": "red", "ka": [0.1, 0, 0], "kd": [0.8, 0, 0], "ks": [0, 0, 0], "ns": 1 },
        "lights": [ { "kind": "spot", "position": [0, 0, 5], "direction": [0, 0, -1],
                      "half_angle": 30, "exponent": 2, "color": [1, 0.5, 0.5],
                      "attenuation": [1, 0, 0.5] },
                    { "kind": "point", "position": [1, 1, 1] } ],
        "attenuation": [0.5, 0.25, 0], "fog": "exp:0.5:0.25,0.5,1",
        "representation": "points", "point_size": 5,
        "reflection": "phong", "orient": true, "feature_angle": 30, "weighting": "max",
        "normals": "compute", "background": [0.1, 0.2, 0.3], "ambient": [0, 0, 0],
        "pixel_type": "uint16", "name": "third" }
    ] })"),
    "");
  ASSERT_EQ(this->Shots.size(), 3u);
  const std::string mesh = (this->Folder / "meshes/spot.obj").lexically_normal().string();
  for (const Shot& s : this->Shots)
  {
    EXPECT_EQ(s.Scene.Mesh, mesh) << "relative to the scene file's folder";
    EXPECT_EQ(s.Scene.Size.Width, 320);
  }
  const SceneOptions& a = this->Shots[0].Scene;
  EXPECT_EQ(this->Shots[0].Output, "out/spot_flat_gold_0.png");
  EXPECT_EQ(this->Shots[0].Label, (this->Folder / "scene.json").string() + " shots[0]");
  EXPECT_EQ(a.ShadingRule, Shading::Flat);
  EXPECT_EQ(a.CameraPosition, (Vec3{ 1, 2, 3 }));
  EXPECT_EQ(a.ViewAngle, 40);
  ASSERT_EQ(a.Lights.size(), 1u);
  EXPECT_EQ(a.Lights[0].Kind, LightKind::Directional);

  const SceneOptions& b = this->Shots[1].Scene;
  EXPECT_EQ(b.ShadingRule, Shading::Phong) << "the default, not the other shot's";
  EXPECT_EQ(b.CameraPosition, (Vec3{ 1, 2, 3 })) << "camera merged key by key";
  EXPECT_EQ(b.ViewAngle, 20);
  EXPECT_EQ(b.EffectiveMaterial().Kd, FindLectureMaterial("gold")->Kd);
  EXPECT_EQ(b.EffectiveMaterial().Ns, 5);
  EXPECT_EQ(this->Shots[1].Output, "out/spot_phong_gold-custom_1.png");

  const Shot& c = this->Shots[2];
  EXPECT_EQ(c.Output, "out/spot_phong_red_2.png");
  EXPECT_EQ(c.Scene.EffectiveMaterial().Kd, (Rgb{ 0.8, 0, 0 }));
  EXPECT_EQ(c.Scene.Attenuation, (Vec3{ 0.5, 0.25, 0 }));
  ASSERT_EQ(c.Scene.Lights.size(), 2u);
  EXPECT_EQ(c.Scene.Lights[0].Attenuation, (Vec3{ 1, 0, 0.5 })) << "the light's own";
  EXPECT_FALSE(c.Scene.Lights[1].Attenuation) << "none of its own: the scene's";
  EXPECT_EQ(a.Attenuation, NoAttenuation) << "the default: none";
  EXPECT_EQ(c.Scene.Fogging.Mode, FogMode::Exp);
  EXPECT_EQ(c.Scene.Fogging.Density, 0.5);
  EXPECT_EQ(c.Scene.Fogging.Color, (Rgb{ 0.25, 0.5, 1 }));
  EXPECT_EQ(c.Scene.Drawn, Representation::Points);
  EXPECT_EQ(c.Scene.PointSize, 5);
  EXPECT_EQ(c.Scene.LineWidth, 1) << "its default";
  EXPECT_EQ(a.Fogging.Mode, FogMode::None);
  EXPECT_EQ(c.Scene.Lights[0].Kind, LightKind::Spot);
  EXPECT_EQ(c.Scene.Lights[0].HalfAngleDeg, 30);
  EXPECT_EQ(c.Scene.Lights[0].Exponent, 2);
  EXPECT_EQ(c.Scene.Lights[0].Color, (Rgb{ 1, 0.5, 0.5 }));
  EXPECT_EQ(c.Scene.ReflectionModel, Reflection::Phong);
  EXPECT_TRUE(c.Scene.Computed.Orient);
  EXPECT_EQ(c.Scene.Computed.FeatureAngle, 30);
  EXPECT_EQ(c.Scene.Computed.Weighting, "max");
  EXPECT_EQ(c.Scene.Normals, NormalsMode::Compute);
  EXPECT_EQ(c.Scene.Background, (Rgb{ 0.1, 0.2, 0.3 }));
  EXPECT_EQ(c.Scene.Pixels, PixelType::UInt16);
}

TEST_F(SceneFile, WithoutShotsTheTopLevelIsTheShotAndOutputCanComeFromTheCommandLine)
{
  ASSERT_EQ(Read(R"({ "mesh": "/abs/cow.obj" })", "pictures/{name}-{mesh}.exr"), "");
  ASSERT_EQ(this->Shots.size(), 1u);
  EXPECT_EQ(this->Shots[0].Scene.Mesh, "/abs/cow.obj");
  EXPECT_EQ(this->Shots[0].Output, "pictures/0-cow.exr");
  EXPECT_EQ(this->Shots[0].Label, (this->Folder / "scene.json").string());
}

TEST_F(SceneFile, EachKindOfMistakeNamesItsJsonPath)
{
  const std::string head = R"({ "mesh": "m.obj", "output": "{index}.png", "shots": [ {}, {}, {}, )";
  const std::vector<std::pair<std::string, std::string>> cases{
    { R"({ "mesh": )", "not JSON: line 1, column 11: syntax error while parsing value" },
    { R"([1, 2])", "expected an object, not [1,2]" },
    // Found by fuzz_scene_file: nlohmann's parser throws out_of_range, not
    // parse_error, for a number beyond double's range.
    { R"({ "size": [7e999, 1] })", "not JSON: number overflow parsing '7e999'" },
    { R"({ "colour": [1, 0, 0] })", "colour: unknown key (known: name, mesh, output" },
    { head + R"({ "lights": [ { "kind": "laser" } ] } ] })",
      "shots[3].lights[0].kind: unknown kind \"laser\" (known: point, directional, spot)" },
    { head + R"({ "lights": [ { "kind": "point" } ] } ] })",
      "shots[3].lights[0].position: missing for a point light" },
    { head + R"({ "lights": [ { "kind": "point", "position": [0, 0], "colour": 1 } ] } ] })",
      "shots[3].lights[0].colour: unknown key" },
    { head + R"({ "lights": [ { "kind": "directional", "direction": [0, 0, 0] } ] } ] })",
      "shots[3].lights[0]: direction '0,0,0' has zero length" },
    { head +
        R"({ "lights": [ { "kind": "spot", "position": [0, 0, 1], "direction": [0, 0, -1], "half_angle": 120 } ] } ] })",
      "shots[3].lights[0]: spot half-angle '120' is outside (0, 90] degrees" },
    { head +
        R"({ "lights": [ { "kind": "directional", "direction": [0, 0, -1], "attenuation": [1, 0, 1] } ] } ] })",
      "shots[3].lights[0].attenuation: not used by a directional light" },
    { head +
        R"({ "lights": [ { "kind": "point", "position": [0, 0, 1], "attenuation": [0, 0, 0] } ] } ] })",
      "shots[3].lights[0]: attenuation '0,0,0' is all zero" },
    { head + R"({ "fog": "linear:5,1" } ] })",
      "shots[3].fog: fog END '1' is not beyond START '5'" },
    { head + R"({ "fog": 0.5 } ] })", "shots[3].fog: " },
    { head + R"({ "representation": "lines" } ] })", "shots[3].representation: " },
    { head + R"({ "line_width": 17 } ] })", "shots[3].line_width: " },
    { head + R"({ "point_size": 2.5 } ] })", "shots[3].point_size: " },
    { head + R"({ "attenuation": [1, -1, 0] } ] })",
      "shots[3].attenuation: attenuation '1,-1,0' has a negative coefficient" },
    { head + R"({ "camera": { "view_angle": 200 } } ] })",
      "shots[3].camera.view_angle: '200' is outside (0, 180) degrees" },
    { head + R"({ "camera": { "dolly": 2 } } ] })", "shots[3].camera.dolly: unknown key" },
    { head + R"({ "camera": { "view": "sideways" } } ] })",
      "shots[3].camera.view: unknown view \"sideways\" (known: front, back, left, right, top, "
      "bottom, iso)" },
    { head + R"({ "camera": { "orthographic": "yes" } } ] })",
      "shots[3].camera.orthographic: expected true or false, not \"yes\"" },
    { head + R"({ "size": [100000, 10] } ] })", "shots[3].size: '100000x10' is outside 1x1 to" },
    { head + R"({ "size": "640x480" } ] })", "shots[3].size: expected [width, height] in pixels" },
    { head + R"({ "shading": "toon" } ] })",
      "shots[3].shading: unknown shading \"toon\" (known: none, flat, gouraud, phong, raytrace)" },
    { head + R"({ "material": "silver" } ] })", "shots[3].material: unknown material \"silver\"" },
    { head + R"({ "material": { "name": "red", "kd": [1, 1, 1] } } ] })",
      "shots[3].material.name: names a whole material: \"base\", or all of ka, kd, ks, ns" },
    { head + R"({ "material": { "base": "gold", "kd": [1, -1, 1] } } ] })",
      "shots[3].material.kd: '1,-1,1' is negative" },
    { head + R"({ "ambient": [1, 2] } ] })", "shots[3].ambient: expected three numbers [x, y, z]" },
    { head + R"({ "feature_angle": 270 } ] })", "shots[3].feature_angle: " },
    { head + R"({ "output": "{colour}.png" } ] })",
      "shots[3].output: unknown field {colour} in \"{colour}.png\" (known: {index}, {material}" },
    { head + R"({ "output": "1.png" } ] })",
      "shots[3].output: \"1.png\" is also shots[1]'s output" },
    { R"({ "mesh": "m.obj", "output": "a.png", "shots": [ {}, {} ] })",
      "shots[1].output: \"a.png\" is also shots[0]'s output" },
    { R"({ "output": "a.png" })", "mesh: missing: every shot needs a mesh" },
    { R"({ "mesh": "m.obj" })", "output: missing: every shot needs an output (or give -o)" },
    { R"({ "mesh": "m.obj", "output": "a.png", "shots": [] })",
      "shots: expected a non-empty array" },
    { R"({ "mesh": "m.obj", "output": "a.png", "lights": {} })",
      "lights: expected an array of lights" },
    { R"({ "mesh": 7, "output": "a.png" })", "mesh: expected a string, not 7" },
  };
  for (const auto& [text, message] : cases)
  {
    const std::string problem = Read(text);
    EXPECT_EQ(problem.rfind(message, 0), 0u) << "scene: " << text << "\ngot: " << problem;
    EXPECT_TRUE(this->Shots.empty());
  }
  EXPECT_EQ(ReadSceneFile((this->Folder / "none.json").string(), "", this->Shots),
    "cannot open: No such file or directory");
}

TEST(OutputTemplate, FillsEveryFieldAndSaysWhatIsWrong)
{
  Shot shot;
  shot.Scene.Mesh = "/data/stanford-bunny.ply";
  shot.Scene.ShadingRule = Shading::Gouraud;
  shot.Scene.MaterialName = "gold";
  shot.Scene.Size = { 640, 480 };
  std::string out;
  ASSERT_EQ(ExpandOutputTemplate("{mesh}/{shading}-{reflection}-{material}-{weighting}-{size}-"
                                 "{index}-{name}-{{x}}.png",
              shot, "", 7, 1000, out),
    "");
  EXPECT_EQ(out, "stanford-bunny/gouraud-blinn-gold-angle-640x480-007-007-{x}.png");
  ASSERT_EQ(ExpandOutputTemplate("{name}.png", shot, "front", 7, 10, out), "");
  EXPECT_EQ(out, "front.png");
  EXPECT_EQ(ExpandOutputTemplate("{mesh.png", shot, "", 0, 1, out),
    "unmatched '{' in \"{mesh.png\" (write {{ for a brace)");
  EXPECT_EQ(ExpandOutputTemplate("mesh}.png", shot, "", 0, 1, out),
    "unmatched '}' in \"mesh}.png\" (write }} for a brace)");
}

TEST(OutputTemplate, AnOrbitMakesAFilePerFrameOrOneAnimation)
{
  Shot shot;
  shot.Scene.Mesh = "spot.obj";
  shot.Scene.Orbit = 100;
  shot.Scene.Azimuth = 10;
  std::vector<Shot> shots;
  ASSERT_EQ(ExpandShot("{mesh}/{frame}-{{frame}}.png", shot, "", 0, 1, shots), "");
  ASSERT_EQ(shots.size(), 100u);
  EXPECT_EQ(shots[0].Output, "spot/00-{frame}.png"); // as wide as 99
  EXPECT_EQ(shots[99].Output, "spot/99-{frame}.png");
  EXPECT_EQ(shots[99].Scene.Azimuth, 10 + 356.4);
  EXPECT_FALSE(shots[99].Animation);
  shots.clear();
  ASSERT_EQ(ExpandShot("{mesh}.GIF", shot, "", 0, 1, shots), "");
  ASSERT_EQ(shots.size(), 1u);
  EXPECT_EQ(shots[0].Output, "spot.GIF");
  EXPECT_TRUE(shots[0].Animation);
  EXPECT_EQ(shots[0].Scene.Azimuth, 10);
  EXPECT_EQ(ExpandShot("{mesh}.png", shot, "", 0, 1, shots),
    "\"{mesh}.png\" has no {frame} (a picture per frame of --orbit) nor the extension .gif or "
    ".mp4 (one animation of them all)");
  shot.Scene.Orbit = 0;
  EXPECT_EQ(ExpandShot("{frame}.png", shot, "", 0, 1, shots).rfind("unknown field {frame}", 0), 0u);
}

TEST(SceneSchema, ListsTheNameTablesChoices)
{
  // The schema is data, compiled in; its choices are the name tables', so
  // a value added to a table shows here until the schema has it too.
  const auto schema = nlohmann::json::parse(SceneSchema());
  const auto& shot = schema["$defs"]["shot"]["properties"];
  EXPECT_EQ(shot["shading"]["enum"].get<std::vector<std::string>>(), Names<Shading>());
  EXPECT_EQ(shot["reflection"]["enum"].get<std::vector<std::string>>(), Names<Reflection>());
  EXPECT_EQ(shot["lights"]["items"]["properties"]["kind"]["enum"].get<std::vector<std::string>>(),
    Names<LightKind>());
  EXPECT_EQ(shot["normals"]["enum"].get<std::vector<std::string>>(), Names<NormalsMode>());
  EXPECT_EQ(shot["weighting"]["enum"].get<std::vector<std::string>>(),
    Names<vtkShadelabMeshNormals::Weightings>());
  EXPECT_EQ(shot["pixel_type"]["enum"].get<std::vector<std::string>>(), Names<PixelType>());
  EXPECT_EQ(shot["up"]["enum"].get<std::vector<std::string>>(), Names<UpAxis>());
  EXPECT_EQ(shot["camera"]["properties"]["view"]["enum"].get<std::vector<std::string>>(),
    Names<ViewPreset>());
  EXPECT_EQ(
    shot["camera"]["properties"]["fit"]["enum"].get<std::vector<std::string>>(), Names<FitMode>());
  EXPECT_EQ(shot["texture_wrap"]["enum"].get<std::vector<std::string>>(), Names<TextureWrap>());
  EXPECT_EQ(shot["texture_filter"]["enum"].get<std::vector<std::string>>(), Names<TextureFilter>());
}

// --texture's keys: the image's path relative to the scene file's folder,
// as the mesh's; a wrong choice names its key.
TEST_F(SceneFile, TextureKeysAreTheTextureOptions)
{
  ASSERT_EQ(Read(R"({ "mesh": "meshes/grid.off", "output": "{index}.png",
    "texture": "images/checker.png", "texture_wrap": "clamp", "texture_filter": "nearest" })"),
    "");
  ASSERT_EQ(this->Shots.size(), 1u);
  const SceneOptions& o = this->Shots[0].Scene;
  EXPECT_EQ(o.Texture, (this->Folder / "images" / "checker.png").string());
  EXPECT_EQ(o.TextureWrapping, TextureWrap::Clamp);
  EXPECT_EQ(o.TextureFiltering, TextureFilter::Nearest);
  EXPECT_EQ(Read(R"({ "mesh": "m.off", "output": "o.png", "texture_wrap": "wobble" })"),
    "texture_wrap: unknown texture wrap \"wobble\" (known: repeat, clamp, mirror)");
}

// The example scenes read (the parser takes every key they use).
TEST(SceneFiles, TheExamplesRead)
{
  for (const auto& entry : std::filesystem::directory_iterator(SHADELAB_SOURCE_DIR "/data/scenes"))
  {
    std::vector<Shot> shots;
    EXPECT_EQ(ReadSceneFile(entry.path().string(), "", shots), "") << entry.path();
    EXPECT_FALSE(shots.empty()) << entry.path();
  }
}

// Save scene (the inspector's): the written file reads back as the same
// scene, every number to the last bit, as the options would give it.
TEST_F(SceneFile, AWrittenSceneReadsBackTheSame)
{
  SceneOptions s;
  s.Mesh = (this->Folder / "meshes" / "spot.obj").string();
  s.ShadingRule = Shading::Flat;
  s.ReflectionModel = Reflection::Phong;
  s.MaterialName = "gold";
  s.Ks = Rgb{ 0.1 + 0.2, 0, 1.0 / 3 };
  s.Ns = 1.0 / 7;
  s.Ambient = { 0.25, 1.0 / 9, 0 };
  Light spot;
  spot.Kind = LightKind::Spot;
  spot.Position = { 1.0 / 3, -2, 5 };
  spot.Direction = { 0, -1.0 / 3, -1 };
  spot.HalfAngleDeg = 12.5;
  spot.Exponent = 2.0 / 3;
  Light sun;
  sun.Kind = LightKind::Directional;
  sun.Direction = { 1, 2, 3 };
  sun.Color = { 0.5, 0.25, 1 };
  s.Lights = { spot, sun, Light{} };
  s.Size = { 321, 123 };
  s.CameraPosition = Vec3{ 3.9, 1.5, -2.2 + 1e-12 };
  s.CameraFocalPoint = Vec3{ 0.1, 0.2, 0.3 };
  s.CameraViewUp = Vec3{ 0, 0, 1 };
  s.ViewAngle = 100.0 / 3;
  s.Orthographic = true;
  s.ParallelScale = 0.7;
  s.Background = { 0.5, 0.5, 1 };
  s.Edges = true;
  s.EdgeWidth = 2.5;
  s.NormalGlyphs = true;
  s.Normals = NormalsMode::Compute;
  s.Computed.Weighting = "area";
  s.Computed.FeatureAngle = 45.5;
  s.Computed.Orient = true;
  s.Texture = (this->Folder / "meshes" / "spot.png").string();
  s.TextureWrapping = TextureWrap::Mirror;
  s.TextureFiltering = TextureFilter::Nearest;
  ASSERT_EQ(Read(WriteSceneText(s, "out.png")), "");
  ASSERT_EQ(this->Shots.size(), 1u);
  EXPECT_EQ(this->Shots[0].Output, "out.png");
  // The reader resolves a changed material whole, under a name of its own.
  SceneOptions expected = s;
  const Material m = s.EffectiveMaterial();
  expected.MaterialName = "gold-custom";
  expected.Ka = m.Ka;
  expected.Kd = m.Kd;
  expected.Ks = m.Ks;
  expected.Ns = m.Ns;
  EXPECT_EQ(SceneArguments(this->Shots[0].Scene), SceneArguments(expected));
  EXPECT_EQ(this->Shots[0].Scene.Mesh, s.Mesh);
}

// The material as written says whether it replaces the mesh's parts' own:
// none given keeps them, a named one (a table row chosen in the window, even
// the default's) replaces every part's whole, coefficients alone replace
// only themselves.
TEST_F(SceneFile, AWrittenMaterialOverridesTheMeshsMaterialsAsTheOptionsDid)
{
  SceneOptions s;
  s.Mesh = (this->Folder / "meshes" / "spot.obj").string();
  ASSERT_EQ(Read(WriteSceneText(s, "none.png")), "");
  ASSERT_EQ(this->Shots.size(), 1u);
  EXPECT_FALSE(this->Shots[0].Scene.MaterialGiven);

  s.MaterialGiven = true;
  ASSERT_EQ(Read(WriteSceneText(s, "named.png")), "");
  EXPECT_TRUE(this->Shots[0].Scene.MaterialGiven);
  EXPECT_EQ(this->Shots[0].Scene.MaterialName, "chrome");

  s.MaterialGiven = false;
  s.Kd = Rgb{ 0.25, 0.5, 1 };
  ASSERT_EQ(Read(WriteSceneText(s, "kd.png")), "");
  const SceneOptions& kd = this->Shots[0].Scene;
  EXPECT_FALSE(kd.MaterialGiven);
  EXPECT_EQ(kd.Kd, s.Kd);
  EXPECT_FALSE(kd.Ka || kd.Ks || kd.Ns);
  EXPECT_EQ(SceneArguments(kd), SceneArguments(s));
}
