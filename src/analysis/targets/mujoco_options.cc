// MuJoCo's compiler options as a URDF's <mujoco><compiler .../></mujoco> sets them
// (ReadMujocoCompilerOptions). MJCF's <compiler> element belongs here too.
#include <tinyxml2.h>

#include <cstdlib>
#include <string>

#include "massprops/analysis/target_profile.h"

namespace massprops {

MujocoCompilerOptions ReadMujocoCompilerOptions(std::string_view urdf_text) {
  MujocoCompilerOptions options;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(urdf_text.data(), urdf_text.size()) != tinyxml2::XML_SUCCESS) return options;
  const tinyxml2::XMLElement* robot = doc.RootElement();
  if (robot == nullptr) return options;
  const tinyxml2::XMLElement* mujoco = robot->FirstChildElement("mujoco");
  if (mujoco == nullptr) return options;
  const tinyxml2::XMLElement* compiler = mujoco->FirstChildElement("compiler");
  if (compiler == nullptr) return options;
  auto flag = [&](const char* name, bool* value) {
    if (const char* text = compiler->Attribute(name)) {
      if (std::string(text) == "true") *value = true;
      if (std::string(text) == "false") *value = false;
    }
  };
  flag("fusestatic", &options.fusestatic);
  flag("discardvisual", &options.discardvisual);
  flag("balanceinertia", &options.balanceinertia);
  auto number = [&](const char* name, double* value) {
    if (const char* text = compiler->Attribute(name)) {
      char* end = nullptr;
      const double x = std::strtod(text, &end);
      if (end != text) *value = x;
    }
  };
  number("boundmass", &options.boundmass);
  number("boundinertia", &options.boundinertia);
  if (const char* text = compiler->Attribute("inertiafromgeom")) {
    const std::string v = text;
    if (v == "true") options.inertiafromgeom = MujocoCompilerOptions::InertiaFromGeom::kTrue;
    if (v == "false") options.inertiafromgeom = MujocoCompilerOptions::InertiaFromGeom::kFalse;
    if (v == "auto") options.inertiafromgeom = MujocoCompilerOptions::InertiaFromGeom::kAuto;
  }
  return options;
}

}  // namespace massprops
