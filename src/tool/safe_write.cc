#include "safe_write.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace massprops::cli {

bool WriteAll(int fd, const std::string& data) {
  std::size_t written = 0;
  while (written < data.size()) {
    const ssize_t n = ::write(fd, data.data() + written, data.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    if (n == 0) return false;  // nothing written and no error: give up rather than spin
    written += static_cast<std::size_t>(n);
  }
  return true;
}

namespace {

std::string Reason() { return std::strerror(errno); }

mode_t CreationMode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

std::string FolderOf(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// Temporary file beside `path`, then rename; `existing` is the stat of the file it replaces.
std::optional<std::string> ReplaceAtomically(const std::string& path, const std::string& data,
                                             const struct stat* existing) {
  const std::string dir = FolderOf(path);
  const std::size_t slash = path.rfind('/');
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  std::string name = dir + "/." + base + ".massprops-XXXXXX";
  std::vector<char> buffer(name.begin(), name.end());
  buffer.push_back('\0');
  const int fd = ::mkstemp(buffer.data());  // O_CREAT | O_EXCL, mode 0600: never follows a link.
  if (fd < 0) {
    return "cannot create a temporary file in " + dir + " (to replace " + path +
           " atomically): " + Reason();
  }
  const std::string tmp(buffer.data());
  auto fail = [&](const std::string& what) -> std::optional<std::string> {
    const std::string message = what + ": " + Reason();
    ::close(fd);
    ::unlink(tmp.c_str());
    return message;
  };
  if (!WriteAll(fd, data)) return fail("cannot write " + tmp);
  const mode_t mode = existing != nullptr ? (existing->st_mode & 07777) : CreationMode();
  if (::fchmod(fd, mode) != 0) return fail("cannot set the mode of " + tmp);
  if (existing != nullptr && (existing->st_uid != ::geteuid() || existing->st_gid != ::getegid())) {
    // Keep the owner when permitted (root); otherwise the new file is the caller's.
    (void)!::fchown(fd, existing->st_uid, existing->st_gid);
  }
  if (::fsync(fd) != 0) return fail("cannot write " + tmp + " to disk");
  if (::close(fd) != 0) {
    const std::string message = "cannot write " + tmp + ": " + Reason();
    ::unlink(tmp.c_str());
    return message;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string message = "cannot replace " + path + ": " + Reason();
    ::unlink(tmp.c_str());
    return message;
  }
  const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);  // The rename, durable.
  if (dir_fd >= 0) {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> WriteFileSafely(const std::string& path_in, const std::string& data,
                                           std::vector<std::string>* notes) {
  std::string path = path_in;
  struct stat link_st {};
  if (::lstat(path.c_str(), &link_st) == 0 && S_ISLNK(link_st.st_mode)) {
    // Follow the link to its final target; the link itself stays.
    char resolved[PATH_MAX];
    if (::realpath(path.c_str(), resolved) == nullptr) {
      return path + " is a symbolic link whose target cannot be resolved: " + Reason();
    }
    path = resolved;
  }
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (errno != ENOENT) return "cannot write " + path + ": " + Reason();
    return ReplaceAtomically(path, data, nullptr);
  }
  if (S_ISDIR(st.st_mode)) return "cannot write " + path + ": it is a directory";
  if (!S_ISREG(st.st_mode)) {
    // A device, FIFO or socket: written in place, never replaced by a regular file.
    const int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) return "cannot open " + path + " for writing: " + Reason();
    if (!WriteAll(fd, data)) {
      const std::string message = "cannot write " + path + ": " + Reason();
      ::close(fd);
      return message;
    }
    if (::close(fd) != 0) return "cannot write " + path + ": " + Reason();
    return std::nullopt;
  }
  // Read-only: not writable by the caller, or (for root, who may write anything) without any
  // write permission bit: replacing it through the folder would go around the owner's intent.
  const bool denied = ::access(path.c_str(), W_OK) != 0;
  if (denied || (st.st_mode & 0222) == 0) {
    char mode[8];
    std::snprintf(mode, sizeof(mode), "%04o", static_cast<unsigned>(st.st_mode & 07777));
    return path + " is read-only (mode " + mode + "): not replaced; make it writable first " +
           "(chmod u+w) if it should change";
  }
  if (st.st_nlink > 1 && notes != nullptr) {
    notes->push_back(path + " has " + std::to_string(st.st_nlink) +
                     " hard links: it was replaced by a new file under this name only; the " +
                     std::to_string(st.st_nlink - 1) + " other name(s) keep the old content");
  }
  return ReplaceAtomically(path, data, &st);
}

int FinishStandardOutput(int code) {
  std::cout.flush();
  const bool stream_failed = !std::cout.good();
  errno = 0;
  const bool flush_failed = std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
  if (stream_failed || flush_failed) {
    const int saved = errno;
    std::cerr << "massprops: error: cannot write to standard output"
              << (saved != 0 ? std::string(": ") + std::strerror(saved) : std::string())
              << "; the output is incomplete\n";
    return 2;
  }
  return code;
}

}  // namespace massprops::cli
