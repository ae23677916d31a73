// Differential test of the URDF reader against urdfdom 3 on every `urdf` row of the shared corpus
// (../shared/corpus/MANIFEST.tsv). The reader builds its model from urdf::parseURDF, so this test
// checks the plumbing, file by file:
//  - `urdf-not-loadable` is reported on exactly the files urdf::parseURDF refuses (returns no
//    model), and those files are still read (leniently) into a model; the one exception is a
//    file that is not XML (a NUL byte), which is a read error, and urdfdom must refuse it too;
//  - on every other file the model has urdfdom's links and joints (counts, also against the
//    MANIFEST `links` column; root; names; each link's parent joint), masses, inertias, origins and
//    axes bit for bit, and urdfdom's geometries; the only links whose inertial differs are those
//    urdfdom says it could not read ("Could not parse inertial element for Link [...]"), which
//    carry `inertial-unreadable` instead.

#include <console_bridge/console.h>
#include <gtest/gtest.h>
#include <urdf_parser/urdf_parser.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "corpus_manifest.h"
#include "massprops/io/urdf_reader.h"

namespace massprops {
namespace {

const std::string kCorpus = MASSPROPS_CORPUS_DIR;

struct CorpusFile {
  std::string path;  // relative to the corpus folder
  int links = -1;    // MANIFEST `links` column
};

std::vector<CorpusFile> UrdfRows() {
  std::vector<CorpusFile> rows;
  for (const test_support::ManifestRow& row : test_support::ReadCorpusManifest("urdf")) {
    rows.push_back({row.file, row.links});
  }
  return rows;
}

// Collects what urdfdom logs at error level while it parses.
class ErrorCollector : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) errors.push_back(text);
  }
  std::vector<std::string> errors;
};

Eigen::Matrix3d ToMatrix(const urdf::Rotation& q) {
  return Eigen::Quaterniond(q.w, q.x, q.y, q.z).toRotationMatrix();
}

Eigen::Vector3d ToVector(const urdf::Vector3& v) { return Eigen::Vector3d(v.x, v.y, v.z); }

void ExpectSamePose(const urdf::Pose& expected, const Pose& actual, const std::string& what) {
  EXPECT_EQ(actual.p_AB, ToVector(expected.position)) << what;
  EXPECT_EQ(actual.R_AB, ToMatrix(expected.rotation)) << what;
}

void ExpectSameGeometry(const urdf::Geometry& expected, const Geometry& actual,
                        const std::string& what) {
  switch (expected.type) {
    case urdf::Geometry::BOX:
      ASSERT_EQ(actual.type, Geometry::Type::kBox) << what;
      EXPECT_EQ(actual.size, ToVector(static_cast<const urdf::Box&>(expected).dim)) << what;
      break;
    case urdf::Geometry::CYLINDER:
      ASSERT_EQ(actual.type, Geometry::Type::kCylinder) << what;
      EXPECT_EQ(actual.radius, static_cast<const urdf::Cylinder&>(expected).radius) << what;
      EXPECT_EQ(actual.length, static_cast<const urdf::Cylinder&>(expected).length) << what;
      break;
    case urdf::Geometry::SPHERE:
      ASSERT_EQ(actual.type, Geometry::Type::kSphere) << what;
      EXPECT_EQ(actual.radius, static_cast<const urdf::Sphere&>(expected).radius) << what;
      break;
    case urdf::Geometry::MESH:
      ASSERT_EQ(actual.type, Geometry::Type::kMesh) << what;
      EXPECT_EQ(actual.uri, static_cast<const urdf::Mesh&>(expected).filename) << what;
      EXPECT_EQ(actual.scale, ToVector(static_cast<const urdf::Mesh&>(expected).scale)) << what;
      break;
  }
}

Joint::Type ToType(int urdfdom_type) {
  switch (urdfdom_type) {
    case urdf::Joint::REVOLUTE:
      return Joint::Type::kRevolute;
    case urdf::Joint::CONTINUOUS:
      return Joint::Type::kContinuous;
    case urdf::Joint::PRISMATIC:
      return Joint::Type::kPrismatic;
    case urdf::Joint::FLOATING:
      return Joint::Type::kFloating;
    case urdf::Joint::PLANAR:
      return Joint::Type::kPlanar;
    case urdf::Joint::FIXED:
      return Joint::Type::kFixed;
    default:
      return Joint::Type::kOther;
  }
}

