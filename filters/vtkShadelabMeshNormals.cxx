#include "vtkShadelabMeshNormals.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMath.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <array>
#include <cmath>
#include <cstring>
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

const char* const WeightingNames[] = { "uniform", "area", "angle", "max", "loop" };

// The input's triangles as 3 point ids a face, or an error.
struct TriangleIds
{
  template <typename CellState>
  void operator()(
    CellState& state, vtkIdType points, std::vector<vtkIdType>& ids, std::string& error) const
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
        ids[3 * f + k] = id;
      }
    }
  }
};

// True when face g has the directed edge a -> b.
bool HasEdge(const vtkIdType* g, vtkIdType a, vtkIdType b)
{
  return (g[0] == a && g[1] == b) || (g[1] == a && g[2] == b) || (g[2] == a && g[0] == b);
}

// Reverses faces so that neighbours across each manifold edge use the edge in
// opposite directions, spreading out from the lowest-numbered face of each
// edge-connected part (vtkPolyDataNormals's Consistency). Returns whether a
// face was reversed. Works on the ids, not on OpenMesh: OpenMesh refuses
// exactly the inconsistent faces this must see.
bool Orient(std::vector<vtkIdType>& tri, vtkIdType points)
{
  const vtkIdType faces = static_cast<vtkIdType>(tri.size() / 3);
  // The faces around each point, as offsets into one list.
  std::vector<vtkIdType> first(points + 1, 0);
  for (vtkIdType id : tri)
  {
    ++first[id + 1];
  }
  for (vtkIdType p = 0; p < points; ++p)
  {
    first[p + 1] += first[p];
  }
  std::vector<vtkIdType> around(tri.size());
  std::vector<vtkIdType> fill(first.begin(), first.end() - 1);
  for (vtkIdType f = 0; f < faces; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      around[fill[tri[3 * f + k]]++] = f;
    }
  }

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
        const vtkIdType a = tri[3 * f + k];
        const vtkIdType b = tri[3 * f + (k + 1) % 3];
        if (a == b)
        {
          continue;
        }
        // The one other face on edge a-b; none (boundary) or several
        // (non-manifold) pass no orientation on.
        vtkIdType other = -1;
        int count = 0;
        for (vtkIdType i = first[a]; i < first[a + 1]; ++i)
        {
          const vtkIdType g = around[i];
          const vtkIdType* ids = &tri[3 * g];
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
        vtkIdType* ids = &tri[3 * other];
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

// The connectivity of one input: what survives a change of weighting or of
// feature angle.
struct vtkShadelabMeshNormals::Cache
{
  vtkPolyData* Input = nullptr; // identity only, never dereferenced
  vtkMTimeType InputTime = 0;
  bool Consistency = false;

  vtkIdType Points = 0;               // OpenMesh vertex i < Points is input point i
  std::vector<vtkIdType> Triangles;   // 3 input point ids a face, as oriented
  bool Reversed = false;              // Consistency reversed some faces
  TriMesh Mesh;                       // face f is input face f
  std::vector<vtkIdType> CopyOf;      // OpenMesh vertex Points + i copies CopyOf[i]
  std::vector<bool> InDuplicatedFace; // per input point
  vtkIdType DuplicatedFaces = 0;

  void Build(vtkPolyData* input, bool consistency, std::vector<vtkIdType>&& triangles);

  /**
   * Groups the faces around each vertex at feature edges (faces whose unit
   * normals' dot product is below cosFeature) and at boundary and
   * non-manifold edges. Gives each output point's input point (`source`),
   * each face corner's output point, and which input points were split.
   */
  void Split(double cosFeature, const std::vector<Vec3>& faceNormal, std::vector<vtkIdType>& source,
    std::vector<vtkIdType>& cornerPoint, std::vector<bool>& split) const;
};

void vtkShadelabMeshNormals::Cache::Build(
  vtkPolyData* input, bool consistency, std::vector<vtkIdType>&& triangles)
{
  this->Input = input;
  this->InputTime = input->GetMTime();
  this->Consistency = consistency;
  this->Points = input->GetNumberOfPoints();
  this->Triangles = std::move(triangles);
  this->Reversed = consistency && Orient(this->Triangles, this->Points);

  const vtkIdType faces = static_cast<vtkIdType>(this->Triangles.size() / 3);
  TriMesh& mesh = this->Mesh;
  mesh.clear();
  mesh.reserve(this->Points, 3 * faces / 2 + 3, faces);
  vtkPoints* points = input->GetPoints();
  for (vtkIdType i = 0; i < this->Points; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    mesh.add_vertex(Vec3(p[0], p[1], p[2]));
  }
  this->CopyOf.clear();
  this->InDuplicatedFace.assign(this->Points, false);
  this->DuplicatedFaces = 0;

  QuietOpenMesh quiet;
  for (vtkIdType f = 0; f < faces; ++f)
  {
    const vtkIdType* ids = &this->Triangles[3 * f];
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
      corner[k] = mesh.add_vertex(mesh.point(corner[k]));
      this->CopyOf.push_back(ids[k]);
      this->InDuplicatedFace[ids[k]] = true;
    }
    mesh.add_face(corner[0], corner[1], corner[2]);
    ++this->DuplicatedFaces;
  }
}

