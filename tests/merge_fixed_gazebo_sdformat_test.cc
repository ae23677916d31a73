// `merge-fixed --target gazebo` (MergeFixedJoints with Target::kGazebo) on the corpus, checked two
// ways. For every `urdf` row of ../shared/corpus/MANIFEST.tsv that massprops reads without errors
// and that has a fixed joint, the merged URDF is read back and each of its links (a body as Gazebo
// simulates it) is compared:
//   (a) with an independent composition written here in long double, to 1e-12 relative: the
//       members of a body are the original links whose nearest ancestor through joints that is
//       still a link of the merged file is that body; each member's inertial is moved into the
//       body frame R along the joint origins (X_RL = X_RP·X_PC), then, by the parallel-axis
//       theorem (Steiner; e.g. Goldstein, Poole & Safko, Classical Mechanics, 3rd ed., sec. 5.3)
//       in the stable order of DESIGN.md: composite mass m = Σ m_i, composite center of mass
//       c = Σ m_i·c_i / m first, then I = Σ [R_i·I_i·R_iᵀ + m_i·(|d_i|²·1 − d_i·d_iᵀ)] with
//       d_i = c_i − c (each central inertia shifted away from its own center of mass);
//   (b) with libsdformat 12's own lumping, to 1e-6 relative: sdf::Root::Load of the ORIGINAL URDF
//       converts it to SDF and lumps fixed joints, honouring <disableFixedJointLumping> and
//       <preserveFixedJoint> (gazebosim/sdformat src/parser_urdf.cc); each of its links is
//       compared with the merged link of the same name (libsdformat itself drifts by about 1e-8
//       near pitch = ±π/2, tests/lumping_sdformat_test.cc).
// libsdformat's known behaviours are accounted for as in lumping_sdformat_test.cc: massless links
// and bodies are not modeled by it, and its own error below a massless welded link is listed.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
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
#include "massprops/io/model_reader.h"
#include "massprops/output/merge_fixed.h"

