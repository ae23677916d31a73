// `merge-fixed` on SDF (MergeFixedJoints, Target::kGeneric) checked with libsdformat 12, the
// reference implementation of SDFormat's pose and frame semantics. For every `sdf` row of
// ../shared/corpus/MANIFEST.tsv that libsdformat loads without errors, and for the hand-made
// fixtures of testdata/merge_sdf/ (hand-computed in merge_fixed_test.cc), the merged file is
// written and BOTH files are loaded with libsdformat (sdf::Root::Load), which must:
//   - load the merged file without errors, with (links − merged links) links per model;
//   - find, for each welded group of the ORIGINAL (union of libsdformat's fixed joints between
//     two links of the model), exactly one of its links left, whose mass, center of mass and
//     inertia about it (each in the model frame) equal the composite of the group computed here
//     in long double from libsdformat's view of the original (member inertials moved into the
//     model frame by the resolved link poses; then, by the parallel-axis theorem (Steiner; e.g.
//     Goldstein, Poole & Safko, Classical Mechanics, 3rd ed., sec. 5.3) in DESIGN.md's stable
//     order: m = Σ m_i, c = Σ m_i·c_i / m, I = Σ [I_i + m_i·(|d_i|²·1 − d_i·d_iᵀ)], d_i = c_i − c),
//     to 1e-9 relative;
//   - give every remaining link, every visual and collision (now in its group's root, by name or
//     renamed "LINK__NAME"), every explicit <frame> and every remaining joint the same pose in the
//     world (model pose · pose in the model frame) as in the original, to 1e-9, each joint axis
//     the same direction in the model frame, and joints and frames the group root as body.
// Files merge-fixed refuses ("not supported") and files without a welded group are counted and
// listed; docs/targets.md quotes the line printed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sdf/Collision.hh>
#include <sdf/Console.hh>
#include <sdf/Frame.hh>
#include <sdf/Joint.hh>
#include <sdf/JointAxis.hh>
#include <sdf/Link.hh>
#include <sdf/Model.hh>
#include <sdf/ParserConfig.hh>
#include <sdf/Root.hh>
#include <sdf/Visual.hh>
#include <sdf/World.hh>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "corpus_manifest.h"
#include "massprops/io/model_reader.h"
#include "massprops/output/merge_fixed.h"

namespace massprops {
namespace {

const std::string kCorpus = MASSPROPS_CORPUS_DIR;

using Real = long double;
using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;

using test_support::CorpusModelPaths;

// A rigid pose in long double: R_AB and p_AB.
struct PoseL {
  Mat3 R = Mat3::Identity();
  Vec3 p = Vec3::Zero();
  PoseL operator*(const PoseL& o) const { return {R * o.R, p + R * o.p}; }
};

PoseL ToPose(const ignition::math::Pose3d& X) {
  PoseL out;
  out.p = Vec3(X.Pos().X(), X.Pos().Y(), X.Pos().Z());
  const Eigen::Quaterniond q(X.Rot().W(), X.Rot().X(), X.Rot().Y(), X.Rot().Z());
  out.R = q.normalized().toRotationMatrix().cast<Real>();
  return out;
}

// Mass, center of mass and inertia about it, in the model frame.
struct Body {
  Real mass = 0;
  Vec3 com = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
};

Body LinkBodyInModel(const sdf::Link& link, const PoseL& X_ML) {
  const ignition::math::Inertiald& in = link.Inertial();
  const PoseL X_MI = X_ML * ToPose(in.Pose());
  const ignition::math::Matrix3d moi = in.MassMatrix().Moi();
  Mat3 I;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) I(r, c) = moi(r, c);
  }
  return {in.MassMatrix().Mass(), X_MI.p, X_MI.R * I * X_MI.R.transpose()};
}

Body Compose(const std::vector<Body>& parts) {
  Body out;
  Vec3 weighted = Vec3::Zero();
  for (const Body& b : parts) {
    out.mass += b.mass;
    weighted += b.mass * b.com;
  }
  if (out.mass != 0) out.com = weighted / out.mass;
  for (const Body& b : parts) {
    const Vec3 d = b.com - out.com;
    out.inertia += b.inertia + b.mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  }
  return out;
}

