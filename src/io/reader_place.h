#pragma once
// Private to io: what the readers (urdf_reader.cc and src/io/urdf/, sdf_reader.cc and src/io/sdf/,
// and the MJCF reader beside them) share about where a thing is written and what it refers to: an
// element's file and line, and a mesh reference.
#include <Eigen/Core>
#include <string>

#include "massprops/model/model.h"

namespace tinyxml2 {
class XMLNode;
}

namespace massprops::internal {

/// The line of `node` in its document (tinyxml2 counts from 1); 0 when node is null.
int LineOf(const tinyxml2::XMLNode* node);

/// Where `node` is written: {file, LineOf(node), column 0}.
SourceLocation PlaceOf(const std::string& file, const tinyxml2::XMLNode* node);

/// Makes *g a mesh geometry that refers to `uri` as written (package://, model://, file:// or a
/// path; the mesh part resolves it when the mesh is read), scaled by `scale` along its axes.
void SetMeshReference(std::string uri, const Eigen::Vector3d& scale, Geometry* g);

}  // namespace massprops::internal
