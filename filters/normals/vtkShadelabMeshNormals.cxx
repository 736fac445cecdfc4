#include "vtkShadelabMeshNormals.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMath.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <future>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkShadelabMeshNormals);

namespace
{
// Double points: the normals are computed in double and stored as float.
struct MeshTraits : public OpenMesh::DefaultTraits
{
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;
using Vec3 = OpenMesh::Vec3d;

// Point ids as OpenMesh numbers its handles (int): half the memory of
// vtkIdType for the largest arrays; bigger meshes are refused.
using Id = int;

Vec3 PointAt(const double* xyz, vtkIdType i)
{
  return Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
}

// A vertex normal's sum this much shorter than the sum of its weights is
// taken as zero: terms that cancel leave about 1e-16 of them in rounding,
// pointing anywhere, and a real normal is never this close to cancelling.
constexpr double CancelledSum = 1e-12;

// The input's triangles as 3 point ids a face, or an error.
struct TriangleIds
{
  template <typename CellState>
  void operator()(
    CellState& state, vtkIdType points, std::vector<Id>& ids, std::string& error) const
  {
    const auto* offsets = state.GetOffsets()->GetPointer(0);
    const auto* connectivity = state.GetConnectivity()->GetPointer(0);
    const vtkIdType faces = state.GetOffsets()->GetNumberOfValues() - 1;
    ids.resize(3 * faces);
    for (vtkIdType f = 0; f < faces; ++f)
    {
      if (offsets[f + 1] - offsets[f] != 3)
      {
        error = "polygon " + std::to_string(f) + " has " +
          std::to_string(offsets[f + 1] - offsets[f]) + " vertices (triangles only)";
        return;
      }
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType id = connectivity[3 * f + k];
        if (id < 0 || id >= points)
        {
          error = "triangle " + std::to_string(f) + " refers to point " + std::to_string(id) +
            " of " + std::to_string(points);
          return;
        }
        ids[3 * f + k] = static_cast<Id>(id);
      }
    }
  }
};

// The indices of `keys` grouped by key, in order (a counting sort): those of
// key k are Items[First[k]] to Items[First[k + 1] - 1].
struct Buckets
{
  std::vector<Id> First;
  std::vector<Id> Items;

  Buckets(const std::vector<Id>& keys, vtkIdType keyCount)
    : First(keyCount + 1, 0)
    , Items(keys.size())
  {
    for (const Id k : keys)
    {
      ++this->First[k + 1];
    }
    std::partial_sum(this->First.begin(), this->First.end(), this->First.begin());
    std::vector<Id> fill(this->First.begin(), this->First.end() - 1);
    for (size_t i = 0; i < keys.size(); ++i)
    {
      this->Items[fill[keys[i]]++] = static_cast<Id>(i);
    }
  }
};

// True when face g has the directed edge a -> b.
bool HasEdge(const Id* g, Id a, Id b)
{
  return (g[0] == a && g[1] == b) || (g[1] == a && g[2] == b) || (g[2] == a && g[0] == b);
}

// Reverses faces so that neighbours across each manifold edge use the edge in
// opposite directions, spreading out from the lowest-numbered face of each
// edge-connected part (vtkPolyDataNormals's Consistency). Returns whether a
// face was reversed. Works on the ids, not on OpenMesh: OpenMesh refuses
// exactly the inconsistent faces this must see.
bool Orient(std::vector<Id>& tri, vtkIdType points)
{
  const vtkIdType faces = static_cast<vtkIdType>(tri.size() / 3);
  // The face corners at each point (corner c is in face c / 3).
  const Buckets around(tri, points);

  bool reversed = false;
  std::vector<bool> reached(faces, false);
  std::vector<vtkIdType> queue;
  for (vtkIdType seed = 0; seed < faces; ++seed)
  {
    if (reached[seed])
    {
      continue;
    }
    reached[seed] = true;
    queue.assign(1, seed);
    while (!queue.empty())
    {
      const vtkIdType f = queue.back();
      queue.pop_back();
      for (int k = 0; k < 3; ++k)
      {
        const Id a = tri[3 * f + k];
        const Id b = tri[3 * f + (k + 1) % 3];
        if (a == b)
        {
          continue;
        }
        // The one other face on edge a-b; none (boundary) or several
        // (non-manifold) pass no orientation on.
        vtkIdType other = -1;
        int count = 0;
        for (vtkIdType i = around.First[a]; i < around.First[a + 1]; ++i)
        {
          const vtkIdType g = around.Items[i] / 3;
          const Id* ids = &tri[3 * g];
          if (g != f && g != other && (ids[0] == b || ids[1] == b || ids[2] == b))
          {
            other = g;
            ++count;
          }
        }
        if (count != 1 || reached[other])
        {
          continue;
        }
        reached[other] = true;
        Id* ids = &tri[3 * other];
        if (HasEdge(ids, a, b))
        {
          std::swap(ids[1], ids[2]);
          reversed = true;
        }
        queue.push_back(other);
      }
    }
  }
  return reversed;
}

// Disables OpenMesh's error stream for a scope: a refused face is expected
// here and handled, not an error to print.
class QuietOpenMesh
{
public:
  QuietOpenMesh()
    : WasEnabled(omerr().is_enabled())
  {
    omerr().disable();
  }
  ~QuietOpenMesh()
  {
    if (this->WasEnabled)
    {
      omerr().enable();
    }
  }

private:
  bool WasEnabled;
};
}

