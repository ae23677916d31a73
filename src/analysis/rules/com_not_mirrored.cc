// com-not-mirrored (warning): a pair of mirrored parts whose centers of mass, or whose products of
// inertia, do not mirror.
//
// Evidence: pairs of links named as the two sides of one part (left/right, l_/r_, _L/_R, ...) or
// drawn by one mesh mirrored (the same file with a scale of opposite handedness, or meshes named
// as the two sides); their poses in the model at the zero configuration; their mass, inertia and
// center of mass; their geometry's bounding boxes.
// Why: the mirror image of a body across a plane has the same mass and principal moments, its
// center of mass is the mirror image of the body's, and its inertia is M·I·M (M the reflection).
// So where two links are mirror images in the model (their origins mirror across a plane of the
// model, their geometry does, their masses and principal moments agree), a center of mass that
// does not land on its twin's mirror image, or products of inertia that do not mirror, are
// numbers copied from one side to the other without mirroring them (the left part's center of
// mass typed onto the right part: off by a centimetre or two, within what com-outside-geometry
// allows). The one of the two whose center of mass lies farther from the middle of its own
// geometry is likely the wrong one; without geometry to tell, the one written later in the file
// (the copy). Two links drawing the same meshes at the same handedness are one part placed twice,
// not mirror images; a pair that is one part turned half a turn about a line through the middle
// (a gripper's two fingers) is symmetric too, and its numbers may follow either map. Their
// geometry must be known on both sides: names alone do not make two parts mirror images.

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "analysis/rules/model_rules.h"
#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kComNotMirrored = "com-not-mirrored";

// Two links are mirror images when their origins mirror across a plane normal to an axis of the
// model within this fraction of their distance (and 1 mm), their masses and principal moments
// agree within kSameBody, and their geometry's boxes mirror within kGeometryMirror of the boxes'
// half-diagonal (and 1 mm).
constexpr double kOriginMirror = 0.02;
constexpr double kSameBody = 0.02;
constexpr double kGeometryMirror = 0.1;
constexpr double kMillimetre = 1e-3;
// A center of mass that misses its twin's mirror image by more than this many of the part's
// half-diagonal (and kComMinOffset) is reported: CAD exports of mirrored parts agree to a few
// tenths of a millimetre; a center of mass copied from the other side misses by its offset from
// the plane's normal, centimetres.
constexpr double kComMirror = 0.1;
constexpr double kComMinOffset = 0.005;  // metres
// Where the two carry the same numbers (masses within kCopyMass, principal moments within
// kCopyMoments of the trace: one part's data written twice, not two parts that differ on
// purpose), the mirror image of one is the other to the exporter's rounding: the center of mass
// is reported beyond twice the miss of their geometry's mirror plus this share of the
// half-diagonal (and kComMinOffset). A centre of mass copied unmirrored onto the twin of a
// 0.3 m part, 2–3.5 cm off, is then found; within kComMirror it was not.
constexpr double kCopyMass = 1e-3;
constexpr double kCopyMoments = 0.01;
constexpr double kComCopyMirror = 0.02;
// Products of inertia that miss their twin's mirror image by more than this share of the trace
// (each product is at most half the trace) while the moments agree.
constexpr double kProductsMirror = 0.05;

// The side a name marks: 'L' or 'R' with the name's other characters, or 0.
struct Side {
  char side = 0;
  std::string key;  // the name with the side's marker replaced by '#'
};

bool Boundary(const std::string& s, std::size_t i) {
  return i >= s.size() || !std::isalnum(static_cast<unsigned char>(s[i]));
}

std::string Lower(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return s;
}

// left/right anywhere (any case), else l/r as a whole token (l_hip, hip_L, arm-r).
Side SideOf(const std::string& name) {
  const std::string lower = Lower(name);
  for (const auto& [word, side] : {std::pair<const char*, char>{"left", 'L'}, {"right", 'R'}}) {
    const std::size_t at = lower.find(word);
    if (at != std::string::npos) {
      return {side, name.substr(0, at) + "#" + name.substr(at + std::string(word).size())};
    }
  }
  for (std::size_t i = 0; i < lower.size(); ++i) {
    if ((lower[i] == 'l' || lower[i] == 'r') && (i == 0 || Boundary(lower, i - 1)) &&
        Boundary(lower, i + 1)) {
      return {lower[i] == 'l' ? 'L' : 'R', name.substr(0, i) + "#" + name.substr(i + 1)};
    }
  }
  return {};
}

