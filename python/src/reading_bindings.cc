// Python bindings of reading (massprops.read, read_all; Model, Link, Joint, Inertial, Geometry,
// Pose, SourceLocation, CompositeInertia, WeldedGroup; massprops.ReadError). Files are read as the
// `massprops` tool reads them. Stubs: the "reading" section of python/massprops/__init__.pyi.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "file_bindings.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/config.h"
#include "massprops/analysis/finding_sources.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/analysis/mass_repair.h"
#include "massprops/analysis/mass_report.h"
#include "massprops/analysis/materials.h"
#include "massprops/analysis/repair.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/core/rotational_inertia.h"
#include "massprops/core/spatial_inertia.h"
#include "massprops/io/model_reader.h"
#include "massprops/io/xacro_trace.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/model/model.h"
#include "massprops/output/report_format.h"
#include "massprops/output/reporters.h"
#include "massprops/output/xml_patch.h"

namespace py = pybind11;

namespace massprops::python {

// massprops.SourceLocation: where an element was read from.
void BindSourceLocation(py::module_& m) {
  py::class_<SourceLocation>(m, "SourceLocation",
                             "Where an element was read from: file, line and column (1-based; "
                             "0 when unknown).")
      .def_readonly("file", &SourceLocation::file, "The path as given (or '<string>').")
      .def_readonly("line", &SourceLocation::line, "1-based line; 0 when unknown.")
      .def_readonly("column", &SourceLocation::column, "1-based column; 0 when unknown.")
      .def("__repr__",
           [](const SourceLocation& l) {
             return "SourceLocation(" + Quote(l.file) + ", line=" + std::to_string(l.line) +
                    ", column=" + std::to_string(l.column) + ")";
           })
      .def("__str__", [](const SourceLocation& l) {
        return l.file + (l.line > 0 ? ":" + std::to_string(l.line) : "");
      });
}

// massprops.Pose: a rigid pose X_AB.
void BindPose(py::module_& m) {
  py::class_<Pose>(m, "Pose",
                   "A rigid pose X_AB: p_AB (position of B's origin from A's, in A) and R_AB "
                   "(rotation re-expressing vectors from B in A).")
      .def_readonly("p_AB", &Pose::p_AB, "The position, a numpy 3-vector.")
      .def_readonly("R_AB", &Pose::R_AB, "The rotation matrix, a numpy 3x3 array.")
      .def("inverse", &Pose::Inverse, "X_BA.")
      .def("is_identity", &Pose::IsIdentity, "True iff exactly the identity.")
      .def("__mul__", &Pose::operator*, py::is_operator(), "X_AC = X_AB * X_BC.")
      .def("__repr__", [](const Pose& X) {
        std::ostringstream out;
        out.precision(17);
        out << "Pose(p_AB=[" << X.p_AB(0) << ", " << X.p_AB(1) << ", " << X.p_AB(2) << "], R_AB=[["
            << X.R_AB(0, 0) << ", " << X.R_AB(0, 1) << ", " << X.R_AB(0, 2) << "], ["
            << X.R_AB(1, 0) << ", " << X.R_AB(1, 1) << ", " << X.R_AB(1, 2) << "], ["
            << X.R_AB(2, 0) << ", " << X.R_AB(2, 1) << ", " << X.R_AB(2, 2) << "]])";
        return out.str();
      });
}

// massprops.Inertial: an <inertial> exactly as written.
void BindInertial(py::module_& m) {
  py::class_<Inertial>(m, "Inertial",
                       "An <inertial> exactly as written: mass, the pose X_BBi of the inertial "
                       "frame in the link frame, and the six numbers about the center of mass "
                       "in Bi (ixy = -∫xy dm, as URDF and SDF write them).")
      .def_readonly("mass", &Inertial::mass, "The <mass> (kg) as written.")
      .def_readonly("X_BBi", &Inertial::X_BBi, "URDF <origin> / SDF <pose> of the inertial.")
      .def_readonly("ixx", &Inertial::ixx,
                    "<inertia ixx> as written (kg·m², about the center of mass, in Bi).")
      .def_readonly("iyy", &Inertial::iyy,
                    "<inertia iyy> as written (kg·m², about the center of mass, in Bi).")
      .def_readonly("izz", &Inertial::izz,
                    "<inertia izz> as written (kg·m², about the center of mass, in Bi).")
      .def_readonly("ixy", &Inertial::ixy,
                    "<inertia ixy> as written (kg·m², about the center of mass, in Bi).")
      .def_readonly("ixz", &Inertial::ixz,
                    "<inertia ixz> as written (kg·m², about the center of mass, in Bi).")
      .def_readonly("iyz", &Inertial::iyz,
                    "<inertia iyz> as written (kg·m², about the center of mass, in Bi).")
      .def_property_readonly("inertia", &InertiaAsWritten,
                             "The 3x3 inertia matrix as written (about the center of mass, in "
                             "Bi).")
      .def_readonly("location", &Inertial::location, "The <inertial> element.")
      .def_readonly("mass_location", &Inertial::mass_location, "The <mass> element.")
      .def_readonly("inertia_location", &Inertial::inertia_location, "The <inertia> element.")
      .def_readonly("pose_location", &Inertial::pose_location, "The <origin>/<pose> element.")
      .def("__repr__", [](const Inertial& in) {
        return "Inertial(mass=" + Repr(in.mass) + ", ixx=" + Repr(in.ixx) +
               ", iyy=" + Repr(in.iyy) + ", izz=" + Repr(in.izz) + ", ixy=" + Repr(in.ixy) +
               ", ixz=" + Repr(in.ixz) + ", iyz=" + Repr(in.iyz) +
               ", line=" + std::to_string(in.location.line) + ")";
      });
}

// massprops.Geometry: a collision or visual geometry of a link.
void BindGeometry(py::module_& m) {
  py::class_<Geometry>(m, "Geometry", "A collision or visual geometry of a link.")
      .def_property_readonly(
          "type", [](const Geometry& g) { return GeometryTypeName(g.type); },
          "'box', 'cylinder', 'sphere', 'capsule', 'ellipsoid', 'mesh' or 'other'.")
      .def_readonly("size", &Geometry::size, "box: full lengths along x, y, z.")
      .def_readonly("radius", &Geometry::radius, "cylinder, sphere, capsule.")
      .def_readonly("length", &Geometry::length, "cylinder, capsule (cylindrical part).")
      .def_readonly("radii", &Geometry::radii, "ellipsoid: semi-axes.")
      .def_readonly("uri", &Geometry::uri, "mesh: the filename/uri as written.")
      .def_readonly("scale", &Geometry::scale, "mesh: the scale.")
      .def_readonly("submesh", &Geometry::submesh,
                    "mesh: the SDF <submesh> name, the one part of the file used ('': all).")
      .def_readonly("center_submesh", &Geometry::center_submesh,
                    "mesh: the SDF <submesh><center> flag (that part recentred).")
      .def_readonly("X_BG", &Geometry::X_BG, "Pose of the geometry in the link frame.")
      .def_readonly("is_collision", &Geometry::is_collision, "False for <visual>.")
      .def_readonly("location", &Geometry::location, "The <collision>/<visual> element.")
      .def("__repr__", [](const Geometry& g) {
        return "Geometry(type=" + Quote(GeometryTypeName(g.type)) +
               (g.is_collision ? ", collision" : ", visual") +
               ", line=" + std::to_string(g.location.line) + ")";
      });
}

// massprops.Link: a link, its inertial as written and as core inertias, its geometries.
void BindLink(py::module_& m) {
  py::class_<Link>(m, "Link",
                   "A link: its name, its <inertial> (or None), geometries and source line.\n\n"
                   ">>> link = massprops.read('robot.urdf').link('arm')\n"
                   ">>> link.mass, link.com, link.inertia")
      .def_readonly("name", &Link::name, "The link's name (SDF: scoped, 'inner::link').")
      .def_readonly("inertial", &Link::inertial, "The Inertial as written, or None.")
      .def_property_readonly(
          "mass",
          [](const Link& l) -> std::optional<double> {
            if (!l.inertial) return std::nullopt;
            return l.inertial->mass;
          },
          "The mass (kg) as written, or None without <inertial>.")
      .def_property_readonly(
          "com",
          [](const Link& l) -> std::optional<Eigen::Vector3d> {
            if (!l.inertial) return std::nullopt;
            return l.inertial->X_BBi.p_AB;
          },
          "The center of mass p_BoBcm_B in the link frame (numpy 3-vector), or None.")
      .def_property_readonly(
          "inertia",
          [](const Link& l) -> std::optional<Eigen::Matrix3d> {
            if (!l.inertial) return std::nullopt;
            return CentralInertiaInLinkFrame(*l.inertial);
          },
          "The inertia about the center of mass expressed in the link frame B "
          "(R_BBi·I·R_BBiᵀ, numpy 3x3), or None.")
      .def(
          "rotational_inertia",
          [](const Link& l) -> std::optional<RotationalInertia<double>> {
            if (!l.inertial) return std::nullopt;
            return Unchecked(CentralInertiaInLinkFrame(*l.inertial));
          },
          "The central inertia in B as a RotationalInertia (not checked: call "
          "could_be_physically_valid()), or None.")
      .def(
          "spatial_inertia",
          [](const Link& l) -> std::optional<SpatialInertia<double>> {
            if (!l.inertial) return std::nullopt;
            return SpatialInertiaAboutLinkOrigin(*l.inertial);
          },
          "The SpatialInertia about the link origin Bo, expressed in B (not checked: call "
          "is_physically_valid()), or None.")
      .def_property_readonly(
          "geometries",
          [](py::object self) { return ReferenceList(self, self.cast<const Link&>().geometries); },
          "Collisions and visuals, in file order.")
      .def_readonly("ignored_rules", &Link::ignored_rules,
                    "Rules disabled by a `<!-- massprops: ignore ... -->` comment.")
      .def_readonly("inertial_unreadable", &Link::inertial_unreadable,
                    "True when the <inertial> could not be read.")
      .def_readonly("location", &Link::location, "The <link> element.")
      .def_property_readonly(
          "line", [](const Link& l) { return l.location.line; }, "Line of the <link> element.")
      .def("__repr__", [](const Link& l) {
        std::string text = "Link(" + Quote(l.name);
        if (l.inertial) text += ", mass=" + Repr(l.inertial->mass);
        return text + ", line=" + std::to_string(l.location.line) + ")";
      });
}

// massprops.Joint: a joint of the model.
void BindJoint(py::module_& m) {
  py::class_<Joint>(m, "Joint", "A joint: name, type, parent and child links, origin, axis.")
      .def_readonly("name", &Joint::name, "The joint's name.")
      .def_readonly("type", &Joint::type_name, "As written: 'revolute', 'fixed', ...")
      .def_readonly("parent", &Joint::parent, "Parent link name ('world' for SDF world joints).")
      .def_readonly("child", &Joint::child, "Child link name.")
      .def_readonly("X_PC", &Joint::X_PC, "Child frame in the parent frame at joint value 0.")
      .def_readonly("axis", &Joint::axis, "Unit axis in the child frame.")
      .def_readonly("location", &Joint::location, "The <joint> element.")
      .def("__repr__", [](const Joint& j) {
        return "Joint(" + Quote(j.name) + ", " + Quote(j.type_name) +
               ", parent=" + Quote(j.parent) + ", child=" + Quote(j.child) + ")";
      });
}

// massprops.CompositeInertia: the composite of several links in the frame of a link.
void BindCompositeInertia(py::module_& m) {
  py::class_<Composite>(m, "CompositeInertia",
                        "The composite mass properties of several links (a welded group or "
                        "the whole model) in the frame of a link.")
      .def_readonly("frame", &Composite::frame, "The link whose frame F expresses the numbers.")
      .def_property_readonly(
          "mass", [](const Composite& c) { return c.inertia.mass; }, "Total mass (kg).")
      .def_property_readonly(
          "com", [](const Composite& c) { return c.inertia.p_RoScm_R; },
          "The composite center of mass from F's origin, in F.")
      .def_property_readonly(
          "inertia_about_com", [](const Composite& c) { return c.inertia.I_SScm_R; },
          "The composite inertia about its center of mass, in F (3x3).")
      .def(
          "calc_inertia_about_origin",
          [](const Composite& c) { return c.inertia.CalcInertiaAboutOrigin(); },
          "The inertia about F's origin, in F.")
      .def(
          "rotational_inertia", [](const Composite& c) { return Unchecked(c.inertia.I_SScm_R); },
          "The central inertia as a RotationalInertia (not checked).")
      .def_readonly("unreachable_links", &Composite::unreachable_links,
                    "Links left out (not reachable from the root through joints).")
      .def("__repr__", [](const Composite& c) {
        return "CompositeInertia(frame=" + Quote(c.frame) + ", mass=" + Repr(c.inertia.mass) +
               ", com=[" + Repr(c.inertia.p_RoScm_R(0)) + ", " + Repr(c.inertia.p_RoScm_R(1)) +
               ", " + Repr(c.inertia.p_RoScm_R(2)) + "])";
      });
}

// massprops.WeldedGroup: links joined by fixed joints, with their composite.
void BindWeldedGroup(py::module_& m) {
  py::class_<PyWeldedGroup>(m, "WeldedGroup",
                            "Links joined by fixed joints (one rigid body), with their "
                            "composite in the root link's frame.")
      .def_readonly("root_link", &PyWeldedGroup::root_link, "The member nearest the model root.")
      .def_readonly("links", &PyWeldedGroup::links, "Names, root first.")
      .def_readonly("link_indices", &PyWeldedGroup::link_indices, "Indices into Model.links.")
      .def_readonly("X_RL", &PyWeldedGroup::X_RL, "Pose of each member in the root frame.")
      .def_readonly("parent_joint", &PyWeldedGroup::parent_joint,
                    "The non-fixed joint attaching the group, or None.")
      .def_readonly("is_moving", &PyWeldedGroup::is_moving,
                    "True when the group can move relative to its parent.")
      .def_readonly("composite", &PyWeldedGroup::composite,
                    "The group's CompositeInertia in the root link's frame.")
      .def("__repr__", [](const PyWeldedGroup& g) {
        return "WeldedGroup(root_link=" + Quote(g.root_link) + ", " +
               std::to_string(g.links.size()) + " links, mass=" + Repr(g.composite.inertia.mass) +
               ")";
      });
}

// massprops.Model: links, joints, welded groups and composite of a model.
void BindModel(py::module_& m) {
  py::class_<Model>(m, "Model",
                    "A robot model read from a URDF or SDF file: links, joints, root link.\n\n"
                    ">>> model = massprops.read('robot.urdf')\n"
                    ">>> [link.name for link in model.links]")
      .def_readonly("name", &Model::name, "The <robot>/<model> name.")
      .def_property_readonly(
          "format", [](const Model& model) { return FormatName(model.format); }, "'urdf' or 'sdf'.")
      .def_readonly("file", &Model::file, "The path as given ('<string>' for text).")
      .def_property_readonly(
          "links",
          [](py::object self) { return ReferenceList(self, self.cast<const Model&>().links); },
          "The links, in file order.")
      .def_property_readonly(
          "joints",
          [](py::object self) { return ReferenceList(self, self.cast<const Model&>().joints); },
          "The joints, in file order.")
      .def_readonly("root_link", &Model::root_link, "The link that is no joint's child.")
      .def_readonly("location", &Model::location, "The <robot>/<model> element.")
      .def_readonly("is_static", &Model::is_static, "SDF <static>true</static>.")
      .def("find_link", &Model::FindLink, py::arg("name"), "Index of the link, or -1.")
      .def(
          "link",
          [](py::object self, const std::string& name) {
            const Model& model = self.cast<const Model&>();
            const int index = model.FindLink(name);
            if (index < 0) throw py::key_error("the model has no link '" + name + "'");
            return py::cast(&model.links[static_cast<std::size_t>(index)],
                            py::return_value_policy::reference_internal, self);
          },
          py::arg("name"), "The link of that name (KeyError if none).")
      .def(
          "welded_groups", [](const Model& model) { return WeldedGroupsOf(model); },
          "The welded groups (links joined by fixed joints), each with its composite.")
      .def(
          "composite",
          [](const Model& model) {
            const ModelCompositeInertia c = CalcModelCompositeInertia(model);
            Composite result{model.root_link, c.inertia, {}};
            for (int i : c.unreachable_links) {
              result.unreachable_links.push_back(model.links[static_cast<std::size_t>(i)].name);
            }
            return result;
          },
          "The whole model's composite at the zero configuration, in the root link's frame.")
      .def("__repr__", [](const Model& model) {
        return "Model(" + Quote(model.name) + ", format=" + Quote(FormatName(model.format)) + ", " +
               std::to_string(model.links.size()) + " links, " +
               std::to_string(model.joints.size()) + " joints)";
      });
}

// The classes of a read model, in the order their names appear in later signatures.
void BindModelClasses(py::module_& m) {
  BindSourceLocation(m);
  BindPose(m);
  BindInertial(m);
  BindGeometry(m);
  BindLink(m);
  BindJoint(m);
  BindCompositeInertia(m);
  BindWeldedGroup(m);
  BindModel(m);
}

void BindReading(py::module_& m) {
  g_read_error = PyErr_NewExceptionWithDoc(
      "massprops.ReadError",
      "A model file could not be read or parsed. Attributes: file, line, column, element, "
      "message (of the first error) and errors (every error as 'file:line:col: element: "
      "message').",
      PyExc_Exception, nullptr);
  if (g_read_error == nullptr) throw py::error_already_set();
  m.add_object("ReadError", py::handle(g_read_error));

  BindModelClasses(m);

  m.def(
      "read",
      [](const py::handle& path_or_text, const std::vector<std::string>& model_paths) {
        return ReadModels(ToSource(path_or_text, "read"), model_paths).front();
      },
      py::arg("path_or_text"), py::kw_only(), py::arg("model_paths") = std::vector<std::string>(),
      R"doc(Reads a URDF or SDF model (format detected by content) and returns its Model.

path_or_text: a path (str or os.PathLike), or the model's text (a str starting with '<', or
bytes). model_paths: folders searched for SDF model:// includes. A world with several models:
the first (read_all returns every one). Raises massprops.ReadError (with file and line) when the
file cannot be read or parsed.

>>> model = massprops.read('robot.urdf')
>>> model.link('arm').mass
)doc");
  m.def(
      "read_all",
      [](const py::handle& path_or_text, const std::vector<std::string>& model_paths) {
        return ReadModels(ToSource(path_or_text, "read_all"), model_paths);
      },
      py::arg("path_or_text"), py::kw_only(), py::arg("model_paths") = std::vector<std::string>(),
      "As read(), every model of the file (an SDF world may hold several).");
}

}  // namespace massprops::python