// The connectivity and the face geometry of one input: what survives a
// change of weighting or of feature angle.
struct vtkShadelabMeshNormals::Cache
{
  vtkPolyData* Input = nullptr; // identity only, never dereferenced
  vtkMTimeType InputTime = 0;
  bool Consistency = false;

  vtkIdType Points = 0;               // OpenMesh vertex i < Points is input point i
  std::vector<Id> Triangles;          // 3 input point ids a face, as oriented
  bool Reversed = false;              // Consistency reversed some faces
  TriMesh Mesh;                       // face f is input face f
  std::vector<Id> CopyOf;             // OpenMesh vertex Points + i copies CopyOf[i]
  std::vector<bool> InDuplicatedFace; // per input point
  vtkIdType DuplicatedFaces = 0;

  vtkSmartPointer<vtkDoubleArray> XYZ;        // the input's points, in double
  std::vector<Vec3> FaceNormal;               // unit; zero for faces of no area
  std::vector<double> DoubleArea;             // |e1 x e2|; zero for faces of no area
  vtkSmartPointer<vtkFloatArray> CellNormals; // FaceNormal as the output stores it
  int WeightsOf = -1;                         // the weighting CornerWeight is for
  std::vector<double> CornerWeight;           // 3 a face

  /** Builds it all, with the corner weights of `weighting` ready. */
  void Build(vtkPolyData* input, bool consistency, std::vector<Id>&& triangles, int weighting);

  /**
   * The weight of each face corner (3 a face) for the Angle or Max
   * weighting, on both cores unless `parallel` is false.
   */
  const std::vector<double>& CornerWeights(int weighting, bool parallel = true);

  /**
   * Groups the faces around each vertex at feature edges (faces whose unit
   * normals' dot product is below cosFeature) and at boundary and
   * non-manifold edges. Gives each output point's input point (`source`),
   * each face corner's output point (`cornerPoint`, 3 a face), and which
   * input points were split.
   */
  void Split(double cosFeature, std::vector<vtkIdType>& source, Id* cornerPoint,
    std::vector<bool>& split) const;

private:
  void ComputeFaceNormals();
};

