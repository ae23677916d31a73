// The mass repairs asked for by name (mass_repair.h): fix --total-mass, --mass, --density,
// --material, on testdata/mass/arm.urdf, with values worked out by hand in the comments.
#include "massprops/analysis/mass_repair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/analysis/materials.h"
#include "massprops/io/model_reader.h"
#include "massprops/mesh/mesh_loader.h"

namespace massprops {
namespace {

const std::string kArm = std::string(MASSPROPS_TESTDATA_DIR) + "/mass/arm.urdf";

Model ReadArm() {
  ReadResult read = ReadModelFile(kArm);
  EXPECT_TRUE(read.ok());
  return read.models.at(0);
}

const Repair* RepairOf(const std::vector<Repair>& repairs, const std::string& link) {
  for (const Repair& r : repairs) {
    if (r.link == link) return &r;
  }
  return nullptr;
}

// Every inertia entry and the mass of `after` are k times those of `before`; the center of mass
// and the frame are unchanged.
void ExpectScaled(const Inertial& before, const Inertial& after, double k) {
  EXPECT_DOUBLE_EQ(after.mass, k * before.mass);
  EXPECT_DOUBLE_EQ(after.ixx, k * before.ixx);
  EXPECT_DOUBLE_EQ(after.iyy, k * before.iyy);
  EXPECT_DOUBLE_EQ(after.izz, k * before.izz);
  EXPECT_DOUBLE_EQ(after.ixy, k * before.ixy);
  EXPECT_DOUBLE_EQ(after.ixz, k * before.ixz);
  EXPECT_DOUBLE_EQ(after.iyz, k * before.iyz);
  EXPECT_EQ(after.X_BBi.p_AB, before.X_BBi.p_AB);
  EXPECT_EQ(after.X_BBi.R_AB, before.X_BBi.R_AB);
}

TEST(MassRepairTest, TotalMassScalesEveryLinkByOneFactorProductsToo) {
  const Model model = ReadArm();
  MassRepairOptions options;
  options.total_mass = 12;  // the masses 1 + 2 + 3 = 6 kg: k = 12 / 6 = 2 (hand-derived)
  std::vector<Repair> repairs;
  std::string error;
  ASSERT_TRUE(PlanMassRepairs(model, options, &repairs, &error)) << error;
  ASSERT_EQ(repairs.size(), 3u);
  for (const Link& link : model.links) {
    const Repair* r = RepairOf(repairs, link.name);
    ASSERT_NE(r, nullptr) << link.name;
    EXPECT_EQ(r->rule, "--total-mass");
    ExpectScaled(*link.inertial, r->after, 2);
  }
  // base: ixy 0.001 -> 0.002, ixz -0.002 -> -0.004, iyz 0.003 -> 0.006 (the products as written).
  const Repair* base = RepairOf(repairs, "base");
  EXPECT_DOUBLE_EQ(base->after.ixy, 0.002);
  EXPECT_DOUBLE_EQ(base->after.ixz, -0.004);
  EXPECT_DOUBLE_EQ(base->after.iyz, 0.006);
}

TEST(MassRepairTest, MassOfOneLinkWithTotalMassGivesTheOthersOneCommonFactor) {
  const Model model = ReadArm();
  MassRepairOptions options;
  // tool weighs 6 kg (was 3: its inertia x 2); the robot 10.5 kg: base and upper share
  // 10.5 - 6 = 4.5 kg, they weighed 1 + 2 = 3 kg, so k = 4.5 / 3 = 1.5 (hand-derived).
  options.link_masses = {{"tool", 6}};
  options.total_mass = 10.5;
  std::vector<Repair> repairs;
  std::string error;
  ASSERT_TRUE(PlanMassRepairs(model, options, &repairs, &error)) << error;
  ASSERT_EQ(repairs.size(), 3u);
  ExpectScaled(*model.links[model.FindLink("tool")].inertial, RepairOf(repairs, "tool")->after, 2);
  EXPECT_EQ(RepairOf(repairs, "tool")->rule, "--mass");
  ExpectScaled(*model.links[model.FindLink("base")].inertial, RepairOf(repairs, "base")->after,
               1.5);
  ExpectScaled(*model.links[model.FindLink("upper")].inertial, RepairOf(repairs, "upper")->after,
               1.5);
  EXPECT_DOUBLE_EQ(RepairOf(repairs, "base")->after.mass, 1.5);
  EXPECT_DOUBLE_EQ(RepairOf(repairs, "upper")->after.izz, 0.09);  // 0.06 x 1.5
  double total = 0;
  for (const Repair& r : repairs) total += r.after.mass;
  EXPECT_DOUBLE_EQ(total, 10.5);
}

TEST(MassRepairTest, TotalAlreadyReachedChangesNothing) {
  const Model model = ReadArm();
  MassRepairOptions options;
  options.total_mass = 6;
  std::vector<Repair> repairs;
  std::string error;
  ASSERT_TRUE(PlanMassRepairs(model, options, &repairs, &error)) << error;
  EXPECT_TRUE(repairs.empty());
}

TEST(MassRepairTest, DensityGivesTheBoxMeshMassAndInertiaInTheInertialFrame) {
  const Model model = ReadArm();
  MeshCache cache;
  MeshResolveOptions resolve;
  resolve.model_file = kArm;
  resolve.use_environment = false;
  resolve.cache = &cache;
  MassRepairOptions options;
  options.closed_mesh = MakeClosedMeshShapeFunction(resolve);
  options.link_densities = {{"upper", FindMaterial("aluminium-6061")->density, "aluminium 6061"}};
  std::vector<Repair> repairs;
  std::string error;
  ASSERT_TRUE(PlanMassRepairs(model, options, &repairs, &error)) << error;
  ASSERT_EQ(repairs.size(), 1u);
  const Repair& r = repairs[0];
  EXPECT_EQ(r.rule, "--material");
  // Box a x b x c = 0.1 x 0.2 x 0.3 m, corner at the origin: V = 0.006 m³, m = 2700 V = 16.2 kg,
  // centroid (0.05, 0.1, 0.15); about it, in the link frame: Ixx = m(b² + c²)/12 = 0.1755,
  // Iyy = m(a² + c²)/12 = 0.135, Izz = m(a² + b²)/12 = 0.0675 (solid cuboid, closed form).
  // The inertial frame is turned 90° about z (x_Bi = y_B, y_Bi = -x_B): ixx = Iyy_B = 0.135,
  // iyy = Ixx_B = 0.1755, izz = 0.0675, no products. The STL's 32-bit floats leave ~1e-7.
  const double tol = 1e-6;
  EXPECT_NEAR(r.after.mass, 16.2, 16.2 * tol);
  EXPECT_NEAR(r.after.X_BBi.p_AB.x(), 0.05, tol);
  EXPECT_NEAR(r.after.X_BBi.p_AB.y(), 0.1, tol);
  EXPECT_NEAR(r.after.X_BBi.p_AB.z(), 0.15, tol);
  EXPECT_NEAR(r.after.ixx, 0.135, 0.135 * tol);
  EXPECT_NEAR(r.after.iyy, 0.1755, 0.1755 * tol);
  EXPECT_NEAR(r.after.izz, 0.0675, 0.0675 * tol);
  EXPECT_EQ(r.after.ixy, 0);
  EXPECT_EQ(r.after.ixz, 0);
  EXPECT_EQ(r.after.iyz, 0);
  // --density with --total-mass: upper is fixed at 16.2 kg; base and tool (1 + 3 = 4 kg) share
  // 24.2 - 16.2 = 8 kg: k = 2.
  options.total_mass = 16.2 + 8;
  ASSERT_TRUE(PlanMassRepairs(model, options, &repairs, &error)) << error;
  ASSERT_EQ(repairs.size(), 3u);
  EXPECT_NEAR(RepairOf(repairs, "base")->after.mass, 2, 2e-6);
  EXPECT_NEAR(RepairOf(repairs, "tool")->after.ixx, 0.006, 0.006 * 1e-6);
}

TEST(MassRepairTest, WrongRequestsAreRefusedWithTheReason) {
  const Model model = ReadArm();
  std::vector<Repair> repairs;
  std::string error;
  MassRepairOptions unknown;
  unknown.link_masses = {{"elbow", 1}};
  EXPECT_FALSE(PlanMassRepairs(model, unknown, &repairs, &error));
  EXPECT_NE(error.find("no link 'elbow'"), std::string::npos) << error;
  MassRepairOptions twice;
  twice.link_masses = {{"tool", 1}};
  twice.link_densities = {{"tool", 1000, ""}};
  EXPECT_FALSE(PlanMassRepairs(model, twice, &repairs, &error));
  EXPECT_NE(error.find("named twice"), std::string::npos) << error;
  MassRepairOptions too_light;  // tool alone weighs 5 kg, more than the 4 asked for
  too_light.link_masses = {{"tool", 5}};
  too_light.total_mass = 4;
  EXPECT_FALSE(PlanMassRepairs(model, too_light, &repairs, &error));
  EXPECT_NE(error.find("already weigh 5 kg"), std::string::npos) << error;
  MassRepairOptions no_mesh;  // base has no geometry
  no_mesh.link_densities = {{"base", 1000, ""}};
  EXPECT_FALSE(PlanMassRepairs(model, no_mesh, &repairs, &error));
  EXPECT_NE(error.find("no closed mesh"), std::string::npos) << error;
}

// A link with both a mass repair and an error repair gets one repair, from the file's numbers to
// the projected scaled inertia (the way massprops fix plans them: mass first, then the errors).
TEST(MassRepairTest, ChainedWithTheProjectionOfAnInvalidInertia) {
  const ReadResult read = ReadModelString(
      "<robot name='r'><link name='a'><inertial><mass value='1'/>"
      "<inertia ixx='0.1' iyy='0.2' izz='0.5' ixy='0' ixz='0' iyz='0'/></inertial></link>"
      "<link name='b'><inertial><mass value='1'/>"
      "<inertia ixx='0.1' iyy='0.1' izz='0.1' ixy='0' ixz='0' iyz='0'/></inertial></link>"
      "<joint name='j' type='revolute'><parent link='a'/><child link='b'/><axis xyz='0 0 1'/>"
      "<limit lower='-1' upper='1' effort='1' velocity='1'/></joint></robot>",
      "chain.urdf");
  ASSERT_TRUE(read.ok());
  const Model& model = read.models[0];
  MassRepairOptions options;
  options.total_mass = 4;  // 2 kg to 4 kg: k = 2
  std::vector<Repair> mass;
  std::string error;
  ASSERT_TRUE(PlanMassRepairs(model, options, &mass, &error)) << error;
  const Model scaled = ApplyRepairs(model, mass);
  const std::vector<Repair> errors = PlanRepairs(scaled, CheckModel(scaled));
  const std::vector<Repair> chained = ChainRepairs(model, mass, errors);
  ASSERT_EQ(chained.size(), 2u);
  const Repair& a = chained[0];
  EXPECT_EQ(a.link, "a");
  EXPECT_EQ(a.rule, "--total-mass");
  EXPECT_EQ(a.method, "scale+project");
  EXPECT_EQ(a.before->ixx, 0.1);  // from the file's numbers
  EXPECT_EQ(a.after.mass, 2);
  // diag(0.2, 0.4, 1.0) fails 0.2 + 0.4 >= 1.0 by 0.4: the nearest valid inertia moves each
  // moment by 0.4/3 along (1, 1, -1) (docs/fix.md): 0.333333, 0.533333, 0.866667.
  EXPECT_NEAR(a.after.ixx, 0.2 + 0.4 / 3, 1e-6);
  EXPECT_NEAR(a.after.iyy, 0.4 + 0.4 / 3, 1e-6);
  EXPECT_NEAR(a.after.izz, 1.0 - 0.4 / 3, 1e-6);
  EXPECT_EQ(chained[1].method, "scale");
  EXPECT_EQ(chained[1].after.ixx, 0.2);
}

TEST(MaterialsTest, TableHoldsTheCitedValuesAndOtherSpellings) {
  // The values of docs/fix.md's table, each from the source CommonMaterials() names.
  EXPECT_EQ(FindMaterial("aluminium-6061")->density, 2700);
  EXPECT_EQ(FindMaterial("Aluminum-6061")->density, 2700);
  EXPECT_EQ(FindMaterial("steel")->density, 7850);
  EXPECT_EQ(FindMaterial("PLA")->density, 1240);
  EXPECT_EQ(FindMaterial("abs")->density, 1040);
  EXPECT_EQ(FindMaterial("petg")->density, 1270);
  EXPECT_EQ(FindMaterial("nylon")->density, 1140);
  EXPECT_EQ(FindMaterial("cfrp")->density, 1570);
  EXPECT_EQ(FindMaterial("wood"), nullptr);
  for (const Material& m : CommonMaterials()) EXPECT_FALSE(m.source.empty()) << m.name;
}

}  // namespace
}  // namespace massprops
