#include "massprops/analysis/target_profile.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "analysis/rule_severity.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/core/rotational_inertia.h"

namespace massprops {
namespace {

// Rule ids of the target layer (docs/targets.md explains each, with its source).
constexpr const char* kMujocoTriangle = "mujoco-rejects-inertia-triangle";
constexpr const char* kMujocoMinValRule = "mujoco-rejects-below-minval";
constexpr const char* kMujocoFusedInertia = "mujoco-rejects-fused-inertia";
constexpr const char* kMujocoGeomMass = "mujoco-rejects-geom-inertia";
constexpr const char* kMujocoNegative = "mujoco-rejects-negative";
constexpr const char* kMujocoUnpredicted = "mujoco-not-predicted";
constexpr const char* kDrakeMassless = "drake-rejects-massless-body";
constexpr const char* kDrakeInvalid = "drake-rejects-invalid-inertia";
constexpr const char* kGazeboLumped = "gazebo-lumps-fixed-joint";

std::string Num(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.6g", x);
  return buffer;
}

std::string Moments(const std::array<double, 3>& m) {
  return Num(m[0]) + ", " + Num(m[1]) + ", " + Num(m[2]);
}

// --------------------------------------------------------------------------- MuJoCo numerics
// Each helper computes what the MuJoCo 2.2.2 function of the same purpose computes, with the
// same order of floating-point operations, so that borderline decisions agree bit for bit.

using Quat = std::array<double, 4>;
using Vec3 = std::array<double, 3>;
using Mat3 = std::array<double, 9>;  // row-major

// Rotation matrix of a unit quaternion (mju_quat2Mat: the identity quaternion gives exactly I).
Mat3 QuatToMatrix(const Quat& q) {
  if (q[0] == 1 && q[1] == 0 && q[2] == 0 && q[3] == 0) return {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const double q00 = q[0] * q[0], q01 = q[0] * q[1], q02 = q[0] * q[2], q03 = q[0] * q[3];
  const double q11 = q[1] * q[1], q12 = q[1] * q[2], q13 = q[1] * q[3];
  const double q22 = q[2] * q[2], q23 = q[2] * q[3], q33 = q[3] * q[3];
  Mat3 r;
  r[0] = q00 + q11 - q22 - q33;
  r[4] = q00 - q11 + q22 - q33;
  r[8] = q00 - q11 - q22 + q33;
  r[1] = 2 * (q12 - q03);
  r[2] = 2 * (q13 + q02);
  r[3] = 2 * (q12 + q03);
  r[5] = 2 * (q23 - q01);
  r[6] = 2 * (q13 - q02);
  r[7] = 2 * (q23 + q01);
  return r;
}

// The compiler's quaternion-to-matrix (mjuu_quat2mat: no identity shortcut).
Mat3 QuatToMatrixCompiler(const Quat& q) {
  const double q00 = q[0] * q[0], q11 = q[1] * q[1], q22 = q[2] * q[2], q33 = q[3] * q[3];
  Mat3 r;
  r[0] = q00 + q11 - q22 - q33;
  r[4] = q00 - q11 + q22 - q33;
  r[8] = q00 - q11 - q22 + q33;
  r[1] = 2 * (q[1] * q[2] - q[0] * q[3]);
  r[2] = 2 * (q[1] * q[3] + q[0] * q[2]);
  r[3] = 2 * (q[1] * q[2] + q[0] * q[3]);
  r[5] = 2 * (q[2] * q[3] - q[0] * q[1]);
  r[6] = 2 * (q[1] * q[3] - q[0] * q[2]);
  r[7] = 2 * (q[2] * q[3] + q[0] * q[1]);
  return r;
}

Quat QuatProduct(const Quat& a, const Quat& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

// Engine normalisation (mju_normalize4): multiply by the inverse norm; tiny → identity.
void NormalizeEngine(Quat* q) {
  Quat& v = *q;
  const double norm = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
  if (norm < kMujocoMinVal) {
    v = {1, 0, 0, 0};
    return;
  }
  const double inverse = 1 / norm;
  for (double& x : v) x *= inverse;
}

// Compiler normalisation (mjuu_normvec): divide by the norm; squared norm below mjEPS → as is.
template <std::size_t N>
void NormalizeCompiler(std::array<double, N>* vec) {
  double sum = 0;
  for (double x : *vec) sum += x * x;
  if (sum < kMujocoEps) return;
  const double norm = std::sqrt(sum);
  for (double& x : *vec) x /= norm;
}

// The compiler's quaternion product (mjuu_mulquat), normalised.
Quat QuatProductCompiler(const Quat& a, const Quat& b) {
  Quat r = QuatProduct(a, b);
  NormalizeCompiler(&r);
  return r;
}

// res = mat1ᵀ·mat2 and res = mat1·mat2 for 3x3, accumulated row by row as mju_mulMatTMat and
// mju_mulMatMat do (a zero multiplier is skipped).
Mat3 MulTransposeLeft(const Mat3& a, const Mat3& b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double s = a[i * 3 + j];
      if (s == 0) continue;
      for (int k = 0; k < 3; ++k) r[j * 3 + k] += b[i * 3 + k] * s;
    }
  }
  return r;
}

Mat3 Mul(const Mat3& a, const Mat3& b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      const double s = a[i * 3 + k];
      if (s == 0) continue;
      for (int j = 0; j < 3; ++j) r[i * 3 + j] += b[k * 3 + j] * s;
    }
  }
  return r;
}

