// Identification of a tree's inertial parameters from recorded torques (identify.h): ordinary
// least squares on the base parameters and the physically consistent fit by Levenberg–Marquardt
// over the log-Cholesky coordinates, each judged on held-out samples.
#include "massprops/analysis/identify.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unsupported/Eigen/LevenbergMarquardt>
#include <utility>
#include <vector>

#include "massprops/analysis/identify_uncertainty.h"

namespace massprops {

namespace {

// A body's scales for the prior: its mass m0 and length L (the root mean square distance of its
// mass from its origin), so that mass, first moments and inertias deviate in units of m0, m0·L
// and m0·L².
Eigen::Matrix<double, 10, 1> PriorScales(const InertialParameters& pi, double fallback_mass) {
  const double m0 = pi[0] > 0 && std::isfinite(pi[0]) ? pi[0] : fallback_mass;
  // tr(Σ) = ½·(Ixx + Iyy + Izz) about the origin: Σ m·|r|².
  const double second_moment = 0.5 * (pi[4] + pi[6] + pi[9]);
  double length = pi[0] > 0 && second_moment > 0 ? std::sqrt(second_moment / pi[0]) : 0.1;
  if (!(length > 1e-3)) length = 1e-3;
  Eigen::Matrix<double, 10, 1> s;
  s << m0, m0 * length, m0 * length, m0 * length, m0 * length * length, m0 * length * length,
      m0 * length * length, m0 * length * length, m0 * length * length, m0 * length * length;
  return s;
}

// The residual of the consistent fit: the data (through R of the QR of [W τ]) and the prior.
struct ConsistentFitFunctor : Eigen::DenseFunctor<double> {
  // `ellipsoids`: per body, the ellipsoid its θ keep it inside (identify_ellipsoid.h), or null
  // for the log-Cholesky coordinates.
  ConsistentFitFunctor(const Eigen::MatrixXd& R, int bodies, const Eigen::VectorXd& prior,
                       const Eigen::VectorXd& prior_weights,
                       std::vector<const BoundingEllipsoid*> ellipsoids)
      : Eigen::DenseFunctor<double>(static_cast<int>(R.cols() - 1),
                                    static_cast<int>(R.rows() + 10 * bodies)),
        R_(R),
        bodies_(bodies),
        prior_(prior),
        weights_(prior_weights),
        ellipsoids_(std::move(ellipsoids)) {}

  // Body b's π(θ) and dπ/dθ.
  InertialParameters BodyParameters(int b, const Eigen::VectorXd& x) const {
    const Eigen::Matrix<double, 10, 1> theta = x.segment<10>(10 * b);
    const BoundingEllipsoid* e = ellipsoids_[static_cast<std::size_t>(b)];
    return e ? InertialParametersFromEllipsoidParameters(theta, *e)
             : InertialParametersFromLogCholesky(theta);
  }
  Eigen::Matrix<double, 10, 10> BodyJacobian(int b, const Eigen::VectorXd& x) const {
    const Eigen::Matrix<double, 10, 1> theta = x.segment<10>(10 * b);
    const BoundingEllipsoid* e = ellipsoids_[static_cast<std::size_t>(b)];
    return e ? InertialParametersFromEllipsoidParametersJacobian(theta, *e)
             : InertialParametersFromLogCholeskyJacobian(theta);
  }

  // The full parameter vector π of x = [θ per body, friction].
  Eigen::VectorXd Parameters(const Eigen::VectorXd& x) const {
    Eigen::VectorXd pi = x;
    for (int b = 0; b < bodies_; ++b) pi.segment<10>(10 * b) = BodyParameters(b, x);
    return pi;
  }

  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
    const Eigen::VectorXd pi = Parameters(x);
    const Eigen::Index c = R_.cols() - 1;
    f.resize(values());
    f.head(R_.rows()) = R_.leftCols(c) * pi - R_.col(c);
    const Eigen::Index inertial = 10 * bodies_;
    f.tail(inertial) = weights_.cwiseProduct(pi.head(inertial) - prior_.head(inertial));
    return 0;
  }

  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jac) const {
    ++jacobians;  // once per iteration
    const Eigen::Index c = R_.cols() - 1;
    Eigen::MatrixXd D = Eigen::MatrixXd::Identity(c, c);
    for (int b = 0; b < bodies_; ++b) D.block<10, 10>(10 * b, 10 * b) = BodyJacobian(b, x);
    jac.resize(values(), inputs());
    jac.topRows(R_.rows()) = R_.leftCols(c) * D;
    const Eigen::Index inertial = 10 * bodies_;
    jac.bottomRows(inertial) = weights_.asDiagonal() * D.topRows(inertial);
    return 0;
  }

