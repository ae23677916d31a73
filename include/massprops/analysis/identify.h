#pragma once
/// @file
/// Identification of a fixed-base tree's inertial parameters from recorded joint torques
/// (docs/identify.md, issue 51): the physically consistent fit and, beside it, ordinary least
/// squares on the base parameters (identifiability.h), with the torque error of each on a
/// held-out part of the recording.
///
/// The consistent fit: each body's 10 parameters π (kinematic_tree.h) are those of the
/// pseudo-inertia J = [Σ h; hᵀ m] (Σ = ½·tr(I)·1 − I, h = m·c, I about the body origin) written
/// J = U·Uᵀ with U upper triangular and exp() on its diagonal, the log-Cholesky parametrization of
/// Rucker and Wensing ("Smooth Parameterizations of Rigid-Body Inertia", RA-L 2022):
///   θ = [α, d1, d2, d3, s12, s23, s13, t1, t2, t3],
///   U = e^α·[[e^d1, s12, s13, t1], [0, e^d2, s23, t2], [0, 0, e^d3, t3], [0, 0, 0, 1]],
/// so J ≻ 0 (a positive mass and a central inertia that a density can have) for every θ. The fit
/// minimises ‖W·π(θ) − τ‖² + λ·Σ_bodies ‖S_b·(π_b(θ) − π_b,prior)‖² over θ and the joints' friction
/// terms (linear, unconstrained), by Levenberg–Marquardt (Eigen's unsupported module), from the
/// prior: the file's values. S_b scales a body's mass, first moments and inertias by the prior's
/// mass m0 and length L (m0, m0·L, m0·L²), and λ is relative to the mean squared torque, so that
/// what the data do not see stays as the file has it.
///
/// Where a body's geometry is known (IdentifyOptions::ellipsoids, from BodyBoundingEllipsoids),
/// its θ are instead the coordinates of identify_ellipsoid.h: every θ is a density inside the
/// ellipsoid that bounds that geometry (Wensing, Kim and Slotine, RA-L 2018), still unconstrained.

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "massprops/analysis/identifiability.h"
#include "massprops/analysis/identify_ellipsoid.h"
#include "massprops/dynamics/kinematic_tree.h"
#include "massprops/dynamics/torque_regressor.h"
#include "massprops/io/trajectory_csv.h"