// The links urdfdom says it could not read the <inertial> of.
std::set<std::string> LinksWithUnreadableInertial(const std::vector<std::string>& errors) {
  const std::string prefix = "Could not parse inertial element for Link [";
  std::set<std::string> names;
  for (const std::string& e : errors) {
    if (e.rfind(prefix, 0) == 0)
      names.insert(e.substr(prefix.size(), e.size() - prefix.size() - 1));
  }
  return names;
}

// Compares massprops' model with urdfdom's, bit for bit.
void ExpectSameModel(const urdf::ModelInterface& expected, const Model& actual,
                     const std::set<std::string>& unreadable) {
  EXPECT_EQ(actual.name, expected.name_);
  ASSERT_EQ(actual.links.size(), expected.links_.size());
  ASSERT_EQ(actual.joints.size(), expected.joints_.size());
  EXPECT_EQ(actual.root_link, expected.getRoot()->name);
  for (const Link& link : actual.links) {
    const std::string what = "link '" + link.name + "'";
    const urdf::LinkConstSharedPtr other = expected.getLink(link.name);
    ASSERT_TRUE(other) << what;
    EXPECT_GT(link.location.line, 0) << what;
    EXPECT_EQ(link.inertial_unreadable, unreadable.count(link.name) > 0) << what;
    // The joint the link hangs from: urdfdom's parent_joint (the last, in name order, of the
    // joints naming it as child) is the first such joint in the Model, which the checks use.
    const int parent = actual.FindParentJoint(link.name);
    EXPECT_EQ(parent >= 0 ? actual.joints[parent].name : std::string(),
              other->parent_joint ? other->parent_joint->name : std::string())
        << what << " parent joint";
    if (link.inertial_unreadable) {
      EXPECT_FALSE(link.inertial.has_value()) << what;
      // What urdfdom loads of it is kept, bit for bit (dex2_5/Left_Hand.urdf: the mass and
      // center of mass as written, the inertia zero and marked unknown; issue 25).
      ASSERT_TRUE(link.loaded_inertial.has_value() && other->inertial) << what;
      const urdf::Inertial& i = *other->inertial;
      EXPECT_EQ(link.loaded_inertial->mass, i.mass) << what;
      EXPECT_EQ(link.loaded_inertial->X_BBi.p_AB,
                Eigen::Vector3d(i.origin.position.x, i.origin.position.y, i.origin.position.z))
          << what;
      EXPECT_EQ(link.loaded_inertial->ixz, i.ixz) << what;
      EXPECT_NE(link.loaded_inertial->unknown, 0u) << what;
    } else {
      ASSERT_EQ(link.inertial.has_value(), static_cast<bool>(other->inertial)) << what;
    }
    if (link.inertial) {
      const urdf::Inertial& i = *other->inertial;
      EXPECT_EQ(link.inertial->mass, i.mass) << what;
      EXPECT_EQ(link.inertial->ixx, i.ixx) << what;
      EXPECT_EQ(link.inertial->ixy, i.ixy) << what;
      EXPECT_EQ(link.inertial->ixz, i.ixz) << what;
      EXPECT_EQ(link.inertial->iyy, i.iyy) << what;
      EXPECT_EQ(link.inertial->iyz, i.iyz) << what;
      EXPECT_EQ(link.inertial->izz, i.izz) << what;
      EXPECT_GT(link.inertial->location.line, 0) << what;
      EXPECT_GT(link.inertial->mass_location.line, 0) << what;
      EXPECT_GT(link.inertial->inertia_location.line, 0) << what;
      ExpectSamePose(i.origin, link.inertial->X_BBi, what + " inertial origin");
    }
    std::vector<const Geometry*> visuals, collisions;
    for (const Geometry& g : link.geometries) (g.is_collision ? collisions : visuals).push_back(&g);
    ASSERT_EQ(visuals.size(), other->visual_array.size()) << what;
    ASSERT_EQ(collisions.size(), other->collision_array.size()) << what;
    for (std::size_t k = 0; k < visuals.size(); ++k) {
      const std::string w = what + " visual #" + std::to_string(k + 1);
      ExpectSamePose(other->visual_array[k]->origin, visuals[k]->X_BG, w);
      ExpectSameGeometry(*other->visual_array[k]->geometry, *visuals[k], w);
    }
    for (std::size_t k = 0; k < collisions.size(); ++k) {
      const std::string w = what + " collision #" + std::to_string(k + 1);
      ExpectSamePose(other->collision_array[k]->origin, collisions[k]->X_BG, w);
      ExpectSameGeometry(*other->collision_array[k]->geometry, *collisions[k], w);
    }
  }
  for (const Joint& joint : actual.joints) {
    const std::string what = "joint '" + joint.name + "'";
    const urdf::JointConstSharedPtr other = expected.getJoint(joint.name);
    ASSERT_TRUE(other) << what;
    EXPECT_GT(joint.location.line, 0) << what;
    EXPECT_EQ(joint.type, ToType(other->type)) << what;
    EXPECT_EQ(joint.parent, other->parent_link_name) << what;
    EXPECT_EQ(joint.child, other->child_link_name) << what;
    ExpectSamePose(other->parent_to_joint_origin_transform, joint.X_PC, what + " origin");
    const Eigen::Vector3d axis = ToVector(other->axis);
    if (joint.type != Joint::Type::kFixed && joint.type != Joint::Type::kFloating) {
      // urdfdom keeps the axis as written; massprops stores it as a unit vector (a zero one as is).
      EXPECT_EQ(joint.axis, axis.norm() > 0 ? Eigen::Vector3d(axis / axis.norm()) : axis) << what;
    }
  }
}

