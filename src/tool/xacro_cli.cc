#include "xacro_cli.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "massprops/analysis/finding_sources.h"
#include "safe_write.h"

namespace massprops::cli {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> SplitWords(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string word; in >> word;) out.push_back(word);
  return out;
}

// The program to run: --xacro-command's words, else `xacro` when it is on PATH.
std::vector<std::string> ExpanderCommand(const XacroOptions& options) {
  if (!options.xacro_command.empty()) return SplitWords(options.xacro_command);
  const char* path = std::getenv("PATH");
  if (path == nullptr) return {};
  std::istringstream dirs(path);
  for (std::string dir; std::getline(dirs, dir, ':');) {
    if (dir.empty()) continue;
    const fs::path candidate = fs::path(dir) / "xacro";
    if (access(candidate.c_str(), X_OK) == 0) return {candidate.string()};
  }
  return {};
}

// Runs argv with standard output captured; nullopt with *error on failure.
std::optional<std::string> RunCapture(const std::vector<std::string>& argv, std::string* error) {
  int fds[2];
  if (pipe(fds) != 0) {
    *error = std::string("cannot make a pipe: ") + std::strerror(errno);
    return std::nullopt;
  }
  const pid_t pid = fork();
  if (pid < 0) {
    *error = std::string("cannot start the expander: ") + std::strerror(errno);
    close(fds[0]);
    close(fds[1]);
    return std::nullopt;
  }
  if (pid == 0) {
    // The expander reads files, never standard input: under `massprops lsp` that is the
    // editor's message stream, which it must not take from the server.
    const int null_fd = open("/dev/null", O_RDONLY);
    if (null_fd >= 0) dup2(null_fd, STDIN_FILENO);
    dup2(fds[1], STDOUT_FILENO);
    close(fds[0]);
    close(fds[1]);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    std::fprintf(stderr, "massprops: cannot run %s: %s\n", args[0], std::strerror(errno));
    _exit(127);
  }
  close(fds[1]);
  std::string out;
  char buffer[65536];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    out.append(buffer, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    *error = "the expander '" + argv[0] + "' failed (exit status " +
             std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")";
    return std::nullopt;
  }
  return out;
}

std::map<std::string, std::string> ParseArgs(const std::vector<std::string>& args) {
  std::map<std::string, std::string> out;
  for (const std::string& a : args) {
    const std::size_t eq = a.find(":=");
    if (eq != std::string::npos) out[a.substr(0, eq)] = a.substr(eq + 2);
  }
  return out;
}

// The folder of the package that holds `file`: the nearest folder upward with a package.xml.
std::string PackageRootOf(const std::string& file) {
  std::error_code ec;
  fs::path dir = fs::path(file).parent_path();
  if (dir.empty()) dir = ".";
  for (fs::path d = dir; !d.empty(); d = d.parent_path()) {
    if (fs::exists(d / "package.xml", ec)) return d.lexically_normal().string();
    if (d == d.parent_path() || d == ".") break;
  }
  return dir.lexically_normal().string();
}

}  // namespace

void AddXacroOptions(CLI::App* command, XacroOptions* options) {
  command
      ->add_option("--xacro-arg", options->xacro_args,
                   "A xacro argument NAME:=VALUE for the expansion of a .xacro FILE (repeatable)")
      ->type_name("NAME:=VALUE")
      ->allow_extra_args(false);
  command->add_option("--xacro-command", options->xacro_command,
                      "The program that expands a .xacro FILE (its words, then FILE and the "
                      "--xacro-arg values); default: xacro on PATH");
  command->add_option("--expanded", options->expanded,
                      "An expansion made elsewhere (URDF): checked, and traced to --source-root");
  command
      ->add_option("--source-root", options->source_roots,
                   "Folder of the xacro package's sources, searched recursively for .xacro, "
                   ".urdf and .yaml files (repeatable; default: the package of FILE)")
      ->type_name("DIR")
      ->allow_extra_args(false);
}

bool IsXacroRun(const XacroOptions& options, const std::string& file) {
  if (!options.expanded.empty()) return true;
  return file.size() > 6 && file.compare(file.size() - 6, 6, ".xacro") == 0;
}

