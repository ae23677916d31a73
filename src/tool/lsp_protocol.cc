#include "lsp_protocol.h"

#include <poll.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <string>

namespace massprops::cli::lsp {
namespace {

constexpr std::size_t kMaxHeaderBytes = 64 * 1024;

// The value of the Content-Length header in `header` (the lines before the blank one, names
// compared without case); -1 when it is missing or not a number.
long long ContentLength(std::string_view header) {
  std::size_t pos = 0;
  while (pos < header.size()) {
    std::size_t end = header.find("\r\n", pos);
    if (end == std::string_view::npos) end = header.size();
    const std::string_view line = header.substr(pos, end - pos);
    pos = end + 2;
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos) continue;
    std::string name(line.substr(0, colon));
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (name != "content-length") continue;
    std::string value(line.substr(colon + 1));
    const std::size_t first = value.find_first_not_of(" \t");
    if (first == std::string::npos) return -1;
    char* stop = nullptr;
    errno = 0;
    const long long length = std::strtoll(value.c_str() + first, &stop, 10);
    if (errno != 0 || stop == value.c_str() + first || length < 0) return -1;
    for (; *stop != '\0'; ++stop) {
      if (*stop != ' ' && *stop != '\t') return -1;
    }
    return length;
  }
  return -1;
}

int HexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

bool MessageReader::Fill() {
  if (start_ > 0 && start_ >= buffer_.size() / 2) {  // keep the buffer from growing without end
    buffer_.erase(0, start_);
    start_ = 0;
  }
  char chunk[65536];
  for (;;) {
    const ssize_t n = read(fd_, chunk, sizeof chunk);
    if (n > 0) {
      buffer_.append(chunk, static_cast<std::size_t>(n));
      return true;
    }
    if (n < 0 && errno == EINTR) continue;
    return false;
  }
}

MessageReader::Status MessageReader::Next(nlohmann::json* message, std::string* error) {
  std::size_t header_end = std::string::npos;
  while ((header_end = buffer_.find("\r\n\r\n", start_)) == std::string::npos) {
    if (buffer_.size() - start_ > kMaxHeaderBytes) {
      *error = "a message header longer than 64 KiB without its blank line";
      buffer_.clear();
      start_ = 0;
      return Status::kBadMessage;
    }
    if (!Fill()) return Status::kEnd;
  }
  const long long length =
      ContentLength(std::string_view(buffer_).substr(start_, header_end - start_));
  start_ = header_end + 4;
  if (length < 0) {
    *error = "a message header without a valid Content-Length";
    return Status::kBadMessage;
  }
  const auto size = static_cast<std::size_t>(length);
  if (size > kMaxMessageBytes) {  // read and drop it without holding it
    std::size_t left = size;
    while (left > 0) {
      const std::size_t held = buffer_.size() - start_;
      const std::size_t take = held < left ? held : left;
      start_ += take;
      left -= take;
      if (left > 0) {
        buffer_.clear();
        start_ = 0;
        if (!Fill()) return Status::kEnd;
      }
    }
    *error = "a message of " + std::to_string(size) + " bytes (the most is 512 MiB)";
    return Status::kBadMessage;
  }
  while (buffer_.size() - start_ < size) {
    if (!Fill()) return Status::kEnd;
  }
  const std::string_view body = std::string_view(buffer_).substr(start_, size);
  start_ += size;
  *message = nlohmann::json::parse(body, nullptr, /*allow_exceptions=*/false);
  if (message->is_discarded()) {
    *error = "a message body that is not JSON";
    return Status::kBadMessage;
  }
  if (start_ == buffer_.size()) {
    buffer_.clear();
    start_ = 0;
    if (buffer_.capacity() > (std::size_t{1} << 20)) buffer_.shrink_to_fit();
  }
  return Status::kMessage;
}

bool MessageReader::HasPending() {
  if (start_ < buffer_.size()) return true;
  pollfd descriptor{fd_, POLLIN, 0};
  const int ready = poll(&descriptor, 1, 0);
  return ready > 0;
}

bool WriteMessage(int fd, const nlohmann::json& message) {
  const std::string body = message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  const std::string frame = "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
  std::size_t written = 0;
  while (written < frame.size()) {
    const ssize_t n = write(fd, frame.data() + written, frame.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    written += static_cast<std::size_t>(n);
  }
  return true;
}

std::string PathFromUri(std::string_view uri) {
  constexpr std::string_view kScheme = "file://";
  if (uri.substr(0, kScheme.size()) != kScheme) return {};
  std::string_view rest = uri.substr(kScheme.size());
  const std::size_t slash = rest.find('/');  // skip an authority ("localhost")
  if (slash == std::string_view::npos) return {};
  rest = rest.substr(slash);
  std::string path;
  for (std::size_t i = 0; i < rest.size(); ++i) {
    if (rest[i] == '%' && i + 2 < rest.size() && HexValue(rest[i + 1]) >= 0 &&
        HexValue(rest[i + 2]) >= 0) {
      path.push_back(static_cast<char>(HexValue(rest[i + 1]) * 16 + HexValue(rest[i + 2])));
      i += 2;
    } else {
      path.push_back(rest[i]);
    }
  }
  return path;
}

std::string UriFromPath(std::string_view path) {
  static const char* const kHex = "0123456789ABCDEF";
  std::string uri = "file://";
  for (const char c : path) {
    const auto byte = static_cast<unsigned char>(c);
    if (std::isalnum(byte) || c == '/' || c == '-' || c == '.' || c == '_' || c == '~') {
      uri.push_back(c);
    } else {
      uri.push_back('%');
      uri.push_back(kHex[byte >> 4]);
      uri.push_back(kHex[byte & 15]);
    }
  }
  return uri;
}

std::size_t Utf16Length(std::string_view utf8) {
  std::size_t units = 0;
  for (std::size_t i = 0; i < utf8.size();) {
    const auto lead = static_cast<unsigned char>(utf8[i]);
    std::size_t bytes = 1;
    if (lead >= 0xF0 && lead < 0xF8) {
      bytes = 4;
    } else if (lead >= 0xE0) {
      bytes = 3;
    } else if (lead >= 0xC0) {
      bytes = 2;
    }
    if (lead >= 0xF8 || (lead >= 0x80 && lead < 0xC0) || i + bytes > utf8.size()) bytes = 1;
    units += bytes == 4 ? 2 : 1;
    i += bytes;
  }
  return units;
}

std::size_t ByteOfUtf16Column(std::string_view line, std::size_t utf16_column) {
  std::size_t units = 0;
  std::size_t i = 0;
  while (i < line.size() && units < utf16_column) {
    const auto lead = static_cast<unsigned char>(line[i]);
    std::size_t bytes = lead >= 0xF0 && lead < 0xF8 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
    if (lead >= 0xF8 || (lead >= 0x80 && lead < 0xC0) || i + bytes > line.size()) bytes = 1;
    units += bytes == 4 ? 2 : 1;
    i += bytes;
  }
  return i;
}

}  // namespace massprops::cli::lsp
