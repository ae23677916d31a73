#!/usr/bin/env python3
"""Tests of tools/label_evidence.py (python3 standard library only; run by ctest).

Every expected value is worked out by hand in the comment next to it."""
import math
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import label_evidence as L  # noqa: E402

TESTDATA = os.path.join(ROOT, "testdata")
FIXTURE = "labels/evidence_fixture.urdf"


class SymEigenvaluesTest(unittest.TestCase):
    def test_equal_products_matrix_has_the_hand_derived_moments(self):
        # docs/rules.md's products-sign-suspect example: 0.0055*identity + 0.0045*ones; the ones
        # matrix has eigenvalues 3, 0, 0, so 0.0055 (twice) and 0.0055 + 3*0.0045 = 0.019.
        ev = L.sym_eigenvalues([[0.01, 0.0045, 0.0045], [0.0045, 0.01, 0.0045], [0.0045, 0.0045, 0.01]])
        for got, want in zip(ev, [0.0055, 0.0055, 0.019]):
            self.assertAlmostEqual(got, want, places=12)

    def test_rotated_diagonal_keeps_its_moments(self):
        # R diag(1, 2, 3) R^T with R = Rz(30 deg): a similarity transform keeps 1, 2, 3.
        r = L.rpy_to_r(0, 0, math.radians(30))
        i = L.mat_mul(L.mat_mul(r, [[1, 0, 0], [0, 2, 0], [0, 0, 3]]), L.transpose(r))
        self.assertNotEqual(i[0][1], 0.0)
        for got, want in zip(L.sym_eigenvalues(i), [1.0, 2.0, 3.0]):
            self.assertAlmostEqual(got, want, places=12)


class TolerantParsingTest(unittest.TestCase):
    def test_files_that_real_readers_accept_are_read(self):
        # A comment before the XML declaration (gazebo_models/mpl_right_arm), bytes after the
        # root (pybullet_data/humanoid), an undeclared drake: prefix (drake-models/iiwa7), a
        # default namespace on the root (bullet3/data/Quadrotor).
        for text in (b"<!-- c -->\n<?xml version='1.0'?><robot name='r'><link name='a'/></robot>",
                     b"<robot name='r'><link name='a'/></robot>\n\x01junk",
                     b"<sdf version='1.7'><model name='m'><link name='a'><drake:x/></link></model></sdf>",
                     b"<robot xmlns='http://drake.mit.edu' name='r'><link name='a'/></robot>"):
            root = L.parse_model_xml(text)
            self.assertIn(root.tag, ("robot", "sdf"))
            self.assertEqual([e.get("name") for e in root.iter("link")], ["a"])

    def test_garbage_is_a_parse_error(self):
        with self.assertRaises(L.ET.ParseError):
            L.parse_model_xml(b"solid box\n facet normal 0 0 1")

    def test_an_undeclared_world_root_still_places_the_links(self):
        # drake-models' pr2_simplified.urdf: the only root is <parent link="world"/>, never
        # declared as a <link>. Placing the tree from it: a at (1, 0, 0); b at a's pose composed
        # with (0, 0.5, 0) after a's yaw of 90 deg, i.e. (1, 0, 0) + Rz(90)(0, 0.5, 0) = (0.5, 0, 0).
        text = (b"<robot name='r'><link name='a'/><link name='b'/>"
                b"<joint name='w' type='fixed'><parent link='world'/><child link='a'/>"
                b"<origin xyz='1 0 0' rpy='0 0 1.5707963267948966'/></joint>"
                b"<joint name='j' type='revolute'><parent link='a'/><child link='b'/>"
                b"<origin xyz='0 0.5 0'/></joint></robot>")
        model = L.parse_urdf(L.parse_model_xml(text), "r.urdf", TESTDATA)
        for got, want in zip(model.links["a"].pose[1], [1.0, 0.0, 0.0]):
            self.assertAlmostEqual(got, want, places=12)
        for got, want in zip(model.links["b"].pose[1], [0.5, 0.0, 0.0]):
            self.assertAlmostEqual(got, want, places=12)


class FixtureTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.model, err = L.load_model(os.path.join(TESTDATA, FIXTURE), TESTDATA)
        assert cls.model is not None, err

    def test_mesh_bounding_boxes_are_read_and_scaled(self):
        geoms = self.model.links["base"].geoms
        # box_binary.stl spans (0,0,0)-(0.1,0.2,0.3) (float32); scale 2 along x: 0.2 x 0.2 x 0.3.
        lo, hi = geoms[0].mesh_box
        for got, want in zip([hi[i] - lo[i] for i in range(3)], [0.2, 0.2, 0.3]):
            self.assertAlmostEqual(got, want, places=6)
        # tet_cm.dae: legs 10, 20, 30 in units of 0.01 m (its node's 5 cm shift is ignored, as
        # documented): 0.1 x 0.2 x 0.3 m from the origin.
        lo, hi = geoms[1].mesh_box
        for got, want in zip(lo + hi, [0, 0, 0, 0.1, 0.2, 0.3]):
            self.assertAlmostEqual(got, want, places=9)
        # cube_quads.obj: side 2 centered at the origin, scale 0.01: +-0.01.
        lo, hi = geoms[2].mesh_box
        for got, want in zip(lo + hi, [-0.01] * 3 + [0.01] * 3):
            self.assertAlmostEqual(got, want, places=12)
        # A package outside the corpus is reported, not guessed.
        self.assertIsNone(geoms[3].mesh_box)
        self.assertIn("not in the corpus", geoms[3].mesh_note)

    def test_welded_group_mass_com_and_share(self):
        arm = self.model.links["arm"]
        group = L.welded_group(self.model, "arm")
        self.assertEqual(sorted(group), ["arm", "tool"])
        mass, com, trace, own = L.group_inertia(self.model, arm, group)
        # 2 + 0.5 kg; COM z = (2*0.2 + 0.5*0.4)/2.5 = 0.24.
        self.assertAlmostEqual(mass, 2.5, places=12)
        self.assertAlmostEqual(com[2], 0.24, places=12)
        # Arm trace 2*0.028333 + 0.003333 = 0.06, tool 0.0015; parallel-axis terms 2*m*d^2:
        # 2*2*0.04^2 = 0.0064 and 2*0.5*0.16^2 = 0.0256: 0.0935 in all, the arm's own 0.06.
        self.assertAlmostEqual(trace, 0.0935, places=9)
        self.assertAlmostEqual(own, 0.06, places=9)

    def test_moment_about_the_parent_joint_axis(self):
        # Shoulder axis y through the arm's origin. Arm: Iyy_cm + m d^2 = 0.028333 + 2*0.2^2 =
        # 0.108333; tool: 0.0005 + 0.5*0.4^2 = 0.0805; group 0.188833 kg m^2.
        arm = self.model.links["arm"]
        own = L.moment_about_axis([L.central_in(arm, L.POSE_ID)], [0, 0, 0], [0, 1, 0])
        self.assertAlmostEqual(own, 0.028333333333333333 + 0.08, places=12)
        x_la = L.inverse(arm.pose)
        parts = [L.central_in(self.model.links[n], L.compose(x_la, self.model.links[n].pose))
                 for n in ("arm", "tool")]
        self.assertAlmostEqual(L.moment_about_axis(parts, [0, 0, 0], [0, 1, 0]), 0.188833333333333333, places=12)

    def test_body_box_spans_geometry_child_joints_and_the_welded_group(self):
        # arm (link frame): its box (-0.05,-0.05,0)-(0.05,0.05,0.4), the child joint at z 0.4 and
        # the welded tool sphere r 0.05 there: (-0.05,-0.05,0)-(0.05,0.05,0.45), R =
        # sqrt(0.1^2+0.1^2+0.45^2)/2 = 0.2358495, center o z 0.225. tr/2 + m|c-o|^2 = 0.03 +
        # 2*0.025^2 = 0.03125 over m R^2 = 2*0.055625 = 0.11125: 0.280899.
        box, line = L.body_box(self.model, self.model.links["arm"])
        for got, want in zip(box[0] + box[1], [-0.05, -0.05, 0, 0.05, 0.05, 0.45]):
            self.assertAlmostEqual(got, want, places=12)
        self.assertIn("half-diagonal 0.2358 m", line)
        self.assertIn("tr/2 + m|c-o|^2 = 0.2809 m R^2; COM inside", line)
        # tool (its frame at the arm's z 0.4): the same box shifted by -0.4, o z -0.175;
        # 0.0015/2 + 0.5*0.175^2 = 0.0160625 over 0.5*0.055625 = 0.0278125: 0.577528.
        box, line = L.body_box(self.model, self.model.links["tool"])
        self.assertAlmostEqual(box[0][2], -0.4, places=12)
        self.assertAlmostEqual(box[1][2], 0.05, places=12)
        self.assertIn("tr/2 + m|c-o|^2 = 0.5775 m R^2", line)


