// inertia-not-finite (error): an inertial has a NaN or infinite inertia entry or center of mass.
//
// Evidence: the six numbers of the link's <inertia> and its inertial <origin>/<pose>.
// Why: a non-finite entry makes the inertia, and every composite that includes it, undefined;
// the other rules cannot judge such a link, so CheckModel stops at this one for it.

#include <string>

#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kInertiaNotFinite = "inertia-not-finite";

}  // namespace

const RuleInfo& InertiaNotFiniteRule() {
  static const RuleInfo kInfo{kInertiaNotFinite, Severity::kError, true,
                              "An inertial has a NaN or infinite inertia entry or center of mass."};
  return kInfo;
}

bool CheckInertiaNotFinite(RuleContext& ctx, const Link& link, const std::string& who) {
  const Inertial& in = *link.inertial;
  const Eigen::Matrix3d I_written = WrittenMatrix(in);
  if (I_written.allFinite() && in.X_BBi.p_AB.allFinite() && in.X_BBi.R_AB.allFinite()) {
    return true;
  }
  ctx.Emit(kInertiaNotFinite, link, InertiaLocation(link),
           who + ": the inertial has a NaN or infinite number: ixx " + Num(in.ixx) + ", iyy " +
               Num(in.iyy) + ", izz " + Num(in.izz) + ", ixy " + Num(in.ixy) + ", ixz " +
               Num(in.ixz) + ", iyz " + Num(in.iyz) + ", center of mass " + Vec(in.X_BBi.p_AB),
           {{"ixx", in.ixx},
            {"iyy", in.iyy},
            {"izz", in.izz},
            {"ixy", in.ixy},
            {"ixz", in.ixz},
            {"iyz", in.iyz}},
           LinkHeadline(link.name, ": the inertial has a NaN or infinite number"),
           {{"ixx_kg_m2", in.ixx},
            {"iyy_kg_m2", in.iyy},
            {"izz_kg_m2", in.izz},
            {"ixy_kg_m2", in.ixy},
            {"ixz_kg_m2", in.ixz},
            {"iyz_kg_m2", in.iyz},
            {"com_x_m", in.X_BBi.p_AB.x()},
            {"com_y_m", in.X_BBi.p_AB.y()},
            {"com_z_m", in.X_BBi.p_AB.z()}},
           "write finite numbers (from the CAD model, or massprops fix --from-geometry)");
  return false;
}

}  // namespace rules
}  // namespace massprops