void vtkShadelabMeshNormals::Cache::Build(
  vtkPolyData* input, bool consistency, std::vector<Id>&& triangles, int weighting)
{
  this->Input = input;
  this->InputTime = input->GetMTime();
  this->Consistency = consistency;
  this->Points = input->GetNumberOfPoints();
  this->Triangles = std::move(triangles);
  this->Reversed = consistency && Orient(this->Triangles, this->Points);

  this->XYZ = vtkDoubleArray::FastDownCast(input->GetPoints()->GetData());
  if (!this->XYZ)
  {
    this->XYZ = vtkSmartPointer<vtkDoubleArray>::New();
    this->XYZ->DeepCopy(input->GetPoints()->GetData());
  }
  const double* p = this->XYZ->GetPointer(0);
  // The face geometry needs no connectivity: it is computed on a second
  // thread while OpenMesh builds hers (add_face is most of the time). A
  // future, so that it is waited for even if the build throws.
  auto faceGeometry = std::async(std::launch::async,
    [this, weighting]
    {
      this->ComputeFaceNormals();
      if (weighting == Angle || weighting == Max)
      {
        // One core: the other is busy with add_face.
        this->CornerWeights(weighting, false);
      }
    });

  const vtkIdType faces = static_cast<vtkIdType>(this->Triangles.size() / 3);
  TriMesh& mesh = this->Mesh;
  // The input's points as OpenMesh's first vertices, set in place.
  mesh.reserve(this->Points, 3 * faces / 2 + 3, faces);
  mesh.resize(this->Points, 0, 0);
  for (vtkIdType i = 0; i < this->Points; ++i)
  {
    mesh.set_point(TriMesh::VertexHandle(static_cast<int>(i)), PointAt(p, i));
  }
  this->InDuplicatedFace.assign(this->Points, false);

  QuietOpenMesh quiet;
  for (vtkIdType f = 0; f < faces; ++f)
  {
    const Id* ids = &this->Triangles[3 * f];
    std::array<TriMesh::VertexHandle, 3> corner;
    for (int k = 0; k < 3; ++k)
    {
      corner[k] = TriMesh::VertexHandle(static_cast<int>(ids[k]));
    }
    // A repeated vertex would corrupt OpenMesh's connectivity; add_face
    // itself refuses complex edges and vertices without changing the mesh.
    const bool repeated = ids[0] == ids[1] || ids[1] == ids[2] || ids[2] == ids[0];
    if (!repeated && mesh.add_face(corner[0], corner[1], corner[2]).is_valid())
    {
      continue;
    }
    // Refused: the face gets copies of its vertices, so it still has
    // normals (and keeps its number: face f stays OpenMesh face f).
    for (int k = 0; k < 3; ++k)
    {
      // From the input: a reference into OpenMesh's points would dangle
      // when add_vertex moves them.
      corner[k] = mesh.add_vertex(PointAt(p, ids[k]));
      this->CopyOf.push_back(ids[k]);
      this->InDuplicatedFace[ids[k]] = true;
    }
    mesh.add_face(corner[0], corner[1], corner[2]);
    ++this->DuplicatedFaces;
  }
  faceGeometry.get();
}

void vtkShadelabMeshNormals::Cache::ComputeFaceNormals()
{
  const double* xyz = this->XYZ->GetPointer(0);
  const vtkIdType faces = static_cast<vtkIdType>(this->Triangles.size() / 3);
  this->FaceNormal.resize(faces);
  this->DoubleArea.resize(faces);
  this->CellNormals = vtkSmartPointer<vtkFloatArray>::New();
  this->CellNormals->SetName("Normals");
  this->CellNormals->SetNumberOfComponents(3);
  this->CellNormals->SetNumberOfTuples(faces);
  float* out = this->CellNormals->GetPointer(0);
  const Id* tri = this->Triangles.data();
  for (vtkIdType f = 0; f < faces; ++f)
  {
    const Vec3 p0 = PointAt(xyz, tri[3 * f]);
    const Vec3 n =
      OpenMesh::cross(PointAt(xyz, tri[3 * f + 1]) - p0, PointAt(xyz, tri[3 * f + 2]) - p0);
    const double length = n.norm();
    // Zero (or overflowing) cross products give no direction: no weight.
    const bool usable = length > 0 && std::isfinite(length);
    this->FaceNormal[f] = usable ? n / length : Vec3(0, 0, 0);
    this->DoubleArea[f] = usable ? length : 0;
    for (int c = 0; c < 3; ++c)
    {
      out[3 * f + c] = static_cast<float>(this->FaceNormal[f][c]);
    }
  }
}

