#pragma once
// How `massprops fix` and `massprops merge-fixed` write files (see docs/fix.md, "How files are
// written"), and how every command makes sure its standard output was written.
#include <optional>
#include <string>
#include <vector>

namespace massprops::cli {

/// Writes `data` to `path` without ever leaving a half-written or wrongly replaced file:
/// - a regular file (new or existing) is written to a temporary file created exclusively
///   (mkstemp: a unique name, O_EXCL, never following a planted link) in the same folder, flushed
///   (fsync) and renamed over `path` when complete. An existing file keeps its mode (and, when
///   permitted, its owner); a new one gets 0666 minus the umask;
/// - a symbolic link is followed: its final target is replaced as above, the link stays a link;
/// - anything that is not a regular file (a device such as /dev/null, a FIFO, a socket) is
///   opened and written in place: it is never replaced by a regular file;
/// - a read-only file is refused (nothing written), and so is a directory;
/// - a file with several hard links is replaced under this name only: a line saying so is added
///   to *notes (the other names keep the old content).
/// Returns nullopt on success, else the error (a sentence naming the file and the system's
/// reason); then `path` is untouched and no temporary file is left.
std::optional<std::string> WriteFileSafely(const std::string& path, const std::string& data,
                                           std::vector<std::string>* notes);

/// Writes all of `data` to the open descriptor `fd` (again after EINTR and short writes); false
/// (errno set) on failure.
bool WriteAll(int fd, const std::string& data);

/// Flushes standard output (std::cout and stdout) and returns `code`, or 2 with a message on
/// standard error when anything written to standard output was lost (a full disk, a closed or
/// unwritable standard output): a report that did not arrive is not a success.
int FinishStandardOutput(int code);

}  // namespace massprops::cli