// The key of a link's meshes, as a side marks them: "" when it has none or no side.
Side MeshSideOf(const Link& link) {
  Side result;
  for (const Geometry& g : link.geometries) {
    if (g.type != Geometry::Type::kMesh) continue;
    const std::size_t slash = g.uri.find_last_of("/\\");
    const Side s = SideOf(slash == std::string::npos ? g.uri : g.uri.substr(slash + 1));
    if (s.side == 0) continue;
    result.side = s.side;
    result.key += s.key + ";";
  }
  return result;
}

// The handedness of a mesh's scale (-1: mirrored), and its file.
std::optional<std::pair<std::string, int>> MirroredMesh(const Link& link) {
  for (const Geometry& g : link.geometries) {
    if (g.type != Geometry::Type::kMesh || g.uri.empty()) continue;
    const double det = g.scale.x() * g.scale.y() * g.scale.z();
    if (det != 0) return std::make_pair(g.uri, det < 0 ? -1 : 1);
  }
  return std::nullopt;
}

}  // namespace

ModelPoses PosesOf(const RuleContext& ctx) {
  const std::size_t n = ctx.model.links.size();
  ModelPoses poses{std::vector<Pose>(n), std::vector<int>(n, -1)};
  for (std::size_t r = 0; r < n; ++r) {
    if (ctx.parent[r] >= 0) continue;
    std::vector<int> stack = {static_cast<int>(r)};
    poses.root[r] = static_cast<int>(r);
    while (!stack.empty()) {
      const int a = stack.back();
      stack.pop_back();
      for (const auto& [c, j] : ctx.children[a]) {
        if (poses.root[c] >= 0) continue;
        poses.X_WL[c] = poses.X_WL[a] * ctx.model.joints[j].X_PC;
        poses.root[c] = static_cast<int>(r);
        stack.push_back(c);
      }
    }
  }
  return poses;
}

namespace {

// The box of link `l`'s known geometry in the model frame (its 8 corners posed), if any.
std::optional<Eigen::AlignedBox3d> ModelBox(const RuleContext& ctx, int l, const Pose& X_WL) {
  const std::optional<GeometryBounds>& b = ctx.BoundsOfLink(l);
  if (!b || b->partial || b->box_B.isEmpty()) return std::nullopt;
  Eigen::AlignedBox3d box;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p = b->box_B.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
    box.extend(X_WL.p_AB + X_WL.R_AB * p);
  }
  return box;
}

Eigen::Vector3d Reflect(const Eigen::Vector3d& p, int axis, double offset) {
  Eigen::Vector3d q = p;
  q(axis) = 2 * offset - p(axis);
  return q;
}

std::vector<std::pair<int, int>> MirroredPairs(const RuleContext& ctx) {
  const Model& model = ctx.model;
  std::map<std::string, std::array<int, 2>> by_name, by_mesh_name;
  std::map<std::string, std::array<int, 2>> by_mesh_file;
  auto add = [](std::map<std::string, std::array<int, 2>>& map, const std::string& key, int side,
                int l) {
    auto it = map.emplace(key, std::array<int, 2>{-1, -1}).first;
    it->second[side] = it->second[side] == -1 ? l : -2;  // -2: not unique
  };
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const Link& link = model.links[i];
    if (!link.inertial || !(link.inertial->mass > 0)) continue;
    const int l = static_cast<int>(i);
    if (const Side s = SideOf(link.name); s.side) add(by_name, s.key, s.side == 'L' ? 0 : 1, l);
    if (const Side s = MeshSideOf(link); s.side) {
      add(by_mesh_name, s.key, s.side == 'L' ? 0 : 1, l);
    }
    if (const auto mesh = MirroredMesh(link)) {
      add(by_mesh_file, mesh->first, mesh->second < 0 ? 1 : 0, l);
    }
  }
  // In the order found, each pair once (a set of those found, not a search of the list).
  std::vector<std::pair<int, int>> pairs;
  std::set<std::pair<int, int>> found;
  for (const auto* map : {&by_name, &by_mesh_name, &by_mesh_file}) {
    for (const auto& [key, sides] : *map) {
      (void)key;
      if (sides[0] < 0 || sides[1] < 0) continue;
      const std::pair<int, int> pair(std::min(sides[0], sides[1]), std::max(sides[0], sides[1]));
      if (found.insert(pair).second) pairs.push_back(pair);
    }
  }
  return pairs;
}