vtkShadelabMeshNormals::vtkShadelabMeshNormals() = default;
vtkShadelabMeshNormals::~vtkShadelabMeshNormals() = default;

bool vtkShadelabMeshNormals::SetWeightingByName(const char* name)
{
  for (int w = Uniform; w <= Loop; ++w)
  {
    if (name && std::strcmp(name, WeightingNames[w]) == 0)
    {
      this->SetWeighting(w);
      return true;
    }
  }
  return false;
}

void vtkShadelabMeshNormals::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Weighting: " << WeightingNames[this->Weighting] << "\n";
  os << indent << "Splitting: " << (this->Splitting ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "Consistency: " << (this->Consistency ? "On" : "Off") << "\n";
  os << indent << "NumberOfDuplicatedFaces: " << this->NumberOfDuplicatedFaces << "\n";
  os << indent << "NumberOfConnectivityBuilds: " << this->NumberOfConnectivityBuilds << "\n";
}

namespace
{
// Unit face normals (zero for faces of no area), and each face's |e1 x e2|.
void FaceNormals(const TriMesh& mesh, const std::vector<vtkIdType>& tri, std::vector<Vec3>& normal,
  std::vector<double>& doubleArea)
{
  const size_t faces = tri.size() / 3;
  normal.resize(faces);
  doubleArea.resize(faces);
  const Vec3* p = mesh.points();
  for (size_t f = 0; f < faces; ++f)
  {
    const Vec3& p0 = p[tri[3 * f]];
    const Vec3 n = OpenMesh::cross(p[tri[3 * f + 1]] - p0, p[tri[3 * f + 2]] - p0);
    const double length = n.norm();
    // Zero (or overflowing) cross products give no direction: no weight.
    const bool usable = length > 0 && std::isfinite(length);
    normal[f] = usable ? n / length : Vec3(0, 0, 0);
    doubleArea[f] = usable ? length : 0;
  }
}

// Sums each face's weighted unit normal into the output point of each of its
// corners (corner c of face f is output point cornerPoint[3f + c]).
void SumFaceNormals(int weighting, const TriMesh& mesh, const std::vector<vtkIdType>& tri,
  const std::vector<vtkIdType>& cornerPoint, const std::vector<Vec3>& faceNormal,
  const std::vector<double>& doubleArea, std::vector<Vec3>& sum)
{
  const Vec3* p = mesh.points();
  const size_t faces = tri.size() / 3;
  for (size_t f = 0; f < faces; ++f)
  {
    const double area2 = doubleArea[f];
    if (area2 == 0)
    {
      continue;
    }
    double w[3];
    switch (weighting)
    {
      case vtkShadelabMeshNormals::Uniform:
        w[0] = w[1] = w[2] = 1;
        break;
      case vtkShadelabMeshNormals::Area:
        w[0] = w[1] = w[2] = area2;
        break;
      default:
      {
        // Edge k runs from corner k to corner k + 1.
        const Vec3 e[3] = { p[tri[3 * f + 1]] - p[tri[3 * f]],
          p[tri[3 * f + 2]] - p[tri[3 * f + 1]], p[tri[3 * f]] - p[tri[3 * f + 2]] };
        if (weighting == vtkShadelabMeshNormals::Max)
        {
          // Max 1999: (a x b) / (|a|^2 |b|^2) with a, b the corner's edges;
          // |a x b| is the same at every corner: twice the area.
          const double l[3] = { e[0].sqrnorm(), e[1].sqrnorm(), e[2].sqrnorm() };
          w[0] = area2 / (l[2] * l[0]);
          w[1] = area2 / (l[0] * l[1]);
          w[2] = area2 / (l[1] * l[2]);
        }
        else
        {
          // The angle at corner k between the edges leaving it, from
          // atan2(|a x b|, a.b): accurate at every size, unlike acos.
          for (int k = 0; k < 3; ++k)
          {
            w[k] = std::atan2(area2, -OpenMesh::dot(e[k], e[(k + 2) % 3]));
          }
        }
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      sum[cornerPoint[3 * f + k]] += w[k] * faceNormal[f];
    }
  }
}
}

int vtkShadelabMeshNormals::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const vtkIdType points = input->GetNumberOfPoints();

