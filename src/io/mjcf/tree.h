#pragma once
// Private to the MJCF reader (src/io/mjcf/*.cc): the XML of an MJCF model as one tree with its
// <include>s expanded in place, every element keeping its file and line; the <compiler>
// settings; the <default> classes; and the numbers and orientations of attributes, read as
// MuJoCo 2.2's XML reader reads them.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "massprops/model/model.h"

namespace massprops {
namespace mjcf {

/// One XML element: its name, attributes in file order, children, and where it was written.
struct Node {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::vector<Node> children;
  int file = 0;  ///< Index into Document::files.
  int line = 0;
  /// The attribute's value, or null.
  const std::string* Find(const std::string& key) const;
};

/// The whole model: files[0] the main file, then each included file once per include.
struct Document {
  std::vector<std::string> files;
  Node root;  ///< <mujoco>, its <include>s replaced by the children of the included roots.
  SourceLocation Where(const Node& node) const { return {files[node.file], node.line, 0}; }
};

/// Parses `xml` (named `file_name`) and every file it <include>s (relative to the folder of
/// `file_name`, as MuJoCo 2.2 resolves them), to at most `max_depth` levels. Returns false and
/// appends to *errors (file:line, the element) when a file cannot be read or parsed, the root is
/// not <mujoco>, or an include is missing, recursive or too deep.
bool LoadDocument(const std::string& xml, const std::string& file_name, int max_depth,
                  Document* document, std::vector<ReadError>* errors);

/// The <compiler> attributes that decide mass properties (MuJoCo 2.2's defaults).
struct Compiler {
  bool degree = true;            ///< angle="degree" (the default) or "radian".
  std::string eulerseq = "xyz";  ///< Lower case: rotating axes; upper case: fixed axes.
  std::string meshdir, assetdir;
  int inertiafromgeom = 2;  ///< 0 false, 1 true, 2 auto.
  double boundmass = 0, boundinertia = 0;
  bool balanceinertia = false;
  double settotalmass = -1;
  int inertiagrouprange[2] = {0, 5};
  bool exactmeshinertia = false;
  bool discardvisual = false;
  bool fusestatic = false;
  bool global = false;  ///< coordinate="global" (refused by the reader).
};

/// The attributes a <default> class gives each element kind ("geom", "joint", "mesh", ...),
/// with the parent classes' attributes already merged in.
using ClassAttributes = std::map<std::string, std::map<std::string, std::string>>;

/// Everything read from the model's sections other than the bodies, and the errors met.
struct Context {
  const Document* document = nullptr;
  Compiler compiler;
  std::map<std::string, ClassAttributes> classes;  ///< "main" is the top <default>.
  std::map<std::string, int> class_lines;          ///< The <default> element of each class.
  std::map<std::string, const Node*> meshes;       ///< <asset><mesh> by name.
  std::vector<ReadError> errors;
  std::vector<ReadError> warnings;

  void Error(const Node& node, const std::string& element, const std::string& message);
  void Warning(const Node& node, const std::string& element, const std::string& message);
};

/// Reads <compiler>, <default> and <asset><mesh> of the whole document into *context.
void ReadSections(const Document& document, Context* context);

/// One element with the class that applies to it: the attribute's own value, else the class's
/// (the element's class="", else the childclass of the nearest enclosing body, else "main").
struct Element {
  const Node* node = nullptr;
  const std::map<std::string, std::string>* defaults = nullptr;  ///< May be null.
  std::string class_name;
  /// The value and whether it came from the class.
  const std::string* Get(const std::string& key, bool* from_class = nullptr) const;
};

/// `node` of kind node->name with the class chosen as Element says.
Element MakeElement(const Context& context, const Node& node, const std::string& childclass);

/// Reads exactly `count` numbers (or between min_count and count when min_count > 0 is given)
/// from the attribute `key` of `element`; nullopt when absent. A text that is not such numbers
/// (or not finite) is an error through context (and nullopt).
std::optional<std::vector<double>> Numbers(Context* context, const Element& element,
                                           const std::string& key, int count, int min_count = -1,
                                           const std::string& what = "");

/// The orientation given by quat, axisangle, euler, xyaxes or zaxis (the element's own, else its
/// class's), as MuJoCo's compiler turns each into a unit quaternion (angles in the compiler's
/// unit, euler in its eulerseq). Identity when none is given; errors through context.
Eigen::Quaterniond Orientation(Context* context, const Element& element, const std::string& what);

/// MuJoCo's mjuu_z2quat: the shortest rotation taking +z to `vec` (vec need not be unit).
Eigen::Quaterniond RotationFromZ(const Eigen::Vector3d& vec);

}  // namespace mjcf
}  // namespace massprops
