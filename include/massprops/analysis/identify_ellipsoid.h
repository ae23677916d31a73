#pragma once
/// @file
/// The bounding-ellipsoid condition of identification (docs/identify.md, issue 51): where a
/// body's geometry is known, its identified parameters are the moments of a density inside the
/// ellipsoid E = {x : (x − x0)ᵀ Q⁻¹ (x − x0) <= 1} that encloses that geometry (Wensing, Kim and
/// Slotine, "Linear Matrix Inequalities for Physically Consistent Inertial Parameter
/// Identification", RA-L 2018: tr(J·Q̃) >= 0 for every density inside E, which in E's normalized
/// frame x' = A·(x − x0), A = Q^(−1/2), reads tr(Σ') <= m, Σ' = ∫x'x'ᵀ dm).
///
/// The parametrization: with J' = T·J·Tᵀ (T = [A, −A·x0; 0, 1]) the pseudo-inertia in the
/// normalized frame, J' = U·Uᵀ, U upper triangular with last row [0 0 0 e^α], so m = e^{2α} and
/// tr(Σ') = e^{2α}·‖w‖², w the 9 entries of U's first three rows over e^α. The coordinates
///   θ = [α, d1, d2, d3, s12, s23, s13, t1, t2, t3]   (the log-Cholesky order of identify.h)
/// give v = [e^d1, e^d2, e^d3, s12, s23, s13, t1, t2, t3] and w = v / √(1 + ‖v‖²), so ‖w‖ < 1
/// (a strict interior) and U's diagonal is positive (J ≻ 0) for every finite θ: every θ is a body
/// inside E, and the fit is unconstrained. J = T⁻¹·J'·T⁻ᵀ is linear in J'.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "massprops/analysis/link_shape.h"
#include "massprops/dynamics/kinematic_tree.h"
#include "massprops/model/model.h"

namespace massprops {

/// E = {x : (x − x0)ᵀ Q⁻¹ (x − x0) <= 1}, in a body's frame B (metres).
struct BoundingEllipsoid {
  Eigen::Vector3d x0 = Eigen::Vector3d::Zero();
  Eigen::Matrix3d Q_inverse = Eigen::Matrix3d::Identity();  ///< Symmetric positive definite.
};

/// The coordinates θ of a body inside its ellipsoid (see the file comment).
using EllipsoidParameters = Eigen::Matrix<double, 10, 1>;

/// A prior whose ratio (EllipsoidRatioOf) exceeds this is first contracted about x0 to it
/// (EllipsoidParametersFromInertialParameters): the coordinates of a body on E's boundary are
/// infinite, and those within 1% of it large.
constexpr double kEllipsoidPriorRatio = 0.99;

/// Whether `e` can be used: finite, Q⁻¹ symmetric (to 1e-9 of its size) and positive definite.
/// Never throws.
bool IsUsableEllipsoid(const BoundingEllipsoid& e);

/// tr(Q⁻¹·(Σ + m·(c − x0)(c − x0)ᵀ)) / m of parameters π (Σ the central second moment): at most
/// 1 for any density inside E; +∞ when m <= 0 (no density has such parameters). Computed from
/// the second moment about x0 (no center of mass is formed). About 60 flops.
double EllipsoidRatioOf(const InertialParameters& pi, const BoundingEllipsoid& e);

/// π(θ): the parameters of a density inside E for every finite θ (EllipsoidRatioOf < 1, J ≻ 0).
/// Precondition: IsUsableEllipsoid(e). About 1 µs (a 3 × 3 eigendecomposition).
InertialParameters InertialParametersFromEllipsoidParameters(const EllipsoidParameters& theta,
                                                             const BoundingEllipsoid& e);

/// dπ/dθ (10 × 10), exact (the chain rule through the log-Cholesky map of identify.h).
Eigen::Matrix<double, 10, 10> InertialParametersFromEllipsoidParametersJacobian(
    const EllipsoidParameters& theta, const BoundingEllipsoid& e);

/// θ(π), the inverse of InertialParametersFromEllipsoidParameters to round-off for a body inside
/// E with ratio at most `max_ratio` (in (0, 1)). Otherwise π is first moved to such a body: a
/// pseudo-inertia that is not positive definite to the nearest that is (as
/// LogCholeskyFromInertialParameters does, in E's normalized frame), then a body whose ratio r
/// exceeds max_ratio is contracted about x0 by k = √(max_ratio / r): each mass element at x is
/// moved to x0 + k·(x − x0), so its mass is kept, its center of mass moves to x0 + k·(c − x0)
/// and its central second moment becomes k²·Σ, and the ratio becomes max_ratio. Never throws
/// for finite π and a usable e.
EllipsoidParameters EllipsoidParametersFromInertialParameters(
    const InertialParameters& pi, const BoundingEllipsoid& e,
    double max_ratio = kEllipsoidPriorRatio);

/// Per body of `tree` (tree order): the bounding ellipsoid, in the body frame, of the geometry
/// (collision and visual) of its link and of the links welded to it (MeasureLink of their
/// geometries posed in the body frame: Khachiyan's minimum-volume ellipsoid of their hull, grown
/// to hold every point), or nullopt when that geometry is not known: a link of the body with
/// geometry that is not whole (a mesh that could not be read, `points` empty, an unknown type), a
/// link with mass but no geometry, or geometry in a plane. A welded link with neither geometry nor
/// mass (a frame such as a tool flange) adds nothing. `points` reads the meshes
/// (MakeLinkPointsFunction); empty: links with meshes are not known. Never throws.
std::vector<std::optional<BoundingEllipsoid>> BodyBoundingEllipsoids(
    const Model& model, const KinematicTree& tree, const LinkPointsFunction& points = {});

}  // namespace massprops