// What a mirrored pair's numbers miss by.
struct Mismatch {
  int a = -1, b = -1;      // a is written first in the file
  int axis = 0;            // the plane's normal: a model axis
  double offset = 0;       // the plane's place along it
  Eigen::Vector3d ca, cb;  // centers of mass in the model frame
  std::optional<Eigen::AlignedBox3d> box_a, box_b;
  bool com_bad = false, products_bad = false;
  double com_miss = 0, products_miss = 0;
};

// How far a center of mass c lies from the middle of `box`, in the box's half-sizes (largest
// over the axes: 1 on a face); -1 without a box.
double OffCenter(const Eigen::Vector3d& c, const std::optional<Eigen::AlignedBox3d>& box) {
  if (!box) return -1;
  const Eigen::Vector3d h = 0.5 * box->sizes().cwiseMax(Eigen::Vector3d::Constant(1e-9));
  return ((c - box->center()).cwiseAbs().cwiseQuotient(h)).maxCoeff();
}

// The headline of link `bad` whose numbers do not mirror those of its twin `good`: the twin
// named when both names fit, else "its twin" (the help names it).
std::string MirrorHeadline(const std::string& bad, const std::string& good, bool com_bad,
                           double com_miss) {
  const std::string what =
      com_bad ? ": center of mass " + FormatLength(com_miss) + " off the mirror image of "
              : std::string(": products of inertia do not mirror those of ");
  const std::string twin = com_bad ? "its twin's" : "its twin";
  return FirstThatFits({"link '" + bad + "'" + what + "link '" + good + "' (copied unmirrored?)",
                        LinkHeadline(bad, what + twin + " (copied unmirrored?)")});
}

void ReportMirrorMismatch(RuleContext& ctx, const Mismatch& m) {
  const Link& la = ctx.model.links[m.a];
  const Link& lb = ctx.model.links[m.b];
  const char axis_name = static_cast<char>('x' + m.axis);
  // Which is likely wrong: the center of mass farther from the middle of its own geometry (the
  // copy sits where its twin's part is, not where its own is); else the one written later.
  const double off_a = OffCenter(m.ca, m.box_a), off_b = OffCenter(m.cb, m.box_b);
  int wrong = m.b;
  std::string why = "it is written after '" + la.name +
                    "' in the file (a copy is usually made from the part written first; the "
                    "numbers alone cannot tell)";
  if (m.com_bad && off_a >= 0 && std::max(off_a, off_b) > 1.25 * std::min(off_a, off_b)) {
    wrong = off_a > off_b ? m.a : m.b;
    const double own = wrong == m.a ? off_a : off_b, other = wrong == m.a ? off_b : off_a;
    why = "its center of mass lies " + Num(own) +
          " half-sizes from the middle of its geometry's box, its twin's " + Num(other);
  }
  const Link& bad = wrong == m.a ? la : lb;
  const Link& good = wrong == m.a ? lb : la;
  const Eigen::Vector3d expected = Reflect(wrong == m.a ? m.cb : m.ca, m.axis, m.offset);
  std::string what;
  if (m.com_bad) {
    what = "their centers of mass do not: that of '" + bad.name + "' is at " +
           Vec(wrong == m.a ? m.ca : m.cb) + " in the model frame, " + Num(m.com_miss) +
           " m from the mirror image " + Vec(expected) + " of that of '" + good.name + "'";
  }
  if (m.products_bad) {
    what += std::string(what.empty() ? "" : "; and ") +
            "their products of inertia do not mirror (they miss the mirror image by " +
            Format("%.3g%%", 100 * m.products_miss) + " of the trace while the moments agree)";
  }
  ctx.Emit(kComNotMirrored, bad, m.com_bad ? PoseLocation(bad) : InertiaLocation(bad),
           "links '" + la.name + "' and '" + lb.name + "' are mirror images across the plane " +
               std::string(1, axis_name) + " = " + Num(m.offset) +
               " m of the model (their origins, geometry, mass and principal moments mirror), "
               "but " +
               what + ": '" + bad.name + "' is likely the wrong one, as " + why +
               "; numbers copied from one side to the other without mirroring them",
           {{"com_miss", m.com_miss},
            {"products_miss", m.products_miss},
            {"expected_com_x", expected.x()},
            {"expected_com_y", expected.y()},
            {"expected_com_z", expected.z()}},
           MirrorHeadline(bad.name, good.name, m.com_bad, m.com_miss),
           {{"com_off_mirror_image_m", m.com_miss},
            {"products_off_mirror_image_percent", 100 * m.products_miss},
            {"mirror_plane_offset_m", m.offset}},
           m.com_bad ? "write " + Vec(expected) + " (model frame): the COM of '" + good.name +
                           "' mirrored across " + std::string(1, axis_name) + " = " +
                           FormatLength(m.offset)
                     : "write the products of '" + good.name +
                           "' here, negated where the mirror plane flips them");
}