// Diagonal inertia `local` in a frame rotated by q, as the 6 numbers {xx, yy, zz, xy, xz, yz}
// (mjuu_globalinertia).
std::array<double, 6> RotateDiagonalInertia(const Vec3& local, const Quat& q) {
  const Mat3 m = QuatToMatrixCompiler(q);
  const Mat3 t = {m[0] * local[0], m[3] * local[0], m[6] * local[0],
                  m[1] * local[1], m[4] * local[1], m[7] * local[1],
                  m[2] * local[2], m[5] * local[2], m[8] * local[2]};
  return {m[0] * t[0] + m[1] * t[3] + m[2] * t[6], m[3] * t[1] + m[4] * t[4] + m[5] * t[7],
          m[6] * t[2] + m[7] * t[5] + m[8] * t[8], m[0] * t[1] + m[1] * t[4] + m[2] * t[7],
          m[0] * t[2] + m[1] * t[5] + m[2] * t[8], m[3] * t[2] + m[4] * t[5] + m[5] * t[8]};
}

// Parallel-axis term m·(|d|²·1 − d·dᵀ) as {xx, yy, zz, xy, xz, yz} (mjuu_offcenter).
std::array<double, 6> OffCenter(double mass, const Vec3& d) {
  return {mass * (d[1] * d[1] + d[2] * d[2]),
          mass * (d[0] * d[0] + d[2] * d[2]),
          mass * (d[0] * d[0] + d[1] * d[1]),
          -mass * d[0] * d[1],
          -mass * d[0] * d[2],
          -mass * d[1] * d[2]};
}

// Pose composition: (pos, quat) ← (pos, quat) ∘ (add_pos, add_quat) (mjuu_frameaccum).
void FrameAccumulate(Vec3* pos, Quat* quat, const Vec3& add_pos, const Quat& add_quat) {
  const Mat3 m = QuatToMatrixCompiler(*quat);
  for (int i = 0; i < 3; ++i) {
    (*pos)[i] += m[i * 3] * add_pos[0] + m[i * 3 + 1] * add_pos[1] + m[i * 3 + 2] * add_pos[2];
  }
  *quat = QuatProductCompiler(*quat, add_quat);
}

// A rotation matrix as a unit quaternion (w >= 0 branch chosen by the largest component).
Quat MatrixToQuat(const Eigen::Matrix3d& R) {
  Eigen::Quaterniond q(R);
  q.normalize();
  Quat out = {q.w(), q.x(), q.y(), q.z()};
  if (R.isIdentity(0)) out = {1, 0, 0, 0};
  return out;
}

}  // namespace

MujocoEigen MujocoEig3(const std::array<double, 6>& full) {
  const Mat3 mat = {full[0], full[3], full[4], full[3], full[1],
                    full[5], full[4], full[5], full[2]};
  constexpr double kEigEps = 1e-12;
  MujocoEigen out;
  Quat quat = {1, 0, 0, 0};
  std::array<double, 3>& eigval = out.values;
  for (int iter = 0; iter < 500; ++iter) {
    const Mat3 v = QuatToMatrix(quat);
    const Mat3 d = Mul(MulTransposeLeft(v, mat), v);
    eigval = {d[0], d[4], d[8]};
    // The largest off-diagonal entry (row r, column c) and the axis of the rotation that
    // annihilates it.
    int r = 0, c = 0, axis = 0;
    if (std::fabs(d[1]) > std::fabs(d[2]) && std::fabs(d[1]) > std::fabs(d[5])) {
      r = 0, c = 1, axis = 2;
    } else if (std::fabs(d[2]) > std::fabs(d[5])) {
      r = 0, c = 2, axis = 1;
    } else {
      r = 1, c = 2, axis = 0;
    }
    if (std::fabs(d[3 * r + c]) < kEigEps) break;
    // Symmetric 2x2 Schur rotation (Golub & Van Loan, Algorithm 8.4.1).
    const double tau = (d[4 * c] - d[4 * r]) / (2 * d[3 * r + c]);
    const double t = tau >= 0 ? 1.0 / (tau + std::sqrt(1 + tau * tau))
                              : -1.0 / (-tau + std::sqrt(1 + tau * tau));
    const double cosine = 1.0 / std::sqrt(1 + t * t);
    if (cosine > 1.0 - kEigEps) break;
    Quat rotation = {0, 0, 0, 0};
    double half_sine = std::sqrt(0.5 - 0.5 * cosine);
    if (tau >= 0) half_sine = -half_sine;
    if (axis == 1) half_sine = -half_sine;
    rotation[axis + 1] = half_sine;
    rotation[0] = std::sqrt(1.0 - half_sine * half_sine);
    NormalizeEngine(&rotation);
    quat = QuatProduct(quat, rotation);
    NormalizeEngine(&quat);
  }
  // Decreasing order by three compare-and-swap steps (pairs 0-1, 1-2, 0-1), each swap turning the
  // frame by 90° about the third axis.
  for (int j = 0; j < 3; ++j) {
    const int lead = j % 2;
    if (eigval[lead] < eigval[lead + 1]) {
      std::swap(eigval[lead], eigval[lead + 1]);
      Quat turn = {0.707106781186548, 0, 0, 0};
      turn[(lead + 2) % 3 + 1] = turn[0];
      quat = QuatProduct(quat, turn);
      NormalizeEngine(&quat);
    }
  }
  out.quat = quat;
  return out;
}

// ----------------------------------------------------------------------------- the profiles

