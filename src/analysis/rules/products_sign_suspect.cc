// products-sign-suspect (warning): the products of inertia have the wrong sign.
//
// Evidence: the written inertia; for a valid inertia, the link's geometry as a solid
// (primitives, or a mesh through CheckOptions::shape: FindProductsSignEvidence in checks.cc).
// Why: URDF and SDF write the products of inertia as −∫xy dm; an exporter that writes +∫xy dm
// (or a part copied from its mirror image) flips their sign. Two cases:
//  - the inertia is invalid as written (inertia_not_physical.cc) but valid with the products
//    negated: flipping them is the one-number fix;
//  - the inertia is valid both ways, but the products that the geometry implies for the link's
//    mass point the opposite way (cosine <= −0.9, within a factor 2 in size, every moment within
//    a factor 2: the geometry describes the body).

#include <Eigen/Core>
#include <optional>
#include <string>

#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kProductsSignSuspect = "products-sign-suspect";

}  // namespace

const RuleInfo& ProductsSignSuspectRule() {
  static const RuleInfo kInfo{
      kProductsSignSuspect, Severity::kWarning, true,
      "The products of inertia have the wrong sign: the inertia is invalid as written but valid "
      "with them negated, or the geometry's products have the opposite sign."};
  return kInfo;
}

void CheckProductsSignWhenInvalid(RuleContext& ctx, const Link& link, const std::string& who) {
  const Inertial& in = *link.inertial;
  const Eigen::Matrix3d I_written = WrittenMatrix(in);
  Eigen::Matrix3d I_negated = -I_written;
  I_negated.diagonal() = I_written.diagonal();
  if (!IsValid(I_negated, ctx.options.tolerance)) return;
  const Validity vn = Analyze(I_negated);
  ctx.Emit(
      kProductsSignSuspect, link, InertiaLocation(link),
      who +
          ": the inertia is invalid as written but valid with the products of inertia "
          "negated (ixy, ixz, iyz = " +
          Num(in.ixy) + ", " + Num(in.ixz) + ", " + Num(in.iyz) +
          "; negated, the principal moments are " + Num(vn.moments(0)) + ", " + Num(vn.moments(1)) +
          ", " + Num(vn.moments(2)) +
          "): the exporter probably wrote +∫xy dm where URDF/SDF expect -∫xy dm",
      {{"ixy", in.ixy},
       {"ixz", in.ixz},
       {"iyz", in.iyz},
       {"negated_principal_min", vn.moments(0)},
       {"negated_principal_mid", vn.moments(1)},
       {"negated_principal_max", vn.moments(2)}},
      LinkHeadline(link.name, ": inertia valid only with ixy, ixz, iyz negated (sign convention?)"),
      {{"ixy_kg_m2", in.ixy},
       {"ixz_kg_m2", in.ixz},
       {"iyz_kg_m2", in.iyz},
       {"smallest_moment_if_negated_kg_m2", vn.moments(0)}},
      "negate the products (URDF/SDF want -∫xy dm): massprops fix --apply "
      "products-sign-suspect");
}

void CheckProductsSignAgainstGeometry(RuleContext& ctx, const JudgedLink& judged) {
  if (!judged.valid || !judged.shape) return;
  const Link& link = *judged.link;
  const Inertial& in = *link.inertial;
  Eigen::Matrix3d I_negated = -judged.I_written;
  I_negated.diagonal() = judged.I_written.diagonal();
  const std::optional<ProductsSignEvidence> evidence = FindProductsSignEvidence(in, *judged.shape);
  if (!evidence || !IsValid(I_negated, ctx.options.tolerance)) return;
  const Eigen::Vector3d& g = evidence->geometry_products;
  ctx.Emit(kProductsSignSuspect, link, InertiaLocation(link),
           judged.who + ": the products of inertia (ixy, ixz, iyz = " + Num(in.ixy) + ", " +
               Num(in.ixz) + ", " + Num(in.iyz) + ") have the opposite sign of those its " +
               judged.geometry_name + " geometry implies for its mass (" + Num(g.x()) + ", " +
               Num(g.y()) + ", " + Num(g.z()) + "; negated they differ by " +
               Format("%.2g%%", 100 * evidence->mismatch_negated) + ", as written by " +
               Format("%.3g%%", 100 * evidence->mismatch_as_written) +
               "): they were probably written as +∫xy dm where URDF/SDF expect -∫xy dm, or "
               "copied from a mirror-image part",
           {{"ixy", in.ixy},
            {"ixz", in.ixz},
            {"iyz", in.iyz},
            {"geometry_ixy", g.x()},
            {"geometry_ixz", g.y()},
            {"geometry_iyz", g.z()},
            {"cosine", evidence->cosine},
            {"mismatch_as_written", evidence->mismatch_as_written},
            {"mismatch_negated", evidence->mismatch_negated}},
           LinkHeadline(link.name, ": products of inertia opposite those of its " +
                                       judged.geometry_name + " (sign or mirror?)"),
           {{"ixy_kg_m2", in.ixy},
            {"ixz_kg_m2", in.ixz},
            {"iyz_kg_m2", in.iyz},
            {"geometry_ixy_kg_m2", g.x()},
            {"geometry_ixz_kg_m2", g.y()},
            {"geometry_iyz_kg_m2", g.z()},
            {"cosine", evidence->cosine}},
           "negate the products (URDF/SDF want -∫xy dm): massprops fix --apply "
           "products-sign-suspect");
}

}  // namespace rules
}  // namespace massprops
