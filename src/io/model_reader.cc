#include "massprops/io/model_reader.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <system_error>

#include "massprops/io/sdf_reader.h"
#include "massprops/io/urdf_reader.h"

namespace massprops {
namespace {

constexpr const char* kStdinName = "<stdin>";

// "1.5 MiB", or "1000 bytes" below 1 MiB (a limit set that low would print as 0.0 MiB).
std::string MebibytesText(std::size_t bytes) {
  if (bytes < (std::size_t{1} << 20)) return std::to_string(bytes) + " bytes";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.1f MiB", static_cast<double>(bytes) / (1 << 20));
  return buffer;
}

ReadError FileError(const std::string& file, std::string message) {
  return MakeReadError(file, 0, "file", std::move(message));
}

// Reads `stream` to its end in chunks, giving up as soon as more than max_bytes have arrived.
std::optional<ReadError> ReadStream(std::FILE* stream, const std::string& shown_name,
                                    std::size_t max_bytes, std::size_t expected_size,
                                    std::string* contents) {
  constexpr std::size_t kChunk = 64 * 1024;
  contents->clear();
  if (expected_size > 0) contents->reserve(expected_size);
  std::unique_ptr<char[]> chunk(new char[kChunk]);
  for (;;) {
    const std::size_t got = std::fread(chunk.get(), 1, kChunk, stream);
    if (got > 0) {
      if (contents->size() + got > max_bytes) {
        contents->clear();
        contents->shrink_to_fit();
        return FileError(shown_name, "input is larger than the limit of " +
                                         MebibytesText(max_bytes) +
                                         "; refusing to read it (the command line's "
                                         "--max-input-size raises the limit)");
      }
      contents->append(chunk.get(), got);
    }
    if (got < kChunk) {
      if (std::ferror(stream)) {
        return FileError(shown_name, std::string("read error: ") + std::strerror(errno));
      }
      return std::nullopt;
    }
  }
}

}  // namespace

std::optional<Model::Format> DetectModelFormat(std::string_view xml) {
  std::size_t i = 0;
  if (xml.substr(0, 3) == "\xEF\xBB\xBF") i = 3;
  const auto skip_past = [&](std::string_view terminator) {
    const std::size_t end = xml.find(terminator, i);
    i = end == std::string_view::npos ? xml.size() : end + terminator.size();
  };
  while (i < xml.size()) {
    const char c = xml[i];
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      ++i;
    } else if (c != '<') {
      return std::nullopt;
    } else if (xml.compare(i, 4, "<!--") == 0) {
      skip_past("-->");
    } else if (xml.compare(i, 2, "<?") == 0) {
      skip_past("?>");
    } else if (xml.compare(i, 2, "<!") == 0) {
      // A DOCTYPE, possibly with an internal subset in brackets.
      const std::size_t bracket = xml.find('[', i);
      const std::size_t close = xml.find('>', i);
      if (bracket != std::string_view::npos && bracket < close) {
        i = bracket;
        skip_past("]");
      }
      skip_past(">");
    } else {
      std::size_t end = i + 1;
      while (end < xml.size() && xml[end] != '>' && xml[end] != '/' && xml[end] != ' ' &&
             xml[end] != '\t' && xml[end] != '\n' && xml[end] != '\r') {
        ++end;
      }
      const std::string_view name = xml.substr(i + 1, end - i - 1);
      if (name == "robot") return Model::Format::kUrdf;
      if (name == "sdf") return Model::Format::kSdf;
      if (name == "mujoco") return Model::Format::kMjcf;
      return std::nullopt;
    }
  }
  return std::nullopt;
}

std::optional<ReadError> ReadInputFile(const std::string& path, std::size_t max_bytes,
                                       std::string* contents) {
  if (path == "-") return ReadStream(stdin, kStdinName, max_bytes, 0, contents);

  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) {
    return FileError(path, "cannot open: " + (ec ? ec.message() : std::string("no such file")));
  }
  if (std::filesystem::is_directory(status)) {
    return FileError(path, "is a directory, not a model file");
  }
  std::size_t expected_size = 0;
  if (std::filesystem::is_regular_file(status)) {
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size <= max_bytes) expected_size = static_cast<std::size_t>(size);
    if (!ec && size > max_bytes) {
      return FileError(path, "file is " + MebibytesText(static_cast<std::size_t>(size)) +
                                 ", larger than the limit of " + MebibytesText(max_bytes) +
                                 "; refusing to read it (the command line's "
                                 "--max-input-size raises the limit)");
    }
  }
  std::FILE* stream = std::fopen(path.c_str(), "rb");
  if (stream == nullptr) {
    return FileError(path, std::string("cannot open: ") + std::strerror(errno));
  }
  std::optional<ReadError> error = ReadStream(stream, path, max_bytes, expected_size, contents);
  std::fclose(stream);
  return error;
}

namespace {

// "UTF-16LE", "UTF-16BE", "UTF-32LE" or "UTF-32BE" when the text starts with that byte order
// mark or with "<" in that encoding (XML 1.0, appendix F); nullptr otherwise.
const char* Utf16Or32(std::string_view t) {
  auto starts = [&](std::string_view prefix) {
    return t.size() >= prefix.size() && t.compare(0, prefix.size(), prefix) == 0;
  };
  using namespace std::string_view_literals;
  if (starts("\xFF\xFE\0\0"sv) || starts("<\0\0\0"sv)) return "UTF-32LE";
  if (starts("\0\0\xFE\xFF"sv) || starts("\0\0\0<"sv)) return "UTF-32BE";
  if (starts("\xFF\xFE"sv) || starts("<\0"sv)) return "UTF-16LE";
  if (starts("\xFE\xFF"sv) || starts("\0<"sv)) return "UTF-16BE";
  return nullptr;
}

}  // namespace

ReadResult ReadModelString(const std::string& xml, const std::string& file_name,
                           const ReadOptions& options) {
  const std::optional<Model::Format> format = DetectModelFormat(xml);
  if (format == Model::Format::kUrdf) return ReadUrdfString(xml, file_name, options.max_file_bytes);
  if (format == Model::Format::kSdf) {
    SdfReadOptions sdf = options.sdf;
    sdf.max_file_bytes = options.max_file_bytes;
    return ReadSdfString(xml, file_name, sdf);
  }
  if (format == Model::Format::kMjcf) return ReadMjcfString(xml, file_name, options.mjcf);
  ReadResult result;
  ReadError error;
  error.location.file = file_name;
  error.location.line = 1;
  error.element = "document";
  error.message =
      xml.empty()
          ? "the file is empty"
          : "neither URDF, SDF nor MJCF: the first element is not <robot>, <sdf> or <mujoco>";
  if (const char* encoding = Utf16Or32(xml)) {
    error.message = std::string("the file is encoded in ") + encoding +
                    "; massprops reads UTF-8 (convert it, e.g. iconv -f " + encoding + " -t UTF-8)";
  }
  result.errors.push_back(std::move(error));
  return result;
}

ReadResult ReadModelFile(const std::string& path, const ReadOptions& options) {
  std::string contents;
  if (std::optional<ReadError> error = ReadInputFile(path, options.max_file_bytes, &contents)) {
    ReadResult result;
    result.errors.push_back(std::move(*error));
    return result;
  }
  return ReadModelString(contents, path == "-" ? kStdinName : path, options);
}

}  // namespace massprops
