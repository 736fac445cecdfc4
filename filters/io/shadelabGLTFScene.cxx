#include "shadelabGLTFScene.h"

#include "shadelabMeshReadError.h"

#include <cmath>
#include <string>
#include <utility>

namespace shadelab::gltf
{
namespace
{
constexpr Matrix Identity = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };

Matrix Multiply(const Matrix& a, const Matrix& b)
{
  Matrix product{};
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      for (int k = 0; k < 4; ++k)
      {
        product[4 * r + c] += a[4 * r + k] * b[4 * k + c];
      }
    }
  }
  return product;
}

// T * R * S from a node's translation, rotation (x y z w) and scale.
Matrix FromTRS(const Json& node, const std::string& where)
{
  const std::vector<double> t = Numbers(node, "translation", where, 3, { 0, 0, 0 });
  std::vector<double> q = Numbers(node, "rotation", where, 4, { 0, 0, 0, 1 });
  const std::vector<double> s = Numbers(node, "scale", where, 3, { 1, 1, 1 });
  const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(length > 0) || !std::isfinite(length))
  {
    Fail(where + ".rotation is not a rotation quaternion");
  }
  for (double& value : q)
  {
    value /= length;
  }
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  const double r[9] = { 1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
    2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), 2 * (x * z - y * w),
    2 * (y * z + x * w), 1 - 2 * (x * x + y * y) };
  Matrix m = Identity;
  for (int row = 0; row < 3; ++row)
  {
    for (int col = 0; col < 3; ++col)
    {
      m[4 * row + col] = r[3 * row + col] * s[col];
    }
    m[4 * row + 3] = t[row];
  }
  return m;
}

Matrix LocalMatrix(const Json& node, const std::string& where)
{
  if (!node.contains("matrix"))
  {
    return FromTRS(node, where);
  }
  if (node.contains("translation") || node.contains("rotation") || node.contains("scale"))
  {
    Fail(where + " has both a matrix and translation, rotation or scale");
  }
  const std::vector<double> columns = Numbers(node, "matrix", where, 16, {});
  Matrix m;
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      m[4 * r + c] = columns[4 * c + r];
    }
  }
  return m;
}

// The scene's root nodes, or without scenes those that are nobody's child.
std::vector<std::uint64_t> RootNodes(const Json& root)
{
  const Json& scenes = List(root, "scenes");
  const Json& nodes = List(root, "nodes");
  std::vector<std::uint64_t> roots;
  if (root.contains("scene") || !scenes.empty())
  {
    const std::uint64_t index = Unsigned(root, "scene", "the document", 0);
    const Json& scene = Item(root, "scenes", index, "the document's scene");
    const std::string where = "scene " + std::to_string(index);
    for (std::size_t k = 0; k < List(scene, "nodes").size(); ++k)
    {
      roots.push_back(UnsignedAt(scene["nodes"], k, where + ".nodes"));
    }
    return roots;
  }
  std::vector<bool> isChild(nodes.size(), false);
  for (std::size_t n = 0; n < nodes.size(); ++n)
  {
    const Json& node = Item(root, "nodes", n, "the document");
    const std::string where = "node " + std::to_string(n) + ".children";
    for (std::size_t k = 0; k < List(node, "children").size(); ++k)
    {
      const std::uint64_t child = UnsignedAt(node["children"], k, where);
      if (child < nodes.size())
      {
        isChild[child] = true;
      }
    }
  }
  for (std::size_t n = 0; n < nodes.size(); ++n)
  {
    if (!isChild[n])
    {
      roots.push_back(n);
    }
  }
  return roots;
}
}

std::vector<MeshInstance> SceneMeshes(const Json& root)
{
  std::vector<MeshInstance> instances;
  if (!root.contains("scene") && List(root, "scenes").empty() && List(root, "nodes").empty())
  {
    for (std::size_t m = 0; m < List(root, "meshes").size(); ++m)
    {
      instances.push_back({ m, Identity });
    }
    return instances;
  }
  const std::vector<std::uint64_t> roots = RootNodes(root);
  std::vector<bool> reached(List(root, "nodes").size(), false);
  // Depth-first with a stack of its own: a chain of many nodes must not
  // overflow the call stack.
  std::vector<std::pair<std::uint64_t, Matrix>> stack;
  for (auto r = roots.rbegin(); r != roots.rend(); ++r)
  {
    stack.emplace_back(*r, Identity);
  }
  while (!stack.empty())
  {
    const auto [index, parent] = stack.back();
    stack.pop_back();
    const std::string where = "node " + std::to_string(index);
    const Json& node = Item(root, "nodes", index, "a scene");
    if (reached[index])
    {
      Fail(where + " is reached twice: nodes must form trees");
    }
    reached[index] = true;
    const Matrix world = Multiply(parent, LocalMatrix(node, where));
    if (node.contains("mesh"))
    {
      const std::uint64_t mesh = Unsigned(node, "mesh", where);
      Item(root, "meshes", mesh, where);
      instances.push_back({ mesh, world });
    }
    const Json& children = List(node, "children");
    for (std::size_t k = children.size(); k-- > 0;)
    {
      stack.emplace_back(UnsignedAt(children, k, where + ".children"), world);
    }
  }
  return instances;
}

WorldTransform::WorldTransform(const Matrix& m)
  : M(m)
{
  const auto a = [&](int r, int c) { return m[4 * r + c]; };
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      this->Cofactor[3 * r + c] = a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1);
    }
  }
  this->Determinant =
    a(0, 0) * this->Cofactor[0] + a(0, 1) * this->Cofactor[1] + a(0, 2) * this->Cofactor[2];
}

void WorldTransform::Point(const float* p, std::vector<double>& out) const
{
  for (int r = 0; r < 3; ++r)
  {
    out.push_back(this->M[4 * r] * p[0] + this->M[4 * r + 1] * p[1] + this->M[4 * r + 2] * p[2] +
      this->M[4 * r + 3]);
  }
}

// The inverse transpose is the cofactor matrix over the determinant; only
// its sign matters before renormalising (and a singular transform, a
// node scaled to nothing, gives what the cofactors give, or zero).
void WorldTransform::Normal(const float* n, std::vector<float>& out) const
{
  const double sign = this->Determinant < 0 ? -1 : 1;
  double v[3];
  for (int r = 0; r < 3; ++r)
  {
    v[r] = sign *
      (this->Cofactor[3 * r] * n[0] + this->Cofactor[3 * r + 1] * n[1] +
        this->Cofactor[3 * r + 2] * n[2]);
  }
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (const double component : v)
  {
    out.push_back(static_cast<float>(length > 0 ? component / length : component));
  }
}
}
