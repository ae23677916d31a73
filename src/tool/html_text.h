#pragma once
// Text placed into the tool's self-contained HTML pages (`massprops view`, `identify --html`).

#include <cstddef>
#include <string>

namespace massprops::cli {

/// `text` as HTML character data or a quoted attribute value: & < > " escaped.
inline std::string EscapeHtml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

/// `script` made safe as the content of a <script> element: "</script" can only stand in a
/// string, a comment or a regular expression of valid script, where "<\/script" means the same,
/// so the element cannot end early.
inline std::string ScriptElementText(std::string script) {
  for (std::size_t at = script.find("</script"); at != std::string::npos;
       at = script.find("</script", at)) {
    script.insert(at + 1, "\\");
  }
  return script;
}

}  // namespace massprops::cli