  const Eigen::MatrixXd& R_;
  int bodies_;
  Eigen::VectorXd prior_, weights_;
  std::vector<const BoundingEllipsoid*> ellipsoids_;
  mutable int jacobians = 0;
};

std::string StatusInWords(Eigen::LevenbergMarquardtSpace::Status status) {
  using S = Eigen::LevenbergMarquardtSpace::Status;
  switch (status) {
    case S::RelativeReductionTooSmall:
    case S::RelativeErrorTooSmall:
    case S::RelativeErrorAndReductionTooSmall:
    case S::CosinusTooSmall:
      return "converged";
    case S::TooManyFunctionEvaluation:
      return "stopped at the evaluation limit";
    case S::FtolTooSmall:
    case S::XtolTooSmall:
    case S::GtolTooSmall:
      return "converged to the precision of doubles";
    default:
      return "did not run (improper input)";
  }
}

// The samples [first, first + count) a block at a time: the stacked regressor W of the block's
// samples (rows: samples × joints, as StackTorqueRegressor orders them) and their torques τ
// stacked alike, passed to use(W, τ). No matrix of all the samples is made: 20 000 samples of a
// 7-joint arm made one of 102 MB (and a copy of it beside τ), whose first touch alone cost more
// CPU than the regressor's arithmetic; a block of 256 samples (1.3 MB there) stays in cache.
template <typename Use>
void ForEachSampleBlock(const KinematicTree& tree, const OrderedTrajectory& data,
                        Eigen::Index first, Eigen::Index count, const RegressorOptions& options,
                        Use use) {
  constexpr Eigen::Index kSamplesPerBlock = 256;
  const Eigen::Index n = tree.size();
  Eigen::MatrixXd W(std::min(kSamplesPerBlock, count) * n, CountRegressorColumns(tree, options));
  Eigen::VectorXd tau(W.rows());
  for (Eigen::Index start = first; start < first + count; start += kSamplesPerBlock) {
    const Eigen::Index samples = std::min(kSamplesPerBlock, first + count - start);
    for (Eigen::Index k = 0; k < samples; ++k) {
      const Eigen::Index s = start + k;
      CalcTorqueRegressor(tree, data.q.row(s).transpose(), data.dq.row(s).transpose(),
                          data.ddq.row(s).transpose(), options, W.middleRows(k * n, n));
      tau.segment(k * n, n) = data.tau.row(s).transpose();
    }
    use(W.topRows(samples * n), tau.head(samples * n));
  }
}

// Per joint RMS of W·π − τ over the samples [first, first + count), for each π of `pis`.
std::vector<Eigen::VectorXd> JointRms(const KinematicTree& tree, const OrderedTrajectory& data,
                                      Eigen::Index first, Eigen::Index count,
                                      const RegressorOptions& options,
                                      const std::vector<const Eigen::VectorXd*>& pis) {
  const int n = tree.size();
  std::vector<Eigen::VectorXd> sums(pis.size(), Eigen::VectorXd::Zero(n));
  ForEachSampleBlock(tree, data, first, count, options,
                     [&](const Eigen::Ref<const Eigen::MatrixXd>& W,
                         const Eigen::Ref<const Eigen::VectorXd>& tau) {
                       for (std::size_t i = 0; i < pis.size(); ++i) {
                         const Eigen::VectorXd e = W * *pis[i] - tau;
                         for (Eigen::Index r = 0; r < e.size(); ++r) sums[i][r % n] += e[r] * e[r];
                       }
                     });
  for (Eigen::VectorXd& sum : sums)
    sum = (sum / static_cast<double>(std::max<Eigen::Index>(count, 1))).cwiseSqrt();
  return sums;
}

