#include "lsp_server.h"

#include <algorithm>
#include <csignal>
#include <exception>
#include <utility>

#include "lsp_protocol.h"
#include "massprops/analysis/target_profile.h"

namespace massprops::cli::lsp {
namespace {

using nlohmann::json;

// JSON-RPC and LSP error codes.
constexpr int kParseError = -32700;
constexpr int kInvalidRequest = -32600;
constexpr int kMethodNotFound = -32601;
constexpr int kInvalidParams = -32602;
constexpr int kInternalError = -32603;
constexpr int kServerNotInitialized = -32002;

json ErrorResponse(const json& id, int code, const std::string& message) {
  return {{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}};
}

json Notification(const std::string& method, json params) {
  return {{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}};
}

// A message to the client's log (window/logMessage; type 1 error, 2 warning, 3 info).
json LogMessage(int type, const std::string& text) {
  return Notification("window/logMessage", {{"type", type}, {"message", "massprops: " + text}});
}

std::vector<std::string> StringList(const json& value) {
  std::vector<std::string> out;
  if (!value.is_array()) return out;
  for (const json& item : value) {
    if (item.is_string()) out.push_back(item.get<std::string>());
  }
  return out;
}

// The string at `key` of `object`, or `fallback`.
std::string StringAt(const json& object, const char* key, const std::string& fallback = "") {
  if (!object.is_object()) return fallback;
  const auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : fallback;
}

// Applies the client's initializationOptions (docs/editors.md) to `options`; returns the
// problems found (an unknown target), each a sentence.
std::vector<std::string> ApplyInitializationOptions(const json& init, ServerOptions* options) {
  std::vector<std::string> problems;
  if (!init.is_object()) return problems;
  options->config = StringAt(init, "config", options->config);
  const std::string target = StringAt(init, "target", options->target);
  if (!target.empty() && !ParseTarget(target)) {
    problems.push_back("unknown target '" + target + "' in initializationOptions; ignored");
  } else {
    options->target = target;
  }
  for (const std::string& path : StringList(init.value("modelPaths", json()))) {
    options->model_paths.push_back(path);
  }
  for (const std::string& path : StringList(init.value("packagePaths", json()))) {
    options->package_paths.push_back(path);
  }
  options->docs_url = StringAt(init, "docsUrl", options->docs_url);
  const json xacro = init.value("xacro", json());
  if (xacro.is_object()) {
    options->xacro.xacro_command = StringAt(xacro, "command", options->xacro.xacro_command);
    if (xacro.contains("args")) options->xacro.xacro_args = StringList(xacro["args"]);
    if (xacro.contains("enabled") && xacro["enabled"].is_boolean()) {
      options->xacro_enabled = xacro["enabled"].get<bool>();
    }
  }
  return problems;
}

// The UTF-8 byte offset of an LSP position in `text` (clamped to the text).
std::size_t OffsetOf(const std::string& text, const json& position) {
  const int line = position.value("line", 0);
  std::size_t start = 0;
  for (int i = 0; i < line; ++i) {
    const std::size_t newline = text.find('\n', start);
    if (newline == std::string::npos) return text.size();
    start = newline + 1;
  }
  std::size_t end = text.find('\n', start);
  if (end == std::string::npos) end = text.size();
  const int column = std::max(0, position.value("character", 0));
  return start + ByteOfUtf16Column(std::string_view(text).substr(start, end - start),
                                   static_cast<std::size_t>(column));
}

// Applies one TextDocumentContentChangeEvent: the whole text, or (a client that sends ranges
// although the server asked for full sync) the text of a range.
void ApplyChange(const json& change, std::string* text) {
  if (!change.is_object() || !change.contains("text") || !change["text"].is_string()) return;
  const std::string& replacement = change["text"].get_ref<const std::string&>();
  if (!change.contains("range") || !change["range"].is_object()) {
    *text = replacement;
    return;
  }
  const json& range = change["range"];
  const std::size_t start = OffsetOf(*text, range.value("start", json::object()));
  const std::size_t end = std::max(start, OffsetOf(*text, range.value("end", json::object())));
  text->replace(start, end - start, replacement);
}

}  // namespace

Server::Server(ServerOptions options, SendFunction send)
    : options_(std::move(options)), send_(std::move(send)) {}

const Document* Server::Find(const std::string& uri) const {
  const auto it = documents_.find(uri);
  return it == documents_.end() ? nullptr : &it->second;
}

void Server::Handle(const json& message) {
  if (!message.is_object() || !message.contains("method") || !message["method"].is_string()) {
    if (message.is_object() && message.contains("id") && !message.contains("result") &&
        !message.contains("error")) {
      send_(ErrorResponse(message["id"], kInvalidRequest, "a request without a method"));
    }
    return;  // a response to nothing the server asked, or garbage without an id
  }
  const std::string method = message["method"].get<std::string>();
  const json params = message.value("params", json::object());
  const bool is_request = message.contains("id");
  try {
    if (is_request) {
      HandleRequest(method, message["id"], params);
    } else {
      HandleNotification(method, params);
    }
  } catch (const json::exception& error) {  // params of the wrong shape
    if (is_request) {
      send_(ErrorResponse(message["id"], kInvalidParams, method + ": " + error.what()));
    } else {
      send_(LogMessage(1, method + ": " + error.what()));
    }
  } catch (const std::exception& error) {
    if (is_request) {
      send_(ErrorResponse(message["id"], kInternalError, method + ": " + error.what()));
    } else {
      send_(LogMessage(1, method + ": " + error.what()));
    }
  }
}

json Server::Initialize(const json& params) {
  const json init = params.is_object() ? params.value("initializationOptions", json()) : json();
  for (const std::string& problem : ApplyInitializationOptions(init, &options_)) {
    send_(LogMessage(2, problem));
  }
  return {{"capabilities",
           {{"positionEncoding", "utf-16"},
            {"textDocumentSync",
             {{"openClose", true}, {"change", 1}, {"save", {{"includeText", false}}}}},
            {"hoverProvider", true},
            {"codeActionProvider", {{"codeActionKinds", {"quickfix", "refactor.rewrite"}}}}}},
          {"serverInfo", {{"name", "massprops"}, {"version", MASSPROPS_VERSION}}}};
}

Document* Server::CheckedDocument(const json& params) {
  const std::string uri = params.at("textDocument").at("uri").get<std::string>();
  const auto it = documents_.find(uri);
  if (it == documents_.end()) return nullptr;
  if (it->second.stale) Check(&it->second);
  return &it->second;
}

void Server::HandleRequest(const std::string& method, const json& id, const json& params) {
  const auto reply = [&](json result) {
    send_({{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}});
  };
  if (method == "initialize") {
    reply(Initialize(params));
    initialized_ = true;
    return;
  }
  if (!initialized_) {
    send_(ErrorResponse(id, kServerNotInitialized, "initialize first"));
    return;
  }
  if (shutdown_) {
    send_(ErrorResponse(id, kInvalidRequest, "the server is shutting down"));
    return;
  }
  if (method == "shutdown") {
    shutdown_ = true;
    reply(nullptr);
  } else if (method == "textDocument/hover") {
    const Document* document = CheckedDocument(params);
    const json& position = params.at("position");
    reply(document ? Hover(*document, position.at("line").get<int>(),
                           position.at("character").get<int>())
                   : json());
  } else if (method == "textDocument/codeAction") {
    const Document* document = CheckedDocument(params);
    const json& range = params.at("range");
    const json only = params.value("context", json::object()).value("only", json());
    reply(document ? CodeActions(*document, options_, range.at("start").at("line").get<int>(),
                                 range.at("end").at("line").get<int>(), only)
                   : json::array());
  } else {
    send_(ErrorResponse(id, kMethodNotFound, "massprops lsp does not answer " + method));
  }
}

void Server::HandleNotification(const std::string& method, const json& params) {
  if (method == "exit") {
    exited_ = true;
    return;
  }
  if (!initialized_ || shutdown_) return;  // dropped, as LSP 3.17 says
  if (method == "textDocument/didOpen") {
    const json& item = params.at("textDocument");
    Document document;
    document.uri = item.at("uri").get<std::string>();
    document.path = PathFromUri(document.uri);
    document.text = item.at("text").get<std::string>();
    document.version = item.value("version", 0);
    documents_[document.uri] = std::move(document);
  } else if (method == "textDocument/didChange") {
    const json& item = params.at("textDocument");
    const auto it = documents_.find(item.at("uri").get<std::string>());
    if (it == documents_.end()) return;
    for (const json& change : params.at("contentChanges")) ApplyChange(change, &it->second.text);
    it->second.version = item.value("version", it->second.version + 1);
    it->second.stale = true;
  } else if (method == "textDocument/didSave") {
    // The files beside it (meshes, included files, .massprops.toml) may have changed too.
    const auto it = documents_.find(params.at("textDocument").at("uri").get<std::string>());
    if (it != documents_.end()) it->second.stale = true;
  } else if (method == "textDocument/didClose") {
    const std::string uri = params.at("textDocument").at("uri").get<std::string>();
    if (documents_.erase(uri) > 0) {
      send_(Notification("textDocument/publishDiagnostics",
                         {{"uri", uri}, {"diagnostics", json::array()}}));
    }
  } else if (method == "workspace/didChangeConfiguration") {
    for (auto& [uri, document] : documents_) document.stale = true;
  }
  // initialized, $/cancelRequest, $/setTrace and the rest need nothing.
}

void Server::Check(Document* document) {
  document->analysis.reset();  // the old one's memory is given back before the new is made
  document->analysis = CheckDocument(*document, options_);
  document->stale = false;
  Publish(*document);
}

void Server::Publish(const Document& document) {
  send_(Notification("textDocument/publishDiagnostics",
                     {{"uri", document.uri},
                      {"version", document.version},
                      {"diagnostics", Diagnostics(document, options_)}}));
}

void Server::CheckStale() {
  for (auto& [uri, document] : documents_) {
    if (!document.stale) continue;
    try {
      Check(&document);
    } catch (const std::exception& error) {
      document.stale = false;
      send_(LogMessage(1, "checking " + uri + " failed: " + error.what()));
    }
  }
}

int RunLspServer(int in_fd, int out_fd, const ServerOptions& options) {
  std::signal(SIGPIPE, SIG_IGN);  // a client that went away is a failed write, not a kill
  MessageReader reader(in_fd);
  bool output_open = true;
  Server server(options, [out_fd, &output_open](const json& message) {
    if (output_open) output_open = WriteMessage(out_fd, message);
  });
  for (;;) {
    json message;
    std::string error;
    const MessageReader::Status status = reader.Next(&message, &error);
    if (status == MessageReader::Status::kEnd) break;
    if (status == MessageReader::Status::kBadMessage) {
      WriteMessage(out_fd, ErrorResponse(nullptr, kParseError, error));
      continue;
    }
    server.Handle(message);
    if (server.exited()) return server.exit_code();
    // Every message that has arrived is handled before a check: only the newest text is checked.
    if (!reader.HasPending()) server.CheckStale();
  }
  return 1;  // the input ended without `exit`
}

}  // namespace massprops::cli::lsp