namespace massprops {
namespace {

const std::string kCorpus = MASSPROPS_CORPUS_DIR;

using Real = long double;
using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;

// Mass properties in some frame F: mass, center of mass from F's origin, inertia about the
// center of mass (matrix entries, off-diagonals −∫xy dm), expressed in F.
struct Body {
  Real mass = 0;
  Vec3 com = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
};

// A link's inertial in its own frame B: c = p_BBi, I = R_BBi·I_Bi·R_BBiᵀ (no inertial: nothing).
Body LinkBody(const Link& link) {
  Body body;
  if (!link.inertial) return body;
  const Inertial& in = *link.inertial;
  Mat3 I_Bi;
  // URDF's ixy is the matrix entry −∫xy dm itself (the convention of massprops' Model).
  I_Bi << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  const Mat3 R = in.X_BBi.R_AB.cast<Real>();
  body.mass = in.mass;
  body.com = in.X_BBi.p_AB.cast<Real>();
  body.inertia = R * I_Bi * R.transpose();
  return body;
}

// A pose in long double: R_AB, p_AB.
struct PoseL {
  Mat3 R = Mat3::Identity();
  Vec3 p = Vec3::Zero();
};

// The composite of `parts` (each in the common frame), as the header comment says.
Body Compose(const std::vector<Body>& parts) {
  Body total;
  for (const Body& b : parts) total.mass += b.mass;
  if (total.mass > 0) {
    for (const Body& b : parts) total.com += b.mass * b.com;
    total.com /= total.mass;
  }
  for (const Body& b : parts) {
    const Vec3 d = b.com - total.com;
    total.inertia += b.inertia + b.mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  }
  return total;
}

// The body of every link kept in `merged` (by name): the composite of the original links whose
// nearest ancestor (through joints, itself included) kept in `merged` is that link, in its frame.
// Adds to *gimbal the bodies that lump a joint whose URDF pitch has |sin(pitch)| > 0.99999.
std::map<std::string, Body> ExpectedBodies(const Model& original, const Model& merged,
                                           std::set<std::string>* gimbal) {
  std::set<std::string> kept;
  for (const Link& link : merged.links) kept.insert(link.name);
  std::map<std::string, std::vector<Body>> parts;
  for (const Link& link : original.links) {
    PoseL X_RL;  // composed downward from the body root R, so prepend each joint going up
    std::string at = link.name;
    bool near_gimbal_lock = false;
    for (int steps = 0; kept.count(at) == 0 && steps <= int(original.links.size()); ++steps) {
      const int j = original.FindParentJoint(at);
      if (j < 0) break;
      const Joint& joint = original.joints[j];
      const Mat3 R_PC = joint.X_PC.R_AB.cast<Real>();
      X_RL.p = joint.X_PC.p_AB.cast<Real>() + R_PC * X_RL.p;  // X_PL = X_PC·X_CL
      X_RL.R = R_PC * X_RL.R;
      near_gimbal_lock |= std::abs(R_PC(2, 0)) > 0.99999L;  // R(2,0) = −sin(pitch), Rz·Ry·Rx
      at = joint.parent;
    }
    if (at != link.name && near_gimbal_lock) gimbal->insert(at);
    if (kept.count(at) == 0) {
      ADD_FAILURE() << original.file << ": link '" << link.name << "' belongs to no merged link";
      continue;
    }
    Body b = LinkBody(link);
    b.com = X_RL.p + X_RL.R * b.com;
    b.inertia = X_RL.R * b.inertia * X_RL.R.transpose();
    std::vector<Body>& list = parts[at];
    list.insert(at == link.name ? list.begin() : list.end(), b);  // the root first
  }
  std::map<std::string, Body> bodies;
  for (const auto& [name, list] : parts) {
    // merge_fixed.h: when no member but the root has a mass or an inertia, the root keeps its
    // inertial as written (the composite is then the root's own).
    bool members_contribute = false;
    for (const Body& b : list) {
      members_contribute |= &b != &list.front() && (b.mass != 0 || !b.inertia.isZero(0));
    }
    bodies[name] = members_contribute ? Compose(list) : list.front();
  }
  return bodies;
}

// "" when `got` agrees with `want` within `tolerance` relative (mass to the mass, center of mass
// to max(|c|, radius of gyration), inertia entries to the trace); else what differs.
std::string Differs(const Body& got, const Body& want, Real tolerance) {
  std::ostringstream what;
  what.precision(17);
  const Real trace = std::max(std::abs(want.inertia.trace()), Real(1e-300));
  const Real gyration = want.mass > 0 ? std::sqrt(trace / want.mass) : 0;
  if (std::abs(got.mass - want.mass) > tolerance * std::max(std::abs(want.mass), Real(1e-300))) {
    what << "mass " << double(got.mass) << " (expected " << double(want.mass) << "); ";
  }
  if ((got.com - want.com).norm() > tolerance * std::max(want.com.norm(), gyration)) {
    what << "com [" << got.com.cast<double>().transpose() << "] (expected ["
         << want.com.cast<double>().transpose() << "]); ";
  }
  if ((got.inertia - want.inertia).cwiseAbs().maxCoeff() > tolerance * trace) {
    what << "inertia row0 [" << got.inertia.row(0).cast<double>() << "] (expected ["
         << want.inertia.row(0).cast<double>() << "]), max difference "
         << double((got.inertia - want.inertia).cwiseAbs().maxCoeff()) << "; ";
  }
  return what.str();
}

// libsdformat's link as a Body (Moi() is about the center of mass, expressed in the link frame).
Body SdfBody(const sdf::Link& link) {
  Body body;
  const ignition::math::Inertiald& inertial = link.Inertial();
  body.mass = inertial.MassMatrix().Mass();
  body.com = Vec3(inertial.Pose().Pos().X(), inertial.Pose().Pos().Y(), inertial.Pose().Pos().Z());
  const ignition::math::Matrix3d moi = inertial.Moi();
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) body.inertia(r, k) = moi(r, k);
  }
  return body;
}

// libsdformat's own error (tests/lumping_sdformat_test.cc, docs/report.md): panda_link5_upper has
// no <inertial> and is welded to panda_link5_lower; libsdformat drops it and every link below it.
const char* const kSdformatDropsBelowMasslessLink =
    "drake-models/franka_description/urdf/panda_arm_hand_link5split.urdf";

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool HasFixedJoint(const Model& model) {
  return std::any_of(model.joints.begin(), model.joints.end(),
                     [](const Joint& j) { return j.type == Joint::Type::kFixed; });
}

struct Counts {
  int files = 0, bodies = 0, lumped = 0;                          // (a)
  int sdf_files = 0, sdf_links = 0, sdf_skipped = 0, gimbal = 0;  // (b)
};