// R of the QR of the fitted samples' [W τ] (min(rows, c + 1) × (c + 1)): ‖W·π − τ‖ = ‖R·[π; −1]‖
// for every π and W = Q·R, so the rank, the base parameters, the singular values, least squares
// and the consistent fit are all computed from R. Computed a block of samples at a time: the R so
// far stacked on the block's [W τ], decomposed in place, its R kept (the same R up to the signs of
// its rows, which none of those uses sees: they depend on RᵀR only).
Eigen::MatrixXd CompressSamples(const KinematicTree& tree, const OrderedTrajectory& data,
                                Eigen::Index count, const RegressorOptions& options) {
  const Eigen::Index c = CountRegressorColumns(tree, options);
  Eigen::MatrixXd A;
  Eigen::Index kept = 0;  // rows of R at the top of A
  ForEachSampleBlock(tree, data, 0, count, options,
                     [&](const Eigen::Ref<const Eigen::MatrixXd>& W,
                         const Eigen::Ref<const Eigen::VectorXd>& tau) {
                       if (A.rows() < c + 1 + W.rows())
                         A.conservativeResize(c + 1 + W.rows(), c + 1);
                       A.middleRows(kept, W.rows()).leftCols(c) = W;
                       A.middleRows(kept, W.rows()).col(c) = tau;
                       Eigen::Ref<Eigen::MatrixXd> used = A.topRows(kept + W.rows());
                       const Eigen::HouseholderQR<Eigen::Ref<Eigen::MatrixXd>> qr(used);
                       kept = std::min<Eigen::Index>(kept + W.rows(), c + 1);
                       A.topRows(kept).triangularView<Eigen::StrictlyLower>().setZero();
                     });
  return A.topRows(kept);
}

// OLS through the base columns of the compressed data R (CompressSamples of `samples_rows` rows):
// β̂, its standard errors, and a full π whose base parameters are β̂ and whose dependent parameters
// are the prior's (π_base = β̂ − K·π_dependent).
void FitLeastSquares(const Eigen::MatrixXd& R, Eigen::Index samples_rows,
                     const Eigen::VectorXd& prior, IdentifyResult* out) {
  const Identifiability& id = out->identifiability;
  const int r = id.rank;
  const Eigen::Index c = R.cols() - 1;
  out->least_squares = prior;
  out->base_least_squares.resize(0);
  out->base_standard_error.resize(0);
  if (r == 0) return;  // no data: nothing to solve (and no empty triangular solve)
  Eigen::MatrixXd Rb(R.rows(), r);
  for (int i = 0; i < r; ++i) Rb.col(i) = R.col(id.base[static_cast<std::size_t>(i)].column);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Rb);
  const Eigen::VectorXd beta = qr.solve(R.col(c));
  const double dof = static_cast<double>(std::max<Eigen::Index>(samples_rows - r, 1));
  const double sigma2 = (Rb * beta - R.col(c)).squaredNorm() / dof;
  const Eigen::MatrixXd Rinv =
      qr.matrixQR().topLeftCorner(r, r).triangularView<Eigen::Upper>().solve(
          Eigen::MatrixXd::Identity(r, r));
  out->base_standard_error = (sigma2 * Rinv.rowwise().squaredNorm()).cwiseSqrt();
  out->base_least_squares = beta;
  // π with the prior's values, then each base column set so that B·π = β̂ (B has a 1 at each
  // base column and no other base column's entry in its row).
  Eigen::VectorXd pi = prior;
  for (int i = 0; i < r; ++i) pi[id.base[static_cast<std::size_t>(i)].column] = 0;
  const Eigen::VectorXd rest = id.base_from_full * pi;
  for (int i = 0; i < r; ++i) pi[id.base[static_cast<std::size_t>(i)].column] = beta[i] - rest[i];
  out->least_squares = pi;
}