int Count(const ReadResult& result, const std::string& rule) {
  int n = 0;
  for (const ReadFinding& f : result.findings) n += f.rule == rule ? 1 : 0;
  return n;
}

TEST(CorpusUrdfTest, EveryCorpusUrdfIsUrdfdomsModelOrNotLoadable) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/MANIFEST.tsv");
  const std::vector<CorpusFile> rows = UrdfRows();
  ASSERT_GT(rows.size(), 0u) << "no urdf rows in MANIFEST.tsv";
  int same = 0, refused = 0, not_xml = 0, unreadable_links = 0;
  for (const CorpusFile& row : rows) {
    const std::string path = kCorpus + "/" + row.path;
    SCOPED_TRACE(row.path);
    std::ifstream in(path, std::ios::binary);
    ASSERT_TRUE(in) << "cannot read " << path;
    const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());

    ErrorCollector collector;
    console_bridge::useOutputHandler(&collector);
    const urdf::ModelInterfaceSharedPtr expected = urdf::parseURDF(xml);
    console_bridge::restorePreviousOutputHandler();

    const ReadResult result = ReadUrdfString(xml, path);
    std::string ours;
    for (const ReadError& e : result.errors) ours += e.ToString() + "\n";
    if (!result.ok()) {
      // Only a text that is not XML is a read error (humanoid.urdf holds a NUL byte, which no
      // XML text may; urdfdom reads up to it and refuses the rest).
      EXPECT_FALSE(expected) << "urdfdom loads this file but massprops says:\n" << ours;
      EXPECT_TRUE(result.models.empty());
      std::printf("read error: %s", ours.c_str());
      ++not_xml;
      continue;
    }
    ASSERT_EQ(result.models.size(), 1u);
    const Model& model = result.models[0];
    if (!expected) {
      EXPECT_EQ(Count(result, "urdf-not-loadable"), 1) << "urdfdom refuses this file";
      for (const ReadFinding& f : result.findings) {
        if (f.rule != "urdf-not-loadable") continue;
        EXPECT_EQ(f.location.file, path);
        EXPECT_GT(f.location.line, 0);
        std::printf("not loadable: %s:%d: %s\n", row.path.c_str(), f.location.line,
                    f.message.c_str());
      }
      EXPECT_FALSE(model.links.empty()) << "the lenient reading finds the links";
      ++refused;
      continue;
    }
    EXPECT_EQ(Count(result, "urdf-not-loadable"), 0) << "urdfdom loads this file";
    if (row.links >= 0) {
      EXPECT_EQ(static_cast<int>(model.links.size()), row.links) << "MANIFEST links column";
    }
    const std::set<std::string> unreadable = LinksWithUnreadableInertial(collector.errors);
    EXPECT_EQ(Count(result, "inertial-unreadable"), static_cast<int>(unreadable.size()));
    unreadable_links += static_cast<int>(unreadable.size());
    ExpectSameModel(*expected, model, unreadable);
    ++same;
  }
  std::printf(
      "corpus URDF files: %zu; urdfdom's model: %d (links whose inertial urdfdom cannot read: "
      "%d); refused by urdfdom, read leniently: %d; not XML (read error): %d\n",
      rows.size(), same, unreadable_links, refused, not_xml);
  EXPECT_EQ(same + refused + not_xml, static_cast<int>(rows.size()));
  EXPECT_LE(not_xml, 1);
}

}  // namespace
}  // namespace massprops
