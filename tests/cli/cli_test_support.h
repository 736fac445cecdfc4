// Running the shadelab binary from tests and reading what it wrote.
#ifndef shadelab_cli_test_support_h
#define shadelab_cli_test_support_h

#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace shadelab_test
{
struct RunResult
{
  int ExitCode = -1;
  std::string Stdout;
  std::string Stderr;
};

/**
 * Runs `shadelab ARGS...` with DISPLAY unset (headless, as in CI) and the
 * environment's NAME=VALUE settings; one that runs past ten minutes is
 * stopped and exits 124.
 */
RunResult RunShadelab(
  const std::vector<std::string>& args, const std::vector<std::string>& environment = {});

/** Runs another program of the build (a bench executable) as RunShadelab runs shadelab. */
RunResult RunProgram(const std::filesystem::path& program, const std::vector<std::string>& args,
  const std::vector<std::string>& environment = {});

/**
 * Starts `shadelab ARGS...` as RunShadelab does, without waiting, its
 * stdout and stderr into the given files; returns its process id.
 */
int StartShadelab(const std::vector<std::string>& args, const std::filesystem::path& stdoutFile,
  const std::filesystem::path& stderrFile);

/** Waits for a process StartShadelab started; its exit code (128 + signal when killed). */
int WaitShadelab(int pid);

/** The whole file at path (empty if it cannot be read). */
std::string Slurp(const std::filesystem::path& path);

/**
 * The phases of `-v` output (the lines `PROGRAM: PHASE MS ms, peak MIB MiB`
 * that the benchmark scripts parse), in order; other lines (VTK's messages)
 * are skipped. Fails the test where a peak is not positive or falls.
 */
std::vector<std::string> VerbosePhases(const std::string& text, const std::string& program);

/** The names of the files in folder, sorted. */
std::vector<std::string> FilesIn(const std::filesystem::path& folder);

/** A fresh empty folder under the system's temporary folder, removed by the destructor. */
class TempDir
{
public:
  TempDir();
  ~TempDir();
  std::filesystem::path operator/(const std::string& name) const { return this->Path / name; }
  const std::filesystem::path& path() const { return this->Path; }
  /** The names of the files in it, sorted. */
  std::vector<std::string> Files() const;

private:
  std::filesystem::path Path;
};

struct Image
{
  int Width = 0;
  int Height = 0;
  int Channels = 0;
  std::vector<float> Pixels; // top row first; 8-bit files as 0..255
  std::string Description;   // the ImageDescription attribute
  std::string Format;        // the pixel type as stored
};

/** Reads an image through OpenImageIO; Width 0 when it cannot. */
Image ReadImage(const std::filesystem::path& path);

/** Every subimage of a file (an animated GIF's frames); empty when it cannot be read. */
std::vector<Image> ReadSubimages(const std::filesystem::path& path);

/**
 * The mesh's coverage: pixels with alpha above 0 where the picture has alpha
 * (--background transparent), else pixels that are not black (the default
 * background).
 */
size_t CountCovered(const Image& image);

/** The bounding box of the pixels that are not black, in pixels from the top left. */
struct Silhouette
{
  int Left = 0, Right = -1, Top = 0, Bottom = -1;
  int Width = 0, Height = 0;
};
Silhouette MeasureSilhouette(const Image& image);

using Point3 = std::array<double, 3>;

/** A mesh written by a test: its vertices, and its faces as OBJ lines. */
struct TestShape
{
  std::vector<Point3> Vertices;
  std::string Faces;
  std::string Obj() const;
};

/** A box of the given sides about the origin, its faces wound outwards. */
TestShape Box(const Point3& sides);

/** The camera a picture's metadata (its ImageDescription) records. */
struct RecordedCamera
{
  Point3 Position, Focal, Up;
  bool Orthographic = false;
  double ViewAngle = 0, ParallelScale = 0;
};
RecordedCamera CameraOf(const Image& image);

/** Where points land in a picture, in pixels from its left and top edges. */
struct Extents
{
  double Left = INFINITY, Right = -INFINITY, Top = INFINITY, Bottom = -INFINITY;
};

/**
 * The extents of vertices projected by camera into a width x height
 * picture, which spans [0, width] x [0, height]: VTK's projection, computed
 * here in double (the view angle vertical).
 */
Extents Project(
  const RecordedCamera& camera, const std::vector<Point3>& vertices, int width, int height);

/** A mesh that shadelab makes itself (meshes/: teapot.obj, torus.obj, ...). */
std::filesystem::path TestMesh(const std::string& name);

/** A file of Debian's assimp-testmodels, by its path under /usr/share/assimp/models. */
std::filesystem::path DebianModel(const std::string& path);

/**
 * Khronos' BoxTextured (Debian's, metallic 0) made a metal (metallic 1:
 * kd = ka = 0 and its texture colours ks), written into dir as .gltf beside
 * copies of its buffer and image, or as .glb; its path.
 */
std::filesystem::path MetalBoxTextured(const std::filesystem::path& dir, bool binary);

/** Writes text to path. */
void WriteText(const std::filesystem::path& path, const std::string& text);

/** An 8-bit RGB image file (PNG by the extension), pixels top row first, 3 per pixel. */
void WriteImage8(
  const std::filesystem::path& path, int width, int height, const std::vector<unsigned char>& rgb);

/**
 * An RGB image file of the given pixel type ("uint8", "uint16", "half",
 * "float"; the format by the extension), from values in [0, 1] (floats
 * as they are), top row first, 3 per pixel.
 */
void WriteImage(const std::filesystem::path& path, int width, int height,
  const std::vector<float>& rgb, const std::string& type);

/** An ASCII PLY of one triangle in z = 0 whose vertices are red, green and blue (uchar colours). */
void WriteRgbTriangle(const std::filesystem::path& path);
}

#endif