const std::vector<double>& vtkShadelabMeshNormals::Cache::CornerWeights(
  int weighting, bool parallel)
{
  if (this->WeightsOf == weighting)
  {
    return this->CornerWeight;
  }
  const vtkIdType faces = static_cast<vtkIdType>(this->Triangles.size() / 3);
  this->CornerWeight.resize(3 * faces);
  // The input's points: OpenMesh's may grow meanwhile (Build).
  const double* xyz = this->XYZ->GetPointer(0);
  const Id* tri = this->Triangles.data();
  const double* doubleArea = this->DoubleArea.data();
  double* w = this->CornerWeight.data();
  // Independent per face, so cores can share it.
  auto weigh = [=](vtkIdType begin, vtkIdType end)
  {
    for (vtkIdType f = begin; f < end; ++f)
    {
      const double area2 = doubleArea[f];
      // Edge k runs from corner k to corner k + 1.
      const Vec3 p[3] = { PointAt(xyz, tri[3 * f]), PointAt(xyz, tri[3 * f + 1]),
        PointAt(xyz, tri[3 * f + 2]) };
      const Vec3 e[3] = { p[1] - p[0], p[2] - p[1], p[0] - p[2] };
      double* corner = w + 3 * f;
      if (area2 == 0)
      {
        corner[0] = corner[1] = corner[2] = 0; // a face of no area has no weight
      }
      else if (weighting == vtkShadelabMeshNormals::Max)
      {
        // Max 1999: |a x b| / (|a|^2 |b|^2) for the corner's edges a, b;
        // |a x b| is twice the area at every corner.
        const double l[3] = { e[0].sqrnorm(), e[1].sqrnorm(), e[2].sqrnorm() };
        corner[0] = area2 / (l[2] * l[0]);
        corner[1] = area2 / (l[0] * l[1]);
        corner[2] = area2 / (l[1] * l[2]);
      }
      else
      {
        // The angle between the corner's edges as atan2(|a x b|, a.b),
        // accurate at every size, unlike acos; the third from the sum pi.
        corner[0] = std::atan2(area2, -OpenMesh::dot(e[0], e[2]));
        corner[1] = std::atan2(area2, -OpenMesh::dot(e[1], e[0]));
        corner[2] = vtkMath::Pi() - corner[0] - corner[1];
      }
    }
  };
  if (parallel)
  {
    vtkSMPTools::For(0, faces, weigh);
  }
  else
  {
    weigh(0, faces);
  }
  this->WeightsOf = weighting;
  return this->CornerWeight;
}

vtkShadelabMeshNormals::vtkShadelabMeshNormals() = default;
vtkShadelabMeshNormals::~vtkShadelabMeshNormals() = default;

bool vtkShadelabMeshNormals::SetWeightingByName(const char* name)
{
  const auto weighting = name ? shadelab::FromName<Weightings>(name) : std::nullopt;
  if (weighting)
  {
    this->SetWeighting(*weighting);
  }
  return weighting.has_value();
}

void vtkShadelabMeshNormals::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Weighting: " << shadelab::ToString(static_cast<Weightings>(this->Weighting))
     << "\n";
  os << indent << "Splitting: " << (this->Splitting ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "Consistency: " << (this->Consistency ? "On" : "Off") << "\n";
  os << indent << "NumberOfDuplicatedFaces: " << this->NumberOfDuplicatedFaces << "\n";
  os << indent << "NumberOfConnectivityBuilds: " << this->NumberOfConnectivityBuilds << "\n";
}

