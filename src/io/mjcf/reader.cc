// MJCF into a Model, with the mass properties of MuJoCo 2.2.2's compiler (mjCBody::Compile,
// GeomFrame in src/user/user_objects.cc; mj_setTotalmass for settotalmass): the order of the
// bodies, the inertial frame from the <inertial> or from the geoms, then the bounds and the
// balancing. What is and is not reproduced is listed in docs/mjcf.md.

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "io/mjcf/geom.h"
#include "io/mjcf/mujoco_numbers.h"
#include "io/mjcf/tree.h"
#include "massprops/io/mjcf_reader.h"

namespace massprops {
namespace {

using mjcf::Context;
using mjcf::Element;
using mjcf::kMjMinVal;
using mjcf::Node;

// A body's mass properties as the compiler holds them: mass, the inertial frame (center and
// principal axes) in the body frame, and the principal moments.
struct BodyMass {
  double mass = 0;
  Eigen::Vector3d p_BoBcm_B = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_BBi = Eigen::Quaterniond::Identity();
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();
};

Joint::Type JointType(const std::string& type) {
  if (type == "hinge") return Joint::Type::kRevolute;
  if (type == "slide") return Joint::Type::kPrismatic;
  if (type == "ball") return Joint::Type::kBall;
  if (type == "free") return Joint::Type::kFloating;
  return Joint::Type::kOther;
}

// The principal moments and axes of a symmetric tensor (axes a proper rotation).
void Principal(const Eigen::Matrix3d& I, Eigen::Vector3d* moments, Eigen::Quaterniond* q) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(I);
  *moments = eigen.eigenvalues();
  Eigen::Matrix3d V = eigen.eigenvectors();
  if (V.determinant() < 0) V.col(2) = -V.col(2);
  *q = Eigen::Quaterniond(V);
}

class Builder {
 public:
  Builder(Context* context, const mjcf::Document& document, const MjcfReadOptions& options,
          ReadResult* result)
      : c_(context),
        document_(document),
        meshes_(document.files[0], !options.mujoco_mesh_inertia ? mjcf::MeshMethod::kExact
                                   : context->compiler.exactmeshinertia
                                       ? mjcf::MeshMethod::kMujoco
                                       : mjcf::MeshMethod::kMujocoLegacy),
        result_(result) {}

  void Build(Model* model);

 private:
  void Body(const Node& node, const std::string& parent, const std::string& childclass,
            const Pose& X_WP, Model* model);
  void Contents(const Node& node, bool is_world, const std::string& childclass, const Pose& X_WB,
                Link* link, Joint* joint, Model* model);
  std::optional<BodyMass> Explicit(const Element& inertial, const std::string& what);
  std::optional<BodyMass> FromGeoms(const std::vector<mjcf::GeomReading>& geoms,
                                    std::string* error);
  void Finish(const Node& body, const std::optional<BodyMass>& explicit_mass,
              std::optional<BodyMass> mass, const Pose& X_PB, Link* link);
  bool IsInGroupRange(int group) const {
    return group >= c_->compiler.inertiagrouprange[0] && group <= c_->compiler.inertiagrouprange[1];
  }

  // What MuJoCo's compiler checks after compiling a body (mjCBody::Compile, mjCModel::TryCompile).
  struct Compiled {
    int link = 0;
    int parent = 0;
    bool moves = false;  ///< Has joints of its own.
    BodyMass mass;
  };
  void FindRefusals(const Model& model);

