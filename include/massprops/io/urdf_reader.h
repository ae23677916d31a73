#pragma once
/// @file
/// Reading URDF into a massprops Model through urdfdom (ROS's URDF parser, `urdf::parseURDF`), so
/// that massprops judges exactly the model that robot_state_publisher, MoveIt and the URDF
/// importers of Gazebo and Drake load. A light index of the same text adds the line of every
/// <link>, <joint>, <inertial>, <mass>, <inertia>, <origin>, <collision> and <visual>, and the
/// `<!-- massprops: ignore ... -->` comments of each link; the index decides nothing about
/// validity. It comes from one pass over the text (no second XML parse) when the text is written
/// in the XML URDF files use, else from a tinyxml2 DOM, with the same lines.
///
/// What urdfdom says while it reads (through console_bridge) is captured, never printed:
/// - urdfdom refuses the file: a ReadFinding "urdf-not-loadable" quoting urdfdom's reason, located
///   at the element it names, and a lenient reading of only what carries mass properties (link
///   inertials and geometries; joint type, parent, child, origin, axis), so that files written for
///   Drake or MuJoCo (a `world` parent link, a <limit> without velocity, ...) are still checked;
/// - urdfdom cannot read a link's <inertial> (it logs and keeps a partly read one): a ReadFinding
///   "inertial-unreadable" on that link quoting the text, Link::inertial_unreadable set;
/// - urdfdom drops a <visual>, <collision> or <material> and goes on: nothing is said (no inertial
///   number depends on them; the Model holds the geometries urdfdom kept).
/// A link with several <inertial>s (urdfdom reads the first) and a joint axis of zero length are
/// read warnings. Only an unreadable input (missing file, too large, NUL bytes, malformed XML, no
/// <robot>) is a ReadError.
///
/// urdfdom logs through console_bridge, whose output handler and log level are process-wide. The
/// first read puts one massprops handler in front of the current one, for good: it keeps what a
/// thread logs inside its own `urdf::parseURDF` call and forwards every other message to the
/// handler it found, so reads on several threads run at once and the caller's logging still
/// arrives. A read that finds another handler in front, or the level at
/// CONSOLE_BRIDGE_LOG_NONE, runs alone with massprops' handler and the ERROR level, and puts both
/// back (docs/urdf.md, "console_bridge").

#include <cstddef>
#include <optional>
#include <string>

#include "massprops/model/model.h"

namespace massprops {

/// URDF files (or standard input) larger than this are refused with a ReadError, so that hostile
/// input cannot exhaust memory.
inline constexpr std::size_t kMaxUrdfFileBytes = std::size_t{256} << 20;  // 256 MiB

/// Reads the URDF file at `path`; "-" reads standard input to its end (locations then name the
/// file "<stdin>"). Yields one Model unless the input cannot be read as XML with a <robot> root.
/// Never throws for bad input: each problem is a ReadError, a warning or a ReadFinding naming the
/// file, line and element. Cost: that of urdf::parseURDF plus one pass over the text (a tinyxml2
/// parse for text the pass does not read: a DOCTYPE, CDATA, entities in the indexed values).
ReadResult ReadUrdfFile(const std::string& path);

/// Same as ReadUrdfFile for URDF text already in memory; `file_name` is used in SourceLocations.
/// A text larger than `max_file_bytes` is refused with a ReadError.
ReadResult ReadUrdfString(const std::string& xml, const std::string& file_name,
                          std::size_t max_file_bytes = kMaxUrdfFileBytes);

namespace internal {
/// For tests: the reader's index of `xml` (each line it takes from the text, the ignore comments,
/// the underflowing numbers, the index's warnings) as text, from the light scan of the text
/// (`from_tinyxml2` false) or from a tinyxml2 DOM (true); nullopt when that way gives no index
/// (the scan gives up on text outside the XML it reads; tinyxml2 on text that is not XML with a
/// <robot> root).
std::optional<std::string> DescribeUrdfIndex(const std::string& xml, bool from_tinyxml2);
}  // namespace internal

}  // namespace massprops
