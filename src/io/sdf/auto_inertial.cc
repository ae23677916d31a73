// The SDF reader's <inertial auto="true"> (SDF 1.11, reader.h): the inertia computed from the
// link's collision geometries and their densities, as libsdformat does (auto_inertia.h).
#include "io/sdf/reader.h"

namespace massprops::internal::sdf_reader {

void Reader::ReadAutoInertial(const XMLElement* in, int link_index, int /*top*/, const Pose& X_TB,
                              const Context& ctx, Link* link) {
  (void)X_TB;
  const XMLElement* e = nodes_[link_index].element;
  const std::string lname = "'" + link->name + "'";
  auto unreadable = [&](const SourceLocation& where, const std::string& why) {
    link->inertial_unreadable = true;
    ReadFinding f;
    f.rule = "inertial-unreadable";
    f.model = current_model_name_;
    f.link = link->name;
    f.location = where;
    f.message = "<inertial auto=\"true\"> of link " + lname + " cannot be computed: " + why +
                "; its mass properties are unknown, so its welded group is not checked";
    result_.findings.push_back(std::move(f));
  };
  const SourceLocation in_location = PlaceOf(ctx.file, in);
  if (!options_.compute_auto_inertials) {
    unreadable(in_location, "auto inertials are not computed (compute_auto_inertials is off)");
    return;
  }
  diversion_ = Diversion();
  diversion_.active = true;
  // Density precedence (libsdformat 14, Collision::CalculateInertial): the collision's
  // <density>, else the link's <inertial><density>, else 1000 kg/m³.
  const XMLElement* link_density = in->FirstChildElement("density");
  const double inertial_density =
      Number(link_density, kSdfDefaultDensity, ctx, "<inertial><density> of link " + lname);
  std::optional<double> mass;
  const XMLElement* mass_element = in->FirstChildElement("mass");
  if (mass_element != nullptr) mass = Number(mass_element, 0.0, ctx, "<mass> of link " + lname);
  std::vector<AutoInertiaCollision> collisions;
  size_t g = 0;
  for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    const std::string tag = c->Name();
    if (tag != "collision" && tag != "visual") continue;
    const size_t index = g++;
    if (tag != "collision" || index >= link->geometries.size()) continue;
    AutoInertiaCollision collision;
    collision.name = Attr(c, "name");
    collision.geometry = link->geometries[index];
    const XMLElement* density = c->FirstChildElement("density");
    if (density != nullptr) {
      collision.density = Number(density, kSdfDefaultDensity, ctx,
                                 "<density> of <collision> '" + collision.name + "'");
      collision.density_source = "collision <density>";
    } else if (link_density != nullptr) {
      collision.density = inertial_density;
      collision.density_source = "<inertial><density>";
    } else {
      collision.density = kSdfDefaultDensity;
      collision.density_source = "default density";
    }
    collisions.push_back(std::move(collision));
  }
  diversion_.active = false;
  if (diversion_.failed) {
    unreadable(diversion_.location, diversion_.element + ": " + diversion_.message);
    return;
  }
  if (!mesh_cache_) mesh_cache_ = std::make_unique<MeshCache>();
  MeshResolveOptions mesh_options;
  mesh_options.model_paths = options_.model_paths;
  mesh_options.use_environment = options_.use_environment;
  mesh_options.model_file = ctx.file;
  mesh_options.cache = mesh_cache_.get();
  std::string why;
  const std::optional<AutoInertiaResult> computed =
      CalcAutoInertial(collisions, mass, mesh_options, &why);
  if (!computed) {
    unreadable(in_location, why);
    return;
  }
  Inertial inertial = computed->inertial;
  inertial.location = in_location;
  if (mass_element != nullptr) inertial.mass_location = PlaceOf(ctx.file, mass_element);
  link->inertial = inertial;
  ReadFinding f;
  f.rule = "inertial-auto";
  f.model = current_model_name_;
  f.link = link->name;
  f.location = in_location;
  f.message =
      "link " + lname + ": <inertial auto=\"true\"> (SDF 1.11) computed as " + computed->summary;
  f.values = {{"mass", inertial.mass},
              {"com_x", inertial.X_BBi.p_AB.x()},
              {"com_y", inertial.X_BBi.p_AB.y()},
              {"com_z", inertial.X_BBi.p_AB.z()},
              {"ixx", inertial.ixx},
              {"iyy", inertial.iyy},
              {"izz", inertial.izz},
              {"ixy", inertial.ixy},
              {"ixz", inertial.ixz},
              {"iyz", inertial.iyz},
              {"collisions", static_cast<double>(collisions.size())}};
  result_.findings.push_back(std::move(f));
}

}  // namespace massprops::internal::sdf_reader