  std::vector<Compiled> compiled_;
  Context* c_;
  const mjcf::Document& document_;
  mjcf::MeshSolids meshes_;
  ReadResult* result_;
  int next_id_ = 1;
  std::string model_name_;
};

void Builder::Build(Model* model) {
  const std::string* name = document_.root.Find("model");
  model->name = name ? *name : "MuJoCo Model";
  model_name_ = model->name;
  model->format = Model::Format::kMjcf;
  model->file = document_.files[0];
  model->location = document_.Where(document_.root);
  model->root_link = "world";
  Link world;
  world.name = "world";
  bool seen = false;
  for (const Node& section : document_.root.children) {
    if (section.name != "worldbody") continue;
    if (!seen) world.location = document_.Where(section);
    seen = true;
  }
  if (!seen) world.location = model->location;
  model->links.push_back(world);
  for (const Node& section : document_.root.children) {
    if (section.name != "worldbody") continue;
    Contents(section, true, "", Pose(), nullptr, nullptr, model);
  }
  FindRefusals(*model);
  if (c_->compiler.settotalmass > 0) {
    double total = 0;
    for (const Link& link : model->links) total += link.inertial ? link.inertial->mass : 0;
    if (total > 0) {
      const double scale = c_->compiler.settotalmass / total;
      for (Link& link : model->links) {
        if (!link.inertial) continue;
        Inertial& i = *link.inertial;
        for (double* v : {&i.mass, &i.ixx, &i.iyy, &i.izz, &i.ixy, &i.ixz, &i.iyz}) *v *= scale;
      }
    }
  }
}

void Builder::Body(const Node& node, const std::string& parent, const std::string& inherited_class,
                   const Pose& X_WP, Model* model) {
  const int id = next_id_++;
  const std::string* own_class = node.Find("childclass");
  const std::string childclass = own_class ? *own_class : inherited_class;
  if (own_class && c_->classes.count(*own_class) == 0) {
    c_->Error(node, "<body>", "childclass '" + *own_class + "' is not a <default> class");
  }
  Link link;
  const std::string* name = node.Find("name");
  link.name = name ? *name : "(body " + std::to_string(id) + ")";
  link.location = document_.Where(node);
  const Element element{&node, nullptr, ""};
  Joint joint;
  joint.child = link.name;
  joint.parent = parent;
  joint.location = link.location;
  if (auto v = mjcf::Numbers(c_, element, "pos", 3, -1, "'" + link.name + "'")) {
    joint.X_PC.p_AB << (*v)[0], (*v)[1], (*v)[2];
  }
  joint.X_PC.R_AB = mjcf::Orientation(c_, element, "'" + link.name + "'").toRotationMatrix();
  // coordinate="global": the body's pos and orientation are in the world (mjCBody::MakeLocal).
  const Pose X_WB = c_->compiler.global ? joint.X_PC : X_WP * joint.X_PC;
  if (c_->compiler.global) joint.X_PC = X_WP.Inverse() * X_WB;
  const std::size_t index = model->links.size();
  model->links.push_back(link);
  model->joints.push_back(joint);
  const std::size_t joint_index = model->joints.size() - 1;
  Link body_link = link;
  Joint body_joint = joint;
  Contents(node, false, childclass, X_WB, &body_link, &body_joint, model);
  model->links[index] = std::move(body_link);
  model->joints[joint_index] = std::move(body_joint);
}

void Builder::Contents(const Node& node, bool is_world, const std::string& childclass,
                       const Pose& X_WB, Link* link, Joint* joint, Model* model) {
  // Under coordinate="global" geoms, inertials and joint axes are in the world: X_BW maps them.
  const Pose X_BW = c_->compiler.global ? X_WB.Inverse() : Pose();
  const Eigen::Quaterniond q_BW(X_BW.R_AB);
  const std::string parent = is_world ? "world" : link->name;
  const Node* inertial_node = nullptr;
  std::vector<std::string> joint_types;
  for (const Node& child : node.children) {
    if (child.name == "inertial") inertial_node = &child;
    if (child.name == "freejoint") joint_types.push_back("free");
    if (child.name != "joint") continue;
    const Element e = mjcf::MakeElement(*c_, child, childclass);
    const std::string* type = e.Get("type");
    joint_types.push_back(type ? *type : "hinge");
    if (joint_types.size() == 1 && joint != nullptr) {
      if (const std::string* n = child.Find("name")) joint->name = *n;
      if (auto v = mjcf::Numbers(c_, e, "axis", 3, -1, "axis")) {
        const Eigen::Vector3d axis((*v)[0], (*v)[1], (*v)[2]);
        if (axis.norm() > 0) joint->axis = (X_BW.R_AB * axis).normalized();
      } else {
        joint->axis = Eigen::Vector3d::UnitZ();
      }
    }
  }
  if (joint != nullptr) {
    if (joint_types.empty()) {
      joint->type = Joint::Type::kFixed;
      joint->type_name = "welded";
    } else {
      joint->type = joint_types.size() == 1 ? JointType(joint_types[0]) : Joint::Type::kOther;
      joint->type_name = joint_types[0];
      for (std::size_t i = 1; i < joint_types.size(); ++i) joint->type_name += "+" + joint_types[i];
    }
    if (joint->name.empty()) joint->name = link->name;
  }
  const int inertiafromgeom = c_->compiler.inertiafromgeom;
  const bool infer =
      !is_world && (inertiafromgeom == 1 || (inertiafromgeom == 2 && inertial_node == nullptr));
  std::vector<mjcf::GeomReading> geoms;
  Link* geometry_owner = is_world ? &model->links[0] : link;
  for (const Node& child : node.children) {
    if (child.name != "geom") continue;
    const Element e = mjcf::MakeElement(*c_, child, childclass);
    if (child.Find("class") && c_->classes.count(e.class_name) == 0) {
      c_->Error(child, "<geom>", "class '" + e.class_name + "' is not a <default> class");
    }
    mjcf::GeomReading geom = mjcf::ReadGeom(c_, e, infer, &meshes_);
    if (c_->compiler.global && !is_world) {
      geom.geometry.X_BG = X_BW * geom.geometry.X_BG;
      if (geom.mass) {
        geom.mass->p_BoGcm_B = X_BW.p_AB + X_BW.R_AB * geom.mass->p_BoGcm_B;
        geom.mass->q_BGi = q_BW * geom.mass->q_BGi;
      }
    }
    if (geom.visual_only && c_->compiler.discardvisual) continue;
    geometry_owner->geometries.push_back(geom.geometry);
    geoms.push_back(std::move(geom));
  }
  if (!is_world) {
    Compiled record;
    record.link = model->FindLink(link->name);
    record.parent = model->FindLink(joint->parent);
    record.moves = !joint_types.empty();
    compiled_.push_back(record);
    std::optional<BodyMass> explicit_mass;
    if (inertial_node != nullptr) {
      explicit_mass = Explicit(mjcf::MakeElement(*c_, *inertial_node, ""), "'" + link->name + "'");
      if (explicit_mass && c_->compiler.global) {
        explicit_mass->p_BoBcm_B = X_BW.p_AB + X_BW.R_AB * explicit_mass->p_BoBcm_B;
        explicit_mass->q_BBi = q_BW * explicit_mass->q_BBi;
      }
    }
    std::optional<BodyMass> mass = explicit_mass;
    if (infer) {
      std::string error;
      std::optional<BodyMass> derived = FromGeoms(geoms, &error);
      if (!error.empty()) {
        link->inertial_unreadable = true;
        ReadFinding f;
        f.rule = "inertial-unreadable";
        f.model = model_name_;
        f.link = link->name;
        f.location = link->location;
        f.message = "body '" + link->name + "': " + error +
                    "; its mass properties are unknown, so its welded group is not checked";
        f.help = "fix the mesh named, or give the body an explicit <inertial>";
        result_->findings.push_back(std::move(f));
        mass.reset();
        explicit_mass.reset();
      } else if (derived) {
        mass = derived;
      }
    }
    if (!link->inertial_unreadable) Finish(node, explicit_mass, mass, joint->X_PC, link);
  }
  for (const Node& child : node.children) {
    if (child.name == "body") Body(child, parent, childclass, X_WB, model);
    if (child.name == "composite" || child.name == "frame" || child.name == "replicate") {
      c_->Error(child, "<" + child.name + ">",
                "is not read by massprops (MuJoCo 2.2.2 model "
                "elements only; <composite> is not expanded)");
    }
  }
}

std::optional<BodyMass> Builder::Explicit(const Element& e, const std::string& what) {
  BodyMass m;
  const auto mass = mjcf::Numbers(c_, e, "mass", 1, -1, what);
  const auto pos = mjcf::Numbers(c_, e, "pos", 3, -1, what);
  if (!mass || !pos) {
    c_->Error(*e.node, "<inertial> of " + what, "needs mass and pos (MuJoCo requires both)");
    return std::nullopt;
  }
  m.mass = (*mass)[0];
  m.p_BoBcm_B << (*pos)[0], (*pos)[1], (*pos)[2];
  m.q_BBi = mjcf::Orientation(c_, e, what);
  if (auto full = mjcf::Numbers(c_, e, "fullinertia", 6, -1, what)) {
    const auto& f = *full;
    Eigen::Matrix3d I;
    I << f[0], f[3], f[4], f[3], f[1], f[5], f[4], f[5], f[2];
    Principal(I, &m.moments, &m.q_BBi);
  } else if (auto diag = mjcf::Numbers(c_, e, "diaginertia", 3, -1, what)) {
    m.moments << (*diag)[0], (*diag)[1], (*diag)[2];
  } else {
    c_->Error(*e.node, "<inertial> of " + what, "needs diaginertia or fullinertia");
    return std::nullopt;
  }
  return m;
}

std::optional<BodyMass> Builder::FromGeoms(const std::vector<mjcf::GeomReading>& geoms,
                                           std::string* error) {
  std::vector<const mjcf::GeomMass*> selected;
  for (const mjcf::GeomReading& geom : geoms) {
    if (!IsInGroupRange(geom.group)) continue;
    if (!geom.mass_error.empty()) {
      *error = geom.mass_error;
      return std::nullopt;
    }
    if (geom.mass) selected.push_back(&*geom.mass);
  }
  if (selected.empty()) return std::nullopt;
  BodyMass m;
  if (selected.size() == 1) {
    m.mass = selected[0]->mass;
    m.p_BoBcm_B = selected[0]->p_BoGcm_B;
    m.q_BBi = selected[0]->q_BGi;
    m.moments = selected[0]->moments;
    return m;
  }
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();
  for (const mjcf::GeomMass* g : selected) {
    m.mass += g->mass;
    first_moment += g->mass * g->p_BoGcm_B;
  }
  if (m.mass < kMjMinVal) {
    *error =
        "the mass of its geoms is too small to compute a center of mass (MuJoCo refuses "
        "the model)";
    return std::nullopt;
  }
  m.p_BoBcm_B = first_moment / m.mass;
  Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
  for (const mjcf::GeomMass* g : selected) {
    const Eigen::Matrix3d R = g->q_BGi.toRotationMatrix();
    const Eigen::Vector3d d = g->p_BoGcm_B - m.p_BoBcm_B;
    I += R * g->moments.asDiagonal() * R.transpose() +
         g->mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  Principal(I, &m.moments, &m.q_BBi);
  return m;
}

// The bounds and the balancing of mjCBody::Compile, then the Inertial of the Model: the numbers
// as written when the compiler kept them, else the principal ones.
void Builder::Finish(const Node& body, const std::optional<BodyMass>& explicit_mass,
                     std::optional<BodyMass> mass, const Pose& X_PB, Link* link) {
  const mjcf::Compiler& c = c_->compiler;
  if (!mass) {
    if (!(c.boundmass > 0) && !(c.boundinertia > 0)) return;  // A massless body.
    mass = BodyMass{};
    // The compiler copies the body's frame in its parent into the inertial frame.
    mass->p_BoBcm_B = X_PB.p_AB;
    mass->q_BBi = Eigen::Quaterniond(X_PB.R_AB);
  }
  BodyMass m = *mass;
  m.mass = std::max(m.mass, c.boundmass);
  for (int i = 0; i < 3; ++i) m.moments[i] = std::max(m.moments[i], c.boundinertia);
  const Eigen::Vector3d& d = m.moments;
  if (c.balanceinertia && (d[0] + d[1] < d[2] || d[0] + d[2] < d[1] || d[1] + d[2] < d[0])) {
    m.moments.setConstant(d.sum() / 3);
  }
  compiled_.back().mass = m;
  Inertial inertial;
  inertial.location = document_.Where(body);
  for (const Node& child : body.children) {
    if (child.name == "inertial" && explicit_mass) inertial.location = document_.Where(child);
  }
  inertial.mass_location = inertial.inertia_location = inertial.pose_location = inertial.location;
  inertial.mass = m.mass;
  inertial.X_BBi.p_AB = m.p_BoBcm_B;
  const Node* written = nullptr;
  for (const Node& child : body.children) {
    if (child.name == "inertial") written = &child;
  }
  const bool unchanged = explicit_mass && written && m.moments == explicit_mass->moments &&
                         m.mass == explicit_mass->mass && m.q_BBi.coeffs() == mass->q_BBi.coeffs();
  if (unchanged && written->Find("fullinertia") && c.inertiafromgeom != 1 && !c.global) {
    Element full{written, nullptr, ""};
    const auto f = mjcf::Numbers(c_, full, "fullinertia", 6);
    inertial.ixx = (*f)[0];
    inertial.iyy = (*f)[1];
    inertial.izz = (*f)[2];
    inertial.ixy = (*f)[3];
    inertial.ixz = (*f)[4];
    inertial.iyz = (*f)[5];
    link->inertial = inertial;
    return;
  }
  inertial.X_BBi.R_AB = m.q_BBi.normalized().toRotationMatrix();
  inertial.ixx = m.moments[0];
  inertial.iyy = m.moments[1];
  inertial.izz = m.moments[2];
  link->inertial = inertial;
}

// The refusals of MuJoCo 2.2.2's compiler about mass properties, as ReadFindings with the rule
// ids of the MuJoCo target (target_profile.h): negative mass or moments, moments that break the
// triangle inequality (without balanceinertia), and a moving body whose mass or a moment is
// below mjMINVAL with no static child that has both.
void Builder::FindRefusals(const Model& model) {
  const auto add = [&](const Compiled& body, const char* rule, const std::string& quote) {
    const Link& link = model.links[static_cast<std::size_t>(body.link)];
    ReadFinding f;
    f.rule = rule;
    f.model = model_name_;
    f.link = link.name;
    f.location = link.inertial ? link.inertial->location : link.location;
    f.message = "MuJoCo 2.2.2 refuses the file at body '" + link.name + "': \"" + quote +
                "\" (its principal moments " + std::to_string(body.mass.moments[0]) + ", " +
                std::to_string(body.mass.moments[1]) + ", " + std::to_string(body.mass.moments[2]) +
                ", mass " + std::to_string(body.mass.mass) + " kg)";
    f.values = {{"mass", body.mass.mass},
                {"principal_1", body.mass.moments[0]},
                {"principal_2", body.mass.moments[1]},
                {"principal_3", body.mass.moments[2]}};
    result_->findings.push_back(std::move(f));
  };
  const auto small = [](const BodyMass& m) {
    return m.mass < kMjMinVal || m.moments.minCoeff() < kMjMinVal;
  };
  for (const Compiled& body : compiled_) {
    if (body.link < 0 || model.links[static_cast<std::size_t>(body.link)].inertial_unreadable) {
      continue;
    }
    const Eigen::Vector3d& d = body.mass.moments;
    if (body.mass.mass < 0 || d.minCoeff() < 0) {
      add(body, "mujoco-rejects-negative", "mass and inertia cannot be negative");
    } else if (d[0] + d[1] < d[2] || d[0] + d[2] < d[1] || d[1] + d[2] < d[0]) {
      add(body, "mujoco-rejects-inertia-triangle",
          "inertia must satisfy A + B >= C; use 'balanceinertia' to fix");
    } else if (body.moves && small(body.mass)) {
      bool rescued = false;
      for (const Compiled& child : compiled_) {
        rescued = rescued || (child.parent == body.link && !child.moves && !small(child.mass));
      }
      if (!rescued) {
        add(body, "mujoco-rejects-below-minval",
            "mass and inertia of moving bodies must be larger than mjMINVAL");
      }
    }
  }
}

}  // namespace

ReadResult ReadMjcfString(const std::string& xml, const std::string& file_name,
                          const MjcfReadOptions& options) {
  ReadResult result;
  mjcf::Document document;
  if (!mjcf::LoadDocument(xml, file_name, options.max_include_depth, &document, &result.errors)) {
    return result;
  }
  Context context;
  mjcf::ReadSections(document, &context);
  Model model;
  if (context.errors.empty()) {
    Builder builder(&context, document, options, &result);
    builder.Build(&model);
  }
  result.errors.insert(result.errors.end(), context.errors.begin(), context.errors.end());
  result.warnings.insert(result.warnings.end(), context.warnings.begin(), context.warnings.end());
  if (result.errors.empty()) {
    result.models.push_back(std::move(model));
  } else {
    result.findings.clear();
  }
  return result;
}

}  // namespace massprops
