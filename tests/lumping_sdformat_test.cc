// Against a real peer: libsdformat 12 lumps links joined by fixed joints when it converts URDF to
// SDF (parser_urdf.cc, "fixed joint reduction"). For every `urdf` row of
// ../shared/corpus/MANIFEST.tsv, each link of libsdformat's model is compared with massprops'
// welded group rooted at that link: mass, center of mass and inertia about the center of mass in
// the link frame, to 1e-9 relative. libsdformat's known behaviours are accounted for: a root link
// named "world" is the world (not a link), massless links and groups are not modeled, and
// <disableFixedJointLumping>/<preserveFixedJoint> keep links apart (listed below). Files that
// libsdformat or massprops cannot load are skipped and printed. Differences that are libsdformat's
// own behaviour (or error) are listed below by file and link, with the reason; docs/report.md
// explains each with numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <sdf/Console.hh>
#include <sdf/Link.hh>
#include <sdf/Model.hh>
#include <sdf/Root.hh>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "corpus_manifest.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/io/model_reader.h"

namespace massprops {
namespace {

const std::string kCorpus = MASSPROPS_CORPUS_DIR;

std::vector<std::string> UrdfRows() {
  std::vector<std::string> files;
  for (const test_support::ManifestRow& row : test_support::ReadCorpusManifest("urdf")) {
    files.push_back(row.file);
  }
  return files;
}

struct Difference {
  std::string file;
  std::string link;
  std::string what;
};

// Differences that are libsdformat's, by file and link (evidence in docs/report.md).
struct KnownException {
  const char* file;
  const char* link;
  const char* reason;
};
const KnownException kKnownExceptions[] = {
    // <gazebo reference="joint"><disableFixedJointLumping>true: libsdformat keeps link2a as its
    // own link by request, so link1a holds only its own 100 kg (massprops lumps: 700 kg).
    {"sdformat/test/integration/fixed_joint_reduction_disabled.urdf", "link1a",
     "lumping disabled by a <gazebo> tag"},
    {"sdformat/test/integration/fixed_joint_reduction_disabled.urdf", "link2a",
     "lumping disabled by a <gazebo> tag"},
    // panda_link5_upper has no <inertial> and is welded to panda_link5_lower (2.74 kg); libsdformat
    // drops it and with it every link below it: 3.02 kg of arm and hand vanish (libsdformat's
    // error: a massless link welded to a massive one is valid URDF).
    {"drake-models/franka_description/urdf/panda_arm_hand_link5split.urdf", "panda_link6",
     "dropped below a massless welded link"},
    {"drake-models/franka_description/urdf/panda_arm_hand_link5split.urdf", "panda_link7",
     "dropped below a massless welded link"},
    {"drake-models/franka_description/urdf/panda_arm_hand_link5split.urdf", "panda_leftfinger",
     "dropped below a massless welded link"},
    {"drake-models/franka_description/urdf/panda_arm_hand_link5split.urdf", "panda_rightfinger",
     "dropped below a massless welded link"},
};
// Groups holding a fixed joint whose pitch is within 0.0045 rad of ±90° (|sin(pitch)| > 0.99999,
// rpy near gimbal lock): libsdformat's lumped center of mass and inertia differ by 1e-9 to 2e-6
// relative (it carries the joint rotation through a 6-significant-digit text pose, as
// ignition::math::Pose3d's operator<< prints, e.g. "1.5708 -1.5708 0" comes back as
// "-1.57079 -1.57079 3.14159"); the test checks that each such difference has such a joint.
const char* const kGimbalFiles[] = {
    "unitree_ros/robots/g1_description/g1_29dof_rev_1_0_with_inspire_hand_FTP.urdf",
    "unitree_ros/robots/g1_description/inspire_hand/FTP_left_hand.urdf",
    "unitree_ros/robots/h2_plus/H2_Plus.urdf",
    // The same inspire FTP hand, read since <material> without a name became a warning.
    "unitree_ros/robots/h1_2_description/h1_2_with_FTP_hand.urdf",
};

bool IsKnownException(const Difference& d) {
  for (const KnownException& k : kKnownExceptions) {
    if (d.file == k.file && d.link == k.link) return true;
  }
  return false;
}

// True when the group holds a fixed joint whose URDF pitch has |sin(pitch)| > 0.99999.
bool HasNearGimbalLockFixedJoint(const Model& model, const WeldedGroup& group) {
  for (std::size_t k = 1; k < group.links.size(); ++k) {
    const int j = model.FindParentJoint(model.links[group.links[k]].name);
    if (j < 0) continue;
    const Eigen::Matrix3d& R = model.joints[j].X_PC.R_AB;
    if (std::abs(R(2, 0)) > 0.99999) return true;  // R(2,0) = −sin(pitch) for Rz·Ry·Rx
  }
  return false;
}

// libsdformat treats a root link named "world" as the world: its fixed children become links
// attached to the world, and "world" is no link. The same model without it, for the comparison.
Model WithoutWorldRoot(const Model& model) {
  if (model.root_link != "world") return model;
  Model out = model;
  out.links.erase(std::remove_if(out.links.begin(), out.links.end(),
                                 [](const Link& l) { return l.name == "world"; }),
                  out.links.end());
  out.joints.erase(std::remove_if(out.joints.begin(), out.joints.end(),
                                  [](const Joint& j) { return j.parent == "world"; }),
                   out.joints.end());
  out.root_link.clear();
  return out;
}

TEST(LumpingSdformatTest, EveryLumpedLinkAgreesWithTheWeldedGroup) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/MANIFEST.tsv");
  sdf::Console::Instance()->SetQuiet(true);
  const std::vector<std::string> files = UrdfRows();
  ASSERT_GT(files.size(), 100u) << "corpus MANIFEST.tsv not found under " << kCorpus;
  std::vector<Difference> differences;
  int compared_links = 0, lumped_groups = 0, skipped_files = 0, gimbal_differences = 0;
  for (const std::string& file : files) {
    const std::string path = kCorpus + "/" + file;
    sdf::Root root;
    const sdf::Errors errors = root.Load(path);
    const ReadResult read = ReadModelFile(path);
    // A reader finding (e.g. inertial-unreadable: urdfdom keeps a partly read <inertial>, which
    // libsdformat lumps and massprops deliberately does not hold) makes the models differ.
    if (!errors.empty() || root.Model() == nullptr || !read.ok() || read.models.empty() ||
        !read.findings.empty()) {
      ++skipped_files;
      std::cout << "skipped " << file << ": "
                << (!errors.empty()          ? "libsdformat: " + errors.front().Message()
                    : !read.ok()             ? "massprops: " + read.errors.front().ToString()
                    : !read.findings.empty() ? "massprops: " + read.findings.front().message
                                             : "no model")
                << "\n";
      continue;
    }
    const Model model = WithoutWorldRoot(read.models.front());
    const bool gimbal_file =
        std::find(std::begin(kGimbalFiles), std::end(kGimbalFiles), file) != std::end(kGimbalFiles);
    std::map<std::string, const WeldedGroup*> group_by_root;
    const std::vector<WeldedGroup> groups = FindWeldedGroups(model);
    for (const WeldedGroup& group : groups) group_by_root[group.root_link] = &group;
    std::set<std::string> sdf_links;
    const sdf::Model& sdf_model = *root.Model();
    for (uint64_t i = 0; i < sdf_model.LinkCount(); ++i) {
      const sdf::Link& link = *sdf_model.LinkByIndex(i);
      sdf_links.insert(link.Name());
      const auto it = group_by_root.find(link.Name());
      if (it == group_by_root.end()) {
        differences.push_back({file, link.Name(), "no massprops welded group is rooted here"});
        continue;
      }
      ++compared_links;
      if (it->second->links.size() > 1) ++lumped_groups;
      const CompositeInertia c = CalcCompositeInertia(model, *it->second);
      const ignition::math::Inertiald& inertial = link.Inertial();
      const double mass = inertial.MassMatrix().Mass();
      const Eigen::Vector3d com(inertial.Pose().Pos().X(), inertial.Pose().Pos().Y(),
                                inertial.Pose().Pos().Z());
      const ignition::math::Matrix3d moi = inertial.Moi();
      Eigen::Matrix3d I;
      for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) I(r, k) = moi(r, k);
      }
      std::ostringstream what;
      what.precision(17);
      const double trace = std::max(std::abs(c.I_SScm_R.trace()), 1e-300);
      const double gyration = c.mass > 0 ? std::sqrt(trace / c.mass) : 0;
      if (std::abs(mass - c.mass) > 1e-9 * std::max(std::abs(c.mass), 1e-300)) {
        what << "mass " << mass << " (massprops " << c.mass << "); ";
      }
      if ((com - c.p_RoScm_R).norm() > 1e-9 * std::max(c.p_RoScm_R.norm(), gyration)) {
        what << "com [" << com.transpose() << "] (massprops [" << c.p_RoScm_R.transpose() << "]); ";
      }
      if ((I - c.I_SScm_R).cwiseAbs().maxCoeff() > 1e-9 * trace) {
        what << "inertia [" << I.row(0) << "; " << I.row(1) << "; " << I.row(2) << "] (massprops ["
             << c.I_SScm_R.row(0) << "; " << c.I_SScm_R.row(1) << "; " << c.I_SScm_R.row(2)
             << "]); ";
      }
      if (!what.str().empty()) {
        if (gimbal_file) {
          // Known: see kGimbalFiles. The group must hold a near-gimbal-lock fixed joint and the
          // difference stay below 1e-5 relative.
          ++gimbal_differences;
          EXPECT_TRUE(HasNearGimbalLockFixedJoint(model, *it->second))
              << file << " " << link.Name();
          EXPECT_LE((com - c.p_RoScm_R).norm(), 1e-5 * std::max(c.p_RoScm_R.norm(), gyration));
          EXPECT_LE((I - c.I_SScm_R).cwiseAbs().maxCoeff(), 1e-5 * trace);
          continue;
        }
        differences.push_back({file, link.Name(), what.str()});
      }
    }
    for (const WeldedGroup& group : groups) {
      if (sdf_links.count(group.root_link) == 0) {
        const CompositeInertia c = CalcCompositeInertia(model, group);
        // Known behaviour: libsdformat does not model massless links (nor massless groups).
        if (c.mass == 0) continue;
        std::ostringstream what;
        what << "libsdformat has no link for this group (mass " << c.mass << ", "
             << group.links.size() << " links)";
        differences.push_back({file, group.root_link, what.str()});
      }
    }
  }
  std::cout << "compared " << compared_links << " links (" << lumped_groups << " lumped groups) in "
            << files.size() - skipped_files << " files; skipped " << skipped_files << "\n";
  std::cout << gimbal_differences << " near-gimbal-lock differences (kGimbalFiles)\n";
  EXPECT_GT(lumped_groups, 300);
  std::set<std::pair<std::string, std::string>> seen;
  for (const Difference& d : differences) {
    seen.emplace(d.file, d.link);
    if (IsKnownException(d)) {
      std::cout << "known libsdformat difference: " << d.file << " | " << d.link << " | " << d.what
                << "\n";
    } else {
      ADD_FAILURE() << d.file << " | " << d.link << " | " << d.what;
    }
  }
  // The list of exceptions stays honest: each one still happens.
  for (const KnownException& k : kKnownExceptions) {
    EXPECT_EQ(seen.count({k.file, k.link}), 1u) << "no longer differs: " << k.file << " " << k.link;
  }
  EXPECT_GT(gimbal_differences, 0);
}

}  // namespace
}  // namespace massprops
