#pragma once
// Private to io: the state of one SDF read (sdf_reader.cc, docs/architecture.md), shared by the
// files of src/io/sdf/, one per seam of the reader:
//   elements.cc       the elements and their values: models, links, joints, frames, numbers, poses
//                     as written, a link's <inertial> and geometries;
//   includes.cc       <include>: the model paths, the files, merged includes, unresolved ones;
//   frames.cc         the pose graph: relative_to, attached_to, placement_frame, resolved lazily;
//   models.cc         the Models built from the graph (links, joints, axes, the root link);
//   auto_inertial.cc  <inertial auto="true"> (SDF 1.11) from the collision geometries.
#include <tinyxml2.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "io/reader_place.h"
#include "io/sdf_values.h"
#include "massprops/io/auto_inertia.h"
#include "massprops/io/sdf_reader.h"

namespace massprops::internal::sdf_reader {

namespace fs = std::filesystem;
using internal::Attr;
using internal::Text;
using tinyxml2::XMLComment;
using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;
using tinyxml2::XMLNode;

constexpr int kWorld = -1;     // The world (or the root of a file holding a lone model).
constexpr int kNotFound = -2;  // A reference that names nothing.
constexpr int kMaxResolveDepth = 1000;
constexpr int kMaxNestingDepth = 100;

struct Version {
  int major = 1;
  int minor = 0;
  bool AtLeast(int a, int b) const { return major > a || (major == a && minor >= b); }
};

struct Node {
  enum class Kind { kModel, kLink, kJoint, kFrame };
  Kind kind = Kind::kLink;
  std::string name;  // Scoped from the root: "top::nested::link".
  int scope = kWorld;
  Version version;
  std::string relative_to;  // As written; "" = default.
  Pose X_raw;
  std::string attached_to;      // kFrame.
  std::string placement_frame;  // kModel.
  std::string canonical_link;   // kModel.
  bool is_static = false;       // kModel: <static>true</static> (of the model or its <include>).
  const XMLElement* element = nullptr;
  SourceLocation location;
  int state = 0;  // 0 = unresolved, 1 = resolving, 2 = resolved.
  Pose X_SF;      // Pose in the frame of the containing model (or the world).
  // kJoint:
  std::string parent, child;
  // kModel: the link and model nodes directly inside, in file order.
  std::vector<int> members;
  bool axis_in_model_frame_1_4 = false;  // kJoint of a top-level SDF 1.4 model.
  // Read from a model merged into its parent (<include merge="true">): "__model__" of the merged
  // model means this proxy frame of the parent scope.
  std::string merge_proxy;
};

/// "<model> 'name'" and so on: how a message names the node's element.
std::string Describe(const Node& node);

/// `s` without leading and trailing whitespace.
std::string Trim(std::string_view s);

/// "MAJOR.MINOR" into *v; false when the text is not of that form.
bool ParseVersion(const std::string& text, Version* v);

/// The bytes of the file at `path` ("-": standard input) into *text, at most kMaxSdfFileBytes;
/// false with the reason in *why.
bool ReadWholeFile(const std::string& path, std::size_t max_bytes, std::string* text,
                   std::string* why);

/// Parses `xml` into `doc`; on failure returns the error (line in `line`).
bool ParseXml(const std::string& xml, XMLDocument* doc, std::string* why, int* line);

/// Appends the rules of every <!-- massprops: ignore rule-id ... --> comment anywhere inside the
/// link element `e`.
void ReadIgnoredRules(const XMLElement* e, std::vector<std::string>* ignored_rules);

/// The Joint::Type of an SDF joint type name (kOther for those massprops does not model).
Joint::Type JointType(const std::string& t);

/// State of one read: the pose graph, the errors, the include stack.
class Reader {
 public:
  Reader(const SdfReadOptions& options, std::string top_file);

  ReadResult Read(const std::string& xml, const std::string& file_name,
                  std::vector<SdfModelFrames>* frames);

 private:
  struct Context {
    std::string file;
    Version version;
    int depth = 0;
    std::string merge_proxy;  // Reading the children of a merged include (see Node).
  };

