#pragma once
/// @file
/// Which parameter combinations recorded motion determines: the base parameters of a stacked
/// joint-torque regressor W (dynamics/torque_regressor.h), by QR with column pivoting
/// (Gautier, "Numerical calculation of the base inertial parameters of robots", J. Robotic
/// Systems 1991; Khalil and Dombre 2002, §12.4). With W·P = Q·[R11 R12; 0 0], R11 of rank r:
///   the base columns are the r first pivots; the others are combinations of them,
///   W_dependent = W_base·K with K = R11⁻¹·R12; the base parameters are β = π_base + K·π_dependent
///   (so that W·π = W_base·β for every π), and are all the data can determine.
/// The rank is decided with a relative tolerance on |R_ii| (the default: 1e-8 of the largest,
/// far above round-off and below any real excitation of double data).

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace massprops {

struct IdentifiabilityOptions {
  /// A column counts as independent while |R_ii| > relative_tolerance · |R_00|.
  double relative_tolerance = 1e-8;
  /// Coefficients of K with |K_ij| ≤ this are left out of BaseParameter::terms (not of
  /// base_from_full).
  double coefficient_tolerance = 1e-9;
};

/// One base parameter, in words: the column it is named after plus the dependent columns that
/// regroup into it, β = column + Σ coefficient·other.
struct BaseParameter {
  int column = -1;
  std::string name;
  std::vector<std::pair<double, std::string>> terms;  ///< (coefficient, column name)
  /// "upper.izz + 0.64·fore.m + 0.8·fore.mx" (6 significant digits).
  std::string ToString() const;
};

struct Identifiability {
  int rank = 0;                     ///< Number of base parameters.
  std::vector<BaseParameter> base;  ///< In pivot order (best determined first).
  std::vector<int> unidentified;    ///< Columns that enter no base parameter (all-zero data).
  /// β = base_from_full · π: rank × columns.
  Eigen::MatrixXd base_from_full;
  /// σ_max / σ_min of W restricted to the base columns (∞ when rank is 0). Cost: an SVD of
  /// the base columns.
  double condition_number = 0;
};

/// The base parameters of the stacked regressor W (rows: samples × joints; columns named by
/// `column_names`, one each: RegressorColumnNames). Throws std::invalid_argument when the names
/// are not one per column. Cost: the pivoted QR of W, O(rows · columns²).
Identifiability AnalyzeIdentifiability(const Eigen::MatrixXd& W,
                                       const std::vector<std::string>& column_names,
                                       const IdentifiabilityOptions& options = {});

/// The links none of whose 10 inertial columns ("LINK.m" ... "LINK.izz") enters a base
/// parameter with a non-zero coefficient: the data say nothing about their mass properties.
/// In the order of the columns.
std::vector<std::string> UnexcitedLinks(const Identifiability& identifiability,
                                        const std::vector<std::string>& column_names);

}  // namespace massprops
