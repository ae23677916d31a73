#pragma once
// Private to src/output: merge-fixed for SDF input (MergeFixedJoints in merge_fixed.h calls it).

#include <string>

#include "massprops/model/model.h"
#include "massprops/output/merge_fixed.h"

namespace massprops::internal {

// Merges every welded group of every model of the SDF text `xml` (`read` is its ReadModelString
// result, without errors) into the group's root link by editing the document (tinyxml2): the
// root link's <inertial> becomes the composite, the members' visuals, collisions, sensors and
// the other posed children of a link move into it with composed poses, the members and the fixed
// joints between them are removed, and poses, frames and joints that named a member are
// re-pointed to the root with composed poses. What cannot be edited correctly (a member inside a
// nested model or an include, a reference from outside the model, a placement_frame naming a
// member, a moving joint inside a group, an unreadable member inertial) is a "not supported"
// error naming the file, line and element; nothing is written then.
MergeFixedResult MergeFixedSdf(const std::string& xml, const std::string& file_name,
                               const ReadResult& read);

}  // namespace massprops::internal
