#pragma once
// Private to the MJCF reader: one <geom> as MuJoCo 2.2.2's compiler reads it (mjCGeom::Compile,
// GetVolume, SetInertia in src/user/user_objects.cc), its Geometry for the Model, and its mass,
// center and inertia in the body frame.

#include <Eigen/Core>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "io/mjcf/mesh.h"
#include "io/mjcf/tree.h"
#include "massprops/model/model.h"

namespace massprops {
namespace mjcf {

/// A geom's part of its body's mass properties, in the body frame B.
struct GeomMass {
  double mass = 0;
  Eigen::Vector3d p_BoGcm_B = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_BGi = Eigen::Quaterniond::Identity();  ///< Principal frame Gi of the geom.
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();          ///< About Gcm, along Gi's axes.
};

/// One geom: what the Model keeps and what the compiler makes of its mass.
struct GeomReading {
  Geometry geometry;
  int group = 0;
  bool visual_only = false;      ///< contype and conaffinity both 0.
  std::optional<GeomMass> mass;  ///< Only when asked for (ReadGeom's want_mass).
  /// Why the mass could not be computed (a mesh that cannot be read or MuJoCo refuses).
  std::string mass_error;
};

/// The meshes of one read, each loaded and integrated once per method.
class MeshSolids {
 public:
  MeshSolids(const std::string& model_file, MeshMethod method)
      : model_file_(model_file), method_(method) {}
  /// The solid of the <mesh> asset `node` (its file or vertex/face, with its scale), or nullopt
  /// and *error; the mesh is read and integrated only when `compute` (else only uri and scale).
  std::optional<MeshSolid> Get(Context* context, const Node& node, bool compute, std::string* uri,
                               Eigen::Vector3d* scale, std::string* error);

 private:
  struct Entry {
    std::optional<MeshSolid> solid;
    std::string uri, error;
    Eigen::Vector3d scale = Eigen::Vector3d::Ones();
    bool computed = false;
  };
  std::string model_file_;
  MeshMethod method_;
  std::map<const Node*, Entry> entries_;
};

/// Reads the geom `element` of a body. want_mass: the compiler infers the body's inertia from
/// its geoms, so the geom's mass properties are computed. Number errors go through context.
GeomReading ReadGeom(Context* context, const Element& element, bool want_mass, MeshSolids* meshes);

}  // namespace mjcf
}  // namespace massprops
