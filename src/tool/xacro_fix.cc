#include "xacro_fix.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "massprops/core/format_number.h"
#include "massprops/output/xml_patch.h"
#include "safe_write.h"

namespace massprops::cli {
namespace {

// One byte range of a source file to replace.
struct Edit {
  std::string file;
  std::size_t offset = 0, length = 0;
  std::string old_text, new_text;
  int line = 0;
  std::string how;
  std::string link, number;  // the first repaired number it writes
};

const TracedNumber* FindNumber(const XacroTrace& trace, const std::string& link,
                               const std::string& element, const std::string& attribute) {
  for (const TracedNumber& n : trace.numbers) {
    if (n.link == link && n.element == element && n.attribute == attribute) return &n;
  }
  return nullptr;
}

bool SamePlace(const SourcePlace& a, const SourcePlace& b) {
  return a.file == b.file && a.line == b.line && a.offset == b.offset && a.how == b.how;
}

std::string ReadText(const std::string& path, bool* ok) {
  std::ifstream in(path, std::ios::binary);
  *ok = static_cast<bool>(in);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The new text of a place: its blank-separated numbers with those at first_token.. replaced.
std::string NewText(const std::string& old_text, const FieldChange& change) {
  if (change.new_values.size() == 1 && change.first_token == 0 &&
      old_text.find_first_of(" \t") == std::string::npos) {
    return FormatShortest(change.new_values[0]);
  }
  std::istringstream in(old_text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  for (std::size_t i = 0; i < change.new_values.size(); ++i) {
    const std::size_t at = static_cast<std::size_t>(change.first_token) + i;
    if (at < words.size()) words[at] = FormatShortest(change.new_values[i]);
  }
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i) out += (i ? " " : "") + words[i];
  return out;
}

}  // namespace

int FixXacroSources(const XacroOptions& options, const std::string& top, const XacroRun& run,
                    const std::vector<Repair>& repairs, const std::string& patched_expansion,
                    const XacroFixRequest& request) {
  const XacroTrace trace = TraceXacro(run.expansion.text, run.expansion.name, run.expansion.trace);
  // What each repaired number becomes: (link, element, attribute) → new text of the number.
  std::map<std::tuple<std::string, std::string, std::string>, std::vector<double>> wanted;
  for (const Repair& r : repairs) {
    for (const FieldChange& c : r.changes) {
      const TracedNumber* n = FindNumber(trace, r.link, c.element, c.attribute);
      if (!n) continue;
      std::vector<double> values;
      std::istringstream in(n->expanded_value);
      for (double v; in >> v;) values.push_back(v);
      for (std::size_t i = 0; i < c.new_values.size(); ++i) {
        const std::size_t at = static_cast<std::size_t>(c.first_token) + i;
        if (at < values.size()) values[at] = c.new_values[i];
      }
      wanted[{r.link, c.element, c.attribute}] = values;
    }
  }

  std::vector<Edit> edits;
  int by_hand = 0;
  auto refuse = [&](const Repair& r, const FieldChange& c, const std::string& where,
                    const std::string& reason) {
    ++by_hand;
    std::string values;
    for (double v : c.new_values) values += (values.empty() ? "" : " ") + FormatShortest(v);
    std::cout << where << ": link '" << r.link << "': change " << c.element
              << (c.element == "mass" ? "" : " " + c.attribute) << " to " << values
              << " by hand: " << reason << "\n";
  };
  for (const Repair& r : repairs) {
    if (r.inserts_inertial || r.inserts_origin) {
      ++by_hand;
      std::cout << run.expansion.name << ": link '" << r.link << "': " << DescribeRepair(r)
                << ": the repair adds an element, which is not written into xacro sources; add "
                   "it by hand\n";
      continue;
    }
    // A repair is written whole or not at all: a part of it could leave the link worse.
    const int refused_before = by_hand;
    std::vector<std::pair<Edit, const FieldChange*>> planned;
    for (const FieldChange& c : r.changes) {
      const TracedNumber* n = FindNumber(trace, r.link, c.element, c.attribute);
      const std::string generated =
          run.expansion.name + ":" + std::to_string(n ? n->expanded_line : c.line);
      if (!n || n->places.empty()) {
        refuse(r, c, generated, "the number was not traced to the sources");
        continue;
      }
      if (n->places.size() > 1) {
        std::string all;
        for (const SourcePlace& p : n->places) all += " " + p.file + ":" + std::to_string(p.line);
        refuse(r, c, generated, "it is written at several places, none closer to the link:" + all);
        continue;
      }
      const SourcePlace& place = n->places.front();
      const std::string where = place.file + ":" + std::to_string(place.line);
      if (place.how == "computed") {
        std::string inputs;
        for (const std::string& i : place.inputs) inputs += (inputs.empty() ? "" : ", ") + i;
        refuse(r, c, where,
               "the value is computed (from " + inputs + "), not written: change its inputs");
        continue;
      }
      if (place.how == "parameter") {
        refuse(r, c, where,
               "the value is a macro argument or property (" + place.text +
                   "), which other places may read");
        continue;
      }
      if (!place.editable) {
        refuse(r, c, where, "the text there cannot be replaced exactly");
        continue;
      }
      // Shared: every other number written at this place must become the same.
      std::set<std::string> others;
      const std::vector<double>& mine = wanted[{r.link, c.element, c.attribute}];
      for (const TracedNumber& other : trace.numbers) {
        if (&other == n) continue;
        if (std::none_of(other.places.begin(), other.places.end(),
                         [&](const SourcePlace& p) { return SamePlace(p, place); })) {
          continue;
        }
        auto w = wanted.find({other.link, other.element, other.attribute});
        if (w == wanted.end() || w->second != mine) others.insert(other.link);
      }
      if (!others.empty()) {
        std::string list;
        for (const std::string& l : others) list += (list.empty() ? "'" : ", '") + l + "'";
        refuse(r, c, where, "the value is shared with " + list + ", which need no such repair");
        continue;
      }
      Edit edit;
      edit.file = place.file;
      edit.offset = place.offset;
      edit.length = place.length;
      edit.old_text = place.text;
      edit.new_text = NewText(place.text, c);
      edit.line = place.line;
      edit.how = place.how;
      edit.link = r.link;
      edit.number = NumberName(*n);
      planned.emplace_back(edit, &c);
    }
    for (const auto& [edit, change] : planned) {
      if (by_hand > refused_before) {
        refuse(r, *change, edit.file + ":" + std::to_string(edit.line),
               "the other numbers of this repair cannot be written, and a part of a repair is "
               "not written");
        continue;
      }
      const bool duplicate = std::any_of(edits.begin(), edits.end(), [&](const Edit& e) {
        return e.file == edit.file && e.offset == edit.offset;
      });
      if (!duplicate) edits.push_back(edit);
    }
  }

  // Apply per file, from the end so that offsets stay valid.
  std::map<std::string, std::vector<Edit>> by_file;
  for (const Edit& e : edits) by_file[e.file].push_back(e);
  std::map<std::string, std::pair<std::string, std::string>> texts;  // file → (before, after)
  for (auto& [file, list] : by_file) {
    bool ok = false;
    std::string text = ReadText(file, &ok);
    if (!ok) {
      std::cerr << "massprops: error: cannot read " << file << "; nothing written\n";
      return 2;
    }
    std::string after = text;
    std::sort(list.begin(), list.end(),
              [](const Edit& a, const Edit& b) { return a.offset > b.offset; });
    for (const Edit& e : list) {
      if (e.offset + e.length > after.size() ||
          after.compare(e.offset, e.length, e.old_text) != 0) {
        std::cerr << "massprops: error: " << file << ":" << e.line << " no longer holds '"
                  << e.old_text << "'; nothing written\n";
        return 2;
      }
      after.replace(e.offset, e.length, e.new_text);
    }
    texts[file] = {text, after};
  }
  for (const Edit& e : edits) {
    std::cout << e.file << ":" << e.line << ": link '" << e.link << "': " << e.number << " "
              << e.old_text << " -> " << e.new_text << " (" << e.how << ")\n";
  }
  if (request.diff || request.dry_run) {
    for (const auto& [file, pair] : texts) std::cout << UnifiedDiff(pair.first, pair.second, file);
  }
  if (!request.in_place || request.dry_run) {
    std::cout << "massprops: " << edits.size() << " source value(s) to change, " << by_hand
              << " to change by hand; nothing written (--in-place writes)\n";
    return by_hand > 0 ? 1 : 0;
  }
  std::vector<std::string> notes;
  for (const auto& [file, pair] : texts) {
    if (!request.backup.empty()) {
      if (auto error = WriteFileSafely(file + request.backup, pair.first, &notes)) {
        std::cerr << "massprops: error: " << *error << "; nothing written\n";
        return 2;
      }
    }
    if (auto error = WriteFileSafely(file, pair.second, &notes)) {
      std::cerr << "massprops: error: " << *error << "; " << file << " is unchanged\n";
      return 2;
    }
  }
  for (const std::string& note : notes) std::cerr << "massprops: " << note << "\n";

  // Verify. With an expander: the new expansion must differ from the old only on the lines of
  // the repaired numbers, and trace them to the edited places. Without one (or when it prints
  // the same text, as a recorded expansion does): the expected expansion (the repairs written
  // into the old one) must trace each edited number to its edited place.
  std::string error;
  std::optional<std::string> again = edits.empty() ? std::nullopt : ReExpand(options, top, &error);
  std::string checked = patched_expansion;
  std::string how_checked;
  if (again && *again != run.expansion.text) {
    const LineChanges changes = DiffLines(run.expansion.text, *again);
    const LineChanges expected = DiffLines(run.expansion.text, patched_expansion);
    if (changes.removed != expected.removed) {
      std::cerr << "massprops: error: the new expansion changed other lines than those of the "
                   "repaired numbers ("
                << UnifiedDiff(run.expansion.text, *again, "expansion") << ")\n";
      return 2;
    }
    checked = *again;
    how_checked = "re-expanded";
  } else {
    how_checked = again ? "the expander printed the same text (a recorded expansion?); checked by "
                          "tracing the expected expansion to the edited sources"
                        : "re-expansion could not be verified (" + error +
                              "); checked by tracing the expected expansion to the edited sources";
  }
  const XacroTrace after = TraceXacro(checked, run.expansion.name, run.expansion.trace);
  int verified = 0;
  for (const Edit& e : edits) {
    bool ok = false;
    for (const TracedNumber& n : after.numbers) {
      if (n.link != e.link || NumberName(n) != e.number) continue;
      ok = n.places.size() == 1 && n.places[0].file == e.file && n.places[0].line == e.line &&
           n.places[0].text == e.new_text;
    }
    if (!ok) {
      std::cerr << "massprops: error: after the edit, " << e.file << ":" << e.line
                << " does not give link '" << e.link << "' its repaired " << e.number << "\n";
      return 2;
    }
    ++verified;
  }
  std::cout << "massprops: wrote " << edits.size() << " source value(s) in " << texts.size()
            << " file(s), " << verified << " verified (" << how_checked << "); " << by_hand
            << " to change by hand\n";
  return by_hand > 0 ? 1 : 0;
}

}  // namespace massprops::cli
