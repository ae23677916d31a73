#pragma once
// `--max-input-size SIZE` on check and report: the largest model file read (the readers refuse
// larger ones, so that a wrong or hostile input cannot take the machine's memory; the default is
// kMaxModelFileBytes, 256 MiB). Generated worlds of 10^6 links are larger (docs/benchmarks.md
// section 11).
#include <CLI/CLI.hpp>
#include <cstddef>
#include <limits>

#include "massprops/io/model_reader.h"

namespace massprops::cli {

/// Adds `--max-input-size SIZE` to a subcommand: bytes, or with a unit K, M, G (KiB, MiB, GiB:
/// powers of 1024; "300M", "2G", "2GiB"). `*bytes` keeps its value when the option is not given.
inline CLI::Option* AddMaxInputSizeOption(CLI::App* command, std::size_t* bytes) {
  return command
      ->add_option("--max-input-size", *bytes,
                   "Refuse model files larger than this: bytes, or with a unit K, M or G "
                   "(powers of 1024; default 256M)")
      ->type_name("SIZE")
      ->transform(CLI::AsSizeValue(/*kb_is_1000=*/false))
      ->check(CLI::Range(std::size_t{1}, std::numeric_limits<std::size_t>::max()));
}

}  // namespace massprops::cli