  // While a link's <inertial> is read, number and pose errors are diverted here: they cost the
  // link (inertial-unreadable), not the file.
  struct Diversion {
    bool active = false;
    bool failed = false;
    SourceLocation location;
    std::string element;
    std::string message;
  };

  // ------------------------------------------------------------ errors
  void Error(const std::string& file, const XMLElement* e, const std::string& element,
             const std::string& message);
  void Warning(const std::string& file, const XMLElement* e, const std::string& element,
               const std::string& message);

  // ------------------------------------------------------------ numbers

  /// Reads one number from element `e` (text), or `fallback` when e is null.
  double Number(const XMLElement* e, double fallback, const Context& ctx,
                const std::string& element);

  Eigen::Vector3d Vector(const XMLElement* e, const Eigen::Vector3d& fallback, const Context& ctx,
                         const std::string& element);

  /// Parses a <pose> element (nullptr: identity).
  Pose ParsePose(const XMLElement* e, const Context& ctx, const std::string& element);

  /// relative_to of a pose element. SDF < 1.7: libsdformat's 1.6->1.7 converter moves the
  /// "frame" attribute to relative_to, and keeps a relative_to already written (honored too).
  static std::string RelativeTo(const XMLElement* pose, const Version& v);

  // ------------------------------------------------------------ graph building
  std::string Prefix(int scope) const { return scope == kWorld ? "" : nodes_[scope].name + "::"; }

  int AddNode(Node node, const Context& ctx);

  /// A node read from a model merged into the enclosing one: its references to the merged model's
  /// frame ("__model__", or the default) name the proxy frame instead (libsdformat's
  /// "_merged__NAME__model__").
  static void ApplyMerge(Node* node, const std::string& proxy);

  void ReadWorld(const XMLElement* world, const Context& ctx);

  /// Reads a <model>; `include` (may be null) is the <include> that brought it in, whose <name>,
  /// <pose> and <placement_frame> override the model's own. Returns the node index or kNotFound.
  int ReadModel(const XMLElement* model, int scope, const Context& ctx, const XMLElement* include);

  void ReadModelChildren(const XMLElement* model, int scope, const Context& ctx);

  void ReadFrame(const XMLElement* frame, int scope, const Context& ctx);

  void ReadJoint(const XMLElement* joint, int scope, const Context& ctx);

  void ReadLink(const XMLElement* link, int scope, const Context& ctx);

  /// Resolves an <include>: returns the node of the model it brings in, or kNotFound.
  int ReadInclude(const XMLElement* include, int scope, const Context& ctx);

  std::optional<std::string> FindModelFile(const std::string& uri, const std::string& base_dir,
                                           std::string* why);

  // ------------------------------------------------------------ pose resolution
  /// The node named `ref` as seen from inside `scope`; kWorld for the scope's own frame
  /// ("__model__", or "world" at the root); kNotFound when it names nothing.
  int Lookup(const std::string& ref, int scope) const {
    if (ref == "__model__") return scope;
    if (scope == kWorld && ref == "world") return kWorld;
    const auto it = by_name_.find(Prefix(scope) + ref);
    return it == by_name_.end() ? kNotFound : it->second;
  }

  /// Pose of node (or scope) `target` in the frame of `scope`, which must contain it.
  std::optional<Pose> PoseInScope(int target, int scope, int depth);

  /// Pose of node i in the frame of its containing model (or the world); nullopt after an error.
  std::optional<Pose> Resolve(int i, int depth);

  /// The link node that frame `i` is attached to (kNotFound if none).
  int AttachedLink(int i, int depth) const;

