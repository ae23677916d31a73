// `massprops lsp`: the language server (lsp_server.h, docs/editors.md) on standard input and
// output.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

#include "commands.h"
#include "lsp_server.h"
#include "target_cli.h"

namespace massprops::cli {

void AddLspCommand(CLI::App& app, std::function<int()>* run) {
  auto options = std::make_shared<lsp::ServerOptions>();
  auto no_xacro = std::make_shared<bool>(false);
  CLI::App* lsp = app.add_subcommand(
      "lsp",
      "Run the language server (Language Server Protocol 3.17 over standard input and output): "
      "the findings of check on the editor's unsaved text, hover with a link's mass properties, "
      "and fix's repairs as code actions. See docs/editors.md.");
  lsp->add_option("--config", options->config,
                  "Configuration file for every document (default: the .massprops.toml found "
                  "upward from each document)")
      ->check(CLI::ExistingFile);
  AddTargetOption(lsp, &options->target);
  lsp->add_option("--model-path", options->model_paths,
                  "Folder searched for SDF model:// URIs (repeatable)")
      ->type_name("DIR")
      ->allow_extra_args(false);
  lsp->add_option("--package-path", options->package_paths,
                  "Folder searched for package:// meshes (repeatable)")
      ->type_name("DIR")
      ->allow_extra_args(false);
  lsp->add_option("--xacro-command", options->xacro.xacro_command,
                  "The program that expands .xacro documents (default: xacro on PATH)");
  lsp->add_option("--xacro-arg", options->xacro.xacro_args,
                  "A xacro argument NAME:=VALUE for every .xacro document (repeatable)")
      ->type_name("NAME:=VALUE")
      ->allow_extra_args(false);
  lsp->add_flag("--no-xacro", *no_xacro, "Do not expand .xacro documents");
  lsp->add_option("--docs-url", options->docs_url,
                  "Base URL of the docs folder, for each diagnostic's link to its rule (default: "
                  "the docs installed with massprops, as a file:// URL)");
  lsp->callback([run, options, no_xacro] {
    *run = [options, no_xacro] {
      options->xacro_enabled = !*no_xacro;
      return lsp::RunLspServer(STDIN_FILENO, STDOUT_FILENO, *options);
    };
  });
}

}  // namespace massprops::cli
