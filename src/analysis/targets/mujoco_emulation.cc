// MuJoCo 2.2.2's compiler on a URDF, emulated (PredictMujoco): mjXURDF's body tree, each body's
// compile (mjCBody::Compile: the inertial, the geoms' inertia, the bounds, the sign and triangle
// tests), fusestatic (mjCModel::FuseStatic) and the mjMINVAL test of the moving bodies. The
// numerics are MuJoCo's own (mujoco_numerics.h). The emulation of other inputs (MJCF) belongs
// beside it, sharing MjBody, GeomFrame and FuseStatic.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "analysis/targets/mujoco_numerics.h"
#include "analysis/targets/target_layer.h"

namespace massprops {

using namespace targets;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct MjGeom {
  double mass = 0;
  Vec3 inertia{};
  Vec3 pos{};
  Quat quat{1, 0, 0, 0};
};

struct MjBody {
  int link = -1;
  std::string name;
  int parent = 0;             // index into the body list (0: world)
  std::vector<int> children;  // indices into the body list
  bool moving = false;
  Vec3 pos{};  // in the parent body's frame
  Quat quat{1, 0, 0, 0};
  Vec3 ipos{};  // inertial frame in the body frame
  Quat iquat{1, 0, 0, 0};
  double mass = 0;
  Vec3 inertia{};
  std::vector<int> fused_links;
};

// mjMAX(a, b) as MuJoCo writes it: a NaN `a` gives b.
double MjMax(double a, double b) { return a > b ? a : b; }

class MujocoEmulator {
 public:
  MujocoEmulator(const Model& model, const MujocoCompilerOptions& options)
      : model_(model), options_(options) {}

  MujocoPrediction Run() {
    // The MJCF reader compiles as MuJoCo does and reports its refusals (mjcf_reader.h).
    if (model_.format == Model::Format::kMjcf) return out_;
    if (model_.format != Model::Format::kUrdf) {
      out_.unsupported.push_back("only URDF models are predicted (MuJoCo reads SDF not at all)");
      return out_;
    }
    if (!BuildTree()) return out_;
    // Bodies compile in depth-first order (mjCModel::TryCompile → mjCBody::Compile); the first
    // refusal stops the compiler.
    for (std::size_t i = 1; i < bodies_.size(); ++i) CompileBody(static_cast<int>(i));
    std::vector<int> order;  // the global body list, without the world
    for (std::size_t i = 1; i < bodies_.size(); ++i) order.push_back(static_cast<int>(i));
    if (options_.fusestatic) FuseStatic(&order);
    CheckMovingBodies(order);
    for (int b : order) {
      const MjBody& body = bodies_[b];
      MujocoBody mb;
      mb.name = body.name;
      mb.link = body.link;
      mb.moving = body.moving;
      mb.mass = body.mass;
      mb.inertia = body.inertia;
      mb.fused_links = body.fused_links;
      out_.bodies.push_back(std::move(mb));
    }
    return out_;
  }

 private:
  void Error(const char* rule, const std::string& message, int body, bool names_body = true) {
    MujocoError e;
    e.rule = rule;
    e.message = message;
    if (body > 0) {
      e.body = names_body ? bodies_[body].name : "";
      e.link = bodies_[body].link;
      e.inertia = bodies_[body].inertia;
      e.mass = bodies_[body].mass;
    }
    out_.errors.push_back(std::move(e));
  }

