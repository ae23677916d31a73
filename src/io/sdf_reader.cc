// Reading SDFormat into massprops Models (see sdf_reader.h).
//
// The reader walks the XML once (plus the files that <include> pulls in) and records every
// frame-bearing element (model, link, joint, frame) as a node of one pose graph, named by its scope
// from the file's root ("model::nested::link"). Poses are resolved lazily, each in the frame of the
// model that contains the element, following libsdformat 12:
//   - a link, a nested model and a frame without attached_to default to the containing model frame;
//   - a frame with attached_to defaults to that frame; a joint defaults to its child frame;
//   - a model's placement_frame P turns the given pose X_RP into X_RM = X_RP * X_MP^-1;
//   - SDF < 1.7: the pose attribute "frame" is read as relative_to (libsdformat's 1.6->1.7
//     converter renames it); the joint axis <xyz> is expressed in the model frame for SDF 1.4
//     joints of top-level models (the 1.4->1.5 converter adds use_parent_model_frame=true) and when
//     <use_parent_model_frame> is true (1.5, 1.6), else in the joint frame;
//   - SDF >= 1.7: <xyz expressed_in="..."> names the frame, default the joint frame.
//
// The reader's parts are in src/io/sdf/ (reader.h says which file holds which); this file reads
// the <sdf> root and holds the public functions.

#include "massprops/io/sdf_reader.h"

#include "io/sdf/reader.h"

namespace massprops {
namespace internal::sdf_reader {

ReadResult Reader::Read(const std::string& xml, const std::string& file_name,
                        std::vector<SdfModelFrames>* frames) {
  if (xml.size() > options_.max_file_bytes) {
    result_.errors.push_back(MakeReadError(file_name, 0, "<sdf>",
                                           "the input has " + std::to_string(xml.size()) +
                                               " bytes, more than the limit of " +
                                               std::to_string(options_.max_file_bytes)));
    return std::move(result_);
  }
  auto doc = std::make_unique<XMLDocument>();
  std::string why;
  int line = 0;
  if (!ParseXml(xml, doc.get(), &why, &line)) {
    result_.errors.push_back(MakeReadError(file_name, line, "<sdf>", why));
    return std::move(result_);
  }
  const XMLElement* root = doc->RootElement();
  if (root == nullptr || std::string(root->Name()) != "sdf") {
    Error(file_name, root, root ? std::string("<") + root->Name() + ">" : "<sdf>",
          "the root element must be <sdf>");
    return std::move(result_);
  }
  Context ctx;
  ctx.file = file_name;
  const std::string version_text = Attr(root, "version");
  if (!ParseVersion(version_text, &ctx.version)) {
    Error(file_name, root, "<sdf>",
          "the version attribute '" + version_text + "' is not of the form MAJOR.MINOR");
    return std::move(result_);
  }
  if (!ctx.version.AtLeast(1, 4) || ctx.version.AtLeast(2, 0)) {
    Warning(file_name, root, "<sdf>",
            "SDF version " + version_text + " is outside 1.4-1.11; read with 1.x rules");
  }
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(file_name, ec);
  include_stack_.push_back(ec ? file_name : canonical.string());
  for (const XMLElement* c = root->FirstChildElement(); c; c = c->NextSiblingElement()) {
    const std::string tag = c->Name();
    if (tag == "world") {
      ReadWorld(c, ctx);
    } else if (tag == "model") {
      const int m = ReadModel(c, kWorld, ctx, nullptr);
      if (m >= 0) top_models_.push_back(m);
    }
  }
  if (top_models_.empty() && result_.errors.empty()) {
    Warning(file_name, root, "<sdf>", "the file holds no <model>");
  }
  if (result_.errors.empty()) {
    BuildModels();
  }
  if (!result_.errors.empty()) {
    result_.models.clear();
    frames_.clear();
  }
  if (frames != nullptr) *frames = std::move(frames_);
  documents_.push_back(std::move(doc));
  return std::move(result_);
}

}  // namespace internal::sdf_reader

ReadResult ReadSdfString(const std::string& xml, const std::string& file_name,
                         const SdfReadOptions& options, std::vector<SdfModelFrames>* frames) {
  internal::sdf_reader::Reader reader(options, file_name);
  return reader.Read(xml, file_name, frames);
}

ReadResult ReadSdfString(const std::string& xml, const std::string& file_name,
                         const SdfReadOptions& options) {
  return ReadSdfString(xml, file_name, options, nullptr);
}

ReadResult ReadSdfFile(const std::string& path, const SdfReadOptions& options) {
  return ReadSdfFile(path, options, nullptr);
}

ReadResult ReadSdfFile(const std::string& path, const SdfReadOptions& options,
                       std::vector<SdfModelFrames>* frames) {
  std::string text;
  std::string why;
  if (!internal::sdf_reader::ReadWholeFile(path, options.max_file_bytes, &text, &why)) {
    ReadResult result;
    result.errors.push_back(MakeReadError(path, 0, "<sdf>", why));
    return result;
  }
  return ReadSdfString(text, path, options, frames);
}

}  // namespace massprops