const char* ToString(Target target) {
  switch (target) {
    case Target::kGeneric:
      return "generic";
    case Target::kMujoco:
      return "mujoco";
    case Target::kDrake:
      return "drake";
    case Target::kGazebo:
      return "gazebo";
  }
  return "generic";
}

std::optional<Target> ParseTarget(std::string_view text) {
  for (Target t : {Target::kGeneric, Target::kMujoco, Target::kDrake, Target::kGazebo}) {
    if (text == ToString(t)) return t;
  }
  return std::nullopt;
}

const std::vector<RuleInfo>& TargetRules() {
  static const std::vector<RuleInfo> kRules = {
      {kMujocoTriangle, Severity::kError, true,
       "--target mujoco: MuJoCo refuses a body whose principal moments (as it computes them) "
       "break A + B >= C exactly ('balanceinertia' accepts it)."},
      {kMujocoMinValRule, Severity::kError, true,
       "--target mujoco: MuJoCo refuses a moving body whose mass or a principal moment is below "
       "mjMINVAL = 1e-15 ('boundmass'/'boundinertia' accept it)."},
      {kMujocoFusedInertia, Severity::kError, true,
       "--target mujoco: fusing static bodies (fusestatic) gives an inertia with a principal "
       "moment below 1e-14, which MuJoCo refuses."},
      {kMujocoGeomMass, Severity::kError, true,
       "--target mujoco: a body without <inertial> gets its inertia from its geoms, and they "
       "have too little mass (or a degenerate inertia) for MuJoCo."},
      {kMujocoNegative, Severity::kError, true,
       "--target mujoco: a negative mass or principal moment survives 'boundmass'/'boundinertia'."},
      {kMujocoUnpredicted, Severity::kNote, true,
       "--target mujoco: part of MuJoCo's decision cannot be predicted from the file (mesh "
       "volumes, joint types MuJoCo does not know)."},
      {kDrakeMassless, Severity::kError, true,
       "--target drake: a massless body with no mass outboard of it (Drake cannot invert the "
       "articulated inertia)."},
      {kDrakeInvalid, Severity::kError, true,
       "--target drake: Drake's RotationalInertia::CouldBePhysicallyValid refuses the inertia."},
      {kGazeboLumped, Severity::kNote, true,
       "--target gazebo: links joined by fixed joints are lumped into one body (no "
       "<disableFixedJointLumping>/<preserveFixedJoint>)."},
  };
  return kRules;
}

TargetProfile GetTargetProfile(Target target) {
  TargetProfile p;
  p.target = target;
  switch (target) {
    case Target::kGeneric:
      p.summary = "massprops' own physics test (scale-free tolerance 1e-6 of the trace)";
      break;
    case Target::kMujoco:
      // MuJoCo judges each body on its own (triangle test before fusion) and each moving body
      // after fusion (mjMINVAL): its own findings are the errors; the physics rules say when
      // physics disagrees.
      p.overrides["inertia-not-physical"] = Severity::kWarning;
      p.overrides["massless-moving-body"] = Severity::kWarning;
      p.overrides["zero-inertia-about-joint-axis"] = Severity::kWarning;
      p.overrides[kDrakeMassless] = std::nullopt;
      p.overrides[kDrakeInvalid] = std::nullopt;
      p.overrides[kGazeboLumped] = std::nullopt;
      p.merges_fixed_joints = true;
      p.summary =
          "MuJoCo 2.2.2 compiler on URDF: fusestatic, exact A + B >= C on its own eigenvalues, "
          "mjMINVAL = 1e-15 on moving bodies";
      break;
    case Target::kDrake:
      // Drake's own test (drake-rejects-invalid-inertia) decides; the physics rules say when
      // physics disagrees.
      p.overrides["massless-moving-body"] = std::nullopt;  // drake-rejects-massless-body decides
      p.overrides["inertia-not-physical"] = Severity::kWarning;
      p.overrides[kMujocoUnpredicted] = std::nullopt;
      p.overrides[kGazeboLumped] = std::nullopt;
      p.summary =
          "Drake: CouldBePhysicallyValid (tolerance 16 eps times max(1, tr/2)); a massless "
          "body is accepted when mass lies outboard of it";
      break;
    case Target::kGazebo:
      p.merges_fixed_joints = true;
      p.overrides[kMujocoUnpredicted] = std::nullopt;
      p.overrides[kDrakeMassless] = std::nullopt;
      p.overrides[kDrakeInvalid] = std::nullopt;
      p.summary =
          "Gazebo (libsdformat 12 URDF conversion): fixed joints lumped unless "
          "disableFixedJointLumping/preserveFixedJoint; the lumped bodies are judged";
      break;
  }
  return p;
}

void ApplyTargetProfile(Target target, CheckOptions* options) {
  const TargetProfile p = GetTargetProfile(target);
  if (p.tolerance) options->tolerance = *p.tolerance;
  for (const auto& [rule, level] : p.overrides) options->overrides[rule] = level;
}

// ---------------------------------------------------------------------------- MuJoCo options

