// Many meshes in one process: `shadelab render A.obj B.obj -o 'thumbs/{mesh}.png'`,
// folders and globs; each picture is the one a render of that mesh alone gives.
#include "cli_test_support.h"

#include <gtest/gtest.h>

using namespace shadelab_test;

TEST(ManyMeshes, EachPictureIsTheOneItsMeshAloneGives)
{
  TempDir dir;
  const RunResult r =
    RunShadelab({ "render", TestMesh("teapot.obj").string(), TestMesh("torus.obj").string(), "-o",
      (dir / "thumbs" / "{mesh}.png").string(), "--size", "96x72", "--material", "gold" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  EXPECT_EQ(r.Stderr, "");
  for (const std::string mesh : { "teapot", "torus" })
  {
    SCOPED_TRACE(mesh);
    ASSERT_EQ(RunShadelab(
                { "render", TestMesh(mesh + ".obj").string(), "-o",
                  (dir / (mesh + "-alone.png")).string(), "--size", "96x72", "--material", "gold" })
                .ExitCode,
      0);
    const Image many = ReadImage(dir / "thumbs" / (mesh + ".png"));
    ASSERT_EQ(many.Width, 96);
    EXPECT_EQ(many.Pixels, ReadImage(dir / (mesh + "-alone.png")).Pixels);
  }
}

TEST(ManyMeshes, FoldersAndGlobsNameTheirMeshFiles)
{
  TempDir meshes, out;
  for (const std::string name : { "b.obj", "a.stl" })
  {
    std::filesystem::copy_file(
      TestMesh(name == "b.obj" ? "torus.obj" : "teapot.stl"), meshes / name);
  }
  WriteText(meshes / "notes.txt", "not a mesh");
  ASSERT_EQ(RunShadelab({ "render", meshes.path().string(), "-o",
                          (out / "folder" / "{index}-{mesh}.png").string(), "--size", "32x32" })
              .ExitCode,
    0);
  EXPECT_EQ(FilesIn(out / "folder"), (std::vector<std::string>{ "0-a.png", "1-b.png" }));
  ASSERT_EQ(RunShadelab({ "render", (meshes / "*.obj").string(), "-o",
                          (out / "glob" / "{mesh}.png").string(), "--size", "32x32" })
              .ExitCode,
    0);
  EXPECT_EQ(FilesIn(out / "glob"), (std::vector<std::string>{ "b.png" }));
}

TEST(ManyMeshes, MistakesAreOneLineErrors)
{
  TempDir dir;
  std::filesystem::create_directory(dir / "empty");
  const std::string teapot = TestMesh("teapot.obj").string(),
                    torus = TestMesh("torus.obj").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
    { { teapot, torus, "-o", (dir / "one.png").string() },
      "shadelab: error: --output: \"" + (dir / "one.png").string() + "\" is the output of " +
        teapot + " and " + torus + ": name each mesh's, as with {mesh} or {index}\n" },
    { { (dir / "empty").string(), "-o", (dir / "{mesh}.png").string() },
      "shadelab: error: " + (dir / "empty").string() +
        ": no mesh files in the folder (known: .obj .ply .stl .off .gltf .glb .vtp .vtk)\n" },
    { { (dir / "*.ply").string(), "-o", (dir / "{mesh}.png").string() },
      "shadelab: error: " + (dir / "*.ply").string() + ": matches no file\n" },
  };
  for (const auto& [args, message] : cases)
  {
    std::vector<std::string> words{ "render" };
    words.insert(words.end(), args.begin(), args.end());
    const RunResult r = RunShadelab(words);
    EXPECT_NE(r.ExitCode, 0);
    EXPECT_EQ(r.Stderr, message);
  }
  EXPECT_EQ(dir.Files(), std::vector<std::string>{ "empty" });
}