std::optional<Expansion> MakeExpansion(const XacroOptions& options, const std::string& top,
                                       std::string* error) {
  Expansion expansion;
  expansion.trace.args = ParseArgs(options.xacro_args);
  expansion.trace.source_roots = options.source_roots;
  if (!options.expanded.empty()) {
    std::ifstream in(options.expanded, std::ios::binary);
    if (!in) {
      *error = "cannot read the expansion " + options.expanded;
      return std::nullopt;
    }
    std::ostringstream text;
    text << in.rdbuf();
    expansion.text = text.str();
    expansion.name = options.expanded;
    expansion.trace.exclude_files.push_back(options.expanded);
    if (expansion.trace.source_roots.empty()) {
      if (top.empty()) {
        *error = "--expanded needs --source-root DIR: the folder of the sources it was made from";
        return std::nullopt;
      }
      expansion.trace.source_roots.push_back(PackageRootOf(top));
    }
    return expansion;
  }
  std::vector<std::string> argv = ExpanderCommand(options);
  if (argv.empty()) {
    *error = "no xacro program found on PATH to expand " + top +
             ": install ROS's xacro, name an expander with --xacro-command CMD, or expand "
             "elsewhere and check the result with `massprops check --expanded robot.urdf "
             "--source-root PKG_DIR`";
    return std::nullopt;
  }
  argv.push_back(top);
  argv.insert(argv.end(), options.xacro_args.begin(), options.xacro_args.end());
  std::optional<std::string> text = RunCapture(argv, error);
  if (!text) return std::nullopt;
  expansion.text = std::move(*text);
  expansion.name = "<expansion of " + top + ">";
  if (expansion.trace.source_roots.empty()) {
    expansion.trace.source_roots.push_back(PackageRootOf(top));
  }
  return expansion;
}

std::optional<std::string> ReExpand(const XacroOptions& options, const std::string& top,
                                    std::string* error) {
  std::vector<std::string> argv = ExpanderCommand(options);
  if (argv.empty() || top.empty()) {
    *error = "no expander available (no .xacro FILE, or no xacro on PATH and no --xacro-command)";
    return std::nullopt;
  }
  argv.push_back(top);
  argv.insert(argv.end(), options.xacro_args.begin(), options.xacro_args.end());
  return RunCapture(argv, error);
}

std::optional<XacroRun> StartXacroRun(const XacroOptions& options, const std::string& top,
                                      std::string* error) {
  std::optional<Expansion> expansion = MakeExpansion(options, top, error);
  if (!expansion) return std::nullopt;
  XacroRun run;
  run.expansion = std::move(*expansion);
  if (!options.expanded.empty()) {
    run.checked_file = options.expanded;
    return run;
  }
  std::string pattern = (fs::temp_directory_path() / "massprops-expansion-XXXXXX").string();
  const int fd = mkstemp(pattern.data());
  if (fd < 0) {
    *error = std::string("cannot write the expansion to a temporary file: ") + std::strerror(errno);
    return std::nullopt;
  }
  const std::string& text = run.expansion.text;
  const bool complete = WriteAll(fd, text);
  close(fd);
  run.checked_file = pattern;
  run.temporary = true;
  if (!complete) {
    std::remove(pattern.c_str());
    *error = "cannot write the expansion to a temporary file";
    return std::nullopt;
  }
  return run;
}

void FinishXacroRun(XacroRun* run, FileResult* result) {
  const std::string& name = run->expansion.name;
  if (run->temporary) {
    std::remove(run->checked_file.c_str());
    result->path = name;
    for (Finding& f : result->findings) {
      if (f.location.file.empty() || f.location.file == run->checked_file) f.location.file = name;
    }
    for (ReadError& e : result->errors) {
      if (e.location.file.empty() || e.location.file == run->checked_file) e.location.file = name;
    }
  }
  const XacroTrace trace = TraceXacro(run->expansion.text, name, run->expansion.trace);
  for (const ReadError& e : trace.errors) {
    std::cerr << "massprops: warning: " << e.ToString() << " (the trace goes on without it)\n";
  }
  AttachSources(trace, name, result);
}