MujocoCompilerOptions ReadMujocoCompilerOptions(std::string_view urdf_text) {
  MujocoCompilerOptions options;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(urdf_text.data(), urdf_text.size()) != tinyxml2::XML_SUCCESS) return options;
  const tinyxml2::XMLElement* robot = doc.RootElement();
  if (robot == nullptr) return options;
  const tinyxml2::XMLElement* mujoco = robot->FirstChildElement("mujoco");
  if (mujoco == nullptr) return options;
  const tinyxml2::XMLElement* compiler = mujoco->FirstChildElement("compiler");
  if (compiler == nullptr) return options;
  auto flag = [&](const char* name, bool* value) {
    if (const char* text = compiler->Attribute(name)) {
      if (std::string(text) == "true") *value = true;
      if (std::string(text) == "false") *value = false;
    }
  };
  flag("fusestatic", &options.fusestatic);
  flag("discardvisual", &options.discardvisual);
  flag("balanceinertia", &options.balanceinertia);
  auto number = [&](const char* name, double* value) {
    if (const char* text = compiler->Attribute(name)) {
      char* end = nullptr;
      const double x = std::strtod(text, &end);
      if (end != text) *value = x;
    }
  };
  number("boundmass", &options.boundmass);
  number("boundinertia", &options.boundinertia);
  if (const char* text = compiler->Attribute("inertiafromgeom")) {
    const std::string v = text;
    if (v == "true") options.inertiafromgeom = MujocoCompilerOptions::InertiaFromGeom::kTrue;
    if (v == "false") options.inertiafromgeom = MujocoCompilerOptions::InertiaFromGeom::kFalse;
    if (v == "auto") options.inertiafromgeom = MujocoCompilerOptions::InertiaFromGeom::kAuto;
  }
  return options;
}

// ------------------------------------------------------------------------- MuJoCo emulation

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

// ------------------------------------------------------------------------------- the layer

namespace {

std::optional<Severity> SeverityOf(const std::string& rule, const CheckOptions& options) {
  return RuleSeverity(rule, options);
}

bool Ignored(const Link& link, const std::string& rule) {
  for (const std::string& ignored : link.ignored_rules) {
    if (ignored == "all" || ignored == rule) return true;
  }
  return false;
}

const SourceLocation& InertiaLocationOf(const Link& link) {
  if (link.inertial) {
    if (link.inertial->inertia_location.line > 0) return link.inertial->inertia_location;
    if (link.inertial->location.line > 0) return link.inertial->location;
  }
  return link.location;
}

Eigen::Matrix3d WrittenMatrixOf(const Inertial& in) {
  Eigen::Matrix3d I;
  I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  return I;
}

bool PhysicallyValid(const Eigen::Matrix3d& I, double tolerance) {
  return internal::IsPhysicallyValidInertia(I(0, 0), I(1, 1), I(2, 2), I(1, 0), I(2, 0), I(2, 1),
                                            tolerance);
}

bool HasCollision(const Link& link) {
  for (const Geometry& g : link.geometries) {
    if (g.is_collision) return true;
  }
  return false;
}

class FindingSink {
 public:
  FindingSink(const Model& model, const CheckOptions& options) : model_(model), options_(options) {}

  void Emit(const std::string& rule, int link_index, const SourceLocation& location,
            std::string message, std::vector<std::pair<std::string, double>> values) {
    const std::optional<Severity> severity = SeverityOf(rule, options_);
    if (!severity) return;
    Finding f;
    if (link_index >= 0) {
      const Link& link = model_.links[link_index];
      if (Ignored(link, rule)) return;
      f.link = link.name;
    }
    f.rule = rule;
    f.severity = *severity;
    f.model = model_.name;
    f.location = location;
    f.message = std::move(message);
    f.values = std::move(values);
    findings_.push_back(std::move(f));
  }
  std::vector<Finding> Take() { return std::move(findings_); }

 private:
  const Model& model_;
  const CheckOptions& options_;
  std::vector<Finding> findings_;
};

// What physics says about MuJoCo's refusal, and which compiler option accepts the file.
std::string ExplainMujocoError(const Model& model, const MujocoError& e, const MujocoBody* body,
                               double tolerance) {
  const Link* link = e.link >= 0 ? &model.links[e.link] : nullptr;
  std::string text;
  if (e.rule == kMujocoTriangle) {
    const std::array<double, 3>& m = e.inertia;
    text = "its principal moments, as MuJoCo's eigen-solver computes them, are " + Moments(m) +
           ": " + Num(m[1]) + " + " + Num(m[2]) + " < " + Num(m[0]) +
           " (MuJoCo's test is exact, "
           "without tolerance). ";
    if (link && link->inertial && PhysicallyValid(WrittenMatrixOf(*link->inertial), tolerance)) {
      text += "Physics disagrees: the inertia is valid within " + Num(tolerance) +
              " of its trace (a thin shape written with rounded numbers). ";
    } else {
      text += "Physics agrees: no real body has this inertia. ";
    }
    const double mean = (m[0] + m[1] + m[2]) / 3;
    text +=
        "Accepted with <mujoco><compiler balanceinertia=\"true\"/></mujoco> (all three "
        "moments become their mean " +
        Num(mean) + "), or after `massprops fix --target mujoco` (the nearest valid inertia)";
  } else if (e.rule == kMujocoMinValRule) {
    const std::array<double, 3>& m = e.inertia;
    text = "after fusing static bodies its mass is " + Num(e.mass) + " and its principal moments " +
           Moments(m) + " (mjMINVAL = 1e-15, an absolute bound). ";
    if (e.mass < kMujocoMinVal) {
      text +=
          "Physics agrees when nothing with mass moves with it; a massless intermediate link "
          "of a multi-axis joint is fine in physics (Drake accepts it), not in MuJoCo. ";
    } else {
      text +=
          "Physics disagrees: a principal moment of 0 is a valid thin rod or point mass "
          "(MuJoCo's floor is absolute, not relative to the body's size). ";
    }
    text +=
        "Accepted with <mujoco><compiler boundmass=\"1e-6\" boundinertia=\"1e-9\"/></mujoco> "
        "(raises every body below them)";
    if (link && HasCollision(*link)) {
      text +=
          ", or inertiafromgeom=\"true\" (every body's inertia from its collision geoms, the "
          "written ones ignored)";
    }
    text += ", or after `massprops fix --target mujoco` (a negligible mass and moment floor)";
  } else if (e.rule == kMujocoFusedInertia) {
    text =
        "fusing the links welded to it by fixed joints (fusestatic, on for URDF) gives the "
        "principal moments " +
        Moments(e.inertia) + ", the smallest below 1e-14";
    if (body != nullptr && !body->fused_links.empty()) {
      text += " (fused: ";
      for (std::size_t i = 0; i < body->fused_links.size(); ++i) {
        text += (i ? ", '" : "'") + model.links[body->fused_links[i]].name + "'";
      }
      text += ")";
    }
    text +=
        "; MuJoCo names no body in its message. Accepted with <mujoco><compiler "
        "fusestatic=\"false\"/></mujoco>, or after `massprops fix --target mujoco`";
  } else if (e.rule == kMujocoGeomMass) {
    text =
        "the link has no <inertial>, so MuJoCo takes its inertia from its geoms (density 1000, "
        "visual geoms 0), which give mass " +
        Num(e.mass) + "; add an <inertial>, or run `massprops fix --target mujoco`";
  } else {
    text = "mass " + Num(e.mass) + ", principal moments " + Moments(e.inertia) +
           " after boundmass/boundinertia";
  }
  return text;
}

}  // namespace

