#pragma once
// Which options of `massprops check` to build before parsing. CLI11 spends about 6 000
// instructions on each option it adds (the option's validators and names, and a comparison with
// every option added before it); for `massprops check -q robot.urdf`, run once per changed file by
// pre-commit hooks, building all 18 of them was 0.3 million instructions of a 4.9 million run
// (callgrind; docs/benchmarks.md, section 3).
//
// An option that no word of the command line names cannot change how CLI11 parses it, so only
// the named ones are built. Anything this does not understand for certain builds them all: a
// word that names no option of check (--help, a typo: CLI11 then gives its usual message), a
// run of short options (-qj2), or `--` (after it every word is a FILE).
#include <algorithm>
#include <initializer_list>
#include <string_view>
#include <utility>
#include <vector>

namespace massprops::cli {

/// Every name of every option of `massprops check` (src/tool/main.cc builds them). A test
/// (cli_test, CheckOptionNamesAreThoseOfTheHelp) asserts that `massprops check --help` lists
/// exactly these, besides -h and --help.
inline const std::vector<std::string_view>& CheckOptionNames() {
  // clang-format off
  static const std::vector<std::string_view> kNames = {
      "--format", "--color", "--fail-on", "--disable", "--severity", "--tolerance", "--config",
      "--model-path", "--target", "--data", "-q", "--quiet", "--brief", "--explain",
      "--statistics", "-j", "--jobs", "--list-rules", "--geometry", "--no-geometry",
      "--geometry-factor", "--package-path", "--no-cache", "--xacro-arg", "--xacro-command",
      "--expanded", "--source-root", "--max-input-size"};
  // clang-format on
  return kNames;
}

class OptionFilter {
 public:
  /// Every option.
  OptionFilter() = default;

  /// The options of `massprops check` that `argv` names, or every option when argv[1] is not
  /// `check` or when a word is not certainly a FILE, a value or the name of one of `known` (a
  /// word like `--format=json` names `--format`). `known`: every name of every option of check (a
  /// name missing from it would only make the command lines that use it build every option).
  static OptionFilter ForCheck(int argc, const char* const* argv,
                               const std::vector<std::string_view>& known = CheckOptionNames()) {
    OptionFilter filter;
    if (argc < 2 || std::string_view(argv[1]) != "check") return filter;
    std::vector<std::string_view> named;
    for (int i = 2; i < argc; ++i) {
      std::string_view word(argv[i]);
      if (word.size() < 2 || word[0] != '-') continue;  // a FILE, `-` (standard input) or a value
      if (word.substr(0, 2) == "--") {
        word = word.substr(0, word.find('='));
      } else if (word.size() > 2) {
        return filter;  // -qj2, -j4, or a negative number
      }
      if (std::find(known.begin(), known.end(), word) == known.end()) return filter;
      named.push_back(word);
    }
    filter.all_ = false;
    filter.named_ = std::move(named);
    return filter;
  }

  /// Whether to build the option with these names (e.g. "-q", "--quiet").
  bool Wants(std::initializer_list<std::string_view> names) const {
    if (all_) return true;
    return std::any_of(names.begin(), names.end(), [this](std::string_view name) {
      return std::find(named_.begin(), named_.end(), name) != named_.end();
    });
  }

  /// Whether every option is built.
  bool all() const { return all_; }

 private:
  bool all_ = true;
  std::vector<std::string_view> named_;
};

}  // namespace massprops::cli