void AttachSources(const XacroTrace& trace, const std::string& generated_name, FileResult* result) {
  AttachXacroSources(trace, generated_name, &result->findings);
}

void AddTraceCommand(CLI::App& app, std::function<int()>* run) {
  struct TraceArgs {
    std::string file;
    std::string format = "text";
    XacroOptions xacro;
  };
  auto args = std::make_shared<TraceArgs>();
  CLI::App* trace = app.add_subcommand(
      "trace",
      "Show where each <inertial> number of a xacro package was written (file, line, how): "
      "expands FILE.xacro, or reads --expanded with --source-root");
  trace->add_option("FILE", args->file, "The package's top .xacro file");
  trace
      ->add_option("--format", args->format, "text, json, or summary (the shares of docs/xacro.md)")
      ->check(CLI::IsMember({"text", "json", "summary"}))
      ->capture_default_str();
  AddXacroOptions(trace, &args->xacro);
  trace->callback([args, run] {
    *run = [args]() -> int {
      if (args->file.empty() && args->xacro.expanded.empty()) {
        std::cerr << "massprops: error: trace needs a .xacro FILE or --expanded FILE\n";
        return 2;
      }
      std::string error;
      std::optional<Expansion> expansion = MakeExpansion(args->xacro, args->file, &error);
      if (!expansion) {
        std::cerr << "massprops: error: " << error << "\n";
        return 2;
      }
      const XacroTrace result = TraceXacro(expansion->text, expansion->name, expansion->trace);
      for (const ReadError& e : result.errors) {
        std::cerr << "massprops: warning: " << e.ToString() << " (traced without it)\n";
      }
      if (args->format == "json") {
        nlohmann::ordered_json numbers = nlohmann::ordered_json::array();
        for (const TracedNumber& n : result.numbers) {
          nlohmann::ordered_json places = nlohmann::ordered_json::array();
          for (const SourcePlace& p : n.places) {
            places.push_back({{"file", p.file},
                              {"line", p.line},
                              {"how", p.how},
                              {"text", p.text},
                              {"inputs", p.inputs},
                              {"editable", p.editable}});
          }
          numbers.push_back({{"link", n.link},
                             {"element", n.element},
                             {"attribute", n.attribute},
                             {"value", n.expanded_value},
                             {"generated_line", n.expanded_line},
                             {"places", places}});
        }
        std::cout << nlohmann::ordered_json{{"generated", expansion->name},
                                            {"source_files", result.source_files},
                                            {"numbers", numbers}}
                         .dump(2)
                  << "\n";
      } else if (args->format == "summary") {
        int one = 0, several = 0, computed = 0, none = 0;
        for (const TracedNumber& n : result.numbers) {
          if (n.places.empty()) {
            ++none;
          } else if (n.places.size() > 1) {
            ++several;
          } else if (n.places.front().how == "computed") {
            ++computed;
          } else {
            ++one;
          }
        }
        std::cout << result.numbers.size() << "\t" << one << "\t" << several << "\t" << computed
                  << "\t" << none << "\n";
      } else {
        for (const TracedNumber& n : result.numbers) {
          std::cout << n.link << " " << NumberName(n) << " " << n.expanded_value << " (generated "
                    << n.expanded_line << "): ";
          if (n.places.empty()) std::cout << "not traced";
          if (n.places.size() > 1) std::cout << n.places.size() << " places: ";
          for (std::size_t i = 0; i < n.places.size(); ++i) {
            const SourcePlace& p = n.places[i];
            std::cout << (i ? "; " : "") << p.file << ":" << p.line << " " << p.how;
            if (!p.inputs.empty()) {
              std::cout << " (";
              for (std::size_t k = 0; k < p.inputs.size(); ++k) {
                std::cout << (k ? ", " : "") << p.inputs[k];
              }
              std::cout << ")";
            }
          }
          std::cout << "\n";
        }
      }
      return 0;
    };
  });
}

}  // namespace massprops::cli
