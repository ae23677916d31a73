#include "massprops/analysis/materials.h"

#include <cctype>
#include <string>

namespace massprops {

const std::vector<Material>& CommonMaterials() {
  static const std::vector<Material> kMaterials = {
      {"aluminium-6061", "aluminium 6061", 2700,
       "Aluminum Association typical value for 6061-T6 (2.70 g/cm³, ASM/MatWeb data sheet "
       "'Aluminum 6061-T6; 6061-T651')"},
      {"steel", "steel", 7850, "EN 1993-1-1 (Eurocode 3) §3.2.6: structural steel, 7850 kg/m³"},
      {"pla", "PLA", 1240, "NatureWorks Ingeo 4043D technical data sheet: specific gravity 1.24"},
      {"abs", "ABS", 1040, "Stratasys ABS-M30 data sheet: specific gravity 1.04"},
      {"petg", "PETG", 1270, "Eastman Eastar copolyester 6763 data sheet: 1.27 g/cm³"},
      {"nylon", "nylon (PA66)", 1140, "DuPont Zytel 101L (PA66) data sheet: 1140 kg/m³"},
      {"carbon-fibre", "carbon-fibre composite", 1570,
       "Hexcel HexPly 8552 product data sheet: IM7/8552 cured laminate 1.57 g/cm³"},
  };
  return kMaterials;
}

const Material* FindMaterial(std::string_view name) {
  std::string key;
  for (char c : name) key += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (key == "aluminum-6061" || key == "aluminium" || key == "aluminum") key = "aluminium-6061";
  if (key == "cfrp" || key == "carbon-fiber") key = "carbon-fibre";
  for (const Material& m : CommonMaterials()) {
    if (m.name == key) return &m;
  }
  return nullptr;
}

std::string MaterialNames() {
  std::string names;
  for (const Material& m : CommonMaterials()) names += (names.empty() ? "" : ", ") + m.name;
  return names;
}

}  // namespace massprops