  if (!this->Cached || this->Cached->Input != input ||
    this->Cached->InputTime != input->GetMTime() || this->Cached->Consistency != this->Consistency)
  {
    std::vector<vtkIdType> triangles;
    std::string error;
    input->GetPolys()->Visit(TriangleIds{}, points, triangles, error);
    if (!error.empty())
    {
      vtkErrorMacro(<< error);
      this->Cached.reset();
      return 0;
    }
    this->Cached = std::make_unique<Cache>();
    this->Cached->Build(input, this->Consistency, std::move(triangles));
    ++this->NumberOfConnectivityBuilds;
  }
  const Cache& cache = *this->Cached;
  const TriMesh& mesh = cache.Mesh;
  const std::vector<vtkIdType>& tri = cache.Triangles;
  const vtkIdType faces = static_cast<vtkIdType>(tri.size() / 3);
  this->NumberOfDuplicatedFaces = cache.DuplicatedFaces;

  std::vector<Vec3> faceNormal;
  std::vector<double> doubleArea;
  FaceNormals(mesh, tri, faceNormal, doubleArea);

  // Each output point's input point; corners to output points.
  std::vector<vtkIdType> source;
  std::vector<vtkIdType> cornerPoint;
  std::vector<bool> split;
  if (this->Splitting)
  {
    cache.Split(std::cos(vtkMath::RadiansFromDegrees(this->FeatureAngle)), faceNormal, source,
      cornerPoint, split);
  }
  const vtkIdType outputPoints = this->Splitting ? static_cast<vtkIdType>(source.size()) : points;
  const std::vector<vtkIdType>& corners = this->Splitting ? cornerPoint : tri;

  std::vector<Vec3> sum(outputPoints, Vec3(0, 0, 0));
  SumFaceNormals(this->Weighting == Loop ? Angle : this->Weighting, mesh, tri, corners, faceNormal,
    doubleArea, sum);
  if (this->Weighting == Loop)
  {
    // OpenMesh's limit normal where it is one: at an interior vertex whose
    // whole fan is one smooth piece of a manifold mesh.
    for (vtkIdType i = 0; i < points; ++i)
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
      sum[i] = n;
    }
  }

  auto pointNormals = vtkSmartPointer<vtkFloatArray>::New();
  pointNormals->SetName("Normals");
  pointNormals->SetNumberOfComponents(3);
  pointNormals->SetNumberOfTuples(outputPoints);
  float* pn = pointNormals->GetPointer(0);
  for (vtkIdType i = 0; i < outputPoints; ++i)
  {
    const double length = sum[i].norm();
    const Vec3 n = length > 0 && std::isfinite(length) ? sum[i] / length : Vec3(0, 0, 0);
    for (int c = 0; c < 3; ++c)
    {
      pn[3 * i + c] = static_cast<float>(n[c]);
    }
  }
  auto cellNormals = vtkSmartPointer<vtkFloatArray>::New();
  cellNormals->SetName("Normals");
  cellNormals->SetNumberOfComponents(3);
  cellNormals->SetNumberOfTuples(faces);
  float* cn = cellNormals->GetPointer(0);
  for (vtkIdType f = 0; f < faces; ++f)
  {
    for (int c = 0; c < 3; ++c)
    {
      cn[3 * f + c] = static_cast<float>(faceNormal[f][c]);
    }
  }

  // Geometry: the input's as it is unless points were split or faces
  // reversed; only the triangles are kept (verts, lines and strips dropped).
  output->SetPoints(input->GetPoints());
  output->GetPointData()->CopyNormalsOff();
  output->GetCellData()->CopyNormalsOff();
  output->GetCellData()->PassData(input->GetCellData());
  if (this->Splitting || cache.Reversed)
  {
    auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
    connectivity->SetNumberOfValues(3 * faces);
    std::copy(corners.begin(), corners.end(), connectivity->GetPointer(0));
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    polys->SetData(3, connectivity);
    output->SetPolys(polys);
  }
  else
  {
    output->SetPolys(input->GetPolys());
  }
  if (this->Splitting && outputPoints > points)
  {
    auto splitPoints = vtkSmartPointer<vtkPoints>::New();
    splitPoints->SetDataType(input->GetPoints()->GetDataType());
    splitPoints->SetNumberOfPoints(outputPoints);
    auto from = vtkSmartPointer<vtkIdList>::New();
    from->SetNumberOfIds(outputPoints);
    auto to = vtkSmartPointer<vtkIdList>::New();
    to->SetNumberOfIds(outputPoints);
    for (vtkIdType i = 0; i < outputPoints; ++i)
    {
      splitPoints->SetPoint(i, input->GetPoint(source[i]));
      from->SetId(i, source[i]);
      to->SetId(i, i);
    }
    output->SetPoints(splitPoints);
    output->GetPointData()->CopyAllocate(input->GetPointData(), outputPoints);
    output->GetPointData()->CopyData(input->GetPointData(), from, to);
  }
  else
  {
    output->GetPointData()->PassData(input->GetPointData());
  }
  output->GetPointData()->SetNormals(pointNormals);
  output->GetCellData()->SetNormals(cellNormals);
  return 1;
}

