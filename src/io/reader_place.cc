// What the readers share about places and references (reader_place.h).
#include "io/reader_place.h"

#include <tinyxml2.h>

#include <utility>

namespace massprops::internal {

int LineOf(const tinyxml2::XMLNode* node) { return node != nullptr ? node->GetLineNum() : 0; }

SourceLocation PlaceOf(const std::string& file, const tinyxml2::XMLNode* node) {
  return SourceLocation{file, LineOf(node), 0};
}

void SetMeshReference(std::string uri, const Eigen::Vector3d& scale, Geometry* g) {
  g->type = Geometry::Type::kMesh;
  g->uri = std::move(uri);
  g->scale = scale;
}

}  // namespace massprops::internal
