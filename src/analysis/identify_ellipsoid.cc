// The bounding-ellipsoid parametrization of a body's inertial parameters and the bounding
// ellipsoids of a tree's bodies (identify_ellipsoid.h).
#include "massprops/analysis/identify_ellipsoid.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/pseudo_inertia.h"
#include "massprops/analysis/identify.h"
#include "massprops/analysis/link_measure.h"

namespace massprops {

namespace {

using Matrix10 = Eigen::Matrix<double, 10, 10>;
using Vector9 = Eigen::Matrix<double, 9, 1>;
using internal::ParametersOfPseudoInertia;
using internal::PseudoInertiaOf;

// The matrix of π ↦ π' where J' = X·J·Xᵀ (a congruence of the pseudo-inertia: linear in π).
Matrix10 CongruenceMap(const Eigen::Matrix4d& X) {
  Matrix10 M;
  for (int k = 0; k < 10; ++k) {
    const InertialParameters unit = InertialParameters::Unit(k);
    M.col(k) = ParametersOfPseudoInertia(X * PseudoInertiaOf(unit) * X.transpose());
  }
  return M;
}

// T = [A, −A·x0; 0, 1] with A = Q^(−1/2) (symmetric), which maps E onto the unit ball, and T⁻¹.
void NormalizingTransform(const BoundingEllipsoid& e, Eigen::Matrix4d* T, Eigen::Matrix4d* T_inv) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 *
                                                           (e.Q_inverse + e.Q_inverse.transpose()));
  const Eigen::Matrix3d& V = eig.eigenvectors();
  const Eigen::Vector3d root = eig.eigenvalues().cwiseMax(0).cwiseSqrt();
  const Eigen::Matrix3d A = V * root.asDiagonal() * V.transpose();
  const Eigen::Matrix3d A_inv = V * root.cwiseInverse().asDiagonal() * V.transpose();
  T->setIdentity();
  T->topLeftCorner<3, 3>() = A;
  T->block<3, 1>(0, 3) = -A * e.x0;
  T_inv->setIdentity();
  T_inv->topLeftCorner<3, 3>() = A_inv;
  T_inv->block<3, 1>(0, 3) = e.x0;
}

// The log-Cholesky coordinates (identify.h) of the normalized frame's J' = U·Uᵀ that θ stands
// for: [α, log w1, log w2, log w3, w4, ..., w9], with v and w of the header's comment.
struct Normalized {
  LogCholeskyParameters log_cholesky;
  Vector9 v, w;
  double s = 1;  // √(1 + ‖v‖²)
};

Normalized ToNormalized(const EllipsoidParameters& theta) {
  Normalized n;
  n.v.head<3>() = theta.segment<3>(1).array().exp();
  n.v.tail<6>() = theta.tail<6>();
  n.s = std::sqrt(1 + n.v.squaredNorm());
  n.w = n.v / n.s;
  n.log_cholesky[0] = theta[0];
  // log w_i = d_i − log s (exact where w_i itself would underflow).
  n.log_cholesky.segment<3>(1) = theta.segment<3>(1).array() - std::log(n.s);
  n.log_cholesky.tail<6>() = n.w.tail<6>();
  return n;
}

}  // namespace

