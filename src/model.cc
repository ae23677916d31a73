#include "massprops/model.h"

#include <cstddef>
#include <string>

namespace massprops {

int Model::FindLink(const std::string& link_name) const {
  for (std::size_t i = 0; i < links.size(); ++i) {
    if (links[i].name == link_name) return static_cast<int>(i);
  }
  return -1;
}

int Model::FindParentJoint(const std::string& child_link) const {
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].child == child_link) return static_cast<int>(i);
  }
  return -1;
}

// The position is printed as compilers do: "file:line:col" when the column is known, "file:line"
// when only the line is, "file" alone when neither is (e.g. a file that cannot be opened).
std::string ReadError::ToString() const {
  std::string text = location.file.empty() ? std::string("<input>") : location.file;
  if (location.line > 0) {
    text += ':' + std::to_string(location.line);
    if (location.column > 0) text += ':' + std::to_string(location.column);
  }
  text += ": ";
  if (!element.empty()) text += element + ": ";
  text += message;
  return text;
}

}  // namespace massprops
