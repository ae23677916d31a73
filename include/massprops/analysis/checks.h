#pragma once
/// @file
/// The checks behind `massprops check`: each rule looks at a Model (per link and per welded group)
/// and returns Findings. Checks never print and never decide exit codes.

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "massprops/analysis/link_shape.h"
#include "massprops/analysis/repair.h"
#include "massprops/model/model.h"
#include "massprops/model/source_place.h"

namespace massprops {

enum class Severity { kNote = 0, kWarning = 1, kError = 2 };

/// "note", "warning", "error".
const char* ToString(Severity severity);
/// Parses "note" / "warning" / "error"; nullopt otherwise.
std::optional<Severity> ParseSeverity(std::string_view text);

/// One problem found in a model.
struct Finding {
  std::string rule;  ///< Stable kebab-case id, e.g. "inertia-not-physical".
  Severity severity = Severity::kError;
  std::string model;        ///< The model's name.
  std::string link;         ///< The link (for a welded-group finding: the group's root link).
  /// A finding about a welded group of more than one link: its members' names (the root first,
  /// then file order); empty for a finding about one link or the whole model.
  std::vector<std::string> group;
  SourceLocation location;  ///< Where to point the user (usually the <inertial> or <inertia>).
  /// The full reasoning, one sentence that quotes the offending numbers (as before issue 32;
  /// `check --explain` prints it, JSON keeps it as "message").
  std::string message;
  /// One line that says what is wrong with the link in a robot engineer's words, with the one
  /// deciding number and, where the numbers point to one, the likely cause, at most
  /// kMaxHeadlineChars characters: "link 'arm': inertia 1000x too large for its 15 cm box
  /// (looks like kg·mm²)". Numbers are written by finding_text.h (3 significant digits).
  std::string headline;
  /// The named numbers that decided, each name in words a robot engineer reads without the docs
  /// (`radius_of_gyration_m`, not `k_m`) ending in its SI unit (`mass_kg`, `half_diagonal_m`,
  /// `trace_kg_m2`, `density_kg_m3`) or naming a pure number (`ratio`, `triangle_excess_percent`,
  /// `links_count`). Rendered by FormatEvidence (finding_text.h).
  std::vector<std::pair<std::string, double>> evidence;
  /// The next step, concretely: the value to write, or the `massprops fix ...` command.
  std::string help;
  /// Named measured values behind the message (e.g. {"mass", 0}, {"principal_min", -0.1}), for
  /// machine-readable output.
  std::vector<std::pair<std::string, double>> values;
  /// The remedy `massprops fix` would apply (set by AttachRepairs in repair.h; CheckModel leaves
  /// it empty).
  std::optional<Repair> repair;
  /// Where the numbers were written when the model was expanded from xacro (set by the tool from
  /// the xacro trace, io/xacro_trace.h); empty otherwise.
  std::optional<FindingSource> source;
};

/// What a rule is: its id, default severity, whether it runs by default, and a one-line summary.
/// The texts are string literals (static storage): the table of every rule is built at compile
/// time, not copied into strings at every start.
struct RuleInfo {
  std::string_view id;
  Severity default_severity;
  bool enabled_by_default;
  std::string_view summary;
};

/// Every rule, in a stable order (docs/rules.md documents each).
const std::vector<RuleInfo>& AllRules();

struct CheckOptions {
  /// Tolerance of the physical-validity test, relative to the trace of the inertia at the center
  /// of mass (scale-free). See RotationalInertia::CouldBePhysicallyValid.
  double tolerance = 1e-6;
  /// Per-rule overrides: a severity, or nullopt to disable the rule. Rules not named keep their
  /// defaults.
  std::map<std::string, std::optional<Severity>> overrides;
  /// The shape of links whose geometry is not all primitives (meshes), for units-suspect,
  /// products-sign-suspect, inertia-about-origin-suspect, inertia-exceeds-geometry and
  /// com-outside-geometry. Empty (the default): those links are judged without geometry, and
  /// CheckModel reads no file. `massprops check --geometry` sets MakeLinkShapeFunction.
  LinkShapeFunction shape;
  /// The bounding box of links whose geometry includes meshes (read cheaply, no mass
  /// properties: link_shape.h), for units-suspect, inertia-about-origin-suspect,
  /// inertia-exceeds-geometry, com-outside-geometry and the welded-group geometry of these and of
  /// inertial-missing; never for products-sign-suspect. Used where primitives (and `shape`) leave
  /// a link's extent unknown. Empty: such links are judged without it. `massprops check` and
  /// `fix` set MakeLinkBoxFunction by default (`--no-geometry` leaves it empty).
  LinkBoxFunction box;
  /// The points whose hull holds a link's geometry (mesh vertices: MakeLinkPointsFunction), for
  /// inertia-exceeds-geometry's per-axis bound on links whose geometry includes meshes that
  /// were read. Empty: that bound is not used. Set with `box` by default.
  LinkPointsFunction points;
  /// The link's closed meshes as a uniform solid (MakeClosedMeshShapeFunction in
  /// geometry_checks.h: watertight meshes only), for the density rules `density-implausible` and
  /// `cad-default-density` (density_rules.h), which turn a mass into a density by the volume.
  /// Empty: those rules find nothing. `massprops check` and `fix` set it by default, as `box`
  /// (`--no-geometry` leaves it empty); it reads and integrates each mesh file once per run.
  LinkShapeFunction closed_mesh;
};

/// Runs every enabled rule on the model. Findings are ordered by location (line), then rule id.
/// Rules listed in a link's `ignored_rules` are not reported for that link.
std::vector<Finding> CheckModel(const Model& model, const CheckOptions& options = {});

/// The reader's findings (ReadResult::findings) as Findings: each with its rule's severity after
/// `options.overrides` (dropped when the rule is off) and dropped when the link it names has the
/// rule in its `ignored_rules`. In the order the reader gave them.
std::vector<Finding> ReaderFindings(const ReadResult& read, const CheckOptions& options = {});

/// The axis-aligned bounding box, in the link frame B, of the link's primitive geometries (box,
/// cylinder, sphere, capsule, ellipsoid, each posed by X_BG): of its collisions when it has any
/// and they are all primitives, else of its visuals when they are all primitives.
struct GeometryBounds {
  Eigen::AlignedBox3d box_B;   ///< In the link frame B (metres).
  bool from_collision = true;  ///< false: the visual geometry was used.
  int count = 0;               ///< Number of geometries in the box.
  bool from_mesh = false;      ///< The box is that of a LinkShape with meshes (see below).
  /// Some geometry of the link (a mesh whose size is not known) is not in the box: the body may
  /// reach farther than the box, so only "too small" verdicts can be made from it.
  bool partial = false;
  /// The box is that of a visual-only marker of at most 1 cm (it shows where the link is, not
  /// how far its body reaches); partial too.
  bool marker = false;
};

/// The link as a uniform solid of its geometry: from its primitives when its collision
/// geometries (else its visual ones) are all primitives, computed here without reading a file;
/// otherwise from `fallback` when it is set (e.g. meshes through MakeLinkShapeFunction);
/// otherwise nullopt. Never throws.
std::optional<LinkShape> CalcLinkShape(const Link& link, const LinkShapeFunction& fallback = {});

/// What the geometry says about the signs of the products of inertia of a valid inertial.
struct ProductsSignEvidence {
  /// The products (ixy, ixz, iyz as URDF/SDF write them, in the inertial frame Bi) that the
  /// shape implies for the link's mass.
  Eigen::Vector3d geometry_products = Eigen::Vector3d::Zero();
  /// The cosine of the angle between the written and the geometry's products (as 3-vectors).
  double cosine = 0;
  /// ‖p_written − p_geometry‖ / ‖p_geometry‖ and ‖−p_written − p_geometry‖ / ‖p_geometry‖ (their
  /// sum is at least 2).
  double mismatch_as_written = 0;
  double mismatch_negated = 0;
};

/// Evidence that the inertial's products of inertia have the wrong sign: the shape's central
/// inertia (for the inertial's mass, in Bi) has products of at least 10% of its mean moment, the
/// written products are of that size too, every written moment ixx, iyy, izz is within a factor
/// 2 of the shape's (the shape describes this body), and the written products, as a 3-vector,
/// point the opposite way of the shape's (cosine <= -0.9, within about 25°) with a length within a
/// factor 2 of theirs. nullopt otherwise (no evidence either way). This is how
/// products-sign-suspect judges an inertia that is valid both as written and negated.
std::optional<ProductsSignEvidence> FindProductsSignEvidence(const Inertial& inertial,
                                                             const LinkShape& shape);

/// The link's GeometryBounds, or nullopt when its extent is unknown: no geometry, or the chosen
/// set holds a mesh (meshes are not read) or an unknown shape. Never throws. Cost: O(geometries).
std::optional<GeometryBounds> CalcLinkGeometryBounds(const Link& link);

/// The same, and when the primitives give no extent, the box of `shape` (from CalcLinkShape with
/// a mesh-reading fallback), marked from_mesh when the shape came from meshes.
std::optional<GeometryBounds> CalcLinkGeometryBounds(const Link& link,
                                                     const std::optional<LinkShape>& shape);

/// The same, and when that leaves some of the link's geometry of unknown extent (meshes not
/// read), the union `box` gives of every geometry of the link (collision and visual): marked
/// from_mesh when it holds a mesh, partial when some geometry is still unknown. Returns the
/// primitives' (or shape's) answer when `box` is empty, gives nothing, or knows no geometry.
/// Never throws.
std::optional<GeometryBounds> CalcLinkGeometryBounds(const Link& link,
                                                     const std::optional<LinkShape>& shape,
                                                     const LinkBoxFunction& box);

}  // namespace massprops