// libsdformat's view of one model: pose in the world, and per name the poses in the model frame
// of its links, visuals/collisions ("LINK/NAME"), frames and joints, the links' mass properties,
// the joints' bodies and axes, and each link's welded group (by its smallest member name).
struct View {
  PoseL X_WM;
  std::map<std::string, PoseL> links, shapes, frames, joints;
  std::map<std::string, const sdf::Link*> link_ptr;
  std::map<std::string, std::string> frame_body, joint_parent, joint_child;
  std::map<std::string, Vec3> axes;
  std::map<std::string, std::string> group;  // link -> representative
};

PoseL Resolve(const sdf::SemanticPose& pose, const std::string& frame) {
  ignition::math::Pose3d X;
  const sdf::Errors errors = pose.Resolve(X, frame);
  EXPECT_TRUE(errors.empty()) << (errors.empty() ? "" : errors.front().Message());
  return ToPose(X);
}

void CollectShapes(const sdf::Link& link, const PoseL& X_TM, const std::string& prefix, View* v) {
  const std::string name = prefix + link.Name();
  for (uint64_t k = 0; k < link.VisualCount(); ++k) {
    const sdf::Visual* s = link.VisualByIndex(k);
    v->shapes["visual:" + name + "/" + s->Name()] = X_TM * Resolve(s->SemanticPose(), "__model__");
  }
  for (uint64_t k = 0; k < link.CollisionCount(); ++k) {
    const sdf::Collision* s = link.CollisionByIndex(k);
    v->shapes["collision:" + name + "/" + s->Name()] =
        X_TM * Resolve(s->SemanticPose(), "__model__");
  }
}

std::string FindGroup(View* v, const std::string& l) {
  return v->group[l] == l ? l : FindGroup(v, v->group[l]);
}

// Adds `model` (at X_TM in the top model frame T, its names scoped by `prefix`) and the models
// nested in it to the view.
void CollectScope(const sdf::Model& model, const PoseL& X_TM, const std::string& prefix, View* v) {
  for (uint64_t i = 0; i < model.LinkCount(); ++i) {
    const sdf::Link* link = model.LinkByIndex(i);
    const std::string name = prefix + link->Name();
    v->links[name] = X_TM * Resolve(link->SemanticPose(), "__model__");
    v->link_ptr[name] = link;
    v->group[name] = name;
    CollectShapes(*link, X_TM, prefix, v);
  }
  for (uint64_t i = 0; i < model.FrameCount(); ++i) {
    const sdf::Frame* f = model.FrameByIndex(i);
    v->frames[prefix + f->Name()] = X_TM * Resolve(f->SemanticPose(), "__model__");
    std::string body;
    f->ResolveAttachedToBody(body);
    v->frame_body[prefix + f->Name()] = prefix + body;
  }
  for (uint64_t i = 0; i < model.ModelCount(); ++i) {
    const sdf::Model* nested = model.ModelByIndex(i);
    CollectScope(*nested, X_TM * Resolve(nested->SemanticPose(), "__model__"),
                 prefix + nested->Name() + "::", v);
  }
  for (uint64_t i = 0; i < model.JointCount(); ++i) {
    const sdf::Joint* j = model.JointByIndex(i);
    const std::string name = prefix + j->Name();
    v->joints[name] = X_TM * Resolve(j->SemanticPose(), "__model__");
    std::string parent, child;
    j->ResolveParentLink(parent);
    j->ResolveChildLink(child);
    v->joint_parent[name] = parent == "world" ? parent : prefix + parent;
    v->joint_child[name] = prefix + child;
    if (const sdf::JointAxis* axis = j->Axis(0)) {
      ignition::math::Vector3d xyz;
      if (axis->ResolveXyz(xyz, "__model__").empty()) {
        v->axes[name] = X_TM.R * Vec3(xyz.X(), xyz.Y(), xyz.Z()).normalized();
      }
    }
    const std::string& p = v->joint_parent[name];
    const std::string& c = v->joint_child[name];
    if (j->Type() == sdf::JointType::FIXED && v->link_ptr.count(p) && v->link_ptr.count(c)) {
      const std::string a = FindGroup(v, p), b = FindGroup(v, c);
      if (a != b) v->group[std::max(a, b)] = std::min(a, b);
    }
  }
}