int vtkShadelabMeshNormals::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const vtkIdType points = input->GetNumberOfPoints();
  if (!input->GetPoints() && input->GetNumberOfPolys() == 0)
  {
    return 1; // nothing to compute normals for: an empty output, as vtkPolyDataNormals gives
  }

  if (!this->Cached || this->Cached->Input != input ||
    this->Cached->InputTime != input->GetMTime() || this->Cached->Consistency != this->Consistency)
  {
    this->Cached.reset();
    std::vector<Id> triangles;
    std::string error;
    // OpenMesh numbers vertices and halfedges (3 a face, and copies) in int.
    const vtkIdType limit = std::numeric_limits<Id>::max() / 2;
    const vtkIdType cornerCount = input->GetPolys()->GetNumberOfConnectivityIds();
    if (points > limit || cornerCount > limit)
    {
      error = "too large for OpenMesh's int handles: " + std::to_string(points) + " points, " +
        std::to_string(cornerCount) + " triangle corners";
    }
    else
    {
      input->GetPolys()->Visit(TriangleIds{}, points, triangles, error);
    }
    if (!error.empty())
    {
      vtkErrorMacro(<< error);
      return 0;
    }
    auto cache = std::make_unique<Cache>();
    cache->Build(input, this->Consistency, std::move(triangles),
      this->Weighting == Loop ? Angle : this->Weighting);
    this->Cached = std::move(cache);
    ++this->NumberOfConnectivityBuilds;
  }
  Cache& cache = *this->Cached;
  const TriMesh& mesh = cache.Mesh;
  const std::vector<Id>& tri = cache.Triangles;
  const vtkIdType faces = static_cast<vtkIdType>(tri.size() / 3);
  this->NumberOfDuplicatedFaces = cache.DuplicatedFaces;

  // Each output point's input point, and each face corner's output point:
  // the output's own triangles where they differ from the input's.
  vtkSmartPointer<vtkTypeInt32Array> connectivity;
  std::vector<vtkIdType> source;
  std::vector<bool> split;
  if (this->Splitting || cache.Reversed)
  {
    connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
    connectivity->SetNumberOfValues(3 * faces);
  }
  if (this->Splitting)
  {
    cache.Split(std::cos(vtkMath::RadiansFromDegrees(this->FeatureAngle)), source,
      connectivity->GetPointer(0), split);
  }
  else if (cache.Reversed)
  {
    std::copy(tri.begin(), tri.end(), connectivity->GetPointer(0));
  }
  const vtkIdType outputPoints = this->Splitting ? static_cast<vtkIdType>(source.size()) : points;
  const Id* corners = connectivity ? connectivity->GetPointer(0) : tri.data();

  // Each face's weighted unit normal, summed into its corners' points.
  const int weighting = this->Weighting == Loop ? Angle : this->Weighting;
  const double* cornerWeight =
    weighting == Angle || weighting == Max ? cache.CornerWeights(weighting).data() : nullptr;
  // With the sum, the sum of the weights: a sum far shorter than its terms
  // is the rounding left of terms that cancel (a face and its reverse), and
  // its direction means nothing.
  struct Sum
  {
    Vec3 Normal{ 0, 0, 0 };
    double Weight = 0; // beside the normal: one cache line for both
  };
  std::vector<Sum> sum(outputPoints);
  for (vtkIdType f = 0; f < faces; ++f)
  {
    const double area2 = cache.DoubleArea[f];
    if (area2 == 0)
    {
      continue; // a face of no area adds nothing
    }
    for (int k = 0; k < 3; ++k)
    {
      const double w = weighting == Uniform ? 1
        : weighting == Area                 ? area2
                                            : cornerWeight[3 * f + k];
      Sum& s = sum[corners[3 * f + k]];
      s.Normal += w * cache.FaceNormal[f];
      s.Weight += w;
    }
  }
  if (this->Weighting == Loop)
  {
    // OpenMesh's limit normal where it is one: at an interior vertex whose
    // whole fan is one smooth piece of a manifold mesh. Per vertex, on both
    // cores; OpenMesh makes its table of Loop weights on first use, so that
    // happens here first.
    OpenMesh::LoopSchemeMaskDoubleSingleton::Instance();
    vtkSMPTools::For(0, points,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const TriMesh::VertexHandle v(static_cast<int>(i));
          if (mesh.is_boundary(v) || mesh.valence(v) < 3 || cache.InDuplicatedFace[i] ||
            (this->Splitting && split[i]))
          {
            continue;
          }
          TriMesh::Normal n;
          // Unnormalised, and on the side of the faces' normals (OpenMesh
          // crosses its tangents as cross(t_w, t_v) for that).
          mesh.calc_vertex_normal_loop(v, n);
          sum[i] = { n, 0 };
        }
      });
  }

  auto pointNormals = vtkSmartPointer<vtkFloatArray>::New();
  pointNormals->SetName("Normals");
  pointNormals->SetNumberOfComponents(3);
  pointNormals->SetNumberOfTuples(outputPoints);
  float* pn = pointNormals->GetPointer(0);
  for (vtkIdType i = 0; i < outputPoints; ++i)
  {
    const double length = sum[i].Normal.norm();
    const bool defined = length > CancelledSum * sum[i].Weight && std::isfinite(length);
    const Vec3 n = defined ? sum[i].Normal / length : Vec3(0, 0, 0);
    for (int c = 0; c < 3; ++c)
    {
      pn[3 * i + c] = static_cast<float>(n[c]);
    }
  }

  // Geometry: the input's as it is unless points were split or faces
  // reversed; only the triangles are kept (verts, lines and strips dropped).
  output->GetPointData()->CopyNormalsOff();
  output->GetCellData()->CopyNormalsOff();
  output->GetCellData()->PassData(input->GetCellData());
  if (connectivity)
  {
    auto offsets = vtkSmartPointer<vtkTypeInt32Array>::New();
    offsets->SetNumberOfValues(faces + 1);
    Id* offset = offsets->GetPointer(0);
    for (vtkIdType f = 0; f <= faces; ++f)
    {
      offset[f] = static_cast<Id>(3 * f);
    }
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    polys->SetData(offsets, connectivity);
    output->SetPolys(polys);
  }
  else
  {
    output->SetPolys(input->GetPolys());
  }
  if (outputPoints > points)
  {
    // The input's points, then copies of the split ones (with their data).
    auto splitPoints = vtkSmartPointer<vtkPoints>::New();
    splitPoints->SetDataType(input->GetPoints()->GetDataType());
    splitPoints->SetNumberOfPoints(outputPoints);
    splitPoints->GetData()->InsertTuples(0, points, 0, input->GetPoints()->GetData());
    auto from = vtkSmartPointer<vtkIdList>::New();
    auto to = vtkSmartPointer<vtkIdList>::New();
    from->SetNumberOfIds(outputPoints - points);
    to->SetNumberOfIds(outputPoints - points);
    for (vtkIdType i = points; i < outputPoints; ++i)
    {
      from->SetId(i - points, source[i]);
      to->SetId(i - points, i);
    }
    splitPoints->GetData()->InsertTuples(to, from, input->GetPoints()->GetData());
    output->SetPoints(splitPoints);
    vtkPointData* pointData = output->GetPointData();
    pointData->CopyAllocate(input->GetPointData(), outputPoints);
    pointData->CopyData(input->GetPointData(), 0, points, 0);
    pointData->CopyData(input->GetPointData(), from, to);
  }
  else
  {
    output->SetPoints(input->GetPoints());
    output->GetPointData()->PassData(input->GetPointData());
  }
  output->GetPointData()->SetNormals(pointNormals);
  output->GetCellData()->SetNormals(cache.CellNormals);
  return 1;
}

