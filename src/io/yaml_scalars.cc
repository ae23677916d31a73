// The YAML scalars of a text with yaml-cpp (yaml_scalars.h); compiled into the optional module.
#include "io/yaml_scalars.h"

#include <yaml-cpp/yaml.h>

#include <exception>
#include <map>

namespace massprops::internal {
namespace {

struct Walk {
  int max_visits = 0;
  int visits = 0;
  std::vector<std::string> path;
  std::map<std::size_t, std::size_t> by_offset;  // offset -> index in *out
  std::vector<YamlScalarFound>* out = nullptr;

  void Node(const YAML::Node& node, int depth) {
    if (++visits > max_visits || depth > 64) return;
    if (node.IsMap()) {
      // PyYAML keeps the last of duplicated keys: walk them all, later ones win by being later.
      for (auto it = node.begin(); it != node.end(); ++it) {
        path.push_back(it->first.IsScalar() ? it->first.Scalar() : std::string("?"));
        Node(it->second, depth + 1);
        path.pop_back();
      }
    } else if (node.IsSequence()) {
      for (std::size_t i = 0; i < node.size(); ++i) {
        path.push_back("[" + std::to_string(i) + "]");
        Node(node[i], depth + 1);
        path.pop_back();
      }
    } else if (node.IsScalar()) {
      const YAML::Mark mark = node.Mark();
      if (mark.pos < 0) return;
      const auto offset = static_cast<std::size_t>(mark.pos);
      auto found = by_offset.find(offset);
      if (found != by_offset.end()) {
        (*out)[found->second].paths.push_back(path);
        return;
      }
      YamlScalarFound scalar;
      scalar.offset = offset;
      scalar.line = mark.line + 1;
      scalar.text = node.Scalar();
      scalar.paths.push_back(path);
      by_offset[offset] = out->size();
      out->push_back(std::move(scalar));
    }
  }
};

bool ReadScalars(const std::string& text, int max_visits, std::vector<YamlScalarFound>* out,
                 std::string* error) {
  try {
    const YAML::Node root = YAML::Load(text);
    Walk walk;
    walk.max_visits = max_visits;
    walk.out = out;
    walk.Node(root, 0);
    return true;
  } catch (const std::exception& e) {
    *error = e.what();
    return false;
  }
}

}  // namespace
}  // namespace massprops::internal

extern "C" const massprops::internal::YamlReader* massprops_yaml_reader_v1() {
  static const massprops::internal::YamlReader reader{&massprops::internal::ReadScalars};
  return &reader;
}