View Collect(const sdf::Model& model) {
  View v;
  ignition::math::Pose3d X_WM;
  if (model.SemanticPose().Resolve(X_WM).empty()) v.X_WM = ToPose(X_WM);
  CollectScope(model, PoseL(), "", &v);
  for (auto& [link, rep] : v.group) rep = FindGroup(&v, link);
  return v;
}

std::vector<const sdf::Model*> Models(const sdf::Root& root) {
  std::vector<const sdf::Model*> models;
  if (root.Model() != nullptr) models.push_back(root.Model());
  for (uint64_t w = 0; w < root.WorldCount(); ++w) {
    for (uint64_t m = 0; m < root.WorldByIndex(w)->ModelCount(); ++m) {
      models.push_back(root.WorldByIndex(w)->ModelByIndex(m));
    }
  }
  return models;
}

void ExpectPoseNear(const PoseL& a, const PoseL& b, const std::string& what) {
  EXPECT_LE(static_cast<double>((a.p - b.p).norm()),
            1e-9 * std::max(1.0, static_cast<double>(b.p.norm())))
      << what << ": p " << a.p.transpose() << " vs " << b.p.transpose();
  EXPECT_LE(static_cast<double>((a.R - b.R).cwiseAbs().maxCoeff()), 1e-9) << what;
}

void ExpectBodyNear(const Body& merged, const Body& expected, const std::string& what) {
  EXPECT_LE(static_cast<double>(std::abs(merged.mass - expected.mass)),
            1e-12 * static_cast<double>(std::abs(expected.mass)))
      << what << ": mass " << static_cast<double>(merged.mass) << " vs "
      << static_cast<double>(expected.mass);
  if (expected.mass != 0) {
    EXPECT_LE(static_cast<double>((merged.com - expected.com).norm()),
              1e-9 * std::max(1.0, static_cast<double>(expected.com.norm())))
        << what << ": com " << merged.com.transpose() << " vs " << expected.com.transpose();
  }
  const Real scale = std::max<Real>(expected.inertia.cwiseAbs().maxCoeff(), 1e-300L);
  EXPECT_LE(static_cast<double>((merged.inertia - expected.inertia).cwiseAbs().maxCoeff()),
            1e-9 * static_cast<double>(scale))
      << what << ": inertia\n"
      << merged.inertia << "\nvs\n"
      << expected.inertia;
}

struct Counts {
  int loaded = 0, merged_files = 0, groups = 0, merged_links = 0, without_groups = 0;
  int auto_groups = 0;
  int links = 0, shapes = 0, frames = 0, joints = 0;
  std::vector<std::string> refused_by_libsdformat, not_supported;
};

// The name of a shape of `link` (merged into `root`) in the merged model.
std::string MergedShapeKey(const std::string& key, const std::string& root, const View& after) {
  const std::size_t colon = key.find(':'), slash = key.find('/');
  const std::string kind = key.substr(0, colon + 1);
  const std::string link = key.substr(colon + 1, slash - colon - 1);
  const std::string name = key.substr(slash + 1);
  if (after.links.count(link)) return key;
  const std::size_t scope = link.rfind("::");
  const std::string local = scope == std::string::npos ? link : link.substr(scope + 2);
  const std::string renamed = kind + root + "/" + local + "__" + name;
  return after.shapes.count(renamed) ? renamed : kind + root + "/" + name;
}

