#include "massprops/analysis/identifiability.h"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace massprops {

namespace {

// The link of an inertial column "LINK.m" ... "LINK.izz"; empty for other columns.
std::string LinkOfInertialColumn(const std::string& name) {
  static const std::set<std::string> kInertial = {"m",   "mx",  "my",  "mz",  "ixx",
                                                  "ixy", "iyy", "ixz", "iyz", "izz"};
  const std::size_t dot = name.rfind('.');
  if (dot == std::string::npos || kInertial.count(name.substr(dot + 1)) == 0) return "";
  return name.substr(0, dot);
}

}  // namespace

std::string BaseParameter::ToString() const {
  std::ostringstream out;
  out.precision(6);
  out << name;
  for (const auto& [coefficient, other] : terms) {
    out << (coefficient < 0 ? " - " : " + ");
    const double magnitude = std::abs(coefficient);
    if (magnitude != 1) out << magnitude << "·";
    out << other;
  }
  return out.str();
}

Identifiability AnalyzeIdentifiability(const Eigen::MatrixXd& W,
                                       const std::vector<std::string>& column_names,
                                       const IdentifiabilityOptions& options) {
  const Eigen::Index p = W.cols();
  if (static_cast<Eigen::Index>(column_names.size()) != p) {
    throw std::invalid_argument("identifiability: " + std::to_string(column_names.size()) +
                                " column names for " + std::to_string(p) + " columns");
  }
  Identifiability out;
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(W);
  const Eigen::MatrixXd& QR = qr.matrixQR();
  const Eigen::Index diagonal = std::min(W.rows(), p);
  const double largest = diagonal > 0 ? std::abs(QR(0, 0)) : 0.0;
  Eigen::Index r = 0;
  while (r < diagonal && largest > 0 && std::abs(QR(r, r)) > options.relative_tolerance * largest)
    ++r;
  out.rank = static_cast<int>(r);
  const Eigen::VectorXi& pivot = qr.colsPermutation().indices();
  // K = R11⁻¹·R12: how each dependent column is made of the base ones.
  const Eigen::MatrixXd R11 = QR.topLeftCorner(r, r).triangularView<Eigen::Upper>();
  // (Not solved when either side is empty: Eigen's triangular solve reads a coefficient of an
  // empty right-hand side, undefined behaviour that UBSan reports.)
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(r, p - r);
  if (r > 0 && p - r > 0) {
    K = QR.topLeftCorner(r, r).triangularView<Eigen::Upper>().solve(QR.topRightCorner(r, p - r));
  }
  out.base_from_full = Eigen::MatrixXd::Zero(r, p);
  for (Eigen::Index i = 0; i < r; ++i) {
    BaseParameter base;
    base.column = pivot(i);
    base.name = column_names[static_cast<std::size_t>(pivot(i))];
    out.base_from_full(i, pivot(i)) = 1;
    for (Eigen::Index j = 0; j < p - r; ++j) {
      const double k = K(i, j);
      out.base_from_full(i, pivot(r + j)) = k;
      if (std::abs(k) > options.coefficient_tolerance)
        base.terms.emplace_back(k, column_names[static_cast<std::size_t>(pivot(r + j))]);
    }
    out.base.push_back(std::move(base));
  }
  for (Eigen::Index j = 0; j < p - r; ++j) {
    if (r == 0 || K.col(j).cwiseAbs().maxCoeff() <= options.coefficient_tolerance)
      out.unidentified.push_back(pivot(r + j));
  }
  std::sort(out.unidentified.begin(), out.unidentified.end());
  if (r == 0) {
    out.condition_number = std::numeric_limits<double>::infinity();
  } else {
    // W_base = Q1·R11 with Q1 orthonormal: the same singular values as R11.
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(R11);
    const Eigen::VectorXd& s = svd.singularValues();
    out.condition_number = s(0) / s(r - 1);
  }
  return out;
}

std::vector<std::string> UnexcitedLinks(const Identifiability& identifiability,
                                        const std::vector<std::string>& column_names) {
  std::vector<std::string> links;
  std::set<std::string> seen_link, excited;
  for (std::size_t c = 0; c < column_names.size(); ++c) {
    const std::string link = LinkOfInertialColumn(column_names[c]);
    if (link.empty()) continue;
    if (seen_link.insert(link).second) links.push_back(link);
    const bool identified =
        !std::binary_search(identifiability.unidentified.begin(),
                            identifiability.unidentified.end(), static_cast<int>(c));
    if (identified) excited.insert(link);
  }
  std::vector<std::string> unexcited;
  for (const std::string& link : links)
    if (excited.count(link) == 0) unexcited.push_back(link);
  return unexcited;
}

}  // namespace massprops