  // The URDF tree as mjXURDF builds it: a body per link but "world", roots (links that are no
  // joint's child) in file order under the world body, children in joint order.
  bool BuildTree() {
    const int n = static_cast<int>(model_.links.size());
    std::vector<int> parent_of(n, -1);
    std::vector<std::vector<int>> children_of(n);
    std::vector<int> joint_of(n, -1);
    for (std::size_t j = 0; j < model_.joints.size(); ++j) {
      const Joint& joint = model_.joints[j];
      const int p = model_.FindLink(joint.parent), c = model_.FindLink(joint.child);
      if (p < 0 || c < 0) {
        out_.unsupported.push_back("joint '" + joint.name +
                                   "' names a link the file does not have (MuJoCo refuses it)");
        return false;
      }
      if (parent_of[c] >= 0) {
        out_.unsupported.push_back("link '" + joint.child +
                                   "' has several parents (MuJoCo refuses it)");
        return false;
      }
      parent_of[c] = p;
      children_of[p].push_back(c);
      joint_of[c] = static_cast<int>(j);
    }
    bodies_.emplace_back();  // the world body
    bodies_[0].name = "world";
    std::vector<int> body_of(n, 0);
    // Iterative depth-first pre-order (children in joint order).
    for (int root = 0; root < n; ++root) {
      if (parent_of[root] >= 0) continue;
      std::vector<std::pair<int, int>> stack = {{root, 0}};  // (link, parent body)
      while (!stack.empty()) {
        const auto [link, parent_body] = stack.back();
        stack.pop_back();
        int here = parent_body;
        if (model_.links[link].name != "world") {
          here = static_cast<int>(bodies_.size());
          MjBody body;
          body.link = link;
          body.name = model_.links[link].name;
          body.parent = parent_body;
          bodies_.push_back(std::move(body));
          bodies_[parent_body].children.push_back(here);
          body_of[link] = here;
        }
        const std::vector<int>& kids = children_of[link];
        for (auto it = kids.rbegin(); it != kids.rend(); ++it) stack.push_back({*it, here});
      }
    }
    for (std::size_t b = 1; b < bodies_.size(); ++b) {
      MjBody& body = bodies_[b];
      const int j = joint_of[body.link];
      if (j < 0) continue;
      const Joint& joint = model_.joints[j];
      body.pos = {joint.X_PC.p_AB.x(), joint.X_PC.p_AB.y(), joint.X_PC.p_AB.z()};
      body.quat = MatrixToQuat(joint.X_PC.R_AB);
      const std::string& type = joint.type_name;
      if (type == "revolute" || type == "continuous" || type == "prismatic" || type == "floating" ||
          type == "planar") {
        body.moving = true;
      } else if (type != "fixed") {
        out_.unsupported.push_back("joint '" + joint.name + "' has type '" + type +
                                   "', which MuJoCo's URDF reader does not know (MuJoCo 2.2.2 "
                                   "fails on it)");
      }
    }
    return true;
  }

  // The geoms MuJoCo makes of a link (collisions; visuals too when discardvisual is off, with
  // density 0), with their mass and diagonal inertia (mjCGeom::GetVolume, SetInertia).
  std::vector<MjGeom> GeomsOf(const Link& link, bool* known) {
    std::vector<MjGeom> geoms;
    for (const Geometry& g : link.geometries) {
      if (!g.is_collision && options_.discardvisual) continue;
      const double density = g.is_collision ? 1000 : 0;
      MjGeom geom;
      geom.pos = {g.X_BG.p_AB.x(), g.X_BG.p_AB.y(), g.X_BG.p_AB.z()};
      geom.quat = MatrixToQuat(g.X_BG.R_AB);
      double volume = 0;
      switch (g.type) {
        case Geometry::Type::kBox: {
          const Vec3 h = {g.size.x() / 2, g.size.y() / 2, g.size.z() / 2};
          volume = h[0] * h[1] * h[2] * 8;
          geom.mass = density * volume;
          geom.inertia = {geom.mass * (h[1] * h[1] + h[2] * h[2]) / 3,
                          geom.mass * (h[0] * h[0] + h[2] * h[2]) / 3,
                          geom.mass * (h[0] * h[0] + h[1] * h[1]) / 3};
          break;
        }
        case Geometry::Type::kCylinder: {
          const double r = g.radius, half = g.length / 2, height = 2 * half;
          volume = kPi * r * r * height;
          geom.mass = density * volume;
          geom.inertia = {geom.mass * (3 * r * r + height * height) / 12,
                          geom.mass * (3 * r * r + height * height) / 12, geom.mass * r * r / 2};
          break;
        }
        case Geometry::Type::kSphere: {
          const double r = g.radius;
          volume = 4 * kPi * r * r * r / 3;
          geom.mass = density * volume;
          geom.inertia = {2 * geom.mass * r * r / 5, 2 * geom.mass * r * r / 5,
                          2 * geom.mass * r * r / 5};
          break;
        }
        default:
          if (density > 0) *known = false;  // a mesh: its volume decides the mass
          break;
      }
      geoms.push_back(geom);
    }
    return geoms;
  }