// (b): each libsdformat link against the merged link of the same name, and every massive merged
// link has a libsdformat link.
void CompareWithSdformat(const std::string& file, const sdf::Model& sdf_model, const Model& merged,
                         const std::set<std::string>& gimbal, Counts* counts,
                         std::set<std::string>* agreeing) {
  std::map<std::string, const Link*> by_name;
  for (const Link& link : merged.links) by_name[link.name] = &link;
  std::set<std::string> seen;
  for (uint64_t i = 0; i < sdf_model.LinkCount(); ++i) {
    const sdf::Link& link = *sdf_model.LinkByIndex(i);
    seen.insert(link.Name());
    const auto it = by_name.find(link.Name());
    if (it == by_name.end()) {
      ADD_FAILURE() << file << " | " << link.Name() << " | no merged link of that name";
      continue;
    }
    ++counts->sdf_links;
    const std::string what = Differs(LinkBody(*it->second), SdfBody(link), 1e-6L);
    if (what.empty()) {
      agreeing->insert(file + "|" + link.Name());
    } else if (gimbal.count(link.Name()) &&
               Differs(LinkBody(*it->second), SdfBody(link), 1e-5L).empty()) {
      // libsdformat carries the joint rotation through a 6-digit text pose near gimbal lock
      // (tests/lumping_sdformat_test.cc, kGimbalFiles): 1e-9 to 2e-6 relative.
      ++counts->gimbal;
      std::cout << "near-gimbal-lock libsdformat difference: " << file << " | " << link.Name()
                << " | " << what << "\n";
    } else if (file == kSdformatDropsBelowMasslessLink) {
      std::cout << "known libsdformat difference: " << file << " | " << link.Name() << "\n";
    } else {
      ADD_FAILURE() << file << " | " << link.Name() << " | " << what;
    }
  }
  for (const Link& link : merged.links) {
    if (seen.count(link.name) || LinkBody(link).mass == 0) continue;  // massless: not modeled
    if (file == kSdformatDropsBelowMasslessLink) {
      std::cout << "known libsdformat difference: " << file << " | " << link.name
                << " | dropped below a massless welded link\n";
      continue;
    }
    ADD_FAILURE() << file << " | " << link.name << " | libsdformat has no link of that name";
  }
}

TEST(MergeFixedGazeboSdformatTest, EveryMergedBodyAgreesWithLongDoubleAndLibsdformat) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/MANIFEST.tsv");
  sdf::Console::Instance()->SetQuiet(true);
  const std::vector<test_support::ManifestRow> rows = test_support::ReadCorpusManifest("urdf");
  ASSERT_GT(rows.size(), 100u) << "corpus MANIFEST.tsv not found under " << kCorpus;
  Counts counts;
  std::set<std::string> agreeing;  // "file|link" that agree with libsdformat
  for (const test_support::ManifestRow& row : rows) {
    const std::string path = kCorpus + "/" + row.file;
    const ReadResult read = ReadModelFile(path);
    if (!read.ok() || read.models.empty() || !HasFixedJoint(read.models.front())) continue;
    const MergeFixedResult result = MergeFixedJoints(ReadText(path), path, Target::kGazebo);
    ASSERT_TRUE(result.errors.empty()) << row.file << ": " << result.errors.front().ToString();
    const ReadResult reread = ReadModelString(result.text, path);
    ASSERT_TRUE(reread.ok() && reread.models.size() == 1u) << row.file;
    const Model& merged = reread.models.front();
    ++counts.files;
    // (a) every body with mass against the long-double composition, 1e-12 relative.
    std::set<std::string> gimbal;
    for (const auto& [name, want] : ExpectedBodies(read.models.front(), merged, &gimbal)) {
      if (want.mass == 0) continue;  // the root's inertial is then kept as written
      ++counts.bodies;
      const Link& link = merged.links[merged.FindLink(name)];
      EXPECT_EQ(Differs(LinkBody(link), want, 1e-12L), "") << row.file << " | " << name;
    }
    counts.lumped += int(read.models.front().links.size() - merged.links.size());
    // (b) libsdformat's lumping of the original file, 1e-6 relative.
    sdf::Root root;
    const sdf::Errors errors = root.Load(path);
    if (!errors.empty() || root.Model() == nullptr || !read.findings.empty()) {
      ++counts.sdf_skipped;
      std::cout << "not compared with libsdformat: " << row.file << ": "
                << (!errors.empty()         ? errors.front().Message()
                    : read.findings.empty() ? "no model"
                                            : "massprops: " + read.findings.front().message)
                << "\n";
      continue;
    }
    ++counts.sdf_files;
    CompareWithSdformat(row.file, *root.Model(), merged, gimbal, &counts, &agreeing);
  }
  std::cout << "merge-fixed --target gazebo: " << counts.files
            << " corpus URDFs with fixed joints; " << counts.bodies
            << " bodies with mass agree with the long-double composition (1e-12), " << counts.lumped
            << " links lumped; " << counts.sdf_links << " links of " << counts.sdf_files
            << " files compared with libsdformat 12 (1e-6; " << counts.gimbal
            << " near gimbal lock within 1e-5), " << counts.sdf_skipped
            << " files libsdformat or massprops does not load cleanly\n";
  EXPECT_GT(counts.files, 100);
  EXPECT_GT(counts.sdf_links, 500);
  // The file lumping_sdformat_test.cc lists as an exception (disableFixedJointLumping) agrees.
  const std::string disabled = "sdformat/test/integration/fixed_joint_reduction_disabled.urdf";
  for (const char* link : {"link1a", "link2a"}) {
    EXPECT_EQ(agreeing.count(disabled + "|" + link), 1u) << disabled << " " << link;
  }
}

}  // namespace
}  // namespace massprops
