// The bytes that bring an assimp mesh back from the reading process: every
// field there is through and back, and every cut refused.
#include "shadelabAssimpMeshBytes.h"
#include "shadelabMeshReadError.h"

#include <gtest/gtest.h>

namespace
{
// Every field there is, non-default, and every prefix cut short.
TEST(AssimpMeshBytes, DecodeGivesBackWhatEncodeTookAndRefusesAnyCut)
{
  shadelab::AssimpMesh mesh;
  shadelab::PolygonMesh& m = mesh.Mesh;
  m.Points = { 0, 1, 2, 3, 4, 5.5 };
  m.FloatPoints = true;
  m.Normals = { 0, 0, 1, 0, 1, 0 };
  m.Colors = { 1, 0, 0, 1, 0, 1, 0, 0.5 };
  m.TextureCoordinates = { 0.25, 0.75, 1, 0 };
  m.FileVertices = { 7, 8 };
  m.FaceOffsets = { 0, 3 };
  m.FaceIds = { 0, 1, 0 };
  m.StripOffsets = { 0, 3 };
  m.StripIds = { 1, 0, 1 };
  m.Parts = { 0, 1 };
  shadelab::PartMaterial part;
  part.Name = "red";
  part.Index = 3;
  part.Coefficients = { "red", { 0.1, 0.2, 0.3 }, { 1, 0, 0 }, { 0.5, 0.5, 0.5 }, 20, 0.75 };
  part.KdTexture = 0;
  part.KaTexture = 1;
  part.KsTexture = 0;
  part.KsTextureScale = { 0.25, 0.5, 1 };
  mesh.Parts = { part, shadelab::PartMaterial() };
  shadelab::Texture file, embedded;
  file.Source = "/a/b.png";
  file.WrapS = shadelab::gl::ClampToEdge;
  embedded.Bytes = { 0x89, 'P', 'N', 'G', 0 };
  embedded.MinFilter = shadelab::gl::Nearest;
  mesh.Textures = { file, embedded };
  mesh.Warnings = { "one", "" };

  const std::string bytes = shadelab::EncodeAssimpMesh(mesh);
  const shadelab::AssimpMesh back = shadelab::DecodeAssimpMesh(bytes);
  EXPECT_EQ(back.Mesh.Points, m.Points);
  EXPECT_EQ(back.Mesh.FloatPoints, m.FloatPoints);
  EXPECT_EQ(back.Mesh.Normals, m.Normals);
  EXPECT_EQ(back.Mesh.Colors, m.Colors);
  EXPECT_EQ(back.Mesh.TextureCoordinates, m.TextureCoordinates);
  EXPECT_EQ(back.Mesh.FileVertices, m.FileVertices);
  EXPECT_EQ(back.Mesh.FaceOffsets, m.FaceOffsets);
  EXPECT_EQ(back.Mesh.FaceIds, m.FaceIds);
  EXPECT_EQ(back.Mesh.StripOffsets, m.StripOffsets);
  EXPECT_EQ(back.Mesh.StripIds, m.StripIds);
  EXPECT_EQ(back.Mesh.Parts, m.Parts);
  ASSERT_EQ(back.Parts.size(), 2u);
  const shadelab::PartMaterial& p = back.Parts[0];
  EXPECT_EQ(p.Name, "red");
  EXPECT_EQ(p.Index, 3);
  EXPECT_EQ(p.Coefficients.Name, "red");
  EXPECT_EQ(p.Coefficients.Ka, part.Coefficients.Ka);
  EXPECT_EQ(p.Coefficients.Kd, part.Coefficients.Kd);
  EXPECT_EQ(p.Coefficients.Ks, part.Coefficients.Ks);
  EXPECT_EQ(p.Coefficients.Ns, 20);
  EXPECT_EQ(p.Coefficients.Translucency, 0.75);
  EXPECT_EQ(p.KdTexture, 0);
  EXPECT_EQ(p.KaTexture, 1);
  EXPECT_EQ(p.KsTexture, 0);
  EXPECT_EQ(p.KsTextureScale, part.KsTextureScale);
  EXPECT_EQ(back.Parts[1].Index, -1);
  ASSERT_EQ(back.Textures.size(), 2u);
  EXPECT_EQ(back.Textures[0].Source, "/a/b.png");
  EXPECT_EQ(back.Textures[0].WrapS, shadelab::gl::ClampToEdge);
  EXPECT_EQ(back.Textures[1].Bytes, embedded.Bytes);
  EXPECT_EQ(back.Textures[1].MinFilter, shadelab::gl::Nearest);
  EXPECT_EQ(back.Warnings, mesh.Warnings);

  for (size_t size = 0; size < bytes.size(); ++size)
  {
    EXPECT_THROW(shadelab::DecodeAssimpMesh(bytes.substr(0, size)), shadelab::MeshReadError)
      << size << " of " << bytes.size() << " bytes";
  }
  EXPECT_THROW(shadelab::DecodeAssimpMesh(bytes + '\0'), shadelab::MeshReadError);
}
}
