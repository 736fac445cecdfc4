#include "vtkShadelabAssimpReader.h"

#include "shadelabAssimpMeshBytes.h"
#include "shadelabAssimpScene.h"
#include "shadelabCheckedFile.h"
#include "shadelabIsolatedRead.h"
#include "shadelabMeshReadError.h"
#include "shadelabPartMaterials.h"
#include "shadelabTextScanner.h"
#include "shadelabTriangleMesh.h"

#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <set>
#include <string>
#include <utility>

vtkStandardNewMacro(vtkShadelabAssimpReader);

namespace
{
// A file's bytes, read through shadelab::OpenChecked, as assimp reads a file.
class CheckedBytesStream : public Assimp::IOStream
{
public:
  explicit CheckedBytesStream(std::shared_ptr<const std::string> bytes)
    : Bytes(std::move(bytes))
  {
  }

  size_t Read(void* buffer, size_t size, size_t count) override
  {
    if (size == 0)
    {
      return 0;
    }
    count = std::min(count, (this->Bytes->size() - this->Position) / size);
    std::memcpy(buffer, this->Bytes->data() + this->Position, size * count);
    this->Position += size * count;
    return count;
  }

  size_t Write(const void*, size_t, size_t) override { return 0; }

  aiReturn Seek(size_t offset, aiOrigin origin) override
  {
    const size_t base = origin == aiOrigin_SET ? 0
      : origin == aiOrigin_CUR                 ? this->Position
                                               : this->Bytes->size();
    if (offset > this->Bytes->size() - base)
    {
      return aiReturn_FAILURE;
    }
    this->Position = base + offset;
    return aiReturn_SUCCESS;
  }

  size_t Tell() const override { return this->Position; }
  size_t FileSize() const override { return this->Bytes->size(); }
  void Flush() override {}

private:
  std::shared_ptr<const std::string> Bytes;
  size_t Position = 0;
};

// The files that assimp opens: the mesh file as already read, and the
// files it names only where they resolve inside the mesh file's folder (or
// anywhere, when the reader allows outside references), each through
// OpenChecked; nothing is written, made, removed, nor the working folder
// changed. A refused reference is remembered as a warning.
class CheckedIOSystem : public Assimp::IOSystem
{
public:
  CheckedIOSystem(std::string meshFile, std::string bytes, bool allowOutside)
    : MeshFile(std::move(meshFile))
    , MeshBytes(std::make_shared<const std::string>(std::move(bytes)))
    , AllowOutside(allowOutside)
  {
  }

  bool Exists(const char* file) const override
  {
    try
    {
      return file == this->MeshFile || (this->Resolve(file), true);
    }
    catch (const shadelab::MeshReadError&)
    {
      return false;
    }
  }

  char getOsSeparator() const override { return '/'; }

  Assimp::IOStream* Open(const char* file, const char* mode) override
  {
    if (std::strchr(mode, 'w') || std::strchr(mode, 'a') || std::strchr(mode, '+'))
    {
      return nullptr;
    }
    if (file == this->MeshFile)
    {
      return new CheckedBytesStream(this->MeshBytes);
    }
    try
    {
      return new CheckedBytesStream(std::make_shared<const std::string>(
        vtkShadelabFileReader::ReadFileBytes(this->Resolve(file).c_str())));
    }
    catch (const shadelab::MeshReadError& e)
    {
      this->Warnings.insert("refers to " + shadelab::Quote(file) + ", which " + e.what());
      return nullptr;
    }
  }

  void Close(Assimp::IOStream* stream) override { delete stream; }

  bool CreateDirectory(const std::string&) override { return false; }
  bool ChangeDirectory(const std::string&) override { return false; }
  bool DeleteFile(const std::string&) override { return false; }

  // What Open refused, each once.
  std::set<std::string> Warnings;

private:
  // assimp names a file by the mesh file's path and the name it found.
  std::string Resolve(const char* file) const
  {
    const std::string path =
      shadelab::ResolveReference(this->MeshFile, "", file, this->AllowOutside);
    shadelab::OpenChecked(path);
    return path;
  }

  std::string MeshFile;
  std::shared_ptr<const std::string> MeshBytes;
  bool AllowOutside;
};

// assimp's error, which may run over lines and end in one: its first line.
std::string FirstLine(const char* text)
{
  std::string line = text ? text : "";
  line = line.substr(0, line.find_first_of("\r\n"));
  const auto first = line.find_first_not_of(" \t");
  const auto last = line.find_last_not_of(" \t");
  return first == std::string::npos ? "" : line.substr(first, last - first + 1);
}
}

const char* vtkShadelabAssimpReader::GetExtensions()
{
  return ".3d .3ds .3mf .ac .ac3d .acc .amf .ase .ask .assbin .b3d .blend .bsp .bvh .cob .csm "
         ".dae .dxf .enff .fbx .hmp .ifc .ifczip .iqm .irr .irrmesh .lwo .lws .lxo .md2 .md3 "
         ".md5anim .md5camera .md5mesh .mdc .mdl .mesh .mot .ms3d .ndo .nff .ogex .pk3 .pmx .prj "
         ".q3o .q3s .raw .scn .sib .smd .step .stp .ter .uc .vta .x .x3d .x3db .xgl .xml .zae "
         ".zgl";
}

void vtkShadelabAssimpReader::ReadMesh(const char* fileName, vtkPolyData* triangles)
{
  // Read here, so that a folder, a FIFO or a file too big for the memory is
  // the error the other readers give; the child process sees these bytes.
  std::string bytes = ReadFileBytes(fileName);
  const bool normals = this->ReadNormals, allowOutside = this->AllowOutsideReferences;
  shadelab::AssimpMesh mesh = shadelab::DecodeAssimpMesh(shadelab::ReadIsolated("assimp",
    [&]
    {
      Assimp::Importer importer;
      // The importer owns its IO system and deletes it.
      auto* io = new CheckedIOSystem(fileName, std::move(bytes), allowOutside);
      importer.SetIOHandler(io);
      const aiScene* scene = importer.ReadFile(fileName,
        aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
          aiProcess_ValidateDataStructure | aiProcess_PreTransformVertices);
      if (!scene)
      {
        const std::string error = FirstLine(importer.GetErrorString());
        throw shadelab::MeshReadError(error.empty() ? "assimp cannot read it" : error);
      }
      shadelab::AssimpMesh converted =
        shadelab::ConvertAssimpScene(*scene, fileName, normals, allowOutside);
      // The references refused first, then what the conversion noticed.
      converted.Warnings.insert(
        converted.Warnings.begin(), io->Warnings.begin(), io->Warnings.end());
      return shadelab::EncodeAssimpMesh(converted);
    }));
  shadelab::MakeTriangleMesh(shadelab::ToPolyData(std::move(mesh.Mesh)), triangles);
  shadelab::AddPartMaterials(mesh.Parts, triangles);
  shadelab::AddTextures(mesh.Textures, triangles);
  // Warnings only of a mesh that was read: a refused file is its one error.
  for (const std::string& warning : mesh.Warnings)
  {
    vtkWarningMacro(<< warning);
  }
}
