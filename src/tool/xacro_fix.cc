#include "xacro_fix.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

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

// What each repaired number becomes: (link, element, attribute) → its numbers, the repaired ones
// replaced.
using Wanted = std::map<std::tuple<std::string, std::string, std::string>, std::vector<double>>;

Wanted WantedValues(const XacroTrace& trace, const std::vector<Repair>& repairs) {
  Wanted wanted;
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
  return wanted;
}

// Plans the edits of the xacro sources that write the repairs; what cannot be written is left to
// the user, printed (where, and why) as it is met.
class EditPlanner {
 public:
  EditPlanner(const XacroTrace& trace, const std::string& expansion_name,
              const std::vector<Repair>& repairs)
      : trace_(trace), expansion_name_(expansion_name), wanted_(WantedValues(trace, repairs)) {}

  // Plans the edits of one repair: all of its numbers, or none (a part of a repair could leave
  // the link worse).
  void Plan(const Repair& r) {
    if (r.inserts_inertial || r.inserts_origin) {
      ++by_hand_;
      std::cout << expansion_name_ << ": link '" << r.link << "': " << DescribeRepair(r)
                << ": the repair adds an element, which is not written into xacro sources; add "
                   "it by hand\n";
      return;
    }
    const int refused_before = by_hand_;
    std::vector<std::pair<Edit, const FieldChange*>> planned;
    for (const FieldChange& c : r.changes) {
      if (std::optional<Edit> edit = PlanChange(r, c)) planned.emplace_back(*edit, &c);
    }
    for (const auto& [edit, change] : planned) {
      if (by_hand_ > refused_before) {
        Refuse(r, *change, edit.file + ":" + std::to_string(edit.line),
               "the other numbers of this repair cannot be written, and a part of a repair is "
               "not written");
        continue;
      }
      const Edit& planned_edit = edit;  // a lambda may not capture a structured binding
      const bool duplicate = std::any_of(edits_.begin(), edits_.end(), [&](const Edit& e) {
        return e.file == planned_edit.file && e.offset == planned_edit.offset;
      });
      if (!duplicate) edits_.push_back(edit);
    }
  }

  const std::vector<Edit>& edits() const { return edits_; }
  int by_hand() const { return by_hand_; }

 private:
  void Refuse(const Repair& r, const FieldChange& c, const std::string& where,
              const std::string& reason) {
    ++by_hand_;
    std::string values;
    for (double v : c.new_values) values += (values.empty() ? "" : " ") + FormatShortest(v);
    std::cout << where << ": link '" << r.link << "': change " << c.element
              << (c.element == "mass" ? "" : " " + c.attribute) << " to " << values
              << " by hand: " << reason << "\n";
  }