void vtkShadelabMeshNormals::Cache::Split(double cosFeature, std::vector<vtkIdType>& source,
  Id* cornerPoint, std::vector<bool>& split) const
{
  const TriMesh& mesh = this->Mesh;
  const vtkIdType points = this->Points;
  source.resize(points);
  std::iota(source.begin(), source.end(), 0);
  split.assign(points, false);

  // Which edges separate the faces on their two sides: boundary and feature
  // edges. Once per edge, on both cores, before the walks around vertices.
  std::vector<char> separating(mesh.n_edges());
  vtkSMPTools::For(0, static_cast<vtkIdType>(separating.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType e = begin; e < end; ++e)
      {
        const auto a = mesh.face_handle(TriMesh::HalfedgeHandle(static_cast<int>(2 * e)));
        const auto b = mesh.face_handle(TriMesh::HalfedgeHandle(static_cast<int>(2 * e + 1)));
        separating[e] = !a.is_valid() || !b.is_valid() ||
          OpenMesh::dot(this->FaceNormal[a.idx()], this->FaceNormal[b.idx()]) < cosFeature;
      }
    });
  // An edge that OpenMesh holds as manifold may have more faces in the
  // input, duplicated ones: it is non-manifold, and separates too.
  for (size_t c = 0; c < this->CopyOf.size(); c += 3)
  {
    for (size_t k = 0; k < 3; ++k)
    {
      const TriMesh::HalfedgeHandle h =
        mesh.find_halfedge(TriMesh::VertexHandle(static_cast<int>(this->CopyOf[c + k])),
          TriMesh::VertexHandle(static_cast<int>(this->CopyOf[c + (k + 1) % 3])));
      if (h.is_valid())
      {
        separating[h.idx() / 2] = 1;
      }
    }
  }
  auto separates = [&](TriMesh::HalfedgeHandle h) { return separating[h.idx() / 2] != 0; };

  // Input point i's OpenMesh vertices: vertex i, then its copies in order.
  const Buckets copies(this->CopyOf, points);

  // First, on both cores: round the fans of each input point's vertices,
  // the runs of faces between separations, numbered 0, 1, ... per point in
  // the corners (for now) and counted.
  std::vector<int> runs(points, 0);
  vtkSMPTools::For(0, points,
    [&](vtkIdType firstPoint, vtkIdType endPoint)
    {
      struct FanFace
      {
        int Face;           // -1 for the gap of a boundary
        bool SeparatesNext; // from the next face round the fan
      };
      std::vector<FanFace> fan;
      for (vtkIdType i = firstPoint; i < endPoint; ++i)
      {
        auto walk = [&](int vi)
        {
          const TriMesh::HalfedgeHandle start = mesh.halfedge_handle(TriMesh::VertexHandle(vi));
          if (!start.is_valid())
          {
            return; // no face
          }
          // Outgoing halfedges in turn (h -> next(opposite(h))): the face of
          // the next one lies across the edge of this one. The first run
          // starts after the last separation (a closed smooth fan has none
          // and is one run).
          fan.clear();
          TriMesh::HalfedgeHandle h = start;
          do
          {
            fan.push_back({ mesh.face_handle(h).idx(), separates(h) });
            h = mesh.cw_rotated_halfedge_handle(h);
          } while (h != start);
          const size_t n = fan.size();
          size_t begin = 0;
          for (size_t j = 0; j < n; ++j)
          {
            if (fan[j].SeparatesNext)
            {
              begin = j + 1;
              break;
            }
          }
          bool inRun = false;
          for (size_t j = 0; j < n; ++j)
          {
            const FanFace& face = fan[(begin + j) % n];
            if (face.Face >= 0)
            {
              if (!inRun)
              {
                inRun = true;
                ++runs[i];
              }
              // The corner's number in the face: copies are made three at a
              // time in corner order; an original vertex is found by its id
              // (a face that repeats an id was duplicated).
              const Id* ids = &this->Triangles[3 * face.Face];
              const int k = vi >= points ? (vi - points) % 3
                : ids[0] == i            ? 0
                : ids[1] == i            ? 1
                                         : 2;
              cornerPoint[3 * face.Face + k] = runs[i] - 1;
            }
            inRun = inRun && !face.SeparatesNext;
          }
        };
        walk(static_cast<int>(i));
        for (vtkIdType c = copies.First[i]; c < copies.First[i + 1]; ++c)
        {
          walk(static_cast<int>(points + copies.Items[c]));
        }
      }
    });

  // Then the output points: input point i keeps its number for its first
  // run; its other runs become new points, appended in input order.
  std::vector<Id> firstNew(points);
  for (vtkIdType i = 0; i < points; ++i)
  {
    firstNew[i] = static_cast<Id>(source.size());
    split[i] = runs[i] > 1;
    source.insert(source.end(), std::max(runs[i] - 1, 0), i);
  }
  const Id* tri = this->Triangles.data();
  vtkSMPTools::For(0, static_cast<vtkIdType>(this->Triangles.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType c = begin; c < end; ++c)
      {
        const Id run = cornerPoint[c];
        cornerPoint[c] = run == 0 ? tri[c] : firstNew[tri[c]] + run - 1;
      }
    });
}