// Compares one model before and after merging (gtest expectations). Groups with a member in
// `auto_links` (<inertial auto="true">, SDF 1.11: libsdformat 12 predates it and gives its
// default inertial, massprops computes it, tests/sdf_reader_test.cc) are compared by pose only.
void CompareModel(const View& before, const View& after, const std::set<std::string>& auto_links,
                  Counts* counts) {
  ExpectPoseNear(after.X_WM, before.X_WM, "model pose");
  std::map<std::string, std::vector<std::string>> groups;
  for (const auto& [link, rep] : before.group) groups[rep].push_back(link);
  std::map<std::string, std::string> root_of;  // original link -> link left in its group
  std::size_t expected_links = 0;
  for (const auto& [rep, members] : groups) {
    std::vector<std::string> left;
    for (const std::string& m : members) {
      if (after.links.count(m)) left.push_back(m);
    }
    ASSERT_EQ(left.size(), 1u) << "group of " << rep << ": " << members.size() << " links";
    ++expected_links;
    for (const std::string& m : members) root_of[m] = left[0];
    std::vector<Body> parts;
    bool automatic = false;
    for (const std::string& m : members) {
      parts.push_back(LinkBodyInModel(*before.link_ptr.at(m), before.links.at(m)));
      automatic = automatic || auto_links.count(m);
    }
    const std::string& root = left[0];
    if (automatic) {
      ++counts->auto_groups;
    } else {
      ExpectBodyNear(LinkBodyInModel(*after.link_ptr.at(root), after.links.at(root)),
                     Compose(parts), "link " + root);
    }
    ExpectPoseNear(after.X_WM * after.links.at(root), before.X_WM * before.links.at(root),
                   "link " + root);
    ++counts->links;
    if (members.size() > 1) {
      ++counts->groups;
      counts->merged_links += static_cast<int>(members.size()) - 1;
    }
  }
  EXPECT_EQ(after.links.size(), expected_links);
  for (const auto& [key, X] : before.shapes) {
    const std::string link = key.substr(key.find(':') + 1, key.find('/') - key.find(':') - 1);
    const std::string merged_key = MergedShapeKey(key, root_of[link], after);
    ASSERT_TRUE(after.shapes.count(merged_key)) << key << " -> " << merged_key;
    ExpectPoseNear(after.X_WM * after.shapes.at(merged_key), before.X_WM * X, key);
    ++counts->shapes;
  }
  for (const auto& [name, X] : before.frames) {
    ASSERT_TRUE(after.frames.count(name)) << "frame " << name;
    ExpectPoseNear(after.X_WM * after.frames.at(name), before.X_WM * X, "frame " + name);
    const std::string& body = before.frame_body.at(name);
    EXPECT_EQ(after.frame_body.at(name), root_of.count(body) ? root_of[body] : body) << name;
    ++counts->frames;
  }
  for (const auto& [name, X] : after.frames) {
    if (!before.joints.count(name)) continue;
    // A removed fixed joint that something names is now a frame where the joint frame was.
    ExpectPoseNear(after.X_WM * X, before.X_WM * before.joints.at(name), "joint frame " + name);
    const std::string& child = before.joint_child.at(name);
    EXPECT_EQ(after.frame_body.at(name), root_of.count(child) ? root_of[child] : child) << name;
  }
  for (const auto& [name, X] : after.joints) {
    ASSERT_TRUE(before.joints.count(name)) << "joint " << name;
    ExpectPoseNear(after.X_WM * X, before.X_WM * before.joints.at(name), "joint " + name);
    for (auto which : {&View::joint_parent, &View::joint_child}) {
      const std::string& was = (before.*which).at(name);
      EXPECT_EQ((after.*which).at(name), root_of.count(was) ? root_of[was] : was) << name;
    }
    if (before.axes.count(name)) {
      ASSERT_TRUE(after.axes.count(name)) << name;
      EXPECT_LE(static_cast<double>((after.axes.at(name) - before.axes.at(name)).norm()), 1e-9)
          << "axis of " << name;
    }
    ++counts->joints;
  }
}

