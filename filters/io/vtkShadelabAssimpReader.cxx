#include "vtkShadelabAssimpReader.h"

#include "shadelabAssimpScene.h"
#include "shadelabCheckedFile.h"
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
#include <iostream>
#include <memory>
#include <mutex>
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

// assimp's bundled parsers (OpenDDL's, for OpenGEX) write some messages
// straight to std::cerr and std::cout rather than to assimp's logger: those
// streams go nowhere while assimp reads, so that shadelab's stderr stays
// its one line per problem. A mutex: two reads at once must not restore
// each other's streams.
class SilencedStandardStreams
{
public:
  SilencedStandardStreams()
    : Lock(Mutex)
    , OutState(std::cout.rdstate())
    , ErrState(std::cerr.rdstate())
    , Out(std::cout.rdbuf(nullptr))
    , Err(std::cerr.rdbuf(nullptr))
  {
  }
  ~SilencedStandardStreams()
  {
    // A write into no buffer set badbit: the streams' states as they were.
    std::cout.rdbuf(this->Out);
    std::cerr.rdbuf(this->Err);
    std::cout.clear(this->OutState);
    std::cerr.clear(this->ErrState);
  }
  SilencedStandardStreams(const SilencedStandardStreams&) = delete;
  SilencedStandardStreams& operator=(const SilencedStandardStreams&) = delete;

private:
  static std::mutex Mutex;
  std::lock_guard<std::mutex> Lock;
  std::ios_base::iostate OutState, ErrState;
  std::streambuf* Out;
  std::streambuf* Err;
};
std::mutex SilencedStandardStreams::Mutex;

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
  Assimp::Importer importer;
  // The importer owns its IO system and deletes it.
  auto* io = new CheckedIOSystem(fileName, ReadFileBytes(fileName), this->AllowOutsideReferences);
  importer.SetIOHandler(io);
  const aiScene* scene = nullptr;
  {
    const SilencedStandardStreams silence;
    scene = importer.ReadFile(fileName,
      aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
        aiProcess_ValidateDataStructure | aiProcess_PreTransformVertices);
  }
  if (!scene)
  {
    const std::string error = FirstLine(importer.GetErrorString());
    throw shadelab::MeshReadError(error.empty() ? "assimp cannot read it" : error);
  }
  shadelab::AssimpMesh mesh =
    shadelab::ConvertAssimpScene(*scene, fileName, this->ReadNormals, this->AllowOutsideReferences);
  importer.FreeScene(); // the copy is made: assimp's memory goes before VTK's grows
  shadelab::MakeTriangleMesh(shadelab::ToPolyData(std::move(mesh.Mesh)), triangles);
  shadelab::AddPartMaterials(mesh.Parts, triangles);
  shadelab::AddTextures(mesh.Textures, triangles);
  // Warnings only of a mesh that was read: a refused file is its one error.
  for (const std::string& warning : io->Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  for (const std::string& warning : mesh.Warnings)
  {
    vtkWarningMacro(<< warning);
  }
}