  // mjCBody::Compile for one URDF body: the inertial (explicit, or from the geoms), then the
  // bounds, the sign test and the triangle test.
  void CompileBody(int b) {
    MjBody& body = bodies_[b];
    const Link& link = model_.links[body.link];
    if (link.inertial_unreadable) {
      out_.unsupported.push_back("the <inertial> of link '" + link.name +
                                 "' could not be read (inertial-unreadable)");
    }
    const bool from_geoms =
        options_.inertiafromgeom == MujocoCompilerOptions::InertiaFromGeom::kTrue ||
        (!link.inertial &&
         options_.inertiafromgeom == MujocoCompilerOptions::InertiaFromGeom::kAuto);
    if (link.inertial) {
      // mjXURDF::Body: the six numbers through mju_eig3; the inertial frame turned by its
      // principal axes.
      const Inertial& in = *link.inertial;
      const MujocoEigen eig = MujocoEig3({in.ixx, in.iyy, in.izz, in.ixy, in.ixz, in.iyz});
      body.mass = in.mass;
      body.inertia = eig.values;
      body.ipos = {in.X_BBi.p_AB.x(), in.X_BBi.p_AB.y(), in.X_BBi.p_AB.z()};
      body.iquat = QuatProductCompiler(MatrixToQuat(in.X_BBi.R_AB), eig.quat);
    }
    if (from_geoms) {
      bool known = true;
      const std::vector<MjGeom> geoms = GeomsOf(link, &known);
      if (!known) {
        out_.unsupported.push_back("link '" + link.name +
                                   "' takes its inertia from mesh geometry, whose volume MuJoCo "
                                   "computes from the mesh file");
      }
      GeomFrame(b, geoms);
    }
    NormalizeCompiler(&body.iquat);
    // Bounds (boundmass, boundinertia), then the checks (user_objects.cc, mjCBody::Compile).
    body.mass = MjMax(body.mass, options_.boundmass);
    for (double& x : body.inertia) x = MjMax(x, options_.boundinertia);
    const Vec3& I = body.inertia;
    if (body.mass < 0 || I[0] < 0 || I[1] < 0 || I[2] < 0) {
      Error(kMujocoNegative, "mass and inertia cannot be negative", b);
      return;
    }
    if (I[0] + I[1] < I[2] || I[0] + I[2] < I[1] || I[1] + I[2] < I[0]) {
      if (!options_.balanceinertia) {
        Error(kMujocoTriangle, "inertia must satisfy A + B >= C; use 'balanceinertia' to fix", b);
      }
      // balanceinertia (and, past a refusal, the emulation) goes on with the mean.
      const double mean = (I[0] + I[1] + I[2]) / 3.0;
      body.inertia = {mean, mean, mean};
    }
  }

  // mjCBody::GeomFrame: one geom is copied; several are composed and re-diagonalised.
  void GeomFrame(int b, const std::vector<MjGeom>& geoms) {
    MjBody& body = bodies_[b];
    if (geoms.size() == 1) {
      body.ipos = geoms[0].pos;
      body.iquat = geoms[0].quat;
      body.mass = geoms[0].mass;
      body.inertia = geoms[0].inertia;
      return;
    }
    if (geoms.empty()) return;
    double mass = 0;
    Vec3 com{};
    for (const MjGeom& g : geoms) {
      mass += g.mass;
      for (int k = 0; k < 3; ++k) com[k] += g.mass * g.pos[k];
    }
    if (mass < kMujocoMinVal) {
      body.mass = mass;
      Error(kMujocoGeomMass, "body mass is too small, cannot compute center of mass", b);
      return;
    }
    body.mass = mass;
    for (int k = 0; k < 3; ++k) body.ipos[k] = com[k] / mass;
    std::array<double, 6> total{};
    for (const MjGeom& g : geoms) {
      const Vec3 d = {g.pos[0] - body.ipos[0], g.pos[1] - body.ipos[1], g.pos[2] - body.ipos[2]};
      const std::array<double, 6> a = RotateDiagonalInertia(g.inertia, g.quat);
      const std::array<double, 6> c = OffCenter(g.mass, d);
      for (int k = 0; k < 6; ++k) total[k] = total[k] + a[k] + c[k];
    }
    const MujocoEigen eig = MujocoEig3(total);
    body.iquat = eig.quat;
    body.inertia = eig.values;
    if (eig.values[2] < kMujocoEps) {
      Error(kMujocoGeomMass,
            "error 'inertia must have positive eigenvalues' in alternative for principal axes", b);
    }
  }