void vtkShadelabMeshNormals::Cache::Split(double cosFeature, const std::vector<Vec3>& faceNormal,
  std::vector<vtkIdType>& source, std::vector<vtkIdType>& cornerPoint,
  std::vector<bool>& split) const
{
  const TriMesh& mesh = this->Mesh;
  const std::vector<vtkIdType>& tri = this->Triangles;
  const vtkIdType points = this->Points;

  source.resize(points);
  for (vtkIdType i = 0; i < points; ++i)
  {
    source[i] = i;
  }
  cornerPoint.assign(tri.size(), -1);
  split.assign(points, false);
  std::vector<bool> taken(points, false);

  // The faces around one OpenMesh vertex, grouped by a small union-find:
  // neighbours across an edge that is manifold and not a feature join.
  std::vector<int> face;
  std::vector<int> parent;
  std::vector<vtkIdType> groupPoint;
  auto find = [&parent](int i)
  {
    while (parent[i] != i)
    {
      i = parent[i] = parent[parent[i]];
    }
    return i;
  };
  auto local = [&face](int f)
  {
    for (size_t i = 0; i < face.size(); ++i)
    {
      if (face[i] == f)
      {
        return static_cast<int>(i);
      }
    }
    return -1;
  };
  for (const auto v : mesh.vertices())
  {
    const vtkIdType inputPoint = v.idx() < points ? v.idx() : this->CopyOf[v.idx() - points];
    face.clear();
    for (const auto f : v.faces())
    {
      face.push_back(f.idx());
    }
    if (face.empty())
    {
      continue;
    }
    parent.resize(face.size());
    for (size_t i = 0; i < face.size(); ++i)
    {
      parent[i] = static_cast<int>(i);
    }
    for (const auto h : v.outgoing_halfedges())
    {
      if (h.is_boundary() || h.opp().is_boundary())
      {
        continue;
      }
      const int a = h.face().idx();
      const int b = h.opp().face().idx();
      if (OpenMesh::dot(faceNormal[a], faceNormal[b]) >= cosFeature)
      {
        parent[find(local(a))] = find(local(b));
      }
    }
    // Group roots to output points: the input point's own number for the
    // first group that reaches it, new points after the input's for the rest.
    groupPoint.assign(face.size(), -1);
    for (size_t i = 0; i < face.size(); ++i)
    {
      const int root = find(static_cast<int>(i));
      if (groupPoint[root] < 0)
      {
        if (!taken[inputPoint])
        {
          taken[inputPoint] = true;
          groupPoint[root] = inputPoint;
        }
        else
        {
          split[inputPoint] = true;
          groupPoint[root] = static_cast<vtkIdType>(source.size());
          source.push_back(inputPoint);
        }
      }
      // The corner's number in the face: copies are made three at a time in
      // corner order; an original vertex is found by its id (a face that
      // repeats an id was duplicated).
      const vtkIdType* ids = &tri[3 * face[i]];
      const int k = v.idx() >= points ? (v.idx() - points) % 3
        : ids[0] == inputPoint        ? 0
        : ids[1] == inputPoint        ? 1
                                      : 2;
      cornerPoint[3 * face[i] + k] = groupPoint[root];
    }
  }
}
