#pragma once
// sensor_msgs/msg/JointState as ROS 2 serializes it (CDR, the bytes rosbag2 stores): read
// directly, without ROS, for the rosbag2 reader (massprops/io/trajectory_rosbag.h).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace massprops::io_internal {

/// One JointState message. position, velocity and effort may each be empty (the message says
/// nothing of them) or have name.size() entries.
struct JointStateMessage {
  std::int32_t stamp_sec = 0;
  std::uint32_t stamp_nanosec = 0;
  std::string frame_id;
  std::vector<std::string> name;
  std::vector<double> position, velocity, effort;
};

/// The message in `size` bytes: the 4-byte encapsulation header (0x00 0x00: big-endian CDR, 0x00
/// 0x01: little-endian; its 2 option bytes ignored), then XCDR1 with each primitive aligned to its
/// size counted from the end of the header: header.stamp {int32 sec, uint32 nanosec},
/// header.frame_id (uint32 length including the terminating NUL, the bytes), name
/// (uint32 count, strings), position, velocity, effort (uint32 count, float64s; an empty
/// sequence has no padding after its count, as Fast-CDR writes it). nullopt with *error saying
/// what when the bytes end early ("truncated"), the encapsulation is another, or a sequence's
/// length exceeds the bytes left. Never reads past size.
std::optional<JointStateMessage> ParseJointStateCdr(const std::uint8_t* data, std::size_t size,
                                                    std::string* error);

}  // namespace massprops::io_internal