  // mjCModel::FuseStatic: every body without joints is merged into its parent (its mass only
  // when it is at least mjMINVAL and the parent is not the world), its children move up.
  void FuseStatic(std::vector<int>* order) {
    for (std::size_t i = 0; i < order->size();) {
      const int b = (*order)[i];
      MjBody& body = bodies_[b];
      if (body.moving) {
        ++i;
        continue;
      }
      MjBody& par = bodies_[body.parent];
      if (body.parent > 0 && body.mass >= kMujocoMinVal) {
        // The body's inertial frame in the parent's frame.
        Vec3 ipos = body.pos;
        Quat iquat = body.quat;
        FrameAccumulate(&ipos, &iquat, body.ipos, body.iquat);
        const double masses[2] = {par.mass, body.mass};
        const Vec3 inertias[2] = {par.inertia, body.inertia};
        const Vec3 iposes[2] = {par.ipos, ipos};
        const Quat iquats[2] = {par.iquat, iquat};
        par.mass = 0;
        par.ipos = {0, 0, 0};
        for (int j = 0; j < 2; ++j) {
          par.mass += masses[j];
          for (int k = 0; k < 3; ++k) par.ipos[k] += masses[j] * iposes[j][k];
        }
        if (par.mass < kMujocoMinVal) {
          par.mass = 0;
          par.inertia = {0, 0, 0};
          par.ipos = {0, 0, 0};
          par.iquat = {1, 0, 0, 0};
        } else {
          for (int k = 0; k < 3; ++k) par.ipos[k] /= par.mass;
          std::array<double, 6> total{};
          for (int j = 0; j < 2; ++j) {
            const Vec3 d = {iposes[j][0] - par.ipos[0], iposes[j][1] - par.ipos[1],
                            iposes[j][2] - par.ipos[2]};
            const std::array<double, 6> a = RotateDiagonalInertia(inertias[j], iquats[j]);
            const std::array<double, 6> c = OffCenter(masses[j], d);
            for (int k = 0; k < 6; ++k) total[k] += a[k] + c[k];
          }
          const MujocoEigen eig = MujocoEig3(total);
          par.iquat = eig.quat;
          par.inertia = eig.values;
          if (eig.values[2] < kMujocoEps) {
            // MuJoCo names no body here (mjCError(NULL, ...)); the body fused into is `par`.
            Error(kMujocoFusedInertia,
                  "error 'inertia must have positive eigenvalues' in fusing static body inertias",
                  body.parent, /*names_body=*/false);
          }
        }
        par.fused_links.push_back(body.link);
        for (int f : body.fused_links) par.fused_links.push_back(f);
      }
      // The children move to the parent, in the body's place, their frames composed.
      std::vector<int>& siblings = par.children;
      auto at = std::find(siblings.begin(), siblings.end(), b);
      std::vector<int> kids = body.children;
      for (int k : kids) {
        MjBody& kid = bodies_[k];
        Vec3 pos = body.pos;
        Quat quat = body.quat;
        FrameAccumulate(&pos, &quat, kid.pos, kid.quat);
        kid.pos = pos;
        kid.quat = quat;
        kid.parent = body.parent;
      }
      if (at != siblings.end()) {
        const auto index = at - siblings.begin();
        siblings.insert(siblings.begin() + index, kids.begin(), kids.end());
        siblings.erase(siblings.begin() + index + static_cast<long>(kids.size()));
      }
      body.children.clear();
      order->erase(order->begin() + static_cast<long>(i));  // the next body takes index i
    }
  }

  // mjCModel::TryCompile after FuseStatic: a moving body needs mass and every principal moment at
  // least mjMINVAL, unless a static child of it has them (only possible without fusestatic).
  void CheckMovingBodies(const std::vector<int>& order) {
    for (int b : order) {
      const MjBody& body = bodies_[b];
      if (!body.moving) continue;
      auto enough = [](const MjBody& x) {
        return x.mass >= kMujocoMinVal && x.inertia[0] >= kMujocoMinVal &&
               x.inertia[1] >= kMujocoMinVal && x.inertia[2] >= kMujocoMinVal;
      };
      if (enough(body)) continue;
      bool ok = false;
      for (int c : body.children) ok = ok || (!bodies_[c].moving && enough(bodies_[c]));
      if (!ok)
        Error(kMujocoMinValRule, "mass and inertia of moving bodies must be larger than mjMINVAL",
              b);
    }
  }

  const Model& model_;
  const MujocoCompilerOptions& options_;
  std::vector<MjBody> bodies_;
  MujocoPrediction out_;
};

}  // namespace

MujocoPrediction PredictMujoco(const Model& model, const MujocoCompilerOptions& options) {
  return MujocoEmulator(model, options).Run();
}

}  // namespace massprops