// Two links that draw the same mesh files at the same handedness are one part placed twice (a
// robot's two identical arms), not mirror images: their numbers need not mirror.
std::vector<std::pair<std::string, bool>> MeshesOf(const Link& link) {
  std::vector<std::pair<std::string, bool>> meshes;
  for (const Geometry& g : link.geometries) {
    if (g.type != Geometry::Type::kMesh) continue;
    meshes.emplace_back(g.uri, g.scale.x() * g.scale.y() * g.scale.z() < 0);
  }
  std::sort(meshes.begin(), meshes.end());
  return meshes;
}

bool SameMeshes(const Link& a, const Link& b) {
  const std::vector<std::pair<std::string, bool>> ma = MeshesOf(a);
  return !ma.empty() && ma == MeshesOf(b);
}

// The maps that take one side of the model onto the other about the point m: the reflection
// across the plane normal to `axis`, and the half-turns about the two lines through m along the
// other axes (a gripper's two fingers are one part turned, not mirrored). Each as its diagonal.
std::vector<Eigen::Vector3d> SideMaps(int axis) {
  std::vector<Eigen::Vector3d> maps;
  Eigen::Vector3d mirror = Eigen::Vector3d::Ones();
  mirror(axis) = -1;
  maps.push_back(mirror);
  for (int other = 0; other < 3; ++other) {
    if (other == axis) continue;
    Eigen::Vector3d turn = -Eigen::Vector3d::Ones();
    turn(other) = 1;
    maps.push_back(turn);
  }
  return maps;
}

