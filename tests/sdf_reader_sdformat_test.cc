// Differential test: massprops' SDF reader against libsdformat 12 (the reference implementation of
// SDFormat's pose and frame semantics) on every `sdf` row of ../shared/corpus/MANIFEST.tsv.
// For each file that libsdformat loads without errors, the two must agree on: the models and their
// scoped link names (the same set), each link's pose in its model frame and its inertial frame's
// pose in the model frame (to 1e-12 relative to the size of the pose, 1e-12 absolute for
// rotations), mass and the six inertia numbers (exactly: both read the same decimal text), and
// each joint's parent and child links and axis (unit vector in the child link frame, to 1e-12).
// Links with <inertial auto="true"> (SDF 1.11) are compared by pose only: libsdformat 12 predates
// SDF 1.11 and gives them its default inertial (1 kg, diag(1, 1, 1)); their computed values are
// tested against hand derivations in sdf_reader_test.cc. Each mesh's <submesh> name and <center>
// flag equal sdf::Mesh::Submesh() and CenterSubmesh() (collisions and visuals in file order). Files
// that libsdformat rejects (its errors, or SDF versions it does not know) are listed. docs/sdf.md
// quotes the counts printed.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sdf/Collision.hh>
#include <sdf/Geometry.hh>
#include <sdf/Joint.hh>
#include <sdf/JointAxis.hh>
#include <sdf/Link.hh>
#include <sdf/Mesh.hh>
#include <sdf/Model.hh>
#include <sdf/ParserConfig.hh>
#include <sdf/Root.hh>
#include <sdf/Visual.hh>
#include <sdf/World.hh>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "corpus_manifest.h"
#include "massprops/io/sdf_reader.h"
#include "massprops/model/model.h"