bool IsUsableEllipsoid(const BoundingEllipsoid& e) {
  if (!e.x0.allFinite() || !e.Q_inverse.allFinite()) return false;
  const double size = e.Q_inverse.cwiseAbs().maxCoeff();
  if (!((e.Q_inverse - e.Q_inverse.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * size)) {
    return false;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(e.Q_inverse);
  return eig.info() == Eigen::Success && eig.eigenvalues().minCoeff() > 0;
}

double EllipsoidRatioOf(const InertialParameters& pi, const BoundingEllipsoid& e) {
  const double m = pi[0];
  if (!(m > 0)) return HUGE_VAL;
  const Eigen::Matrix4d J = PseudoInertiaOf(pi);
  const Eigen::Vector3d h = pi.segment<3>(1);
  // ∫(x − x0)(x − x0)ᵀ dm = S − h·x0ᵀ − x0·hᵀ + m·x0·x0ᵀ = Σ + m·(c − x0)(c − x0)ᵀ.
  const Eigen::Matrix3d about_x0 = J.topLeftCorner<3, 3>() - h * e.x0.transpose() -
                                   e.x0 * h.transpose() + m * e.x0 * e.x0.transpose();
  return (e.Q_inverse * about_x0).trace() / m;
}

InertialParameters InertialParametersFromEllipsoidParameters(const EllipsoidParameters& theta,
                                                             const BoundingEllipsoid& e) {
  Eigen::Matrix4d T, T_inv;
  NormalizingTransform(e, &T, &T_inv);
  const InertialParameters normalized =
      InertialParametersFromLogCholesky(ToNormalized(theta).log_cholesky);
  return CongruenceMap(T_inv) * normalized;  // J = T⁻¹·J'·T⁻ᵀ
}

Eigen::Matrix<double, 10, 10> InertialParametersFromEllipsoidParametersJacobian(
    const EllipsoidParameters& theta, const BoundingEllipsoid& e) {
  Eigen::Matrix4d T, T_inv;
  NormalizingTransform(e, &T, &T_inv);
  const Normalized n = ToNormalized(theta);
  // d(log-Cholesky)/dθ: α passes through; dw/dv = (1 − w·wᵀ)/s; the diagonal's entries are
  // log w_i (d/dw_i = 1/w_i) of v_i = e^{d_i} (dv_i/dd_i = v_i).
  Matrix10 G = Matrix10::Zero();
  G(0, 0) = 1;
  const Eigen::Matrix<double, 9, 9> dw_dv =
      (Eigen::Matrix<double, 9, 9>::Identity() - n.w * n.w.transpose()) / n.s;
  for (int i = 0; i < 9; ++i) {
    for (int j = 0; j < 9; ++j) {
      const double outer = i < 3 ? 1 / n.w[i] : 1;
      const double inner = j < 3 ? n.v[j] : 1;
      G(i + 1, j + 1) = outer * dw_dv(i, j) * inner;
    }
  }
  return CongruenceMap(T_inv) * InertialParametersFromLogCholeskyJacobian(n.log_cholesky) * G;
}

EllipsoidParameters EllipsoidParametersFromInertialParameters(const InertialParameters& pi,
                                                              const BoundingEllipsoid& e,
                                                              double max_ratio) {
  max_ratio = std::min(std::max(max_ratio, 1e-6), 1 - 1e-9);
  Eigen::Matrix4d T, T_inv;
  NormalizingTransform(e, &T, &T_inv);
  // In the normalized frame: J' = T·J·Tᵀ, moved to positive definite where it is not.
  const LogCholeskyParameters lc = LogCholeskyFromInertialParameters(CongruenceMap(T) * pi);
  Vector9 u;  // U's first three rows over e^α: ‖u‖² is the ratio
  u.head<3>() = lc.segment<3>(1).array().exp();
  u.tail<6>() = lc.tail<6>();
  const double ratio = u.squaredNorm();
  // Scaling U's first three rows by k scales J''s S by k² and h by k, m kept: the contraction
  // x' ↦ k·x' about the normalized frame's origin, i.e. x ↦ x0 + k·(x − x0).
  if (ratio > max_ratio) u *= std::sqrt(max_ratio / ratio);
  const Vector9 v = u / std::sqrt(1 - u.squaredNorm());  // the inverse of w = v/√(1 + ‖v‖²)
  EllipsoidParameters theta;
  theta[0] = lc[0];
  theta.segment<3>(1) = v.head<3>().array().log();
  theta.tail<6>() = v.tail<6>();
  return theta;
}

namespace {

// The pose of link `name` in the frame of `body_link`, through the fixed joints between them;
// false when `name` does not hang below `body_link`.
bool PoseInBody(const Model& model, const std::string& body_link, std::string name, Pose* X_BL) {
  Pose X = Pose();
  for (std::size_t steps = 0; name != body_link; ++steps) {
    const int j = model.FindParentJoint(name);
    if (j < 0 || steps > model.joints.size()) return false;
    const Joint& joint = model.joints[static_cast<std::size_t>(j)];
    X = joint.X_PC * X;
    name = joint.parent;
  }
  *X_BL = X;
  return true;
}

// The ellipsoid of one body's links (the first is the body's own), or nullopt.
std::optional<BoundingEllipsoid> GroupEllipsoid(const Model& model,
                                                const std::vector<std::string>& links,
                                                const LinkPointsFunction& points) {
  Link group;  // every geometry posed in the body frame
  LinkGeometryPoints group_points;
  bool has_mesh = false;
  for (const std::string& name : links) {
    const int index = model.FindLink(name);
    if (index < 0) return std::nullopt;
    const Link& link = model.links[static_cast<std::size_t>(index)];
    if (link.geometries.empty()) {
      if (link.inertial && link.inertial->mass != 0) return std::nullopt;  // mass, no geometry
      continue;  // a frame: no mass, no geometry
    }
    Pose X_BL;
    if (!PoseInBody(model, links.front(), name, &X_BL)) return std::nullopt;
    bool link_has_mesh = false;
    for (Geometry g : link.geometries) {
      link_has_mesh |= g.type == Geometry::Type::kMesh;
      g.X_BG = X_BL * g.X_BG;
      group.geometries.push_back(std::move(g));
    }
    if (!link_has_mesh) continue;
    has_mesh = true;
    const std::optional<LinkGeometryPoints> read = points ? points(link) : std::nullopt;
    if (!read || read->unknown > 0) return std::nullopt;
    for (LinkGeometryPoints::PosedPositions mesh : read->posed) {
      mesh.X_BG = X_BL * mesh.X_BG;
      group_points.posed.push_back(std::move(mesh));
    }
  }
  if (group.geometries.empty()) return std::nullopt;
  const LinkMeasure measure = MeasureLink(
      group, has_mesh ? std::optional<LinkGeometryPoints>(group_points) : std::nullopt, true);
  if (!measure.whole || !measure.has_ellipsoid) return std::nullopt;
  BoundingEllipsoid e;
  e.x0 = measure.x0;
  e.Q_inverse = measure.Q_inverse;
  if (!IsUsableEllipsoid(e)) return std::nullopt;
  return e;
}

}  // namespace

std::vector<std::optional<BoundingEllipsoid>> BodyBoundingEllipsoids(
    const Model& model, const KinematicTree& tree, const LinkPointsFunction& points) {
  std::vector<std::optional<BoundingEllipsoid>> out;
  for (const MovingBody& body : tree.bodies) {
    std::vector<std::string> links = {body.link};
    links.insert(links.end(), body.welded_links.begin(), body.welded_links.end());
    out.push_back(GroupEllipsoid(model, links, points));
  }
  return out;
}

}  // namespace massprops