// The covariance of the consistent estimate over the recording's noise, to first order at the
// solution x: with J = [J_d; J_p] the Jacobian of the data and prior residuals and H = JᵀJ, a
// change ε of the torques moves x by −H⁻¹·J_dᵀ·ε, so Cov(x) = σ̂²·H⁻¹·J_dᵀJ_d·H⁻¹ (the sandwich
// form: the prior shrinks what the data barely see, and the spread over noise with it). σ̂² is the
// data residual over samples_rows − rank. Assumes independent noise of one variance on every
// joint and sample, and a fit close to linear over ±σ̂ (no constraint active: neither the
// log-Cholesky nor the ellipsoid coordinates have one; near an ellipsoid's boundary the map bends).
// Mapped per body to its mass and center of mass c = h/m through dπ/dθ and the Jacobian [−h/m²,
// 1/m] of c, and to its principal moments through their first-order Jacobian
// (identify_uncertainty.h).
void ConsistentCovariance(const ConsistentFitFunctor& functor, const Eigen::VectorXd& x,
                          Eigen::Index samples_rows, IdentifyResult* out) {
  Eigen::VectorXd f;
  Eigen::MatrixXd J;
  functor(x, f);
  functor.df(x, J);
  const Eigen::Index data_rows = functor.R_.rows();
  const double dof =
      static_cast<double>(std::max<Eigen::Index>(samples_rows - out->identifiability.rank, 1));
  const double sigma2 = f.head(data_rows).squaredNorm() / dof;
  const Eigen::MatrixXd Jd = J.topRows(data_rows);
  const Eigen::MatrixXd Hinv =
      (J.transpose() * J).completeOrthogonalDecomposition().pseudoInverse();
  const Eigen::MatrixXd cov = sigma2 * Hinv * (Jd.transpose() * Jd) * Hinv;
  out->mass_standard_error.resize(functor.bodies_);
  out->com_standard_error.resize(3, functor.bodies_);
  out->principal_moments_standard_error.resize(3, functor.bodies_);
  for (int b = 0; b < functor.bodies_; ++b) {
    const Eigen::Matrix<double, 10, 10> D = functor.BodyJacobian(b, x);
    const Eigen::Matrix<double, 10, 10> cov_pi =
        D * cov.block<10, 10>(10 * b, 10 * b) * D.transpose();
    const InertialParameters pi = out->identified.segment<10>(10 * b);
    const double m = pi[0];
    Eigen::Matrix<double, 3, 4> G;
    G.col(0) = -pi.segment<3>(1) / (m * m);
    G.rightCols<3>() = Eigen::Matrix3d::Identity() / m;
    const Eigen::Matrix3d cov_c = G * cov_pi.topLeftCorner<4, 4>() * G.transpose();
    out->mass_standard_error[b] = std::sqrt(std::max(cov_pi(0, 0), 0.0));
    out->com_standard_error.col(b) = cov_c.diagonal().cwiseMax(0.0).cwiseSqrt();
    out->principal_moments_standard_error.col(b) = PrincipalMomentsStandardError(pi, cov_pi);
  }
}

// Levenberg–Marquardt from x, in rounds of at most 300 evaluations, up to
// `evaluations` in all. A body whose fit reaches its ellipsoid's boundary has coordinates v of
// unbounded size there (w = v/√(1 + ‖v‖²)), where every derivative shrinks like 1/‖v‖ and the
// solver's scaling (which only grows) stalls it at the first point of the boundary it reaches.
// So between rounds each such body (ratio above kBoundaryRatio) is mapped to coordinates again,
// contracted about x0 to that ratio (a move of 1/2000 of its size), and the solver restarts with
// a fresh scaling. Stops when a round converges with no body at a boundary, or when a round
// lowered the residual by less than 1e-9 of it. Without ellipsoids: one run, as before.
Eigen::LevenbergMarquardtSpace::Status MinimizeInRounds(ConsistentFitFunctor& functor,
                                                        int evaluations, Eigen::VectorXd* x) {
  const bool bounded = std::any_of(functor.ellipsoids_.begin(), functor.ellipsoids_.end(),
                                   [](const BoundingEllipsoid* e) { return e != nullptr; });
  // No ellipsoid: one run with the whole budget.
  const int round_evaluations = bounded ? 300 : evaluations;
  constexpr double kBoundaryRatio = 0.999;
  Eigen::LevenbergMarquardtSpace::Status status =
      Eigen::LevenbergMarquardtSpace::ImproperInputParameters;
  double before = HUGE_VAL;
  while (evaluations > 0) {
    Eigen::LevenbergMarquardt<ConsistentFitFunctor> lm(functor);
    lm.setMaxfev(std::min(evaluations, round_evaluations));
    status = lm.minimize(*x);
    evaluations -= std::max<int>(static_cast<int>(lm.nfev()), 1);
    const double after = lm.fnorm();
    if (!(after < before * (1 - 1e-9))) break;
    before = after;
    bool remapped = false;
    for (int b = 0; b < functor.bodies_; ++b) {
      const BoundingEllipsoid* e = functor.ellipsoids_[static_cast<std::size_t>(b)];
      if (e == nullptr) continue;
      const InertialParameters pi = functor.BodyParameters(b, *x);
      if (!(EllipsoidRatioOf(pi, *e) > kBoundaryRatio)) continue;
      x->segment<10>(10 * b) = EllipsoidParametersFromInertialParameters(pi, *e, kBoundaryRatio);
      remapped = true;
    }
    if (!remapped && status != Eigen::LevenbergMarquardtSpace::TooManyFunctionEvaluation) break;
  }
  return status;
}