  void BuildModels();
  void BuildModel(const std::vector<int>& tops, const std::vector<int>& world_joints);
  // The models being built into one Model (see BuildModel), as its steps share them.
  struct ModelBuild {
    int top = kWorld;        // The model frame: the model's, or the world's.
    std::string prefix;      // Stripped from scoped names ("" for models joined in the world).
    std::vector<int> order;  // The nodes of the models, in file order (each contiguous).
    std::unordered_map<int, Pose> X_TB;  // Link poses in the model frame T.
    std::optional<Pose> X_WT;            // The model frame in the world (once resolved).
  };
  Model StartModel(const std::vector<int>& tops) const;
  std::vector<int> ModelNodeOrder(const std::vector<int>& tops) const;
  std::string LocalName(const ModelBuild& b, int i) const;
  void ReadModelLinks(ModelBuild* b, Model* model, SdfModelFrames* frames);
  std::optional<Pose> PoseInModel(const ModelBuild& b, int f);
  void ReadModelJoints(const ModelBuild& b, const std::vector<int>& world_joints, Model* model);
  bool ReadJoint(const ModelBuild& b, int i, Joint* joint);
  std::optional<Eigen::Vector3d> ReadJointAxis(const ModelBuild& b, int i, const std::string& what,
                                               const Pose& X_TC);
  void SetRootLink(const ModelBuild& b, const std::vector<int>& tops, Model* model) const;
  int TopOf(int i) const {
    if (i < 0) return i;
    while (nodes_[i].scope != kWorld) i = nodes_[i].scope;
    return i;
  }
  void ReadLinkContents(int link_index, int top, const Pose& X_TB, Link* link);
  void ReadExplicitInertial(const XMLElement* in, int link_index, int top, const Pose& X_TB,
                            const Context& ctx, Link* link);
  Geometry ReadGeometry(const XMLElement* c, int link_index, int top, const Pose& X_TB,
                        const Context& ctx, const std::string& lname);
  void ReadShape(const XMLElement* shape, const Context& ctx, const std::string& swhat,
                 Geometry* g);
  void ReadSubmesh(const XMLElement* submesh, const Context& ctx, const std::string& swhat,
                   Geometry* g);
  bool ResolveInLink(const XMLElement* pose, int link_index, int top, const Pose& X_TB,
                     const Context& ctx, const std::string& what, Pose* X_BF);

  struct IncludeSite {
    std::string file;
    int line = 0;
    std::string uri;
  };
  struct Unresolved {
    std::string scoped;  // The name the missing model would have had, scoped from the root.
    std::string uri;
    std::string file;
    int line = 0;
  };
  std::string OutermostInclude() const;
  void ReportUnresolvedInclude(const XMLElement* include, int scope, const Context& ctx,
                               const std::string& uri, const std::string& why);
  bool InUnresolvedInclude(const std::string& ref, int scope, std::string* which) const;
  void ReportUnresolvedReference(int i, const std::string& ref, const std::string& which);
  int ReadMergedModel(const XMLElement* model, int scope, const Context& ctx,
                      const XMLElement* include);
  void ReadAutoInertial(const XMLElement* inertial, int link_index, int top, const Pose& X_TB,
                        const Context& ctx, Link* link);

  SdfReadOptions options_;
  Diversion diversion_;
  bool aborted_ = false;
  long included_elements_ = 0;
  std::vector<IncludeSite> include_sites_;
  std::vector<Unresolved> unresolved_;
  std::set<int> reported_unresolved_;
  std::unordered_map<std::string, std::pair<std::optional<std::string>, std::string>> resolved_;
  std::unordered_map<std::string, std::string> canonical_;
  std::unordered_map<std::string, std::unique_ptr<XMLDocument>> included_docs_;
  std::unique_ptr<MeshCache> mesh_cache_;
  std::string current_model_name_;  // The Model being built (for findings).
  std::vector<int> world_joints_;   // <joint> nodes directly in a <world> (SDF 1.10+).
  std::string top_file_;
  std::vector<std::string> search_paths_;
  ReadResult result_;
  std::vector<Node> nodes_;
  std::unordered_map<std::string, int> by_name_;
  std::vector<int> top_models_;
  std::vector<SdfModelFrames> frames_;
  std::map<int, Context> link_files_;
  std::vector<std::unique_ptr<XMLDocument>> documents_;
  std::vector<std::string> include_stack_;
  Version include_version_;
  std::string include_file_;
};

}  // namespace massprops::internal::sdf_reader
