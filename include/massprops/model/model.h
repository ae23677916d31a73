#pragma once
/// @file
/// The Model: what massprops reads from a URDF or SDF file, and nothing more. Only what inertia
/// work needs is kept (links with their inertials and geometries, joints, the root link), each
/// element with the SourceLocation it was read from. Numbers are stored as written in the file
/// (no silent fix-ups), so a check can quote them and a fix can rewrite them.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace massprops {

/// Where an element was read from. line and column are 1-based; 0 means unknown.
struct SourceLocation {
  std::string file;  ///< The path as given by the user ("-" or "<stdin>" for standard input).
  int line = 0;
  int column = 0;
};

/// A rigid pose X_AB: the frame B (its origin and its axes) measured and expressed in frame A.
/// p_AB is the position of B's origin from A's origin in A; R_AB re-expresses vectors from B in A.
struct Pose {
  Eigen::Vector3d p_AB = Eigen::Vector3d::Zero();
  Eigen::Matrix3d R_AB = Eigen::Matrix3d::Identity();

  /// X_AC = X_AB * X_BC.
  Pose operator*(const Pose& X_BC) const { return {p_AB + R_AB * X_BC.p_AB, R_AB * X_BC.R_AB}; }
  /// X_BA from X_AB.
  Pose Inverse() const { return {-(R_AB.transpose() * p_AB), R_AB.transpose()}; }
  bool IsIdentity() const { return p_AB.isZero(0) && R_AB.isIdentity(0); }
};

/// The rotation of fixed-axis roll, pitch, yaw angles (radians), as URDF's rpy and SDFormat's pose
/// write them: R = Rz(yaw)·Ry(pitch)·Rx(roll).
Eigen::Matrix3d RotationFromRollPitchYaw(double roll, double pitch, double yaw);

/// An <inertial>: mass, the pose of the inertial frame Bi in the link frame B, and the six
/// numbers of the inertia about Bcm (the origin of Bi) expressed in Bi, exactly as written.
/// Products use the negated convention of URDF and SDF (ixy = -∫xy dm).
struct Inertial {
  double mass = 0;
  Pose X_BBi;  ///< URDF <origin> / SDF <pose> of the inertial, in the link frame.
  double ixx = 0, iyy = 0, izz = 0, ixy = 0, ixz = 0, iyz = 0;
  /// The numbers that could not be read (bits kInertialMass, ...): the value held for them is
  /// what the loader made of the text (0 for urdfdom), not the author's. 0 but in
  /// Link::loaded_inertial.
  unsigned unknown = 0;

  SourceLocation location;          ///< The <inertial> element.
  SourceLocation mass_location;     ///< The <mass> element (line 0 when absent).
  SourceLocation inertia_location;  ///< The <inertia> element (line 0 when absent).
  SourceLocation pose_location;     ///< The <origin>/<pose> element (line 0 when absent).
};

/// Bits of Inertial::unknown: which numbers of an <inertial> are not the author's.
inline constexpr unsigned kInertialMass = 1u << 0;         ///< <mass value>
inline constexpr unsigned kInertialPosition = 1u << 1;     ///< <origin xyz> / <pose> position
inline constexpr unsigned kInertialOrientation = 1u << 2;  ///< <origin rpy> / <pose> rotation
inline constexpr unsigned kInertialIxx = 1u << 3, kInertialIyy = 1u << 4, kInertialIzz = 1u << 5,
                          kInertialIxy = 1u << 6, kInertialIxz = 1u << 7, kInertialIyz = 1u << 8;
/// The six numbers of the inertia.
inline constexpr unsigned kInertialMoments =
    kInertialIxx | kInertialIyy | kInertialIzz | kInertialIxy | kInertialIxz | kInertialIyz;
inline constexpr unsigned kInertialAll =
    kInertialMass | kInertialPosition | kInertialOrientation | kInertialMoments;

/// A collision or visual geometry of a link, with its pose X_BG in the link frame B.
struct Geometry {
  enum class Type { kBox, kCylinder, kSphere, kCapsule, kEllipsoid, kMesh, kOther };
  Type type = Type::kOther;
  Eigen::Vector3d size = Eigen::Vector3d::Zero();  ///< kBox: full lengths along x, y, z.
  double radius = 0;                               ///< kCylinder, kSphere, kCapsule.
  double length =
      0;  ///< kCylinder, kCapsule: along the geometry's z axis (capsule: cylinder part).
  Eigen::Vector3d radii = Eigen::Vector3d::Zero();  ///< kEllipsoid: semi-axes along x, y, z.
  std::string uri;                                  ///< kMesh: the filename/uri, as written.
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();  ///< kMesh.
  /// kMesh, SDF `<submesh><name>`: the one named part of the file this geometry is (libsdformat's
  /// sdf::Mesh::Submesh()); empty: the whole file.
  std::string submesh;
  /// kMesh, SDF `<submesh><center>`: that part recentred on its bounding box's center before the
  /// scale and pose are applied (sdf::Mesh::CenterSubmesh()).
  bool center_submesh = false;
  SourceLocation submesh_location;  ///< The <submesh> element (line 0 when there is none).
  Pose X_BG;
  bool is_collision = true;  ///< false for <visual>.
  SourceLocation location;   ///< The <collision>/<visual> element.
};

/// The axis-aligned bounding box, in the link frame B, of a primitive geometry (box, cylinder,
/// sphere, capsule, ellipsoid) posed by X_BG: exact for every orientation (the box of the rotated
/// shape, not of its rotated box). nullopt for a mesh, kOther, or a non-finite dimension or pose.
/// Cost: about 50 flops.
std::optional<Eigen::AlignedBox3d> CalcPrimitiveBounds(const Geometry& geometry);

