#pragma once
// The language server behind `massprops lsp` (docs/editors.md): the documents an editor has open,
// each checked through `check`'s own pipeline (check_pipeline.h) on its unsaved text, and the
// answers built from the result: diagnostics (lsp_diagnostics.cc), hover (lsp_hover.cc) and code
// actions (lsp_actions.cc). Single-threaded: the loop (RunLspServer) handles every message that
// has arrived before it checks the documents they changed, so a check never runs on text that a
// newer message has already replaced.
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "check_pipeline.h"
#include "massprops/io/model_reader.h"
#include "massprops/output/reporters.h"
#include "xacro_cli.h"

namespace massprops::cli::lsp {

/// How documents are checked: `massprops lsp`'s options, overridden by the client's
/// `initializationOptions` (docs/editors.md lists them).
struct ServerOptions {
  std::string config;  ///< A .massprops.toml for every document; "" to find each one's own.
  std::string target;  ///< A target profile name; "" for the configuration's (else generic).
  std::vector<std::string> model_paths;    ///< Folders searched for SDF model:// URIs.
  std::vector<std::string> package_paths;  ///< Folders searched for package:// meshes.
  XacroOptions xacro;         ///< How a .xacro document is expanded (xacro_command, xacro_args).
  bool xacro_enabled = true;  ///< Check .xacro documents when an expander is found.
  std::string docs_url;       ///< Base URL of the docs folder (codeDescription); "" to find it.
};

/// One check of a document: the text it ran on and everything the answers need.
struct Analysis {
  int version = 0;
  std::string text;    ///< The text that was checked (the buffer, or the xacro expansion).
  bool xacro = false;  ///< The findings were traced from an expansion to the document's lines.
  /// The document is not a robot description (an .xml or .world file with another root): it
  /// gets no diagnostics.
  bool not_a_model = false;
  CheckSettings settings;
  ReadResult read;          ///< The models read from `text` (not from a xacro document).
  FileResult result;        ///< As `check` reports it.
  std::string setup_error;  ///< A configuration or expander error that kept it from running.
};

/// An open document.
struct Document {
  std::string uri;
  std::string path;  ///< The file's path ("" when the URI is not a file://).
  std::string text;
  int version = 0;
  bool stale = true;  ///< The text changed since the last check.
  std::optional<Analysis> analysis;
};

/// Sends one message to the client.
using SendFunction = std::function<void(const nlohmann::json&)>;

class Server {
 public:
  Server(ServerOptions options, SendFunction send);

  /// Handles one message (a request is answered through `send`). Never throws for bad input:
  /// an unknown request gets MethodNotFound, bad parameters InvalidParams.
  void Handle(const nlohmann::json& message);

  /// Checks every open document whose text changed since its last check and publishes its
  /// diagnostics.
  void CheckStale();

  /// True once `exit` has arrived; the exit code is 0 after `shutdown`, else 1 (LSP 3.17).
  bool exited() const { return exited_; }
  int exit_code() const { return shutdown_ ? 0 : 1; }

  /// The document with this URI, or null.
  const Document* Find(const std::string& uri) const;

 private:
  void HandleRequest(const std::string& method, const nlohmann::json& id,
                     const nlohmann::json& params);
  void HandleNotification(const std::string& method, const nlohmann::json& params);
  nlohmann::json Initialize(const nlohmann::json& params);
  // The document of params.textDocument.uri, checked when stale; null when it is not open.
  Document* CheckedDocument(const nlohmann::json& params);
  void Check(Document* document);
  void Publish(const Document& document);

  ServerOptions options_;
  SendFunction send_;
  std::map<std::string, Document> documents_;
  bool initialized_ = false;
  bool shutdown_ = false;
  bool exited_ = false;
};

/// Runs the server on `in_fd`/`out_fd` until `exit` or the end of input; returns the process
/// exit code (0 after shutdown and exit, 1 otherwise).
int RunLspServer(int in_fd, int out_fd, const ServerOptions& options);

/// Checks `document`'s text as `check` would check the file at its path: the configuration
/// that applies to the path (or options.config), the target, meshes resolved from the path's
/// folder; a .xacro document through its expander when one is available. Defined in
/// lsp_check.cc.
Analysis CheckDocument(const Document& document, const ServerOptions& options);

/// The LSP diagnostics of an analysis (lsp_diagnostics.cc).
nlohmann::json Diagnostics(const Document& document, const ServerOptions& options);

/// The LSP Range of a finding's 1-based line in `text`: from its first non-blank character to
/// the end of the line (0-based lines, UTF-16 columns); line 0 or a line beyond the text gives
/// the first line.
nlohmann::json LineRange(const std::string& text, int line);

/// textDocument/hover on an analysed document (lsp_hover.cc): Markdown, or null.
nlohmann::json Hover(const Document& document, int line, int utf16_column);

/// textDocument/codeAction on an analysed document (lsp_actions.cc): the repairs `fix` would
/// make for the findings whose diagnostics overlap the lines first_line..last_line (0-based).
nlohmann::json CodeActions(const Document& document, const ServerOptions& options, int first_line,
                           int last_line, const nlohmann::json& only_kinds);

}  // namespace massprops::cli::lsp
