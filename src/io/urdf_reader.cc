#include "massprops/io/urdf_reader.h"

#include <algorithm>
#include <cstring>

#include "io/urdf/reader.h"

// The Model comes from urdf::parseURDF (urdfdom) whenever urdfdom returns a model; an index of the
// same text gives the line of each element. Only when urdfdom refuses the file does
// massprops read the elements that carry mass properties itself (LenientReader below).
// The reader's parts are in src/io/urdf/ (reader.h says which file holds which); this file reads
// the text's bytes and root and calls them in turn.

namespace massprops {
namespace internal::urdf_reader {

ReadResult Reader::Read(const std::string& xml, std::size_t max_bytes) {
  if (xml.size() > max_bytes) {
    Error(0, "file",
          "the input has " + std::to_string(xml.size()) + " bytes, more than the limit of " +
              std::to_string(max_bytes));
    return std::move(result_);
  }
  if (const void* nul = std::memchr(xml.data(), '\0', xml.size())) {
    const std::size_t offset = static_cast<std::size_t>(static_cast<const char*>(nul) - xml.data());
    Error(1 + static_cast<int>(std::count(xml.data(), xml.data() + offset, '\n')), "file",
          "contains a NUL byte at offset " + std::to_string(offset) +
              ": this is not a text (XML) file");
    return std::move(result_);
  }
  // The index comes from one light pass over the text when it is written in the XML that URDF
  // files use (scan.cc), else from a tinyxml2 DOM (index.cc), which also says what is wrong.
  if (!ScanIndex(xml) && !IndexWithTinyxml2(xml)) return std::move(result_);

  std::vector<std::string> errors;
  const urdf::ModelInterfaceSharedPtr urdf = ParseWithUrdfdom(xml, &errors);
  WarnAboutTextUrdfdomSkips();
  if (urdf) {
    result_.models.push_back(FromUrdfdom(*urdf, errors, xml));
    ReleaseUrdfdomModel(urdf);
    return std::move(result_);
  }
  ReportNotLoadable(errors);
  XMLDocument doc(/*processEntities=*/true, tinyxml2::PRESERVE_WHITESPACE);
  if (!ParseDom(xml, &doc)) return std::move(result_);
  result_.models.push_back(ReadLeniently(file_, doc.FirstChildElement("robot"), &result_));
  return std::move(result_);
}

}  // namespace internal::urdf_reader

ReadResult ReadUrdfString(const std::string& xml, const std::string& file_name,
                          std::size_t max_file_bytes) {
  return internal::urdf_reader::Reader(file_name).Read(xml, max_file_bytes);
}

ReadResult ReadUrdfFile(const std::string& path) {
  std::string contents;
  if (std::optional<ReadError> error = ReadInputFile(path, kMaxUrdfFileBytes, &contents)) {
    ReadResult result;
    result.errors.push_back(std::move(*error));
    return result;
  }
  return ReadUrdfString(contents, path == "-" ? "<stdin>" : path);
}

}  // namespace massprops