namespace {

// Drake's validity test of a central inertia (RotationalInertia::CouldBePhysicallyValid in
// multibody/tree/rotational_inertia.h): principal moments p near non-negative and satisfying the
// triangle inequality within ε = 16·DBL_EPSILON·max(1, tr/2) — an absolute floor of 3.6e-15
// kg·m² below 1 kg·m², relative above.
bool DrakeAccepts(const Eigen::Matrix3d& I, Eigen::Vector3d* moments, double* epsilon) {
  if (!I.allFinite()) return false;
  const Eigen::Vector3d p = internal::ScaledPrincipalMoments(
      I(0, 0), I(1, 1), I(2, 2), I(1, 0), I(2, 0), I(2, 1), PrincipalSolver::kAccurate);
  const double eps = 16 * std::numeric_limits<double>::epsilon() * std::max(1.0, 0.5 * I.trace());
  *moments = p;
  *epsilon = eps;
  return p.minCoeff() + eps >= 0 && p(0) + p(1) + eps >= p(2) && p(0) + p(2) + eps >= p(1) &&
         p(1) + p(2) + eps >= p(0);
}

void CheckDrake(const Model& model, FindingSink* sink) {
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const Link& link = model.links[i];
    if (!link.inertial) continue;
    const Inertial& in = *link.inertial;
    Eigen::Vector3d p = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    double eps = 0;
    if (DrakeAccepts(WrittenMatrixOf(in), &p, &eps) && std::isfinite(in.mass) && in.mass >= 0) {
      continue;
    }
    sink->Emit(kDrakeInvalid, static_cast<int>(i), InertiaLocationOf(link),
               "Drake refuses link '" + link.name +
                   "': its spatial inertia does not pass RotationalInertia::"
                   "CouldBePhysicallyValid() (mass " +
                   Num(in.mass) + ", principal moments " + Num(p(0)) + ", " + Num(p(1)) + ", " +
                   Num(p(2)) + "; Drake's tolerance 16·eps·max(1, tr/2) = " + Num(eps) +
                   " kg·m²); its parser throws when it builds the body",
               {{"mass", in.mass},
                {"principal_min", p(0)},
                {"principal_mid", p(1)},
                {"principal_max", p(2)},
                {"epsilon", eps}});
  }
  // A moving welded group whose subtree (the group and everything outboard) has no mass, or no
  // moment about its revolute axis: Drake's articulated body algorithm meets a singular hinge
  // inertia ("Encountered singular articulated body hinge inertia ... Please ensure that this
  // body has non-zero inertia along all axes of motion", multibody/tree/body_node_impl.cc).
  // A massless body with mass outboard of it is fine.
  if (model.is_static) return;
  const std::vector<WeldedGroup> groups = FindWeldedGroups(model);
  std::vector<bool> reachable;
  const std::vector<Pose> X_WL = CalcLinkPosesInRootFrame(model, &reachable);
  std::vector<std::vector<int>> children(model.links.size());
  for (const Joint& joint : model.joints) {
    const int p = model.FindLink(joint.parent), c = model.FindLink(joint.child);
    if (p >= 0 && c >= 0 && model.FindParentJoint(joint.child) >= 0 &&
        &model.joints[model.FindParentJoint(joint.child)] == &joint) {
      children[p].push_back(c);
    }
  }
  for (const WeldedGroup& group : groups) {
    if (!group.is_moving || group.parent_joint < 0) continue;
    const int root = group.links.front();
    if (!reachable[root]) continue;
    std::vector<MassProperties> parts;
    std::vector<int> stack = {root};
    std::vector<bool> seen(model.links.size(), false);
    while (!stack.empty()) {
      const int l = stack.back();
      stack.pop_back();
      if (seen[l]) continue;
      seen[l] = true;
      if (model.links[l].inertial_unreadable) return;
      const MassProperties local = LinkMassProperties(model.links[l], model.format);
      MassProperties in_W;
      in_W.mass = local.mass;
      in_W.p_FoScm_F = X_WL[l].p_AB + X_WL[l].R_AB * local.p_FoScm_F;
      in_W.I_SScm_F = X_WL[l].R_AB * local.I_SScm_F * X_WL[l].R_AB.transpose();
      parts.push_back(in_W);
      for (int c : children[l]) stack.push_back(c);
    }
    const CompositeInertia composite = ComposeMassProperties(parts);
    if (!std::isfinite(composite.mass) || !composite.I_SScm_R.allFinite()) continue;
    const Joint& joint = model.joints[group.parent_joint];
    const double eps =
        16 * std::numeric_limits<double>::epsilon() * std::max(1.0, composite.I_SScm_R.trace());
    std::string why;
    double value = composite.mass;
    if (!(composite.mass > 0)) {
      why = "it and everything outboard of it have no mass";
    } else if (joint.type == Joint::Type::kRevolute || joint.type == Joint::Type::kContinuous) {
      const Eigen::Vector3d a = (X_WL[root].R_AB * joint.axis).normalized();
      const Eigen::Vector3d d = composite.p_RoScm_R - X_WL[root].p_AB;
      const Eigen::Matrix3d I_o =
          composite.I_SScm_R +
          composite.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
      value = a.dot(I_o * a);
      if (value <= eps) {
        why = "it and everything outboard of it have no moment of inertia about the joint axis (" +
              Num(value) + " kg·m²)";
      }
    }
    if (why.empty()) continue;
    const Link& link = model.links[root];
    sink->Emit(kDrakeMassless, root, link.location,
               "Drake cannot simulate link '" + link.name + "' on " + joint.type_name + " joint '" +
                   joint.name + "': " + why +
                   ", so its articulated body hinge inertia is singular (Drake accepts a massless "
                   "body only when mass lies outboard of it)",
               {{"subtree_mass", composite.mass}, {"value", value}});
  }
}

