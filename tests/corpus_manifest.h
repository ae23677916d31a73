#pragma once
// The rows of ../shared/corpus/MANIFEST.tsv (MASSPROPS_CORPUS_DIR), for the corpus tests.
// Columns: file, format, source_repo, commit, original_path, license, links, notes,
// invalid_inertial_links (the corpus README explains each).

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "shared_data.h"

namespace massprops::test_support {

struct ManifestRow {
  std::string file;         ///< Relative to the corpus folder.
  std::string format;       ///< urdf, sdf, mesh, config or license.
  std::string source_repo;  ///< e.g. "Gepetto/example-robot-data".
  int links = -1;           ///< The `links` column; -1 when empty.
  std::string notes;        ///< The `notes` column (`;`-separated facts).
};

/// The corpus folder (MASSPROPS_CORPUS_DIR).
inline std::string CorpusDir() { return MASSPROPS_CORPUS_DIR; }

/// The corpus's model folders, searched for model:// URIs (the corpus README, "Resolving URIs"),
/// relative to CorpusDir().
inline const std::vector<std::string>& CorpusModelFolders() {
  static const std::vector<std::string> kFolders = {
      "gazebo_models", "sdformat/test/integration/model", "gz-sim/test/worlds/models",
      "example-robot-data/robots"};
  return kFolders;
}

/// CorpusModelFolders() as paths from the working directory.
inline std::vector<std::string> CorpusModelPaths() {
  std::vector<std::string> paths;
  for (const std::string& folder : CorpusModelFolders())
    paths.push_back(CorpusDir() + "/" + folder);
  return paths;
}

/// Every row of the MANIFEST whose format is `format` (every row when `format` is empty), in file
/// order; empty when the corpus is absent.
inline std::vector<ManifestRow> ReadCorpusManifest(const std::string& format = "") {
  std::vector<ManifestRow> rows;
  std::ifstream in(CorpusDir() + "/MANIFEST.tsv");
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    std::string cell;
    while (std::getline(stream, cell, '\t')) cells.push_back(cell);
    if (cells.size() < 2 || (!format.empty() && cells[1] != format)) continue;
    cells.resize(8);
    rows.push_back(
        {cells[0], cells[1], cells[2], cells[6].empty() ? -1 : std::stoi(cells[6]), cells[7]});
  }
  return rows;
}

}  // namespace massprops::test_support