class SdfAxisTest(unittest.TestCase):
    def axis_of(self, flag):
        # Child link c pitched +90 deg about y: its z axis is the model's x axis. The axis
        # xyz 1 0 0 is in the model frame with use_parent_model_frame true (SDFormat writes a
        # boolean as true or 1): (1, 0, 0) in the model; without it, it is in the joint frame =
        # the child's frame: Ry(90 deg)(1, 0, 0) = (0, 0, -1) in the model.
        use = f"<use_parent_model_frame>{flag}</use_parent_model_frame>" if flag else ""
        text = ("<sdf version='1.6'><model name='m'><link name='p'/>"
                "<link name='c'><pose>0 0 0 0 1.5707963267948966 0</pose></link>"
                "<joint name='j' type='revolute'><parent>p</parent><child>c</child>"
                f"<axis><xyz>1 0 0</xyz>{use}</axis></joint></model></sdf>").encode()
        model = L.parse_sdf(L.parse_model_xml(text), "m.sdf", TESTDATA)
        return model.joints[0].axis

    def test_use_parent_model_frame_accepts_true_and_1(self):
        for flag, want in (("true", [1, 0, 0]), ("1", [1, 0, 0]), ("", [0, 0, -1]), ("0", [0, 0, -1])):
            for got, w in zip(self.axis_of(flag), want):
                self.assertAlmostEqual(got, w, places=9, msg=flag)


class CommandLineTest(unittest.TestCase):
    def run_rows(self, rows, *args):
        with tempfile.NamedTemporaryFile("w", suffix=".tsv", delete=False) as f:
            f.write("file\trule\tlink\tlabel\twhy\n" + "".join("\t".join(r) + "\n" for r in rows))
            name = f.name
        try:
            return subprocess.run([sys.executable, os.path.join(ROOT, "tools", "label_evidence.py"), name,
                                   "--corpus", TESTDATA] + list(args),
                                  capture_output=True, text=True, timeout=60, check=False)
        finally:
            os.unlink(name)

    def test_block_gives_k_and_the_solid_box_ratio(self):
        out = self.run_rows([(FIXTURE, "units-suspect", "arm", "real", "x")])
        self.assertEqual(out.returncode, 0, out.stderr)
        # k = sqrt(0.06 / (2*2)) = 0.12247; box half-diagonal sqrt(0.1^2+0.1^2+0.4^2)/2 = 0.21213;
        # for a solid box k/e = 1/sqrt(3) = 0.57735.
        self.assertIn("k = sqrt(tr/(2m)) = 0.1225 m", out.stdout)
        self.assertIn("half-diagonal 0.2121 m; COM inside; k/e = 0.5774", out.stdout)
        self.assertIn("child joint 'wrist_weld' fixed -> 'tool' at (0, 0, 0.4), distance 0.4 m", out.stdout)
        self.assertIn("moment of the welded group about that axis: 0.1888 kg m^2", out.stdout)

    def test_filters_and_bad_rows_do_not_crash(self):
        rows = [(FIXTURE, "units-suspect", "arm", "real", "x"),
                (FIXTURE, "products-sign-suspect", "tool", "real", "x"),
                ("no/such/file.urdf", "units-suspect", "a", "real", "x"),
                ("mesh/not_a_mesh.stl", "units-suspect", "a", "real", "x"),
                (FIXTURE, "units-suspect", "no_such_link", "real", "x")]
        out = self.run_rows(rows, "--rule", "units-suspect")
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertEqual(out.stdout.count("=== "), 4)  # the products-sign row is filtered out
        self.assertEqual(out.stdout.count("\n  not read: "), 2)  # the missing file, the STL
        self.assertIn("link 'no_such_link' not found", out.stdout)
        brief = self.run_rows(rows, "--link", "tool", "--brief")
        self.assertIn("[tool] m 0.5; I diag (0.0005, 0.0005, 0.0005)", brief.stdout)


if __name__ == "__main__":
    unittest.main()
