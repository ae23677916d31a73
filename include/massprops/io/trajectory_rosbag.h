#pragma once
/// @file
/// Recorded joint trajectories from a ROS 2 bag (rosbag2's SQLite storage), the input of
/// identification (docs/identify.md): the sensor_msgs/msg/JointState messages of the bag, read
/// from the stored CDR bytes directly (no ROS needed), as a JointTrajectory like the CSV reader's
/// (massprops/io/trajectory_csv.h).

#include <string>

#include "massprops/io/trajectory_csv.h"

namespace massprops {

/// Reads the bag at `path`: a `.db3` file, or a bag folder (the one holding `metadata.yaml`)
/// whose `.db3` files are read in the order of their names. The topic read is the one of type
/// `sensor_msgs/msg/JointState` (`/joint_states` where there are several, else an error naming
/// them). The joints are those of the first message, in its order; later messages may list them
/// in another order. Time is the header stamp (or the bag's receive timestamp where the stamp is
/// 0), in seconds from the first message. Velocities come from the messages when every message
/// has them, else they are derived from the positions; accelerations always are (as the CSV
/// reader derives them, options.cutoff_hz, said in `notes`).
/// Errors, each naming the file and the problem, no trajectory: not a bag or unreadable (SQLite's
/// message); no JointState topic; a message that does not parse (truncated CDR, with its index);
/// a joint missing from a message or without an effort; a position, velocity or effort array of
/// another length than the names; a value that is not finite (NaN); a time not after the one
/// before; fewer than options.min_samples messages. Needs libsqlite3.so.0 at run time (loaded on
/// the first call; an error says so when absent). Never throws for bad input.
TrajectoryReadResult ReadTrajectoryRosbag(const std::string& path,
                                          const TrajectoryCsvOptions& options = {});

/// True when `path` names a rosbag2 recording: a folder, or a file whose name ends in `.db3`.
bool IsRosbagPath(const std::string& path);

}  // namespace massprops