// Per body, the ellipsoid the fit keeps it inside, or null: where options give a usable one and
// the bound is on.
std::vector<const BoundingEllipsoid*> ImposedEllipsoids(int bodies,
                                                        const IdentifyOptions& options) {
  std::vector<const BoundingEllipsoid*> out(static_cast<std::size_t>(bodies), nullptr);
  if (!options.geometry_bound || options.ellipsoids.size() != out.size()) return out;
  for (std::size_t b = 0; b < out.size(); ++b) {
    const std::optional<BoundingEllipsoid>& e = options.ellipsoids[b];
    if (e && IsUsableEllipsoid(*e)) out[b] = &*e;
  }
  return out;
}

// The consistent fit on the compressed data R; sum_squares = Σ τ² of the fitted samples (the data
// term's scale, which the prior weight is relative to). A body with an imposed ellipsoid whose
// file values have a ratio above kEllipsoidPriorRatio (outside it, or within 1% of its boundary)
// starts from, and is regularised toward, those values contracted about the ellipsoid's center
// to that ratio (EllipsoidParametersFromInertialParameters: mass kept, center of mass moved
// toward x0, central second moment scaled by the square of the factor).
void FitConsistent(const KinematicTree& tree, const Eigen::MatrixXd& R, double sum_squares,
                   Eigen::Index samples_rows, const IdentifyOptions& options, IdentifyResult* out) {
  const int n = tree.size();
  double mean_mass = 0;
  int massive = 0;
  for (const MovingBody& b : tree.bodies) {
    if (b.pi_BBo_B[0] > 0) mean_mass += b.pi_BBo_B[0], ++massive;
  }
  mean_mass = massive > 0 ? mean_mass / massive : 1.0;
  const std::vector<const BoundingEllipsoid*> ellipsoids = ImposedEllipsoids(n, options);
  Eigen::VectorXd weights(10 * n);
  Eigen::VectorXd x = out->file;
  Eigen::VectorXd prior = out->file;
  for (int b = 0; b < n; ++b) {
    const InertialParameters file = out->file.segment<10>(10 * b);
    weights.segment<10>(10 * b) =
        std::sqrt(options.prior_weight * sum_squares) * PriorScales(file, mean_mass).cwiseInverse();
    const BoundingEllipsoid* e = ellipsoids[static_cast<std::size_t>(b)];
    if (e == nullptr) {
      x.segment<10>(10 * b) = LogCholeskyFromInertialParameters(file);
      continue;
    }
    x.segment<10>(10 * b) = EllipsoidParametersFromInertialParameters(file, *e);
    if (!(EllipsoidRatioOf(file, *e) <= kEllipsoidPriorRatio)) {
      prior.segment<10>(10 * b) =
          InertialParametersFromEllipsoidParameters(x.segment<10>(10 * b), *e);
    }
  }
  ConsistentFitFunctor functor(R, n, prior, weights, ellipsoids);
  const Eigen::LevenbergMarquardtSpace::Status status =
      MinimizeInRounds(functor, options.max_function_evaluations, &x);
  out->solver_iterations = functor.jacobians;
  out->solver_status = StatusInWords(status);
  out->identified = functor.Parameters(x);
  ConsistentCovariance(functor, x, samples_rows, out);
}

}  // namespace

OrderedTrajectory OrderTrajectory(const KinematicTree& tree, const JointTrajectory& data) {
  OrderedTrajectory out;
  std::vector<std::string> missing, extra;
  std::vector<int> column(static_cast<std::size_t>(tree.size()), -1);
  for (std::size_t i = 0; i < data.joints.size(); ++i) {
    const int j = tree.FindJoint(data.joints[i]);
    if (j < 0) {
      extra.push_back(data.joints[i]);
    } else {
      column[static_cast<std::size_t>(j)] = static_cast<int>(i);
    }
  }
  for (int j = 0; j < tree.size(); ++j) {
    if (column[static_cast<std::size_t>(j)] < 0) missing.push_back(tree.bodies[j].joint);
  }
  for (const std::string& m : missing) {
    out.error += (out.error.empty() ? "" : "; ") + std::string("joint '") + m +
                 "' of the model has no columns in the data (" + m + ".q, " + m + ".tau)";
  }
  for (const std::string& e : extra) {
    out.error += (out.error.empty() ? "" : "; ") + std::string("joint '") + e +
                 "' in the data is not a moving joint of the model";
  }
  if (!out.ok()) return out;
  const Eigen::Index N = data.time.size();
  out.q.resize(N, tree.size());
  out.dq.resize(N, tree.size());
  out.ddq.resize(N, tree.size());
  out.tau.resize(N, tree.size());
  for (int j = 0; j < tree.size(); ++j) {
    const int i = column[static_cast<std::size_t>(j)];
    out.q.col(j) = data.q.col(i);
    out.dq.col(j) = data.dq.col(i);
    out.ddq.col(j) = data.ddq.col(i);
    out.tau.col(j) = data.tau.col(i);
  }
  return out;
}