// Gazebo (libsdformat's URDF conversion) lumps a link into its parent across a fixed joint
// unless the joint is named by <gazebo reference="JOINT"> with <disableFixedJointLumping>true or
// <preserveFixedJoint>true.
std::set<std::string> PreservedFixedJoints(std::string_view urdf_text) {
  std::set<std::string> joints;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(urdf_text.data(), urdf_text.size()) != tinyxml2::XML_SUCCESS) return joints;
  const tinyxml2::XMLElement* robot = doc.RootElement();
  if (robot == nullptr) return joints;
  for (const tinyxml2::XMLElement* g = robot->FirstChildElement("gazebo"); g;
       g = g->NextSiblingElement("gazebo")) {
    const char* reference = g->Attribute("reference");
    if (reference == nullptr) continue;
    for (const char* tag : {"disableFixedJointLumping", "preserveFixedJoint"}) {
      const tinyxml2::XMLElement* e = g->FirstChildElement(tag);
      if (e && e->GetText() && std::string(e->GetText()).find("true") != std::string::npos) {
        joints.insert(reference);
      }
    }
  }
  return joints;
}

}  // namespace

std::vector<WeldedGroup> GazeboLumpedGroups(const Model& model, std::string_view urdf_text) {
  const bool urdf = model.format == Model::Format::kUrdf;
  const std::set<std::string> preserved =
      urdf ? PreservedFixedJoints(urdf_text) : std::set<std::string>();
  // Links joined by a fixed joint that is not preserved form one body (SDF models are not
  // lumped: lumping is part of the URDF conversion). A root link named "world" is libsdformat's
  // world: what is welded to it stays a link of its own, attached by a fixed joint.
  const bool world_root = urdf && model.root_link == "world";
  Model lumping = model;
  for (Joint& j : lumping.joints) {
    if (j.type != Joint::Type::kFixed) continue;
    if (!urdf || preserved.count(j.name) || (world_root && j.parent == "world")) {
      j.type = Joint::Type::kOther;
    }
  }
  return FindWeldedGroups(lumping);
}

std::vector<GazeboBody> GazeboBodies(const Model& model, std::string_view urdf_text) {
  std::vector<GazeboBody> bodies;
  const bool world_root = model.format == Model::Format::kUrdf && model.root_link == "world";
  for (const WeldedGroup& group : GazeboLumpedGroups(model, urdf_text)) {
    if (world_root && group.root_link == "world") continue;  // the world, not a body
    GazeboBody body;
    body.name = model.links[group.links.front()].name;
    body.links = group.links;
    body.inertia = CalcCompositeInertia(model, group);
    bodies.push_back(std::move(body));
  }
  return bodies;
}