namespace massprops {

/// The log-Cholesky coordinates θ of one body (see the file comment).
using LogCholeskyParameters = Eigen::Matrix<double, 10, 1>;

/// π(θ): the inertial parameters of the pseudo-inertia U·Uᵀ. Physically consistent for every
/// finite θ. About 120 flops.
InertialParameters InertialParametersFromLogCholesky(const LogCholeskyParameters& theta);

/// dπ/dθ (10 × 10), exact. About 1 500 flops.
Eigen::Matrix<double, 10, 10> InertialParametersFromLogCholeskyJacobian(
    const LogCholeskyParameters& theta);

/// θ(π) for parameters whose pseudo-inertia is positive definite (the inverse of
/// InertialParametersFromLogCholesky, to round-off). Parameters that are not (a massless body,
/// an invalid inertia) are first moved to the nearest pseudo-inertia whose eigenvalues are at
/// least `floor` times its largest (and at least 1e-12). Never throws for finite π.
LogCholeskyParameters LogCholeskyFromInertialParameters(const InertialParameters& pi,
                                                        double floor = 1e-6);

/// Whether a body's parameters could be a body's: mass > 0 and the central inertia physically
/// valid (SpatialInertia::IsPhysicallyValid at `relative_tolerance`). Never throws.
bool IsConsistentBody(const InertialParameters& pi, double relative_tolerance = 1e-9);

/// The trajectory's q, q̇, q̈ and τ with their columns in the tree's joint order, or the error.
struct OrderedTrajectory {
  Eigen::MatrixXd q, dq, ddq, tau;  ///< N × tree.size() each
  std::string error;                ///< Names the joints missing on either side; "" when ok.
  bool ok() const { return error.empty(); }
};

/// Matches the trajectory's joints to the tree's by name. Errors: a tree joint the data lack
/// ("joint 'elbow' of the model has no columns in the data (elbow.q, elbow.tau)"), a joint of the
/// data the model does not move ("joint 'gripper' in the data is not a moving joint of the
/// model"); all such joints are named in one message. Never throws.
OrderedTrajectory OrderTrajectory(const KinematicTree& tree, const JointTrajectory& data);

struct IdentifyOptions {
  /// The last `validation_fraction` of the samples are held out (not fitted): [0, 0.9].
  double validation_fraction = 0.3;
  /// λ: weight of the prior relative to the data (see the file comment).
  double prior_weight = 1e-6;
  RegressorOptions regressor;  ///< Friction columns by default.
  IdentifiabilityOptions identifiability;
  int max_function_evaluations = 2000;
  /// Per body (tree order): the ellipsoid bounding its geometry (BodyBoundingEllipsoids), or
  /// nullopt where it is not known. Where one is given and usable (IsUsableEllipsoid), the body's
  /// estimate is the moments of a density inside it by construction (identify_ellipsoid.h);
  /// elsewhere J ≻ 0 only. Empty: no body's geometry is known.
  std::vector<std::optional<BoundingEllipsoid>> ellipsoids;
  /// false: the ellipsoids are neither imposed nor judged (`massprops identify --no-geometry`).
  bool geometry_bound = true;
};

/// One body before and after.
struct BodyEstimate {
  std::string link;
  InertialParameters file;           ///< The prior: the file's values (welded links included).
  InertialParameters least_squares;  ///< OLS base parameters, dependent ones at the file's values.
  InertialParameters identified;     ///< The consistent fit.
  bool least_squares_consistent = false;
  bool identified_consistent = false;
  /// The bound of its geometry's ellipsoid was imposed (IdentifyOptions::ellipsoids).
  bool geometry_bound = false;
  /// Where imposed: EllipsoidRatioOf of the file's, least squares' and the identified values (at
  /// most 1 for a density inside the ellipsoid); NaN elsewhere.
  double file_ellipsoid_ratio = std::numeric_limits<double>::quiet_NaN();
  double least_squares_ellipsoid_ratio = std::numeric_limits<double>::quiet_NaN();
  double identified_ellipsoid_ratio = std::numeric_limits<double>::quiet_NaN();
  /// Where imposed: least squares' ratio is at most 1 + 1e-9 (true where not imposed).
  bool least_squares_within_geometry = true;
};

struct IdentifyResult {
  std::vector<std::string> column_names;
  Identifiability identifiability;  ///< Of the fitted (training) samples.
  std::vector<std::string> unexcited_links;
  int training_samples = 0, validation_samples = 0;
  /// Full parameter vectors in column order (RegressorColumnNames).
  Eigen::VectorXd file, least_squares, identified;
  /// Base parameters β = B·π of each, and the OLS standard error of each (σ̂²·(W_bᵀW_b)⁻¹).
  Eigen::VectorXd base_file, base_least_squares, base_identified, base_standard_error;
  std::vector<BodyEstimate> bodies;
  int inconsistent_least_squares_links = 0;
  /// Bodies whose geometry bound was imposed, and those of them whose least squares estimate lies
  /// outside their ellipsoid (BodyEstimate::least_squares_within_geometry false).
  int geometry_bound_links = 0;
  int least_squares_outside_geometry_links = 0;
  /// Torque RMS per joint on the held-out samples (on the training samples when none are held
  /// out: validation_samples == 0), N·m or N.
  Eigen::VectorXd rms_file, rms_least_squares, rms_identified;
  /// Standard errors of the consistent estimate per body (tree order): of its mass (kg), of
  /// each coordinate of its center of mass (m, a 3 × bodies matrix) and of each principal moment
  /// (kg·m², ascending as BodyCentralProperties::principal; identify_uncertainty.h). The
  /// first-order spread of the estimate over the recording's noise, σ̂²·H⁻¹·J_dᵀJ_d·H⁻¹ at the
  /// solution (J_d the data Jacobian, H = JᵀJ with the prior's rows), σ̂² the data residual per
  /// degree of freedom: independent noise of one variance on every joint and sample. What the data
  /// do not determine stays at the file's value with a small error here: that is not knowledge of
  /// it (identifiability says which combinations the data determine).
  Eigen::VectorXd mass_standard_error;
  Eigen::Matrix3Xd com_standard_error;
  Eigen::Matrix3Xd principal_moments_standard_error;
  int solver_iterations = 0;
  std::string solver_status;  ///< Eigen's LevenbergMarquardt status, in words.
};

/// Identifies the inertial parameters of `tree` from `data` (its columns in tree order:
/// OrderTrajectory). The prior is the tree's own parameters (RegressorParameters). Throws
/// std::invalid_argument when the shapes disagree with the tree, when validation_fraction is
/// outside [0, 0.9], or when fewer than 2 samples remain to fit. Cost: the regressor of every
/// sample (docs/benchmarks.md section 12) and a Householder QR of [W τ] (O(rows · columns²)),
/// both a block of 256 samples at a time (memory O(256 · joints · columns), never the whole W);
/// the identifiability, least squares and every iteration of the fit then work on its R,
/// O(columns³) at most (the iiwa 14 with 20 000 samples: 0.23 s of CPU, docs/identify.md).
IdentifyResult Identify(const KinematicTree& tree, const OrderedTrajectory& data,
                        const IdentifyOptions& options = {});

}  // namespace massprops
