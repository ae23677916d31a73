// One <geom> as MuJoCo 2.2.2's compiler reads it: type (default sphere), size, fromto (for
// capsule, cylinder, box, ellipsoid: the center, the z axis along it and the half length),
// pos and orientation, and its mass: `mass` if given (then density = mass / volume), else
// density (default 1000) × volume; primitives by the formulas of mjCGeom::GetVolume and
// SetInertia (the exact solids), meshes by mesh.h.

#include "io/mjcf/geom.h"

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "io/mjcf/mujoco_numbers.h"
#include "massprops/mesh/mesh_loader.h"

namespace massprops {
namespace mjcf {
namespace {

Pose MakePose(const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  return {p, q.toRotationMatrix()};
}

// Volume and central moments per unit density of a primitive with MuJoCo's half sizes s.
bool PrimitiveSolid(const std::string& type, const Eigen::Vector3d& s, double* volume,
                    Eigen::Vector3d* moments) {
  const double pi = M_PI;
  if (type == "sphere") {
    *volume = 4 * pi * s[0] * s[0] * s[0] / 3;
    moments->setConstant(2 * *volume * s[0] * s[0] / 5);
  } else if (type == "capsule") {
    const double r = s[0], h = 2 * s[1];
    *volume = pi * (r * r * h + 4 * r * r * r / 3);
    const double sphere = *volume * 4 * r / (4 * r + 3 * h), cylinder = *volume - sphere;
    const double side = cylinder * (3 * r * r + h * h) / 12 + 2 * sphere * r * r / 5 +
                        sphere * h * (3 * r + 2 * h) / 8;
    *moments << side, side, cylinder * r * r / 2 + 2 * sphere * r * r / 5;
  } else if (type == "cylinder") {
    const double h = 2 * s[1];
    *volume = pi * s[0] * s[0] * h;
    const double side = *volume * (3 * s[0] * s[0] + h * h) / 12;
    *moments << side, side, *volume * s[0] * s[0] / 2;
  } else if (type == "ellipsoid" || type == "box") {
    const bool box = type == "box";
    *volume = box ? 8 * s[0] * s[1] * s[2] : 4 * pi * s[0] * s[1] * s[2] / 3;
    const double k = *volume / (box ? 3 : 5);
    *moments << k * (s[1] * s[1] + s[2] * s[2]), k * (s[0] * s[0] + s[2] * s[2]),
        k * (s[0] * s[0] + s[1] * s[1]);
  } else {
    return false;
  }
  return true;
}

Geometry MakeGeometry(const std::string& type, const Eigen::Vector3d& s) {
  Geometry g;
  if (type == "box") {
    g.type = Geometry::Type::kBox;
    g.size = 2 * s;
  } else if (type == "sphere") {
    g.type = Geometry::Type::kSphere;
    g.radius = s[0];
  } else if (type == "capsule" || type == "cylinder") {
    g.type = type == "capsule" ? Geometry::Type::kCapsule : Geometry::Type::kCylinder;
    g.radius = s[0];
    g.length = 2 * s[1];
  } else if (type == "ellipsoid") {
    g.type = Geometry::Type::kEllipsoid;
    g.radii = s;
  } else if (type == "mesh") {
    g.type = Geometry::Type::kMesh;
  }
  return g;
}

// Checks the sizes MuJoCo requires positive (its checksize); "" when fine.
std::string SizeProblem(const std::string& type, const Eigen::Vector3d& s) {
  const int needed = type == "sphere"                          ? 1
                     : type == "capsule" || type == "cylinder" ? 2
                     : type == "box" || type == "ellipsoid"    ? 3
                                                               : 0;
  for (int i = 0; i < needed; ++i) {
    if (!(s[i] > 0)) {
      return "size " + std::to_string(i) + " of a " + type + " must be positive (MuJoCo " +
             "refuses the model)";
    }
  }
  return "";
}

// The triangles of a <mesh face="...">: each number must be a whole vertex index (MuJoCo reads
// them as integers and refuses an index outside the vertex list). An error message, or "".
std::string FaceTriangles(const std::vector<double>& face, std::size_t vertex_count,
                          std::vector<std::array<std::int32_t, 3>>* triangles) {
  for (std::size_t i = 0; i < face.size(); i += 3) {
    std::array<std::int32_t, 3> triangle{};
    for (std::size_t k = 0; k < 3; ++k) {
      const double index = face[i + k];
      // Compared as doubles before any conversion: a NaN or a huge number fails here.
      if (!(index >= 0 && index < static_cast<double>(vertex_count)) ||
          index != std::floor(index)) {
        std::ostringstream message;
        message << "<mesh face> number " << i + k << " is " << index
                << ", not a vertex index in [0, " << vertex_count << ")";
        return message.str();
      }
      triangle[k] = static_cast<std::int32_t>(index);
    }
    triangles->push_back(triangle);
  }
  return "";
}

}  // namespace

std::optional<MeshSolid> MeshSolids::Get(Context* context, const Node& node, bool compute,
                                         std::string* uri, Eigen::Vector3d* scale,
                                         std::string* error) {
  auto [it, inserted] = entries_.try_emplace(&node);
  Entry& entry = it->second;
  const std::string* file = node.Find("file");
  const Element element = MakeElement(*context, node, "");
  if (inserted) {
    if (auto v = Numbers(context, element, "scale", 3, -1, "scale")) {
      entry.scale = Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
    }
    if (file != nullptr) {
      const Compiler& c = context->compiler;
      const std::string& dir = !c.meshdir.empty() ? c.meshdir : c.assetdir;
      const std::filesystem::path path(*file);
      entry.uri =
          path.is_absolute() || dir.empty() ? *file : (std::filesystem::path(dir) / path).string();
    }
  }
  if (compute && !entry.computed) {
    entry.computed = true;
    TriangleMesh mesh;
    if (file != nullptr) {
      std::filesystem::path full(entry.uri);
      if (full.is_relative() && model_file_ != "<stdin>") {
        full = std::filesystem::path(model_file_).parent_path() / full;
      }
      if (!LoadMeshFile(full.string(), &mesh, &entry.error) &&
          entry.error.rfind("mesh file '", 0) != 0) {  // else it names the file already
        entry.error = "mesh '" + entry.uri + "': " + entry.error;
      }
    } else {
      auto vertex = Numbers(context, element, "vertex", 1 << 30, 1, "vertex");
      auto face = Numbers(context, element, "face", 1 << 30, 1, "face");
      if (!vertex || vertex->size() % 3 != 0 || !face || face->size() % 3 != 0) {
        entry.error = "a <mesh> without file needs vertex and face (a multiple of 3 numbers " +
                      std::string("each); massprops does not build MuJoCo's convex hull");
      } else {
        for (std::size_t i = 0; i < vertex->size(); i += 3) {
          mesh.vertices.emplace_back((*vertex)[i], (*vertex)[i + 1], (*vertex)[i + 2]);
        }
        entry.error = FaceTriangles(*face, mesh.vertices.size(), &mesh.triangles);
      }
    }
    if (node.Find("refpos") || node.Find("refquat")) {
      entry.error = "<mesh refpos/refquat> is not reproduced by massprops";
    }
    if (entry.error.empty()) {
      std::string why;
      entry.solid = CalcMeshSolid(mesh, entry.scale, method_, &why);
      if (!entry.solid) entry.error = "mesh '" + entry.uri + "': " + why + " (MuJoCo's check)";
    }
  }
  *uri = entry.uri;
  *scale = entry.scale;
  *error = entry.error;
  return entry.solid;
}

GeomReading ReadGeom(Context* context, const Element& element, bool want_mass, MeshSolids* meshes) {
  GeomReading reading;
  const Node& node = *element.node;
  const std::string* name = node.Find("name");
  const std::string what = name ? "'" + *name + "'" : "";
  const std::string* type_text = element.Get("type");
  const std::string type = type_text ? *type_text : "sphere";
  Eigen::Vector3d s = Eigen::Vector3d::Zero();
  if (auto v = Numbers(context, element, "size", 3, 1, what)) {
    for (std::size_t i = 0; i < v->size(); ++i) s[static_cast<int>(i)] = (*v)[i];
  }
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  if (auto v = Numbers(context, element, "pos", 3, -1, what)) p << (*v)[0], (*v)[1], (*v)[2];
  Eigen::Quaterniond q = Orientation(context, element, what);
  if (auto v = Numbers(context, element, "fromto", 6, -1, what)) {
    const Eigen::Vector3d from((*v)[0], (*v)[1], (*v)[2]), to((*v)[3], (*v)[4], (*v)[5]);
    const Eigen::Vector3d vec = from - to;
    if (type != "capsule" && type != "cylinder" && type != "box" && type != "ellipsoid") {
      context->Error(node, "<geom> " + what,
                     "fromto requires capsule, cylinder, box or ellipsoid (MuJoCo refuses it)");
    } else if (vec.norm() / 2 < kMjEps) {
      context->Error(node, "<geom> " + what, "fromto points too close");
    } else {
      s[1] = vec.norm() / 2;
      if (type == "box" || type == "ellipsoid") {
        s[2] = s[1];
        s[1] = s[0];
      }
      p = (from + to) / 2;
      q = RotationFromZ(vec.normalized());
    }
  }
  const Pose X_BG = MakePose(p, q);
  reading.geometry = MakeGeometry(type, s);
  reading.geometry.X_BG = X_BG;
  reading.geometry.location = context->document->Where(node);
  if (auto v = Numbers(context, element, "group", 1, -1, what)) {
    // MuJoCo reads an int: a number outside int's range (or with a fraction) is refused, and is
    // compared as a double before any conversion (a conversion out of range is undefined).
    const double group = (*v)[0];
    if (group >= std::numeric_limits<int>::min() && group <= std::numeric_limits<int>::max() &&
        group == std::floor(group)) {
      reading.group = static_cast<int>(group);
    } else {
      context->Error(node, "<geom> " + what,
                     "group " + *element.Get("group") + " is not an integer");
    }
  }
  double contype = 1, conaffinity = 1;
  if (auto v = Numbers(context, element, "contype", 1, -1, what)) contype = (*v)[0];
  if (auto v = Numbers(context, element, "conaffinity", 1, -1, what)) conaffinity = (*v)[0];
  reading.visual_only = contype == 0 && conaffinity == 0;
  reading.geometry.is_collision = !reading.visual_only;

  double volume = 0;
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();  // Per unit density.
  Eigen::Vector3d p_GoGcm_G = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_GGi = Eigen::Quaterniond::Identity();
  const std::string* mesh_name = element.Get("mesh");
  if (type == "mesh" || mesh_name != nullptr) {
    const auto mesh = mesh_name ? context->meshes.find(*mesh_name) : context->meshes.end();
    if (mesh == context->meshes.end()) {
      context->Error(node, "<geom> " + what,
                     mesh_name ? "names the mesh '" + *mesh_name + "', which no <mesh> defines"
                               : "a mesh geom needs a mesh attribute");
      return reading;
    }
    if (type != "mesh") {
      reading.mass_error = "a " + type + " fitted to mesh '" + *mesh_name +
                           "' (MuJoCo's fitscale) is not reproduced by massprops";
      return reading;
    }
    std::string error;
    const std::optional<MeshSolid> solid = meshes->Get(
        context, *mesh->second, want_mass, &reading.geometry.uri, &reading.geometry.scale, &error);
    if (!want_mass) return reading;
    if (!solid) {
      reading.mass_error = error;
      return reading;
    }
    volume = solid->volume;
    p_GoGcm_G = solid->p_GoGcm_G;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(solid->I_GGcm_G_per_density);
    moments = eigen.eigenvalues();
    Eigen::Matrix3d V = eigen.eigenvectors();
    if (V.determinant() < 0) V.col(2) = -V.col(2);
    q_GGi = Eigen::Quaterniond(V);
  } else {
    const std::string problem = SizeProblem(type, s);
    if (!problem.empty()) context->Error(node, "<geom> " + what, problem);
    if (!want_mass) return reading;
    PrimitiveSolid(type, s, &volume, &moments);  // plane, hfield: no volume.
  }
  GeomMass mass;
  double density = 1000;
  if (auto v = Numbers(context, element, "density", 1, -1, what)) density = (*v)[0];
  double scale = density;  // mass / volume.
  if (auto v = Numbers(context, element, "mass", 1, -1, what)) {
    scale = (*v)[0] == 0 || !(volume > kMjMinVal) ? 0 : (*v)[0] / volume;
  }
  mass.mass = scale * volume;
  mass.moments = scale * moments;
  mass.p_BoGcm_B = p + q * p_GoGcm_G;
  mass.q_BGi = q * q_GGi;
  if (mass.mass < 0 || scale < 0) {
    context->Error(node, "<geom> " + what,
                   "mass, inertia or density are negative (MuJoCo refuses the model)");
  }
  reading.mass = mass;
  return reading;
}

}  // namespace mjcf
}  // namespace massprops
