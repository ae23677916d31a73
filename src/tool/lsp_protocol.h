#pragma once
// The wire of `massprops lsp`: JSON-RPC 2.0 messages framed by `Content-Length` headers
// (Language Server Protocol 3.17, "Base Protocol"), read from and written to file descriptors,
// and the conversions between `file://` URIs and paths. Defined in src/tool/lsp_protocol.cc.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace massprops::cli::lsp {

/// Messages larger than this are refused (read and dropped, answered with a parse error).
inline constexpr std::size_t kMaxMessageBytes = std::size_t{512} << 20;

/// Reads framed messages from a file descriptor through its own buffer, so that it can tell
/// whether more input is waiting (HasPending) before the server checks a document.
class MessageReader {
 public:
  explicit MessageReader(int fd) : fd_(fd) {}

  enum class Status {
    kMessage,     ///< *message holds the next message.
    kEnd,         ///< The input ended (between messages, or inside one: then it is dropped).
    kBadMessage,  ///< A frame whose header or JSON body is malformed; *error says why. The frame
                  ///< was consumed (when its length was readable) and reading can go on.
  };

  /// Blocks until the next whole message has arrived. Never throws for bad input.
  Status Next(nlohmann::json* message, std::string* error);

  /// True when input is waiting: bytes already buffered, or the descriptor is readable now (the
  /// end of input counts). Never blocks.
  bool HasPending();

 private:
  // Reads more bytes into buffer_ (blocking); false at end of input or on a read error.
  bool Fill();

  int fd_;
  std::string buffer_;
  std::size_t start_ = 0;  // the first byte of buffer_ not yet consumed
};

/// Writes `message` framed with its Content-Length to `fd`, whole (retrying short writes).
/// Returns false when the descriptor is closed or a write fails.
bool WriteMessage(int fd, const nlohmann::json& message);

/// The path of a `file://` URI (percent-decoded; `file:///a%20b/x.urdf` → `/a b/x.urdf`); "" for
/// any other scheme.
std::string PathFromUri(std::string_view uri);

/// The `file://` URI of an absolute path, each byte outside the unreserved set and `/`
/// percent-encoded.
std::string UriFromPath(std::string_view path);

/// The number of UTF-16 code units of a UTF-8 string (LSP positions count them): one per
/// character below U+10000, two above; a malformed byte counts as one.
std::size_t Utf16Length(std::string_view utf8);

/// The byte offset in the UTF-8 line `line` of the position `utf16_column` (UTF-16 code units);
/// the line's length when the column lies beyond it.
std::size_t ByteOfUtf16Column(std::string_view line, std::size_t utf16_column);

}  // namespace massprops::cli::lsp