std::vector<Finding> CheckTarget(const Model& model, Target target, const CheckOptions& options,
                                 const MujocoCompilerOptions& mujoco, std::string_view text) {
  FindingSink sink(model, options);
  if (target == Target::kDrake) CheckDrake(model, &sink);
  if (target == Target::kGazebo) {
    for (const GazeboBody& body : GazeboBodies(model, text)) {
      if (body.links.size() < 2) continue;
      std::string names;
      for (std::size_t i = 1; i < body.links.size(); ++i) {
        names += (i > 1 ? ", '" : "'") + model.links[body.links[i]].name + "'";
      }
      const int root = body.links.front();
      const bool valid = body.inertia.I_SScm_R.allFinite() &&
                         PhysicallyValid(body.inertia.I_SScm_R, options.tolerance);
      sink.Emit(kGazeboLumped, root, model.links[root].location,
                "Gazebo lumps " + names + " into link '" + body.name +
                    "' across fixed joints (add <gazebo reference=\"JOINT\"><preserveFixedJoint>"
                    "true</preserveFixedJoint></gazebo> to keep one): it simulates one body of "
                    "mass " +
                    Num(body.inertia.mass) + " kg whose inertia is " +
                    (valid ? "physically valid" : "NOT physically valid"),
                {{"mass", body.inertia.mass}, {"lumped_links", double(body.links.size() - 1)}});
    }
  }
  if (target == Target::kMujoco) {
    const MujocoPrediction prediction = PredictMujoco(model, mujoco);
    for (const std::string& why : prediction.unsupported) {
      sink.Emit(kMujocoUnpredicted, -1, model.location,
                "MuJoCo's decision cannot be fully predicted: " + why, {});
    }
    for (std::size_t i = 0; i < prediction.errors.size(); ++i) {
      const MujocoError& e = prediction.errors[i];
      const MujocoBody* body = nullptr;
      for (const MujocoBody& b : prediction.bodies) {
        if (b.link == e.link) body = &b;
      }
      const Link* link = e.link >= 0 ? &model.links[e.link] : nullptr;
      std::string message = "MuJoCo 2.2.2 refuses the file" +
                            std::string(link ? " at body '" + link->name + "'" : "") + ": \"" +
                            e.message + "\"" +
                            (i == 0 ? " (the first refusal: this is the one MuJoCo reports)" : "") +
                            "; " + ExplainMujocoError(model, e, body, options.tolerance);
      sink.Emit(e.rule, e.link, link ? InertiaLocationOf(*link) : model.location,
                std::move(message),
                {{"mass", e.mass},
                 {"principal_1", e.inertia[0]},
                 {"principal_2", e.inertia[1]},
                 {"principal_3", e.inertia[2]},
                 {"first", i == 0 ? 1.0 : 0.0}});
    }
  }
  return sink.Take();
}

void AddTargetFindings(const Model& model, Target target, const CheckOptions& options,
                       const MujocoCompilerOptions& mujoco, std::vector<Finding>* findings,
                       std::string_view text) {
  if (target == Target::kGeneric) return;
  if (target == Target::kMujoco) {
    // Say what MuJoCo decides about each inertia physics refuses.
    const MujocoPrediction prediction = PredictMujoco(model, mujoco);
    for (Finding& f : *findings) {
      if (f.rule != "inertia-not-physical") continue;
      const int index = model.FindLink(f.link);
      if (index < 0 || !model.links[index].inertial) continue;
      bool refused = false;
      for (const MujocoError& e : prediction.errors) refused |= e.link == index;
      if (f.message.find("composite inertia") != std::string::npos) {
        f.message += " (MuJoCo judges each link on its own before fusing, not the group)";
      } else if (refused) {
        f.message += " (MuJoCo refuses it too: see the mujoco-rejects finding)";
      } else {
        const Inertial& in = *model.links[index].inertial;
        const MujocoEigen eig = MujocoEig3({in.ixx, in.iyy, in.izz, in.ixy, in.ixz, in.iyz});
        f.message += " (MuJoCo 2.2.2 accepts it: its eigen-solver gives the principal moments " +
                     Moments(eig.values) +
                     ", negative ones clamped to 0, which pass its test; physics and MuJoCo "
                     "disagree)";
      }
    }
  }
  if (target == Target::kGazebo) {
    // Gazebo simulates the lumped body: an invalid member of a valid lumped body is a warning.
    for (const GazeboBody& body : GazeboBodies(model, text)) {
      if (body.links.size() < 2 || !body.inertia.I_SScm_R.allFinite() ||
          !PhysicallyValid(body.inertia.I_SScm_R, options.tolerance)) {
        continue;
      }
      for (Finding& f : *findings) {
        if (f.rule != "inertia-not-physical" || f.severity != Severity::kError) continue;
        const int index = model.FindLink(f.link);
        if (std::find(body.links.begin(), body.links.end(), index) == body.links.end()) continue;
        if (f.message.find("composite inertia") != std::string::npos) continue;
        f.severity = Severity::kWarning;
        f.message += " (Gazebo lumps it into '" + body.name +
                     "', whose composite inertia is valid: that is the body it simulates)";
      }
    }
  }
  std::vector<Finding> own = CheckTarget(model, target, options, mujoco, text);
  findings->insert(findings->end(), own.begin(), own.end());
  std::stable_sort(findings->begin(), findings->end(), [](const Finding& a, const Finding& b) {
    if (a.location.line != b.location.line) return a.location.line < b.location.line;
    return a.rule < b.rule;
  });
}

// ------------------------------------------------------------------------------- repairs

