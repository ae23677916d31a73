#pragma once
/// @file
/// One measurement of a link's geometry as placed, for the geometry rules (issue 49): the
/// convex hull K of every geometry of the link (collision and visual,
/// primitives and meshes, in the link frame), its support function h_K, its face normals, its
/// volume and the minimum-volume ellipsoid that encloses it; and the bounds that a non-negative
/// density inside K puts on a mass m, center of mass c and second-moment matrix
/// Σ = ∫(x − c)(x − c)ᵀ dm = ½·tr(I_c)·1 − I_c. Each bound is a necessary condition (any
/// density inside K meets it: tests/link_measure_test.cc).

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "massprops/analysis/link_shape.h"
#include "massprops/model/model.h"

namespace massprops {

/// The measurement of one link's geometry.
struct LinkMeasure {
  /// Every geometry of the link is known (primitives of finite size, meshes read): K is the hull
  /// of the whole link's drawing. False: nothing below may be used.
  bool whole = false;
  bool has_mesh = false;  // some geometry is a mesh (a CAD envelope rather than a primitive)
  /// The primitives (exact support functions) and the hull vertices of the meshes, in B.
  std::vector<const Geometry*> primitives;
  std::vector<Eigen::Vector3d> mesh_vertices_B;
  /// Outward unit normals of the largest faces of the hull (at most kMaxFaceNormals).
  std::vector<Eigen::Vector3d> face_normals_B;
  Eigen::Vector3d center_B = Eigen::Vector3d::Zero();  // center of K's bounding box
  double half_diagonal = 0;                            // of K's bounding box (metres)
  /// The volume of the hull of the meshes' vertices and the primitives' own boxes' corners: at
  /// least the volume of K (metres³); 0 when unknown.
  double volume = 0;
  /// E = {x : (x − x0)ᵀ Q⁻¹ (x − x0) <= 1} ⊇ K (Khachiyan's minimum-volume ellipsoid of the hull's
  /// points, grown until it holds every point).
  bool has_ellipsoid = false;
  Eigen::Vector3d x0 = Eigen::Vector3d::Zero();
  Eigen::Matrix3d Q_inverse = Eigen::Matrix3d::Zero();

  /// h_K(u) = max over x in K of u·x, for a unit u. Cost: O(primitives + hull vertices).
  double Support(const Eigen::Vector3d& u) const;
};

/// Half the width of a primitive along the unit direction v of its own frame: its support
/// function about its center, exact for each shape (a cylinder reaches L/2 along its axis and r
/// across it, not its box's corners). 0 for a mesh or an unknown type.
double HalfWidthAlong(const Geometry& g, const Eigen::Vector3d& v);

/// The measurement of `link` from its primitives and, for its meshes, `points` (the posed mesh
/// positions of MakeLinkPointsFunction; nullopt when not read). `ellipsoid` false: no bounding
/// ellipsoid (Khachiyan's iterations, the measurement's largest cost; has_ellipsoid false).
/// Never throws.
LinkMeasure MeasureLink(const Link& link, const std::optional<LinkGeometryPoints>& points,
                        bool ellipsoid = true);

/// A volume inside the convex hull K of `link`'s whole geometry (metres³; 0 when unknown): the
/// largest of each primitive's own volume and the volume of the hull of the meshes' extreme
/// points along 13 axes (the frame's, its face and body diagonals), all points of K. One pass over
/// the meshes' positions and a hull of at most 26 points: a lower bound that lets a rule that
/// needs volume(K) only above a threshold skip the whole hull (MeasureLink) below it.
double InnerVolume(const Link& link, const std::optional<LinkGeometryPoints>& points);

/// The direction along which a second-moment matrix most exceeds the Bhatia–Davis bound
/// uᵀΣu <= m·(h(u) − u·c)·(u·c + h(−u)) of a body K grown `scale` times about its box's center.
struct DirectionBound {
  double ratio = 0;              // uᵀΣu over the bound (infinite when the bound is 0 or less)
  double second_moment = 0;      // uᵀΣu (kg·m²)
  double bound = 0;              // m·(h(u) − u·c)·(u·c + h(−u)) (kg·m²)
  double ahead = 0, behind = 0;  // h(u) − u·c and u·c + h(−u) of the grown body (metres)
  /// The same distances in K itself (not grown): where the COM sits between its faces.
  double ahead_in_K = 0, behind_in_K = 0;
  /// Unit; its largest component positive (the spread is the same along u and −u).
  Eigen::Vector3d u = Eigen::Vector3d::UnitX();
};
/// Over the principal axes of Σ, the primitives' axes, the hull's face normals and a fixed
/// Fibonacci set of kSphereDirections covering the sphere. Only directions along which c lies
/// inside the grown body (both distances positive) are judged: a center of mass outside is
/// com-outside-geometry's finding.
DirectionBound WorstDirection(const LinkMeasure& measure, double m, const Eigen::Vector3d& c,
                              const Eigen::Matrix3d& Sigma, double scale);

/// tr(Q⁻¹ (Σ + m (c − x0)(c − x0)ᵀ)) / m for the ellipsoid grown `scale` times about x0: at most 1
/// for any density inside it (Wensing, Kim, Slotine 2018: tr(J Q̃) >= 0). NaN without ellipsoid.
double EllipsoidRatio(const LinkMeasure& measure, double m, const Eigen::Vector3d& c,
                      const Eigen::Matrix3d& Sigma, double scale);

/// (6/5)·m·r², r = (3m / (4πρ))^(1/3): the least tr(I_c) of a mass m of density at most ρ (a
/// uniform ball of that density, the most compact body).
double LeastTrace(double m, double density);

constexpr int kSphereDirections = 128;
constexpr int kMaxFaceNormals = 64;
/// The densest element, osmium, 22 590 kg/m³, and lead, 11 340 kg/m³ (CRC Handbook of Chemistry
/// and Physics): no body is more compact than a ball of osmium, and no robot part than one of lead.
constexpr double kOsmiumDensity = 22590;
constexpr double kLeadDensity = 11340;
/// A density reported as denser than lead must pass lead's by this factor: a tessellated mesh's
/// chord error and a rounded mass move a lead counterweight's density by well under 10%
/// (density-implausible, over closed meshes and over the hull).
constexpr double kDenseMargin = 1.1;

}  // namespace massprops
