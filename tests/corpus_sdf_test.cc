// Reads every `sdf` row of ../shared/corpus/MANIFEST.tsv with the model paths of the corpus README
// ("Resolving URIs") and compares the number of links with the MANIFEST `links` column.
//
// What the column counts (corpus README): the <link> elements of the file itself, from a raw XML
// walk; included models are NOT expanded. massprops expands <include>s, so the counts can only
// agree on files without includes (features without "includes="). For files with includes the
// test checks that massprops reads at least the file's own links, and lists the difference.
// Files tinyxml2 cannot parse (the notes say "tinyxml2 cannot parse": an XML declaration after a
// comment) must be rejected with an error naming the file and line (libsdformat rejects them too).

#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "corpus_manifest.h"
#include "massprops/io/sdf_reader.h"
#include "massprops/model/model.h"

namespace massprops {
namespace {

const std::string kCorpus = MASSPROPS_CORPUS_DIR;

struct Row {
  std::string file;
  int links = 0;
  std::string notes;
};

std::vector<Row> SdfRows() {
  std::vector<Row> rows;
  for (const test_support::ManifestRow& row : test_support::ReadCorpusManifest("sdf")) {
    rows.push_back({row.file, row.links, row.notes});
  }
  return rows;
}

SdfReadOptions CorpusOptions() {
  SdfReadOptions options;
  options.model_paths = test_support::CorpusModelPaths();
  options.use_environment = false;
  return options;
}

bool Contains(const std::string& s, const std::string& what) {
  return s.find(what) != std::string::npos;
}

TEST(CorpusSdfTest, EverySdfFileIsReadAndItsLinkCountMatchesTheManifest) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/MANIFEST.tsv");
  const std::vector<Row> rows = SdfRows();
  ASSERT_GT(rows.size(), 100u);  // MANIFEST.tsv lists 130+ sdf rows.
  int read = 0, matched = 0, with_includes = 0, rejected = 0;
  for (const Row& row : rows) {
    SCOPED_TRACE(row.file);
    const ReadResult result = ReadSdfFile(kCorpus + "/" + row.file, CorpusOptions());
    if (Contains(row.notes, "tinyxml2 cannot parse")) {
      ASSERT_FALSE(result.ok());
      EXPECT_GT(result.errors.front().location.line, 0);
      EXPECT_TRUE(Contains(result.errors.front().message, "malformed XML"));
      ++rejected;
      continue;
    }
    if (!result.ok()) {
      // A file massprops rejects must be one that libsdformat 12 rejects too (MANIFEST notes
      // "sdformat12-errors=N(...)"): the relative_to cycle and the joint whose parent is a
      // nested model's "M1::__model__".
      EXPECT_TRUE(Contains(row.notes, "sdformat12-errors")) << result.errors.front().ToString();
      EXPECT_GT(result.errors.front().location.line, 0) << result.errors.front().ToString();
      std::cout << "  rejected: " << result.errors.front().ToString() << "\n";
      ++rejected;
      continue;
    }
    ++read;
    size_t links = 0;
    for (const Model& m : result.models) links += m.links.size();
    if (Contains(row.notes, "includes=")) {
      ++with_includes;
      EXPECT_GE(links, static_cast<size_t>(row.links));
      std::cout << "  includes expanded: " << row.file << ": MANIFEST " << row.links
                << " links in the file itself, massprops " << links << " with the includes\n";
    } else {
      EXPECT_EQ(links, static_cast<size_t>(row.links));
      ++matched;
    }
  }
  std::cout << "corpus sdf: " << rows.size() << " rows, " << read << " read (" << matched
            << " link counts equal to MANIFEST, " << with_includes << " with includes), "
            << rejected << " rejected with an error\n";
}

}  // namespace
}  // namespace massprops