namespace massprops {
namespace {

const std::string kCorpus = MASSPROPS_CORPUS_DIR;

using test_support::CorpusModelPaths;

std::vector<std::string> SdfRows() {
  std::vector<std::string> files;
  for (const test_support::ManifestRow& row : test_support::ReadCorpusManifest("sdf")) {
    files.push_back(row.file);
  }
  return files;
}

Pose ToPose(const ignition::math::Pose3d& X) {
  Pose out;
  out.p_AB = Eigen::Vector3d(X.Pos().X(), X.Pos().Y(), X.Pos().Z());
  out.R_AB = Eigen::Quaterniond(X.Rot().W(), X.Rot().X(), X.Rot().Y(), X.Rot().Z())
                 .normalized()
                 .toRotationMatrix();
  return out;
}

// A mesh geometry's SDF <submesh> as libsdformat reads it; `mesh` false for other shapes.
struct RefSubmesh {
  bool mesh = false;
  std::string name;
  bool center = false;
};

struct RefLink {
  Pose X_MB;   // Link frame in the top model frame.
  Pose X_MBi;  // Inertial frame in the top model frame.
  double mass = 0, ixx = 0, iyy = 0, izz = 0, ixy = 0, ixz = 0, iyz = 0;
  std::vector<RefSubmesh> collisions, visuals;  // in file order
};

RefSubmesh SubmeshOf(const sdf::Geometry* geometry) {
  RefSubmesh r;
  const sdf::Mesh* mesh = geometry != nullptr ? geometry->MeshShape() : nullptr;
  if (mesh == nullptr) return r;
  r.mesh = true;
  r.name = mesh->Submesh();
  r.center = mesh->CenterSubmesh();
  return r;
}
struct RefJoint {
  std::string parent, child;
  Eigen::Vector3d axis_C = Eigen::Vector3d::Zero();
  bool has_axis = false;
};
struct RefModel {
  std::map<std::string, RefLink> links;
  std::map<std::string, RefJoint> joints;
};

// Collects the links and joints of `model` (and of its nested models), X_TM being the model's pose
// in the top model frame T and `prefix` its scope ("" or "nested::").
void Collect(const sdf::Model& model, const Pose& X_TM, const std::string& prefix, RefModel* out) {
  for (uint64_t i = 0; i < model.LinkCount(); ++i) {
    const sdf::Link* link = model.LinkByIndex(i);
    ignition::math::Pose3d X;
    EXPECT_TRUE(link->SemanticPose().Resolve(X, "__model__").empty());
    RefLink r;
    r.X_MB = X_TM * ToPose(X);
    const auto& inertial = link->Inertial();
    r.X_MBi = r.X_MB * ToPose(inertial.Pose());
    r.mass = inertial.MassMatrix().Mass();
    r.ixx = inertial.MassMatrix().Ixx();
    r.iyy = inertial.MassMatrix().Iyy();
    r.izz = inertial.MassMatrix().Izz();
    r.ixy = inertial.MassMatrix().Ixy();
    r.ixz = inertial.MassMatrix().Ixz();
    r.iyz = inertial.MassMatrix().Iyz();
    for (uint64_t c = 0; c < link->CollisionCount(); ++c) {
      r.collisions.push_back(SubmeshOf(link->CollisionByIndex(c)->Geom()));
    }
    for (uint64_t v = 0; v < link->VisualCount(); ++v) {
      r.visuals.push_back(SubmeshOf(link->VisualByIndex(v)->Geom()));
    }
    out->links[prefix + link->Name()] = r;
  }
  for (uint64_t i = 0; i < model.JointCount(); ++i) {
    const sdf::Joint* joint = model.JointByIndex(i);
    RefJoint r;
    std::string parent, child;
    joint->ResolveParentLink(parent);
    joint->ResolveChildLink(child);
    r.parent = parent == "world" ? parent : prefix + parent;
    r.child = prefix + child;
    if (const sdf::JointAxis* axis = joint->Axis(0)) {
      ignition::math::Vector3d xyz;
      if (axis->ResolveXyz(xyz, child).empty()) {
        r.axis_C = Eigen::Vector3d(xyz.X(), xyz.Y(), xyz.Z()).normalized();
        r.has_axis = true;
      }
    }
    out->joints[prefix + joint->Name()] = r;
  }
  for (uint64_t i = 0; i < model.ModelCount(); ++i) {
    const sdf::Model* nested = model.ModelByIndex(i);
    ignition::math::Pose3d X;
    EXPECT_TRUE(nested->SemanticPose().Resolve(X, "__model__").empty());
    Collect(*nested, X_TM * ToPose(X), prefix + nested->Name() + "::", out);
  }
}

void ExpectPoseNear(const Pose& a, const Pose& b, double tol, const std::string& what) {
  EXPECT_LE((a.p_AB - b.p_AB).norm(), tol * std::max(1.0, b.p_AB.norm()))
      << what << ": p " << a.p_AB.transpose() << " vs libsdformat " << b.p_AB.transpose();
  EXPECT_LT((a.R_AB - b.R_AB).cwiseAbs().maxCoeff(), tol) << what << ": R\n"
                                                          << a.R_AB << "\nvs libsdformat\n"
                                                          << b.R_AB;
}

struct Counts {
  int files = 0, agreeing = 0, links = 0, inertials = 0, auto_inertials = 0, joints = 0;
  int world_joint_files = 0;
  int meshes = 0, submeshes = 0;  // mesh geometries compared, those with a <submesh> name
};

// The link's collisions and visuals, each in file order, against libsdformat's: the same count,
// the same shapes a mesh, and each mesh's submesh name and center flag.
void CompareSubmeshes(const Link& link, const RefLink& r, Counts* counts) {
  for (const bool collision : {true, false}) {
    const std::vector<RefSubmesh>& ref = collision ? r.collisions : r.visuals;
    std::vector<const Geometry*> ours;
    for (const Geometry& g : link.geometries) {
      if (g.is_collision == collision) ours.push_back(&g);
    }
    EXPECT_EQ(ours.size(), ref.size()) << link.name << (collision ? " collisions" : " visuals");
    for (std::size_t i = 0; i < ours.size() && i < ref.size(); ++i) {
      const bool mesh = ours[i]->type == Geometry::Type::kMesh;
      EXPECT_EQ(mesh, ref[i].mesh) << link.name << " geometry " << i;
      if (!mesh || !ref[i].mesh) continue;
      EXPECT_EQ(ours[i]->submesh, ref[i].name) << link.name << " geometry " << i;
      EXPECT_EQ(ours[i]->center_submesh, ref[i].center) << link.name << " geometry " << i;
      ++counts->meshes;
      if (!ref[i].name.empty()) ++counts->submeshes;
    }
  }
}

// Loads `path` with libsdformat; when it loads without errors, reads it with massprops and compares
// (gtest expectations). Returns libsdformat's first error, or "" when the file was compared.
std::string CompareWithLibsdformat(const std::string& path, const SdfReadOptions& options,
                                   const sdf::ParserConfig& config, Counts* counts) {
  sdf::Root root;
  const sdf::Errors errors = root.Load(path, config);
  if (!errors.empty()) return errors.front().Message();
  std::vector<const sdf::Model*> ref_models;
  if (root.Model() != nullptr) ref_models.push_back(root.Model());
  for (uint64_t w = 0; w < root.WorldCount(); ++w) {
    for (uint64_t m = 0; m < root.WorldByIndex(w)->ModelCount(); ++m) {
      ref_models.push_back(root.WorldByIndex(w)->ModelByIndex(m));
    }
  }
  std::vector<SdfModelFrames> frames;
  const ReadResult result = ReadSdfFile(path, options, &frames);
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.errors.front().ToString());
  // World joints (SDF 1.10) join their models into one Model "A+B"; libsdformat 12 predates
  // SDF 1.10 and ignores them (two models): such files are counted, not compared.
  for (const Model& model : result.models) {
    if (model.name.find('+') != std::string::npos) {
      ++counts->world_joint_files;
      return "";
    }
  }
  EXPECT_EQ(result.models.size(), ref_models.size());
  if (!result.ok() || result.models.size() != ref_models.size()) return "";
  ++counts->files;
  const int failures_before =
      ::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count();
  for (size_t m = 0; m < ref_models.size(); ++m) {
    const Model& model = result.models[m];
    EXPECT_EQ(model.name, ref_models[m]->Name());
    RefModel ref;
    Collect(*ref_models[m], Pose(), "", &ref);
    EXPECT_EQ(model.links.size(), ref.links.size()) << model.name;
    for (const auto& [name, unused] : ref.links) {
      EXPECT_GE(model.FindLink(name), 0) << "libsdformat's link " << name << " is not read";
    }
    std::set<std::string> auto_links;
    for (const ReadFinding& f : result.findings) {
      if (f.rule == "inertial-auto" && f.model == model.name) auto_links.insert(f.link);
    }
    EXPECT_EQ(frames[m].X_MB.size(), model.links.size());
    if (frames[m].X_MB.size() != model.links.size()) continue;
    for (size_t i = 0; i < model.links.size(); ++i) {
      const Link& link = model.links[i];
      const auto it = ref.links.find(link.name);
      EXPECT_NE(it, ref.links.end()) << "link " << link.name;
      if (it == ref.links.end()) continue;
      const RefLink& r = it->second;
      ExpectPoseNear(frames[m].X_MB[i], r.X_MB, 1e-12, "link " + link.name);
      CompareSubmeshes(link, r, counts);
      ++counts->links;
      if (auto_links.count(link.name)) {
        ++counts->auto_inertials;
        continue;
      }
      if (!link.inertial) continue;  // libsdformat reports its defaults for absent inertials.
      const Inertial& in = *link.inertial;
      ExpectPoseNear(frames[m].X_MB[i] * in.X_BBi, r.X_MBi, 1e-12, "inertial of " + link.name);
      EXPECT_EQ(in.mass, r.mass) << link.name;
      EXPECT_EQ(in.ixx, r.ixx) << link.name;
      EXPECT_EQ(in.iyy, r.iyy) << link.name;
      EXPECT_EQ(in.izz, r.izz) << link.name;
      EXPECT_EQ(in.ixy, r.ixy) << link.name;
      EXPECT_EQ(in.ixz, r.ixz) << link.name;
      EXPECT_EQ(in.iyz, r.iyz) << link.name;
      ++counts->inertials;
    }
    EXPECT_EQ(model.joints.size(), ref.joints.size()) << model.name;
    for (const Joint& joint : model.joints) {
      const auto it = ref.joints.find(joint.name);
      EXPECT_NE(it, ref.joints.end()) << "joint " << joint.name;
      if (it == ref.joints.end()) continue;
      EXPECT_EQ(joint.parent, it->second.parent) << joint.name;
      EXPECT_EQ(joint.child, it->second.child) << joint.name;
      if (it->second.has_axis) {
        EXPECT_LT((joint.axis - it->second.axis_C).norm(), 1e-12)
            << joint.name << ": " << joint.axis.transpose() << " vs libsdformat "
            << it->second.axis_C.transpose();
      }
      ++counts->joints;
    }
  }
  if (::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count() ==
      failures_before) {
    ++counts->agreeing;
  }
  return "";
}

TEST(SdfReaderSdformatTest, EveryCorpusFileLibsdformatLoadsReadsTheSamePosesAndInertias) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/MANIFEST.tsv");
  std::string sdf_path;
  for (const std::string& p : CorpusModelPaths()) sdf_path += (sdf_path.empty() ? "" : ":") + p;
  setenv("SDF_PATH", sdf_path.c_str(), 1);  // libsdformat resolves plain include URIs with it.
  sdf::ParserConfig config;
  for (const std::string& p : CorpusModelPaths()) config.AddURIPath("model://", p);
  SdfReadOptions options;
  options.model_paths = CorpusModelPaths();
  options.use_environment = false;

