#include "massprops/output/identify_report.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "massprops/core/rotational_inertia.h"

namespace massprops {

namespace {

nlohmann::json IdentifyVectorJson(const Eigen::VectorXd& v) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(v[i]);
  return out;
}

nlohmann::json IdentifyBodyJson(const InertialParameters& pi) {
  const BodyCentralProperties p = CentralPropertiesOf(pi);
  return {{"mass", p.mass},
          {"com", IdentifyVectorJson(p.com)},
          {"principal_moments", IdentifyVectorJson(p.principal)},
          {"parameters", IdentifyVectorJson(pi)}};
}

// A ratio, or null where not finite (no bound imposed, or no positive mass).
nlohmann::json RatioJson(double ratio) {
  return std::isfinite(ratio) ? nlohmann::json(ratio) : nlohmann::json(nullptr);
}

// Whether the geometry bound was imposed, the ellipsoid ratio of each estimate and whether least
// squares' lies inside (null where not imposed).
void AddGeometryBoundJson(const BodyEstimate& b, nlohmann::json* link) {
  (*link)["geometry_bound"] = b.geometry_bound;
  if (!b.geometry_bound) {
    (*link)["ellipsoid_ratio"] = nullptr;
    (*link)["least_squares_within_geometry"] = nullptr;
    return;
  }
  (*link)["ellipsoid_ratio"] = {{"file", RatioJson(b.file_ellipsoid_ratio)},
                                {"least_squares", RatioJson(b.least_squares_ellipsoid_ratio)},
                                {"identified", RatioJson(b.identified_ellipsoid_ratio)}};
  (*link)["least_squares_within_geometry"] = b.least_squares_within_geometry;
}

}  // namespace

BodyCentralProperties CentralPropertiesOf(const InertialParameters& pi) {
  BodyCentralProperties out;
  out.mass = pi[0];
  if (!(pi[0] > 0) || !pi.allFinite()) return out;
  out.com = pi.segment<3>(1) / pi[0];
  Eigen::Matrix3d I;
  I << pi[4], pi[5], pi[7], pi[5], pi[6], pi[8], pi[7], pi[8], pi[9];
  const Eigen::Vector3d& c = out.com;
  out.I_BBcm_B = I - pi[0] * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  const Eigen::Matrix3d& J = out.I_BBcm_B;
  out.principal = internal::ScaledPrincipalMoments<double>(
      J(0, 0), J(1, 1), J(2, 2), J(0, 1), J(0, 2), J(1, 2), PrincipalSolver::kAccurate);
  return out;
}

std::string RenderIdentifyJson(const KinematicTree& tree, const IdentifyResult& r) {
  const Identifiability& id = r.identifiability;
  nlohmann::json base = nlohmann::json::array();
  for (std::size_t i = 0; i < id.base.size(); ++i) {
    const Eigen::Index k = static_cast<Eigen::Index>(i);
    base.push_back({{"name", id.base[i].ToString()},
                    {"file", r.base_file[k]},
                    {"least_squares", r.base_least_squares[k]},
                    {"identified", r.base_identified[k]},
                    {"standard_error", r.base_standard_error[k]}});
  }
  nlohmann::json joints = nlohmann::json::array();
  for (int j = 0; j < tree.size(); ++j) {
    joints.push_back({{"joint", tree.bodies[j].joint},
                      {"rms_file", r.rms_file[j]},
                      {"rms_least_squares", r.rms_least_squares[j]},
                      {"rms_identified", r.rms_identified[j]}});
  }
  nlohmann::json links = nlohmann::json::array();
  for (const BodyEstimate& b : r.bodies) {
    nlohmann::json identified = IdentifyBodyJson(b.identified);
    if (r.mass_standard_error.size() == static_cast<Eigen::Index>(r.bodies.size())) {
      const Eigen::Index k = static_cast<Eigen::Index>(&b - r.bodies.data());
      identified["mass_standard_error"] = r.mass_standard_error[k];
      identified["com_standard_error"] = IdentifyVectorJson(r.com_standard_error.col(k));
      identified["principal_moments_standard_error"] =
          IdentifyVectorJson(r.principal_moments_standard_error.col(k));
    }
    nlohmann::json link = {{"link", b.link},
                           {"file", IdentifyBodyJson(b.file)},
                           {"identified", identified},
                           {"least_squares_consistent", b.least_squares_consistent},
                           {"identified_consistent", b.identified_consistent}};
    AddGeometryBoundJson(b, &link);
    links.push_back(link);
  }
  const nlohmann::json out = {
      {"identifiability",
       {{"rank", id.rank},
        {"parameters", r.column_names.size()},
        {"condition_number", std::isfinite(id.condition_number)
                                 ? nlohmann::json(id.condition_number)
                                 : nlohmann::json(nullptr)},
        {"unexcited_links", r.unexcited_links},
        {"base_parameters", base}}},
      {"training_samples", r.training_samples},
      {"validation_samples", r.validation_samples},
      {"joints", joints},
      {"links", links},
      {"inconsistent_least_squares_links", r.inconsistent_least_squares_links},
      {"geometry_bound_links", r.geometry_bound_links},
      {"least_squares_outside_geometry_links", r.least_squares_outside_geometry_links},
      {"solver", {{"status", r.solver_status}, {"iterations", r.solver_iterations}}}};
  return out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace massprops