namespace {

void FillChanges(const Model& model, const Link& link, Repair* repair) {
  repair->changes.clear();
  repair->inserts_origin = false;
  repair->inserts_inertial = !link.inertial.has_value();
  repair->before = link.inertial;
  repair->link_line = link.location.line;
  repair->relative_change = 1;
  if (!link.inertial) return;
  const bool sdf = model.format == Model::Format::kSdf;
  const Inertial& b = *link.inertial;
  const Inertial& a = repair->after;
  auto add = [&](const char* element, const char* attribute, int line,
                 std::vector<double> old_values, std::vector<double> new_values) {
    if (old_values == new_values) return;
    repair->changes.push_back(
        {element, attribute, line, 0, std::move(old_values), std::move(new_values)});
  };
  add("mass", sdf ? "" : "value", b.mass_location.line, {b.mass}, {a.mass});
  if (b.X_BBi.p_AB != a.X_BBi.p_AB) {
    if (b.pose_location.line == 0) repair->inserts_origin = true;
    add(sdf ? "pose" : "origin", sdf ? "" : "xyz", b.pose_location.line,
        {b.X_BBi.p_AB.x(), b.X_BBi.p_AB.y(), b.X_BBi.p_AB.z()},
        {a.X_BBi.p_AB.x(), a.X_BBi.p_AB.y(), a.X_BBi.p_AB.z()});
  }
  const int line = b.inertia_location.line;
  add("inertia", "ixx", line, {b.ixx}, {a.ixx});
  add("inertia", "ixy", line, {b.ixy}, {a.ixy});
  add("inertia", "ixz", line, {b.ixz}, {a.ixz});
  add("inertia", "iyy", line, {b.iyy}, {a.iyy});
  add("inertia", "iyz", line, {b.iyz}, {a.iyz});
  add("inertia", "izz", line, {b.izz}, {a.izz});
  const Eigen::Matrix3d I_before = WrittenMatrixOf(b), I_after = WrittenMatrixOf(a);
  if (I_before.norm() > 0 && I_before != I_after) {
    repair->relative_change = (I_after - I_before).norm() / I_before.norm();
  } else if (I_before == I_after && b.mass != 0) {
    repair->relative_change = std::abs(a.mass - b.mass) / std::abs(b.mass);
  }
}

void SetMatrix(const Eigen::Matrix3d& I, Inertial* in) {
  in->ixx = I(0, 0);
  in->iyy = I(1, 1);
  in->izz = I(2, 2);
  in->ixy = I(0, 1);
  in->ixz = I(0, 2);
  in->iyz = I(1, 2);
}

}  // namespace

std::vector<Repair> PlanTargetRepairs(const Model& model, Target target,
                                      const MujocoCompilerOptions& mujoco,
                                      const std::vector<Repair>& repairs) {
  if (target != Target::kMujoco || model.format != Model::Format::kUrdf) return repairs;
  std::vector<Repair> out = repairs;
  // A negligible mass for bodies MuJoCo finds massless: 1e-6 of the model's mass (at least 1e-9).
  double total = 0;
  for (const Link& link : model.links) {
    if (link.inertial && std::isfinite(link.inertial->mass) && link.inertial->mass > 0) {
      total += link.inertial->mass;
    }
  }
  const double mass_floor = std::max(1e-6 * total, 1e-9);
  Model work = ApplyRepairs(model, out);
  for (int round = 0; round < 4; ++round) {
    const MujocoPrediction prediction = PredictMujoco(work, mujoco);
    if (prediction.accepted() || !prediction.unsupported.empty()) break;
    bool changed = false;
    std::set<int> done;
    for (const MujocoError& e : prediction.errors) {
      if (e.link < 0 || done.count(e.link)) continue;
      done.insert(e.link);
      Link& link = work.links[e.link];
      Inertial after = link.inertial ? *link.inertial : Inertial{};
      std::string method, why;
      if (e.rule == kMujocoTriangle && link.inertial) {
        const Eigen::Matrix3d I = WrittenMatrixOf(after);
        if (!I.allFinite()) continue;
        // Strictly inside the valid set (tolerance < 0 always projects), so that MuJoCo's exact
        // test passes after its own eigen-decomposition.
        SetMatrix(RepairInertia(I, InertiaRepairMethod::kProject, -1), &after);
        method = "mujoco-project";
        why = "MuJoCo refuses the inertia (A + B >= C fails on its principal moments " +
              Moments(e.inertia) + "): replaced by the nearest inertia MuJoCo accepts";
      } else if (e.rule == kMujocoMinValRule || e.rule == kMujocoFusedInertia ||
                 e.rule == kMujocoGeomMass) {
        if (!(after.mass >= kMujocoMinVal) || !std::isfinite(after.mass)) after.mass = mass_floor;
        const double largest =
            std::max({std::fabs(e.inertia[0]), std::fabs(e.inertia[1]), std::fabs(e.inertia[2])});
        const double floor = std::max({1e-9 * largest, mass_floor * 1e-4, 1e-12});
        Eigen::Matrix3d I = WrittenMatrixOf(after);
        if (!I.allFinite()) continue;
        I += floor * Eigen::Matrix3d::Identity();
        SetMatrix(I, &after);
        method = "mujoco-floor";
        why = "MuJoCo refuses body '" + link.name + "' (" + e.message +
              "): mass raised to at least " + Num(after.mass) + " kg and " + Num(floor) +
              " kg·m² added to each moment, negligible next to the model";
      } else {
        continue;
      }
      // Merge with the link's earlier repair, if any.
      auto it = std::find_if(out.begin(), out.end(),
                             [&](const Repair& r) { return r.link == link.name; });
      if (it == out.end()) {
        Repair repair;
        repair.rule = e.rule;
        repair.link = link.name;
        out.push_back(repair);
        it = out.end() - 1;
      }
      it->after = after;
      it->method += (it->method.empty() ? "" : "+") + method;
      it->why += (it->why.empty() ? "" : " Then: ") + why + ".";
      if (std::find(it->resolves.begin(), it->resolves.end(), e.rule) == it->resolves.end()) {
        it->resolves.push_back(e.rule);
      }
      FillChanges(model, model.links[e.link], &*it);
      link.inertial = after;
      changed = true;
    }
    if (!changed) break;
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Repair& a, const Repair& b) { return a.link_line < b.link_line; });
  return out;
}

}  // namespace massprops