void CheckMirroredPair(RuleContext& ctx, int a, int b, const Pose& X_WA, const Pose& X_WB) {
  const Link& la = ctx.model.links[a];
  const Link& lb = ctx.model.links[b];
  if (SameMeshes(la, lb)) return;
  // The plane: normal to the model axis along which the origins differ, through their middle.
  const Eigen::Vector3d d = X_WB.p_AB - X_WA.p_AB;
  int axis = 0;
  d.cwiseAbs().maxCoeff(&axis);
  const double separation = d.norm();
  const double slack = std::max(kMillimetre, kOriginMirror * separation);
  if (!(separation > 10 * kMillimetre)) return;
  if ((d - d(axis) * Eigen::Vector3d::Unit(axis)).norm() > slack) return;
  const Eigen::Vector3d mid = 0.5 * (X_WA.p_AB + X_WB.p_AB);
  // The same body: mass and principal moments.
  const MassProperties pa = LinkMassProperties(la, ctx.model.format);
  const MassProperties pb = LinkMassProperties(lb, ctx.model.format);
  if (!(std::abs(pa.mass - pb.mass) <= kSameBody * std::max(pa.mass, pb.mass))) return;
  const Validity va = Analyze(pa.I_SScm_F), vb = Analyze(pb.I_SScm_F);
  if (!va.finite || !vb.finite || !(va.trace > 0) || !(vb.trace > 0)) return;
  if ((va.moments - vb.moments).norm() > kSameBody * std::max(va.trace, vb.trace)) return;
  // The maps that take the one's geometry onto the other's.
  const std::optional<Eigen::AlignedBox3d> box_a = ModelBox(ctx, a, X_WA);
  const std::optional<Eigen::AlignedBox3d> box_b = ModelBox(ctx, b, X_WB);
  // Their geometry must be known and mirror: names alone do not make two parts mirror images.
  if (!box_a || !box_b) return;
  const double half_diagonal = 0.5 * std::max(box_a->diagonal().norm(), box_b->diagonal().norm());
  std::vector<Eigen::Vector3d> maps;
  double geometry_miss = HUGE_VAL;
  for (const Eigen::Vector3d& t : SideMaps(axis)) {
    Eigen::AlignedBox3d image(mid + t.cwiseProduct(box_a->min() - mid));
    image.extend(mid + t.cwiseProduct(box_a->max() - mid));
    const double miss =
        std::max((image.min() - box_b->min()).norm(), (image.max() - box_b->max()).norm());
    if (miss > std::max(kMillimetre, kGeometryMirror * half_diagonal)) continue;
    maps.push_back(t);
    geometry_miss = std::min(geometry_miss, miss);
  }
  if (maps.empty()) return;
  // The centers of mass and the inertias in the model frame, under each map.
  const Eigen::Vector3d ca = X_WA.p_AB + X_WA.R_AB * pa.p_FoScm_F;
  const Eigen::Vector3d cb = X_WB.p_AB + X_WB.R_AB * pb.p_FoScm_F;
  const double size = half_diagonal;
  const Eigen::Matrix3d Ia_W = X_WA.R_AB * pa.I_SScm_F * X_WA.R_AB.transpose();
  const Eigen::Matrix3d Ib_W = X_WB.R_AB * pb.I_SScm_F * X_WB.R_AB.transpose();
  double com_miss = HUGE_VAL, products_miss = HUGE_VAL, moments_miss = HUGE_VAL;
  for (const Eigen::Vector3d& t : maps) {
    com_miss = std::min(com_miss, (cb - (mid + t.cwiseProduct(ca - mid))).norm());
    const Eigen::Matrix3d diff = Ib_W - t.asDiagonal() * Ia_W * t.asDiagonal();
    moments_miss = std::min(moments_miss, diff.diagonal().norm() / va.trace);
    products_miss = std::min(
        products_miss,
        std::sqrt(diff(0, 1) * diff(0, 1) + diff(0, 2) * diff(0, 2) + diff(1, 2) * diff(1, 2)) /
            va.trace);
  }
  const bool copy = std::abs(pa.mass - pb.mass) <= kCopyMass * std::max(pa.mass, pb.mass) &&
                    (va.moments - vb.moments).norm() <= kCopyMoments * std::max(va.trace, vb.trace);
  const double com_allowed =
      copy ? std::max(kComMinOffset, 2 * geometry_miss + kComCopyMirror * size)
           : std::max(kComMinOffset, kComMirror * size);
  const bool com_bad = com_miss > com_allowed;
  const bool products_bad = moments_miss <= kSameBody && products_miss > kProductsMirror;
  if (!com_bad && !products_bad) return;
  ReportMirrorMismatch(ctx, {a, b, axis, mid(axis), ca, cb, box_a, box_b, com_bad, products_bad,
                             com_miss, products_miss});
}

}  // namespace

const RuleInfo& ComNotMirroredRule() {
  static const RuleInfo kInfo{
      kComNotMirrored, Severity::kWarning, true,
      "Two mirrored parts (by name or mesh) whose centers of mass or products of inertia do not "
      "mirror: one was copied from the other side."};
  return kInfo;
}

void CheckMirroredPairs(RuleContext& ctx) {
  if (ctx.model.is_static || !ctx.RuleOn(kComNotMirrored)) return;
  const std::vector<std::pair<int, int>> pairs = MirroredPairs(ctx);
  if (pairs.empty()) return;
  const ModelPoses poses = PosesOf(ctx);
  for (const auto& [a, b] : pairs) {
    if (poses.root[a] < 0 || poses.root[a] != poses.root[b]) continue;
    ++ctx.stats.mirrored_pairs;
    CheckMirroredPair(ctx, a, b, poses.X_WL[a], poses.X_WL[b]);
  }
}

}  // namespace rules
}  // namespace massprops