  Counts counts;
  std::vector<std::string> rejected;
  for (const std::string& row : SdfRows()) {
    SCOPED_TRACE(row);
    const std::string error = CompareWithLibsdformat(kCorpus + "/" + row, options, config, &counts);
    if (!error.empty()) rejected.push_back(row + " (" + error + ")");
  }
  std::cout << "compared with libsdformat 12: " << counts.files << " files (" << counts.agreeing
            << " agreeing), " << counts.links << " links, " << counts.inertials << " inertials (+"
            << counts.auto_inertials << " auto, pose only), " << counts.joints << " joints, "
            << counts.meshes << " meshes (" << counts.submeshes << " with a <submesh>); "
            << counts.world_joint_files
            << " files with SDF 1.10 world joints not compared (libsdformat 12 predates them); "
            << "libsdformat rejected " << rejected.size() << " files:\n";
  for (const std::string& r : rejected) std::cout << "  " << r << "\n";
  EXPECT_GT(counts.files, 100);  // MANIFEST: most sdf rows have sdformat12_load=ok.
  EXPECT_EQ(counts.agreeing, counts.files);
}

// The hand-written fixtures of sdf_reader_test.cc (whose expected poses are worked out by hand
// there) are also checked against libsdformat, so the hand derivations and the reader agree with
// the reference implementation.
TEST(SdfReaderSdformatTest, TestFixturesReadTheSameAsLibsdformat) {
  const std::string dir = std::string(MASSPROPS_TESTDATA_DIR) + "/sdf";
  const std::string models = dir + "/models";
  setenv("SDF_PATH", models.c_str(), 1);
  sdf::ParserConfig config;
  config.AddURIPath("model://", models);
  SdfReadOptions options;
  options.model_paths = {models};
  options.use_environment = false;
  Counts counts;
  for (const char* name :
       {"frames_1_8.sdf", "placement_world_1_8.sdf", "axis_1.4.sdf", "axis_1.5.sdf", "axis_1.6.sdf",
        "models/massprops_box/box.sdf", "merge_include.sdf", "submesh.sdf"}) {
    SCOPED_TRACE(name);
    const std::string error = CompareWithLibsdformat(dir + "/" + name, options, config, &counts);
    EXPECT_EQ(error, "");
  }
  EXPECT_EQ(counts.files, 8);
  EXPECT_EQ(counts.agreeing, 8);
  // submesh.sdf: 7 meshes, 6 of them with a <submesh> (names and flags in its comment).
  EXPECT_EQ(counts.submeshes, 6);
}

