#pragma once
// Private to io: the state of one URDF read (urdf_reader.cc, docs/architecture.md), shared by the
// files of src/io/urdf/, one per seam of the reader:
//   index.cc         the index of the text from a tinyxml2 DOM: each element's line, ignore
//                    comments, numbers urdfdom reads other than as written (underflows);
//   scan.cc          the same index from one light pass over the text, without a DOM, for the
//                    XML that URDF files are written in (anything else goes to index.cc);
//   urdfdom.cc       urdf::parseURDF with its console_bridge messages captured per thread;
//   from_urdfdom.cc  the Model from urdfdom's, with the index's lines, and the inertials urdfdom
//                    cannot read;
//   not_loadable.cc  urdfdom refuses the file: the finding, at the line its message names;
//   lenient.cc       the lenient reading of what carries mass properties, for such files.
#include <console_bridge/console.h>
#include <tinyxml2.h>
#include <urdf_exception/exception.h>
#include <urdf_model/pose.h>
#include <urdf_model/utils.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>
#include <shared_mutex>
#include <string>
#include <string_view>
#include <system_error>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "io/reader_place.h"
#include "massprops/io/model_reader.h"
#include "massprops/io/urdf_reader.h"

namespace massprops::internal::urdf_reader {

using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;
using tinyxml2::XMLNode;

constexpr const char* kUrdfNotLoadable = "urdf-not-loadable";
constexpr const char* kInertialUnreadable = "inertial-unreadable";

/// Whether c is white space as isspace() in the C locale says.
bool IsSpace(char c);

/// The text quoted in messages: at most 60 characters, control characters made visible.
std::string Quote(std::string_view text);

// ------------------------------------------------------------------ the index

struct IndexedLink {
  std::string name;
  bool has_name = false;
  int line = 0;
  std::vector<int> inertial_lines;  // every <inertial> child (urdfdom reads the first)
  int mass_line = 0, inertia_line = 0, origin_line = 0;  // of the first <inertial>
  struct Holder {
    int line;
    bool is_collision;
  };
  std::vector<Holder> holders;  // <visual>/<collision> children in file order
  std::vector<std::string> ignored_rules;
};

struct IndexedJoint {
  std::string name;
  bool has_name = false;
  int line = 0;
  std::string type;
  int axis_line = 0;  // 0: no <axis>
  bool axis_has_xyz = false;
};

// A number of a link's first <inertial> that urdfdom reads, but not as written: nonzero text below
// the smallest normal double, which urdfdom reads as 0 or as a subnormal (see Underflows).
struct Underflow {
  int link = 0;  // index in UrdfIndex::links
  int line = 0;
  std::string what;     // `<mass value="1e-400">`
  double value = 0;     // what urdfdom reads
  unsigned number = 0;  // which number (an Inertial::unknown bit)
};

// A number of an <inertial> in urdfdom's order of reading (urdf_parser/src/link.cpp): origin xyz,
// rpy, mass, inertia ixx ... izz; each is the attribute of the first child element of its name.
struct InertialNumber {
  const char* element;
  const char* attribute;
  unsigned number;  // an Inertial::unknown bit
};
inline constexpr InertialNumber kInertialNumbers[] = {
    {"origin", "xyz", kInertialPosition}, {"origin", "rpy", kInertialOrientation},
    {"mass", "value", kInertialMass},     {"inertia", "ixx", kInertialIxx},
    {"inertia", "ixy", kInertialIxy},     {"inertia", "ixz", kInertialIxz},
    {"inertia", "iyy", kInertialIyy},     {"inertia", "iyz", kInertialIyz},
    {"inertia", "izz", kInertialIzz}};

// The lines of the elements that carry mass properties, by name and order. Decides nothing.
struct UrdfIndex {
  int robot_line = 0;
  std::vector<IndexedLink> links;
  std::vector<Underflow> underflows;  // at most one per link, the first in urdfdom's order
  std::vector<IndexedJoint> joints;
  std::unordered_map<std::string, int> first_link;   // name -> index in links
  std::unordered_map<std::string, int> first_joint;  // name -> index in joints
};
class Reader {
 public:
  explicit Reader(std::string file_name) : file_(std::move(file_name)) {}
  /// `max_bytes`: a longer text is refused with a ReadError.
  ReadResult Read(const std::string& xml, std::size_t max_bytes = kMaxUrdfFileBytes);
  /// The index of `xml` (with no NUL byte) and its warnings as text, from the light scan or from
  /// tinyxml2; nullopt when that way gives no index (for tests: internal::DescribeUrdfIndex).
  std::optional<std::string> DescribeIndex(const std::string& xml, bool from_tinyxml2);

 private:
  friend class IndexScanner;
  SourceLocation Loc(int line) const { return SourceLocation{file_, line, 0}; }
  void Warning(int line, std::string element, std::string message) {
    result_.warnings.push_back(ReadError{Loc(line), std::move(element), std::move(message)});
  }
  void Error(int line, std::string element, std::string message) {
    result_.errors.push_back(ReadError{Loc(line), std::move(element), std::move(message)});
  }
  bool ParseDom(const std::string& xml, XMLDocument* doc);
  bool ScanIndex(const std::string& xml);
  bool IndexWithTinyxml2(const std::string& xml);
  void BuildIndex(const XMLElement* robot);
  void IndexUnderflow(const XMLElement* inertial, int link);
  bool IndexUnderflowOf(int link, int line, const InertialNumber& n, std::string_view text);
  void CollectIgnoreComments(const XMLNode* node, const std::string& link, IndexedLink* out);
  void IndexComment(std::string_view text, int line, const std::string& link, IndexedLink* out);
  void WarnAboutTextUrdfdomSkips();
  Model FromUrdfdom(const urdf::ModelInterface& urdf, const std::vector<std::string>& errors,
                    const std::string& xml);
  Link LinkFromUrdfdom(const IndexedLink& indexed, const urdf::Link& source);
  void ReportUnreadableInertials(const std::vector<std::string>& unreadable, const std::string& xml,
                                 Model* model);
  Joint JointFromUrdfdom(const IndexedJoint& indexed, const urdf::Joint& source);
  void UseUrdfdomsParentJoints(const urdf::ModelInterface& urdf, Model* model);
  void WarnAboutSecondParents(const Link& link, const std::vector<const Joint*>& joints,
                              const Joint& kept);
  void ReportUnreadableInertial(const XMLElement* link_xml, Link* link);
  void ReportUnderflows(Model* model);
  void InertialUnreadable(int line, Link* link, std::string message, unsigned unknown);
  void ReportNotLoadable(const std::vector<std::string>& errors);
  int LineOfNamed(std::string_view message) const;

  std::string file_;
  ReadResult result_;
  UrdfIndex index_;
};

// ------------------------------------------------------------------ urdfdom.cc
/// urdf::parseURDF of `xml`, with what urdfdom logs through console_bridge meanwhile in *errors.
urdf::ModelInterfaceSharedPtr ParseWithUrdfdom(const std::string& xml,
                                               std::vector<std::string>* errors);
/// Frees urdfdom's model (its links and joints point at each other).
void ReleaseUrdfdomModel(urdf::ModelInterfaceSharedPtr model);

// ------------------------------------------------------------------ lenient.cc
/// The reading of only what carries mass properties of `robot`, for files urdfdom refuses; its
/// findings go to *result.
Model ReadLeniently(const std::string& file, const XMLElement* robot, ReadResult* result);

}  // namespace massprops::internal::urdf_reader