// Merges one file and compares; counts what happened.
void CheckFile(const std::string& path, const std::string& label, const sdf::ParserConfig& config,
               const std::filesystem::path& scratch, Counts* counts) {
  sdf::Root before_root;
  const sdf::Errors errors = before_root.Load(path, config);
  if (!errors.empty()) {
    counts->refused_by_libsdformat.push_back(label + " (" + errors.front().Message() + ")");
    return;
  }
  ++counts->loaded;
  std::string text;
  ASSERT_FALSE(ReadInputFile(path, kMaxModelFileBytes, &text).has_value());
  const MergeFixedResult merged = MergeFixedJoints(text, path);
  if (!merged.errors.empty()) {
    counts->not_supported.push_back(label + ": " + merged.errors.front().ToString());
    return;
  }
  if (merged.groups_merged == 0) {
    ++counts->without_groups;
    return;
  }
  ++counts->merged_files;
  const std::filesystem::path out = scratch / std::filesystem::path(path).filename();
  std::ofstream(out) << merged.text;
  sdf::Root after_root;
  const sdf::Errors after_errors = after_root.Load(out.string(), config);
  ASSERT_TRUE(after_errors.empty())
      << label << ": the merged file: " << after_errors.front().Message() << "\n"
      << merged.text;
  const std::vector<const sdf::Model*> before = Models(before_root), after = Models(after_root);
  ASSERT_EQ(before.size(), after.size());
  const ReadResult read = ReadModelString(text, path);
  for (std::size_t m = 0; m < before.size(); ++m) {
    SCOPED_TRACE("model " + before[m]->Name());
    std::set<std::string> auto_links;
    for (const ReadFinding& f : read.findings) {
      if (f.rule == "inertial-auto" && f.model == before[m]->Name()) auto_links.insert(f.link);
    }
    CompareModel(Collect(*before[m]), Collect(*after[m]), auto_links, counts);
  }
}

TEST(MergeFixedSdfSdformatTest, MergedCorpusFilesLoadWithTheCompositesAndUnchangedPoses) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/MANIFEST.tsv");
  std::string sdf_path;
  for (const std::string& p : CorpusModelPaths()) sdf_path += (sdf_path.empty() ? "" : ":") + p;
  setenv("SDF_PATH", sdf_path.c_str(), 1);  // Both libsdformat and massprops search it.
  sdf::Console::Instance()->SetQuiet(true);
  sdf::ParserConfig config;
  for (const std::string& p : CorpusModelPaths()) config.AddURIPath("model://", p);
  const std::filesystem::path scratch =
      std::filesystem::temp_directory_path() / ("massprops_merge_sdf_" + std::to_string(getpid()));
  std::filesystem::create_directories(scratch);

  Counts counts;
  int rows = 0;
  for (const test_support::ManifestRow& row : test_support::ReadCorpusManifest("sdf")) {
    SCOPED_TRACE(row.file);
    ++rows;
    CheckFile(kCorpus + "/" + row.file, row.file, config, scratch, &counts);
  }
  Counts fixtures;
  for (const char* name : {"two_boxes.sdf", "rotated.sdf", "nested.sdf", "old_frame.sdf"}) {
    SCOPED_TRACE(name);
    CheckFile(std::string(MASSPROPS_TESTDATA_DIR) + "/merge_sdf/" + name, name, config, scratch,
              &fixtures);
  }
  std::filesystem::remove_all(scratch);
  std::cout << "merge-fixed on SDF, checked with libsdformat 12: " << rows << " corpus SDF files, "
            << counts.loaded << " loaded by libsdformat; " << counts.merged_files
            << " with welded groups merged (" << counts.groups << " groups, " << counts.merged_links
            << " links merged; " << counts.auto_groups
            << " with <inertial auto> compared by pose only), " << counts.without_groups
            << " without a welded group, " << counts.not_supported.size()
            << " refused as not supported; compared: " << counts.links << " links, "
            << counts.shapes << " visuals/collisions, " << counts.frames << " frames, "
            << counts.joints << " joints; fixtures: " << fixtures.merged_files << " merged, "
            << fixtures.refused_by_libsdformat.size() << " refused by libsdformat\n";
  for (const std::string& s : counts.not_supported) std::cout << "  not supported: " << s << "\n";
  EXPECT_GT(counts.merged_files, 0);
  EXPECT_EQ(fixtures.merged_files, 4);  // The fixtures load in libsdformat and are merged.
}

}  // namespace
}  // namespace massprops