IdentifyResult Identify(const KinematicTree& tree, const OrderedTrajectory& data,
                        const IdentifyOptions& options) {
  const int n = tree.size();
  if (data.q.cols() != n || data.tau.cols() != n || data.tau.rows() != data.q.rows()) {
    throw std::invalid_argument("identify: the data have " + std::to_string(data.q.cols()) +
                                " joints and " + std::to_string(data.tau.rows()) +
                                " torque rows; the tree has " + std::to_string(n) + " joints");
  }
  if (!(options.validation_fraction >= 0 && options.validation_fraction <= 0.9)) {
    throw std::invalid_argument("identify: validation fraction " +
                                std::to_string(options.validation_fraction) +
                                " is not in [0, 0.9]");
  }
  const Eigen::Index N = data.q.rows();
  const Eigen::Index held = static_cast<Eigen::Index>(std::floor(options.validation_fraction * N));
  const Eigen::Index fit = N - held;
  if (fit < 2) throw std::invalid_argument("identify: fewer than 2 samples to fit");
  IdentifyResult out;
  out.training_samples = static_cast<int>(fit);
  out.validation_samples = static_cast<int>(held);
  out.column_names = RegressorColumnNames(tree, options.regressor);
  const Eigen::MatrixXd R = CompressSamples(tree, data, fit, options.regressor);
  const Eigen::Index c = R.cols() - 1;
  out.identifiability =
      AnalyzeIdentifiability(R.leftCols(c), out.column_names, options.identifiability);
  out.unexcited_links = UnexcitedLinks(out.identifiability, out.column_names);
  out.file = RegressorParameters(tree, options.regressor);
  FitLeastSquares(R, fit * n, out.file, &out);
  FitConsistent(tree, R, data.tau.topRows(fit).squaredNorm(), fit * n, options, &out);
  const std::vector<const BoundingEllipsoid*> ellipsoids = ImposedEllipsoids(n, options);
  const Eigen::MatrixXd& B = out.identifiability.base_from_full;
  out.base_file = B * out.file;
  out.base_identified = B * out.identified;
  for (int b = 0; b < n; ++b) {
    BodyEstimate e;
    e.link = tree.bodies[b].link;
    e.file = out.file.segment<10>(10 * b);
    e.least_squares = out.least_squares.segment<10>(10 * b);
    e.identified = out.identified.segment<10>(10 * b);
    e.least_squares_consistent = IsConsistentBody(e.least_squares);
    e.identified_consistent = IsConsistentBody(e.identified);
    if (!e.least_squares_consistent) ++out.inconsistent_least_squares_links;
    if (const BoundingEllipsoid* bound = ellipsoids[static_cast<std::size_t>(b)]) {
      e.geometry_bound = true;
      e.file_ellipsoid_ratio = EllipsoidRatioOf(e.file, *bound);
      e.least_squares_ellipsoid_ratio = EllipsoidRatioOf(e.least_squares, *bound);
      e.identified_ellipsoid_ratio = EllipsoidRatioOf(e.identified, *bound);
      e.least_squares_within_geometry = e.least_squares_ellipsoid_ratio <= 1 + 1e-9;
      ++out.geometry_bound_links;
      if (!e.least_squares_within_geometry) ++out.least_squares_outside_geometry_links;
    }
    out.bodies.push_back(e);
  }
  const std::vector<Eigen::VectorXd> rms =
      JointRms(tree, data, held > 0 ? fit : 0, held > 0 ? held : fit, options.regressor,
               {&out.file, &out.least_squares, &out.identified});
  out.rms_file = rms[0];
  out.rms_least_squares = rms[1];
  out.rms_identified = rms[2];
  return out;
}

}  // namespace massprops