  // The edit that writes change c of repair r into the one source place of its number; nullopt
  // (after Refuse) when there is no such place or its text cannot be changed alone.
  std::optional<Edit> PlanChange(const Repair& r, const FieldChange& c) {
    const TracedNumber* n = FindNumber(trace_, r.link, c.element, c.attribute);
    const std::string generated =
        expansion_name_ + ":" + std::to_string(n ? n->expanded_line : c.line);
    if (!n || n->places.empty()) {
      Refuse(r, c, generated, "the number was not traced to the sources");
      return std::nullopt;
    }
    if (n->places.size() > 1) {
      std::string all;
      for (const SourcePlace& p : n->places) all += " " + p.file + ":" + std::to_string(p.line);
      Refuse(r, c, generated, "it is written at several places, none closer to the link:" + all);
      return std::nullopt;
    }
    const SourcePlace& place = n->places.front();
    const std::string where = place.file + ":" + std::to_string(place.line);
    if (place.how == "computed") {
      std::string inputs;
      for (const std::string& i : place.inputs) inputs += (inputs.empty() ? "" : ", ") + i;
      Refuse(r, c, where,
             "the value is computed (from " + inputs + "), not written: change its inputs");
      return std::nullopt;
    }
    if (place.how == "parameter") {
      Refuse(r, c, where,
             "the value is a macro argument or property (" + place.text +
                 "), which other places may read");
      return std::nullopt;
    }
    if (!place.editable) {
      Refuse(r, c, where, "the text there cannot be replaced exactly");
      return std::nullopt;
    }
    const std::string others = SharedWith(*n, place, wanted_[{r.link, c.element, c.attribute}]);
    if (!others.empty()) {
      Refuse(r, c, where, "the value is shared with " + others + ", which need no such repair");
      return std::nullopt;
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
    return edit;
  }

  // The links ("'a', 'b'") of the other numbers written at `place` that would not become `mine`
  // (a shared place must give every number that reads it the same new value); "" when none.
  std::string SharedWith(const TracedNumber& n, const SourcePlace& place,
                         const std::vector<double>& mine) const {
    std::set<std::string> others;
    for (const TracedNumber& other : trace_.numbers) {
      if (&other == &n) continue;
      if (std::none_of(other.places.begin(), other.places.end(),
                       [&](const SourcePlace& p) { return SamePlace(p, place); })) {
        continue;
      }
      auto w = wanted_.find({other.link, other.element, other.attribute});
      if (w == wanted_.end() || w->second != mine) others.insert(other.link);
    }
    std::string list;
    for (const std::string& l : others) list += (list.empty() ? "'" : ", '") + l + "'";
    return list;
  }

  const XacroTrace& trace_;
  const std::string& expansion_name_;
  Wanted wanted_;
  std::vector<Edit> edits_;
  int by_hand_ = 0;
};

using Texts = std::map<std::string, std::pair<std::string, std::string>>;  // file → (before, after)

// The edited files' texts before and after the edits (applied per file, from the end so that
// offsets stay valid); false, after an error message, when a file cannot be read or no longer
// holds the text an edit replaces.
bool EditTexts(const std::vector<Edit>& edits, Texts* texts) {
  std::map<std::string, std::vector<Edit>> by_file;
  for (const Edit& e : edits) by_file[e.file].push_back(e);
  for (auto& [file, list] : by_file) {
    bool ok = false;
    std::string text = ReadText(file, &ok);
    if (!ok) {
      std::cerr << "massprops: error: cannot read " << file << "; nothing written\n";
      return false;
    }
    std::string after = text;
    std::sort(list.begin(), list.end(),
              [](const Edit& a, const Edit& b) { return a.offset > b.offset; });
    for (const Edit& e : list) {
      if (e.offset + e.length > after.size() ||
          after.compare(e.offset, e.length, e.old_text) != 0) {
        std::cerr << "massprops: error: " << file << ":" << e.line << " no longer holds '"
                  << e.old_text << "'; nothing written\n";
        return false;
      }
      after.replace(e.offset, e.length, e.new_text);
    }
    (*texts)[file] = {text, after};
  }
  return true;
}

// Writes the edited files (and their backups); false after an error message.
bool WriteSources(const Texts& texts, const XacroFixRequest& request) {
  std::vector<std::string> notes;
  for (const auto& [file, pair] : texts) {
    if (!request.backup.empty()) {
      if (auto error = WriteFileSafely(file + request.backup, pair.first, &notes)) {
        std::cerr << "massprops: error: " << *error << "; nothing written\n";
        return false;
      }
    }
    if (auto error = WriteFileSafely(file, pair.second, &notes)) {
      std::cerr << "massprops: error: " << *error << "; " << file << " is unchanged\n";
      return false;
    }
  }
  for (const std::string& note : notes) std::cerr << "massprops: " << note << "\n";
  return true;
}

// Verifies the written sources. With an expander: the new expansion must differ from the old
// only on the lines of the repaired numbers, and trace them to the edited places. Without one (or
// when it prints the same text, as a recorded expansion does): the expected expansion (the
// repairs written into the old one) must trace each edited number to its edited place. False
// after an error message; else *how_checked says how, *verified counts the edits verified.
bool VerifyEdits(const XacroOptions& options, const std::string& top, const XacroRun& run,
                 const std::string& patched_expansion, const std::vector<Edit>& edits,
                 std::string* how_checked, int* verified) {
  std::string error;
  std::optional<std::string> again = edits.empty() ? std::nullopt : ReExpand(options, top, &error);
  std::string checked = patched_expansion;
  if (again && *again != run.expansion.text) {
    const LineChanges changes = DiffLines(run.expansion.text, *again);
    const LineChanges expected = DiffLines(run.expansion.text, patched_expansion);
    if (changes.removed != expected.removed) {
      std::cerr << "massprops: error: the new expansion changed other lines than those of the "
                   "repaired numbers ("
                << UnifiedDiff(run.expansion.text, *again, "expansion") << ")\n";
      return false;
    }
    checked = *again;
    *how_checked = "re-expanded";
  } else {
    *how_checked = again ? "the expander printed the same text (a recorded expansion?); checked by "
                           "tracing the expected expansion to the edited sources"
                         : "re-expansion could not be verified (" + error +
                               "); checked by tracing the expected expansion to the edited sources";
  }
  const XacroTrace after = TraceXacro(checked, run.expansion.name, run.expansion.trace);
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
      return false;
    }
    ++*verified;
  }
  return true;
}

}  // namespace

int FixXacroSources(const XacroOptions& options, const std::string& top, const XacroRun& run,
                    const std::vector<Repair>& repairs, const std::string& patched_expansion,
                    const XacroFixRequest& request) {
  const XacroTrace trace = TraceXacro(run.expansion.text, run.expansion.name, run.expansion.trace);
  EditPlanner planner(trace, run.expansion.name, repairs);
  for (const Repair& r : repairs) planner.Plan(r);
  const std::vector<Edit>& edits = planner.edits();
  const int by_hand = planner.by_hand();

  Texts texts;
  if (!EditTexts(edits, &texts)) return 2;
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
  if (!WriteSources(texts, request)) return 2;
  std::string how_checked;
  int verified = 0;
  if (!VerifyEdits(options, top, run, patched_expansion, edits, &how_checked, &verified)) return 2;
  std::cout << "massprops: wrote " << edits.size() << " source value(s) in " << texts.size()
            << " file(s), " << verified << " verified (" << how_checked << "); " << by_hand
            << " to change by hand\n";
  return by_hand > 0 ? 1 : 0;
}

}  // namespace massprops::cli