// Every shared file that writes <submesh> (`grep -rl '<submesh' ../shared/corpus` and the labelled
// sets' data.tar.xz) reads the same names and flags as libsdformat: the corpus's
// sdformat/test/sdf/shapes.sdf (a collision 'my_submesh' centred, a visual 'another_submesh' not),
// set 3's zephyr (4 submeshes of wing.dae, all centred: Wing twice, Propeller, Flap_Left,
// Flap_Right) and set 5's mbzirc_usv (5 visuals of USV.dae: USV as placed, Motor_L, Prop_L,
// Motor_R, Prop_R centred; its collisions with <submesh> are commented out). The labelled files
// are taken out of their archives (only the .sdf) into a temporary folder.
TEST(SdfReaderSdformatTest, SharedFilesWithSubmeshesReadTheSameAsLibsdformat) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/sdformat/test/sdf/shapes.sdf");
  sdf::ParserConfig config;
  SdfReadOptions options;
  options.use_environment = false;
  const std::string labelled = test_support::SharedDir() + "/labelled";
  const std::string temporary = ::testing::TempDir() + "/submesh_labelled";
  struct Case {
    std::string path;
    int submeshes;
  };
  std::vector<Case> cases = {{kCorpus + "/sdformat/test/sdf/shapes.sdf", 2}};
  for (const auto& [set, file, submeshes] :
       {std::tuple{"set3", "19_zephyr.sdf", 5}, std::tuple{"set5", "18_mbzirc_usv.sdf", 5}}) {
    const std::string archive = labelled + "/" + set + "/data.tar.xz";
    const std::string folder = temporary + "/" + set;
    const std::string command =
        "mkdir -p '" + folder + "' && tar -xJf '" + archive + "' -C '" + folder + "' files/" + file;
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    cases.push_back({folder + "/files/" + file, submeshes});
  }
  for (const Case& c : cases) {
    SCOPED_TRACE(c.path);
    Counts counts;
    EXPECT_EQ(CompareWithLibsdformat(c.path, options, config, &counts), "");
    EXPECT_EQ(counts.agreeing, 1);
    EXPECT_EQ(counts.submeshes, c.submeshes);
  }
}

}  // namespace
}  // namespace massprops