struct Link {
  std::string name;                  ///< SDF: scoped name of a nested model's link ("inner::link").
  std::optional<Inertial> inertial;  ///< Absent when the file has no <inertial> (massless link).
  std::vector<Geometry> geometries;  ///< Collisions and visuals, in file order.
  /// Rule ids disabled for this link by a `<!-- massprops: ignore rule-id [rule-id...] -->`
  /// comment inside the link element ("all" disables every rule).
  std::vector<std::string> ignored_rules;
  /// The link's <inertial> could not be read (a number that cannot be parsed even leniently):
  /// `inertial` is then absent, a ReadFinding with rule "inertial-unreadable" says why, and the
  /// checks judge nothing about the mass properties of this link or of its welded group.
  bool inertial_unreadable = false;
  /// With inertial_unreadable: what the loader of record loads for the <inertial> (URDF: urdfdom,
  /// which keeps the numbers it read before the <inertia> or <mass> it could not; a file urdfdom
  /// refuses: the lenient reading, every number it can read), Inertial::unknown marking the
  /// numbers that are not the author's. Absent when nothing of it is known (SDF: libsdformat
  /// refuses the link's <inertial>). The report (LinkMassProperties) uses it; the checks do not.
  std::optional<Inertial> loaded_inertial;
  SourceLocation location;  ///< The <link> element.
};

/// Which numbers of the link's mass properties are not the author's (Inertial::unknown bits):
/// 0 unless inertial_unreadable; then those of loaded_inertial, or kInertialAll without it.
inline unsigned UnknownInertialNumbers(const Link& link) {
  if (!link.inertial_unreadable) return 0;
  return link.loaded_inertial ? link.loaded_inertial->unknown : kInertialAll;
}

struct Joint {
  enum class Type {
    kFixed,
    kRevolute,
    kContinuous,
    kPrismatic,
    kFloating,
    kPlanar,
    kBall,
    kUniversal,
    kScrew,
    kOther
  };
  std::string name;
  Type type = Type::kOther;
  std::string type_name;  ///< As written in the file ("revolute", "fixed", ...).
  std::string parent;     ///< Parent link name ("world" for SDF joints to the world).
  std::string child;      ///< Child link name.
  /// Pose of the child link frame C in the parent link frame P with every joint at zero.
  /// URDF: the joint <origin>. SDF: computed from the resolved link poses.
  Pose X_PC;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  ///< Unit axis, expressed in the child frame C.
  SourceLocation location;                          ///< The <joint> element.
};

struct Model {
  enum class Format { kUrdf, kSdf, kMjcf };
  std::string name;
  Format format = Format::kUrdf;
  std::string file;         ///< The path as given.
  std::vector<Link> links;  ///< In file order.
  /// In file order, except that a URDF link that is the child of several joints has the joint
  /// urdfdom hangs it from first among them (the others close loops and are left out of the tree).
  std::vector<Joint> joints;
  std::string root_link;    ///< The link that is no joint's child (URDF: urdfdom's root).
  SourceLocation location;  ///< The <robot>/<model> element.
  /// SDF <static>true</static> (of the top-level model or its <include>): the model never moves,
  /// so its links need no mass properties. Always false for URDF.
  bool is_static = false;

  /// Index of the link with that name, or -1.
  int FindLink(const std::string& name) const;
  /// Index of the joint whose child is that link, or -1 (the root, or a free-floating SDF link).
  int FindParentJoint(const std::string& child_link) const;
};

/// "urdf", "sdf" or "mjcf": the names JSON and Python use.
const char* ToString(Model::Format format);

/// A problem in the input: the file could not be read, parsed, or understood. `element` names the
/// XML element (e.g. "<inertia> of link 'arm'"); `message` says what is wrong and quotes the text.
struct ReadError {
  SourceLocation location;
  std::string element;
  std::string message;
  /// "file:line:col: element: message".
  std::string ToString() const;
};

/// A ReadError at `file`:`line` (column unknown; line 0: the whole file) about `element` (e.g.
/// "<link> 'base'", or "" when no element is to blame).
ReadError MakeReadError(std::string file, int line, std::string element, std::string message);

/// Something a reader found about the model that is a finding rather than a failure to read: the
/// model is still returned and checked. `rule` is a rule id of AllRules() (checks.h), e.g.
/// "urdf-not-loadable", "inertial-unreadable" or "include-unresolved"; `link` is "" when the
/// finding is about the whole file. The tool reports it as a Finding with the rule's configured
/// severity (ReaderFindings in checks.h).
struct ReadFinding {
  std::string rule;
  std::string model;
  std::string link;
  SourceLocation location;
  std::string message;  ///< A sentence that quotes the offending text.
  std::vector<std::pair<std::string, double>> values;
  /// The parts of the finding (as Finding's, analysis/checks.h): one line, the named numbers with
  /// their SI unit in the name, and the next step.
  std::string headline;
  std::vector<std::pair<std::string, double>> evidence;
  std::string help;
};

/// What a reader returns: the models it read (a world may hold several) and the errors it found.
/// A file with errors yields no model unless the errors are confined to elements that can be
/// skipped (then `warnings` says so).
struct ReadResult {
  std::vector<Model> models;
  std::vector<ReadError> errors;
  std::vector<ReadError> warnings;
  std::vector<ReadFinding> findings;  ///< Findings about the models read (see ReadFinding).
  bool ok() const { return errors.empty(); }
};

}  // namespace massprops
