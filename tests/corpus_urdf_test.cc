// Differential test of the URDF reader against urdfdom 3 (the reference for what a URDF means) on
// every `urdf` row of the shared corpus (../shared/corpus/MANIFEST.tsv). For each file:
//  - when urdfdom rejects it (returns no model, or logs an error and keeps a partly filled model),
//    massprops rejects it too with a clear error; the one exception is <capsule>, which urdfdom 3
//    does not know and massprops reads (then everything but the dropped geometries is compared);
//  - when urdfdom accepts it, massprops accepts it and agrees on every link and joint: counts
//    (also with the MANIFEST `links` column), root, joint types, parents, children, origins
//    (positions exactly, rotations to 1e-12), axes, inertials (mass, origin and the six numbers
//    exactly) and geometries (types and sizes exactly).

#include <console_bridge/console.h>
#include <gtest/gtest.h>
#include <urdf_parser/urdf_parser.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "corpus_manifest.h"
#include "massprops/urdf_reader.h"

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
  EXPECT_LT((actual.R_AB - ToMatrix(expected.rotation)).cwiseAbs().maxCoeff(), 1e-12) << what;
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

// Compares massprops' model with urdfdom's. `geometries_too`: false when urdfdom dropped some.
void ExpectSameModel(const urdf::ModelInterface& expected, const Model& actual,
                     bool geometries_too) {
  EXPECT_EQ(actual.name, expected.name_);
  ASSERT_EQ(actual.links.size(), expected.links_.size());
  ASSERT_EQ(actual.joints.size(), expected.joints_.size());
  EXPECT_EQ(actual.root_link, expected.getRoot()->name);
  for (const Link& link : actual.links) {
    const std::string what = "link '" + link.name + "'";
    const urdf::LinkConstSharedPtr other = expected.getLink(link.name);
    ASSERT_TRUE(other) << what;
    ASSERT_EQ(link.inertial.has_value(), static_cast<bool>(other->inertial)) << what;
    if (link.inertial) {
      const urdf::Inertial& i = *other->inertial;
      EXPECT_EQ(link.inertial->mass, i.mass) << what;
      EXPECT_EQ(link.inertial->ixx, i.ixx) << what;
      EXPECT_EQ(link.inertial->ixy, i.ixy) << what;
      EXPECT_EQ(link.inertial->ixz, i.ixz) << what;
      EXPECT_EQ(link.inertial->iyy, i.iyy) << what;
      EXPECT_EQ(link.inertial->iyz, i.iyz) << what;
      EXPECT_EQ(link.inertial->izz, i.izz) << what;
      ExpectSamePose(i.origin, link.inertial->X_BBi, what + " inertial origin");
    }
    if (!geometries_too) continue;
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
    EXPECT_EQ(joint.type, ToType(other->type)) << what;
    EXPECT_EQ(joint.parent, other->parent_link_name) << what;
    EXPECT_EQ(joint.child, other->child_link_name) << what;
    ExpectSamePose(other->parent_to_joint_origin_transform, joint.X_PC, what + " origin");
    const Eigen::Vector3d axis = ToVector(other->axis);
    if (joint.type != Joint::Type::kFixed && joint.type != Joint::Type::kFloating &&
        axis.norm() > 0) {
      // urdfdom 3 keeps the axis as written; massprops stores it as a unit vector.
      EXPECT_LT((joint.axis - axis.normalized()).norm(), 1e-15) << what;
    }
  }
}

// urdfdom 3.0.1 logs these errors, drops the <visual>/<collision> concerned and still returns a
// model (check_urdf passes); massprops reads capsules, and reads the rest with a warning, since no
// inertial number depends on them.
bool IsDroppedElementError(const std::string& e) {
  return e.find("Unknown geometry type 'capsule'") != std::string::npos ||
         e.find("Visual material must contain a name attribute") != std::string::npos ||
         e.find("Mesh scale was specified, but could not be parsed") != std::string::npos ||
         e.find("Could not parse collision element") != std::string::npos ||
         e.find("Could not parse visual element") != std::string::npos;
}

bool OnlyDroppedElementErrors(const std::vector<std::string>& errors) {
  for (const std::string& e : errors) {
    if (!IsDroppedElementError(e)) return false;
  }
  return !errors.empty();
}

bool MentionsCapsule(const std::vector<std::string>& errors) {
  for (const std::string& e : errors) {
    if (e.find("capsule") != std::string::npos) return true;
  }
  return false;
}

TEST(CorpusUrdfTest, EveryCorpusUrdfReadsAsUrdfdomReadsIt) {
  if (!std::filesystem::is_directory(kCorpus)) GTEST_SKIP() << "no corpus at " << kCorpus;
  const std::vector<CorpusFile> rows = UrdfRows();
  ASSERT_GT(rows.size(), 0u) << "no urdf rows in MANIFEST.tsv";
  int agreed = 0, rejected_by_both = 0, capsule = 0, dropped = 0;
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

    if (!expected || (!collector.errors.empty() && !OnlyDroppedElementErrors(collector.errors))) {
      EXPECT_FALSE(result.errors.empty())
          << "urdfdom rejects this file (" << (collector.errors.empty() ? "" : collector.errors[0])
          << ") but massprops accepts it";
      EXPECT_TRUE(result.models.empty());
      for (const ReadError& e : result.errors) {
        EXPECT_EQ(e.location.file, path);
        EXPECT_FALSE(e.message.empty());
      }
      if (!result.errors.empty()) {
        std::printf("rejected by both: %s\n", result.errors[0].ToString().c_str());
      }
      ++rejected_by_both;
      continue;
    }
    ASSERT_TRUE(result.ok()) << "urdfdom accepts this file but massprops says:\n" << ours;
    ASSERT_EQ(result.models.size(), 1u);
    const Model& model = result.models[0];
    if (row.links >= 0) {
      EXPECT_EQ(static_cast<int>(model.links.size()), row.links) << "MANIFEST links column";
    }
    const bool with_dropped = !collector.errors.empty();
    ExpectSameModel(*expected, model, /*geometries_too=*/!with_dropped);
    if (with_dropped && !MentionsCapsule(collector.errors)) {
      EXPECT_FALSE(result.warnings.empty()) << "urdfdom dropped an element: say so";
      ++dropped;
    } else if (with_dropped) {
      bool has_capsule = false;
      for (const Link& link : model.links) {
        for (const Geometry& g : link.geometries) has_capsule |= g.type == Geometry::Type::kCapsule;
      }
      EXPECT_TRUE(has_capsule);
      ++capsule;
    } else {
      ++agreed;
    }
  }
  std::printf(
      "corpus URDF files: %zu; same model as urdfdom: %d; rejected by both: %d; "
      "accepted with capsules urdfdom drops: %d; read with a warning where urdfdom drops a "
      "visual: %d\n",
      rows.size(), agreed, rejected_by_both, capsule, dropped);
  EXPECT_EQ(agreed + rejected_by_both + capsule + dropped, static_cast<int>(rows.size()));
}

}  // namespace
}  // namespace massprops
