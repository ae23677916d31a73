// The renderings of the mass report (text tables, JSON, CSV); the numbers come from
// ComputeMassReport (analysis/mass_report.h).
#include "massprops/output/report_format.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "massprops/analysis/welded_groups.h"
#include "massprops/core/format_number.h"
#include "massprops/output/reporters.h"

namespace massprops {

namespace {

nlohmann::json Vec(const Eigen::Vector3d& v) { return {v(0), v(1), v(2)}; }
nlohmann::json Mat(const Eigen::Matrix3d& m) {
  return {Vec(m.row(0).transpose()), Vec(m.row(1).transpose()), Vec(m.row(2).transpose())};
}

// The names of the unknown parts of a body (BodyMassProperties::unknown), in the schema's words.
std::vector<std::string> UnknownNames(unsigned unknown) {
  std::vector<std::string> names;
  if (unknown & kUnknownMass) names.push_back("mass");
  if (unknown & kUnknownCom) names.push_back("com");
  if (unknown & kUnknownInertia) names.push_back("inertia");
  return names;
}

std::string JoinedWords(const std::vector<std::string>& words, const char* separator) {
  std::string text;
  for (std::size_t i = 0; i < words.size(); ++i) text += (i ? separator : "") + words[i];
  return text;
}

// A body's numbers; those it does not know are null, and "unknown" names them (only then).
void AddBody(const BodyMassProperties& body, nlohmann::json* out) {
  nlohmann::json& j = *out;
  const bool mass = !(body.unknown & kUnknownMass), com = !(body.unknown & kUnknownCom);
  const bool inertia = !(body.unknown & kUnknownInertia);
  j["frame"] = body.frame;
  j["mass"] = mass ? nlohmann::json(body.mass) : nlohmann::json();
  j["com"] = com ? Vec(body.com) : nlohmann::json();
  j["inertia_about_com"] = inertia ? Mat(body.inertia_about_com) : nlohmann::json();
  j["principal_moments"] = inertia ? Vec(body.principal_moments) : nlohmann::json();
  j["principal_axes"] = inertia ? Mat(body.principal_axes) : nlohmann::json();
  j["equivalent_box"] =
      inertia && body.equivalent_box ? Vec(*body.equivalent_box) : nlohmann::json();
  j["digits_lost"] = inertia && com ? nlohmann::json(body.digits_lost) : nlohmann::json();
  if (body.unknown != 0) j["unknown"] = UnknownNames(body.unknown);
}

// A model's target part (docs/report.md): "target", "target_bodies" and MuJoCo's verdict.
void AddTargetJson(const ModelTargetReport& target, nlohmann::json* model) {
  nlohmann::json& j = *model;
  j["target"] = ToString(target.target);
  j["target_bodies"] = nlohmann::json::array();
  for (const TargetBody& b : target.bodies) {
    if (b.properties) {
      j["target_bodies"].push_back({{"name", b.name},
                                    {"links", b.links},
                                    {"frame", b.properties->frame},
                                    {"mass", b.properties->mass},
                                    {"com", Vec(b.properties->com)},
                                    {"inertia_about_com", Mat(b.properties->inertia_about_com)}});
    } else {
      j["target_bodies"].push_back({{"name", b.name},
                                    {"links", b.links},
                                    {"moving", b.moving},
                                    {"mass", b.mass},
                                    {"principal_moments", b.mujoco_moments}});
    }
  }
  if (target.target != Target::kMujoco) return;
  j["target_accepted"] = target.accepted;
  j["target_refusal"] = target.accepted ? nlohmann::json()
                                        : nlohmann::json{{"message", target.refusal_message},
                                                         {"body", target.refusal_body}};
  j["target_not_predicted"] = target.not_predicted;
}

void WriteJson(std::ostream& out, const std::vector<ModelMassReport>& reports,
               const std::vector<MassReportError>& errors,
               const std::vector<ModelTargetReport>& targets) {
  nlohmann::json root;
  root["models"] = nlohmann::json::array();
  for (std::size_t i = 0; i < reports.size(); ++i) {
    const ModelMassReport& report = reports[i];
    nlohmann::json model;
    model["name"] = report.name;
    model["file"] = report.file;
    model["links"] = nlohmann::json::array();
    for (const LinkMassReport& link : report.links) {
      nlohmann::json j;
      j["name"] = link.name;
      AddBody(link.properties, &j);
      if (link.geometry) {
        const LinkGeometryComparison& g = *link.geometry;
        if (!g.error.empty()) {
          j["geometry"] = {{"error", g.error}};
        } else {
          nlohmann::json rel = nlohmann::json::array();
          for (int k = 0; k < 3; ++k) {
            const double v = g.moment_rel_diff(k);
            rel.push_back(std::isfinite(v) ? nlohmann::json(v) : nlohmann::json());
          }
          j["geometry"] = {{"source", g.from_collision ? "collision" : "visual"},
                           {"com", Vec(g.geometry.com)},
                           {"inertia_about_com", Mat(g.geometry.inertia_about_com)},
                           {"principal_moments", Vec(g.geometry.principal_moments)},
                           {"moment_rel_diff", std::move(rel)},
                           {"axis_angle_deg", g.axis_angle_deg ? nlohmann::json(*g.axis_angle_deg)
                                                               : nlohmann::json()}};
          nlohmann::json meshes = nlohmann::json::array();
          for (const LinkGeometryComparison::Mesh& mesh : g.meshes) {
            const MeshDiagnostics& d = mesh.diagnostics;
            meshes.push_back({{"uri", mesh.uri},
                              {"path", mesh.path},
                              {"found_by", ToString(mesh.found_by)},
                              {"triangles", d.num_triangles},
                              {"model", ToString(d.model)},
                              {"winding_inverted", d.winding_inverted},
                              {"boundary_edges", d.boundary_edges},
                              {"non_manifold_edges", d.non_manifold_edges},
                              {"inconsistent_edges", d.inconsistent_edges},
                              {"degenerate_triangles", d.degenerate_triangles},
                              {"note", DescribeMeshDiagnostics(d)}});
          }
          j["geometry"]["meshes"] = std::move(meshes);
        }
      }
      model["links"].push_back(std::move(j));
    }
    model["welded_groups"] = nlohmann::json::array();
    for (const GroupMassReport& group : report.welded_groups) {
      nlohmann::json j;
      j["root_link"] = group.root_link;
      j["links"] = group.links;
      AddBody(group.properties, &j);
      if (!group.incomplete_links.empty()) j["incomplete_links"] = group.incomplete_links;
      model["welded_groups"].push_back(std::move(j));
    }
    if (report.total) {
      nlohmann::json j;
      AddBody(*report.total, &j);
      j["unreachable_links"] = report.unreachable_links;
      if (!report.total_incomplete_links.empty()) {
        j["incomplete_links"] = report.total_incomplete_links;
      }
      model["total"] = std::move(j);
    } else {
      model["total"] = nullptr;
    }
    if (i < targets.size() && targets[i].target != Target::kGeneric) {
      AddTargetJson(targets[i], &model);
    }
    root["models"].push_back(std::move(model));
  }
  root["errors"] = nlohmann::json::array();
  for (const MassReportError& e : errors) {
    root["errors"].push_back({{"file", e.file}, {"line", e.line}, {"message", e.message}});
  }
  // nlohmann::json prints the shortest decimal that reads back to the same double.
  out << root.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
}

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string Number(double value, int digits) {
  if (value == 0) value = 0;              // no "-0"
  return FormatPrecision(value, digits);  // printf's "%.*g"
}

constexpr int kCsvDigits = std::numeric_limits<double>::max_digits10;

// The CSV rows of the report: the columns every row has, then the optional geometry columns
// (--geometry) and target columns (--target).
class CsvWriter {
 public:
  CsvWriter(std::ostream& out, bool geometry, bool target)
      : out_(out), geometry_(geometry), target_(target) {}

  void Header() const {
    out_ << "file,model,kind,name,frame,mass,com_x,com_y,com_z,ixx,iyy,izz,ixy,ixz,iyz,"
            "principal_moment_1,principal_moment_2,principal_moment_3,"
            "axis_1_x,axis_1_y,axis_1_z,axis_2_x,axis_2_y,axis_2_z,axis_3_x,axis_3_y,axis_3_z,"
            "box_1,box_2,box_3,digits_lost,links";
    if (geometry_) {
      out_ << ",geometry_source,geometry_com_x,geometry_com_y,geometry_com_z,geometry_ixx,"
              "geometry_iyy,geometry_izz,geometry_ixy,geometry_ixz,geometry_iyz,"
              "geometry_principal_moment_1,geometry_principal_moment_2,"
              "geometry_principal_moment_3,geometry_rel_diff_1,geometry_rel_diff_2,"
              "geometry_rel_diff_3,geometry_axis_angle_deg,geometry_error";
    }
    if (target_) out_ << ",target,target_moving,target_message";
    out_ << '\n';
  }

  // A row of a body with all its numbers; `target` "" for the report's own rows.
  void BodyRow(const ModelMassReport& report, const char* kind, const std::string& name,
               const BodyMassProperties& b, const std::vector<std::string>& members,
               const LinkGeometryComparison* comparison, const std::string& target) const {
    Start(report, kind, name, b.frame);
    // An unknown number is an empty field (BodyMassProperties::unknown).
    const bool mass = !(b.unknown & kUnknownMass), com = !(b.unknown & kUnknownCom);
    const bool inertia = !(b.unknown & kUnknownInertia);
    const auto field = [&](bool known, double v, int digits) {
      out_ << ',';
      if (known) out_ << Number(v, digits);
    };
    field(mass, b.mass, kCsvDigits);
    for (int i = 0; i < 3; ++i) field(com, b.com(i), kCsvDigits);
    const Eigen::Matrix3d& I = b.inertia_about_com;
    for (double v : {I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)}) {
      field(inertia, v, kCsvDigits);
    }
    for (int i = 0; i < 3; ++i) field(inertia, b.principal_moments(i), kCsvDigits);
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < 3; ++i) field(inertia, b.principal_axes(i, k), kCsvDigits);
    }
    for (int k = 0; k < 3; ++k) {
      field(inertia && b.equivalent_box, b.equivalent_box ? (*b.equivalent_box)(k) : 0, kCsvDigits);
    }
    field(inertia && com, b.digits_lost, 4);
    out_ << ',' << Joined(members);
    GeometryFields(comparison);
    TargetFields(target, "", "");
    out_ << '\n';
  }

  // A MuJoCo body: its mass and principal moments; the other numbers are empty.
  void MujocoRow(const ModelMassReport& report, const TargetBody& b) const {
    Start(report, "target_body", b.name, "");
    out_ << ',' << Number(b.mass, kCsvDigits) << ",,,,,,,,,";
    for (double m : b.mujoco_moments) out_ << ',' << Number(m, kCsvDigits);
    out_ << ",,,,,,,,,,,,,," << Joined(b.links);
    GeometryFields(nullptr);
    TargetFields("mujoco", b.moving ? "true" : "false", "");
    out_ << '\n';
  }

  // A row without numbers: MuJoCo's refusal or a reason it is not predicted.
  void MessageRow(const ModelMassReport& report, const char* kind, const std::string& name,
                  const std::string& message) const {
    Start(report, kind, name, "");
    out_ << ",,,,,,,,,,,,,,,,,,,,,,,,,,,";
    GeometryFields(nullptr);
    TargetFields("mujoco", "", message);
    out_ << '\n';
  }

 private:
  void Start(const ModelMassReport& report, const char* kind, const std::string& name,
             const std::string& frame) const {
    out_ << CsvField(report.file) << ',' << CsvField(report.name) << ',' << kind << ','
         << CsvField(name) << ',' << CsvField(frame);
  }
  static std::string Joined(const std::vector<std::string>& members) {
    std::string joined;
    for (std::size_t i = 0; i < members.size(); ++i) joined += (i ? ";" : "") + members[i];
    return CsvField(joined);
  }
  void GeometryFields(const LinkGeometryComparison* c) const {
    if (!geometry_) return;
    if (c == nullptr || !c->error.empty()) {
      for (int i = 0; i < 17; ++i) out_ << ',';
      out_ << ',' << (c == nullptr ? std::string() : CsvField(c->error));
      return;
    }
    out_ << ',' << (c->from_collision ? "collision" : "visual");
    for (int i = 0; i < 3; ++i) out_ << ',' << Number(c->geometry.com(i), kCsvDigits);
    const Eigen::Matrix3d& G = c->geometry.inertia_about_com;
    for (double v : {G(0, 0), G(1, 1), G(2, 2), G(0, 1), G(0, 2), G(1, 2)}) {
      out_ << ',' << Number(v, kCsvDigits);
    }
    for (int k = 0; k < 3; ++k) {
      out_ << ',' << Number(c->geometry.principal_moments(k), kCsvDigits);
    }
    for (int k = 0; k < 3; ++k) {
      out_ << ',';
      if (std::isfinite(c->moment_rel_diff(k))) out_ << Number(c->moment_rel_diff(k), kCsvDigits);
    }
    out_ << ',';
    if (c->axis_angle_deg) out_ << Number(*c->axis_angle_deg, kCsvDigits);
    out_ << ',';
  }
  void TargetFields(const std::string& target, const char* moving,
                    const std::string& message) const {
    if (target_) out_ << ',' << target << ',' << moving << ',' << CsvField(message);
  }

  std::ostream& out_;
  bool geometry_;
  bool target_;
};

// The target part of one model's CSV rows (after its own rows).
void WriteCsvTarget(const CsvWriter& csv, const ModelMassReport& report,
                    const ModelTargetReport& target) {
  for (const TargetBody& b : target.bodies) {
    if (b.properties) {
      csv.BodyRow(report, "target_body", b.name, *b.properties, b.links, nullptr,
                  ToString(target.target));
    } else {
      csv.MujocoRow(report, b);
    }
  }
  if (target.target != Target::kMujoco) return;
  if (!target.accepted) {
    csv.MessageRow(report, "target_refusal", target.refusal_body, target.refusal_message);
  }
  for (const std::string& why : target.not_predicted) {
    csv.MessageRow(report, "target_not_predicted", "", why);
  }
}

void WriteCsv(std::ostream& out, const std::vector<ModelMassReport>& reports,
              const std::vector<ModelTargetReport>& targets) {
  // With --geometry, every row gets the geometry comparison's columns too (empty for groups,
  // totals and links without one), so that the header does not change otherwise; the same for
  // the target columns with --target.
  bool geometry = false;
  for (const ModelMassReport& report : reports) {
    for (const LinkMassReport& link : report.links) geometry = geometry || link.geometry;
  }
  bool target = false;
  for (const ModelTargetReport& t : targets) target = target || t.target != Target::kGeneric;
  const CsvWriter csv(out, geometry, target);
  csv.Header();
  for (std::size_t i = 0; i < reports.size(); ++i) {
    const ModelMassReport& report = reports[i];
    for (const LinkMassReport& link : report.links) {
      csv.BodyRow(report, "link", link.name, link.properties, {link.name},
                  link.geometry ? &*link.geometry : nullptr, "");
    }
    for (const GroupMassReport& group : report.welded_groups) {
      csv.BodyRow(report, "welded_group", group.root_link, group.properties, group.links, nullptr,
                  "");
    }
    if (report.total) csv.BodyRow(report, "total", report.name, *report.total, {}, nullptr, "");
    if (i < targets.size()) WriteCsvTarget(csv, report, targets[i]);
  }
}

// Prints rows as columns: the first `text_columns` left-aligned, the others right-aligned.
void WriteTable(std::ostream& out, const std::vector<std::vector<std::string>>& rows,
                std::size_t text_columns) {
  constexpr std::size_t kMaxCell = 80;
  std::vector<std::size_t> width;
  for (const auto& row : rows) {
    if (width.size() < row.size()) width.resize(row.size(), 0);
    for (std::size_t c = 0; c < row.size(); ++c) {
      width[c] = std::max(width[c], ShortenLongWords(row[c], kMaxCell).size());
    }
  }
  for (const auto& row : rows) {
    std::string line = " ";
    for (std::size_t c = 0; c < row.size(); ++c) {
      // A hostile 10 MB name is shortened, so that it does not pad every row.
      const std::string cell = ShortenLongWords(row[c], kMaxCell);
      const std::string pad(width[c] - cell.size(), ' ');
      line += ' ';
      line += c < text_columns ? cell + pad : pad + cell;
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out << line << '\n';
  }
}

// The rows of the text report's geometry table (a header, then one row per link compared with its
// geometry); the notes of links without a geometry inertia and of meshes with diagnostics go to
// *notes.
std::vector<std::vector<std::string>> GeometryRows(const ModelMassReport& report,
                                                   std::vector<std::string>* notes) {
  constexpr int kDigits = 6;
  std::vector<std::vector<std::string>> g{{"link", "source", "I1_geometry", "I2_geometry",
                                           "I3_geometry", "rel_diff_1", "rel_diff_2", "rel_diff_3",
                                           "axis_angle_deg"}};
  for (const auto& link : report.links) {
    if (!link.geometry) continue;
    const LinkGeometryComparison& c = *link.geometry;
    if (!c.error.empty()) {
      notes->push_back("link '" + link.name + "': no geometry inertia: " + c.error);
      continue;
    }
    for (const LinkGeometryComparison::Mesh& mesh : c.meshes) {
      const std::string note = DescribeMeshDiagnostics(mesh.diagnostics);
      if (!note.empty()) {
        notes->push_back("link '" + link.name + "': mesh '" + mesh.uri + "': " + note);
      }
    }
    std::vector<std::string> row{link.name, c.from_collision ? "collision" : "visual"};
    for (int k = 0; k < 3; ++k) row.push_back(Number(c.geometry.principal_moments(k), kDigits));
    for (int k = 0; k < 3; ++k) {
      row.push_back(std::isfinite(c.moment_rel_diff(k)) ? Number(c.moment_rel_diff(k), 3) : "n/a");
    }
    row.push_back(c.axis_angle_deg ? Number(*c.axis_angle_deg, 3) : "n/a");
    g.push_back(std::move(row));
  }
  return g;
}

void WriteText(std::ostream& out, const std::vector<ModelMassReport>& reports, double threshold) {
  constexpr int kDigits = 6;
  for (const ModelMassReport& report : reports) {
    out << "model '" << ShortenLongWords(report.name) << "' (" << report.file << ")\n";
    struct Entry {
      std::string kind, name;
      const BodyMassProperties* body;
      const std::vector<std::string>* incomplete_links;  // of a composite; null for a link
    };
    std::vector<Entry> entries;
    for (const auto& link : report.links) {
      entries.push_back({"link", link.name, &link.properties, nullptr});
    }
    for (const auto& group : report.welded_groups) {
      entries.push_back({"group", group.root_link, &group.properties, &group.incomplete_links});
    }
    if (report.total) {
      entries.push_back({"total", report.name, &*report.total, &report.total_incomplete_links});
    }

    std::vector<std::vector<std::string>> a{{"kind", "name", "frame", "mass", "com_x", "com_y",
                                             "com_z", "ixx", "iyy", "izz", "ixy", "ixz", "iyz"}};
    std::vector<std::vector<std::string>> b{
        {"kind", "name", "I1", "I2", "I3", "axis1", "axis2", "axis3", "box_1", "box_2", "box_3"}};
    auto axis = [&](const Eigen::Matrix3d& R, int k) {
      return "[" + Number(R(0, k), 4) + " " + Number(R(1, k), 4) + " " + Number(R(2, k), 4) + "]";
    };
    std::vector<std::string> notes;
    for (const Entry& e : entries) {
      const BodyMassProperties& p = *e.body;
      const Eigen::Matrix3d& I = p.inertia_about_com;
      const bool mass = !(p.unknown & kUnknownMass), com = !(p.unknown & kUnknownCom);
      const bool inertia = !(p.unknown & kUnknownInertia);
      const auto cell = [](bool known, const std::string& text) {
        return known ? text : std::string("unknown");
      };
      a.push_back({e.kind, e.name, p.frame, cell(mass, Number(p.mass, kDigits)),
                   cell(com, Number(p.com(0), kDigits)), cell(com, Number(p.com(1), kDigits)),
                   cell(com, Number(p.com(2), kDigits)), cell(inertia, Number(I(0, 0), kDigits)),
                   cell(inertia, Number(I(1, 1), kDigits)), cell(inertia, Number(I(2, 2), kDigits)),
                   cell(inertia, Number(I(0, 1), kDigits)), cell(inertia, Number(I(0, 2), kDigits)),
                   cell(inertia, Number(I(1, 2), kDigits))});
      std::vector<std::string> row{e.kind,
                                   e.name,
                                   cell(inertia, Number(p.principal_moments(0), kDigits)),
                                   cell(inertia, Number(p.principal_moments(1), kDigits)),
                                   cell(inertia, Number(p.principal_moments(2), kDigits)),
                                   cell(inertia, axis(p.principal_axes, 0)),
                                   cell(inertia, axis(p.principal_axes, 1)),
                                   cell(inertia, axis(p.principal_axes, 2))};
      for (int k = 0; k < 3; ++k) {
        row.push_back(!inertia           ? "unknown"
                      : p.equivalent_box ? Number((*p.equivalent_box)(k), kDigits)
                                         : "-");
      }
      b.push_back(std::move(row));
      if (p.unknown != 0) {
        const std::string unknown = JoinedWords(UnknownNames(p.unknown), ", ");
        if (e.incomplete_links == nullptr) {
          notes.push_back(e.kind + " '" + e.name +
                          "': its <inertial> could not be read wholly (inertial-unreadable; "
                          "`massprops check` says which number): " +
                          unknown + " unknown; the other numbers are what the loader loads");
        } else {
          notes.push_back(e.kind + " '" + e.name + "': incomplete: " + unknown +
                          " unknown, since the numbers of " +
                          JoinedWords(*e.incomplete_links, ", ") + " are partly unknown");
        }
        continue;  // no other note on numbers that are not known
      }
      if (!p.equivalent_box && p.mass > 0) {
        notes.push_back(e.kind + " '" + e.name +
                        "': no equivalent box: the principal moments violate the triangle "
                        "inequality (or are not finite)");
      }
      // Not for a point mass (tr(I) = 0: no central inertia to lose digits of) nor a dummy mass
      // of 1 g or less (a marker: its inertia does not matter; the same bound as the geometry
      // rules' dummy masses, docs/rules.md).
      if (p.digits_lost > threshold && I.trace() > 0 && p.mass > 1e-3) {
        notes.push_back(e.kind + " '" + e.name + "': about " + Number(p.digits_lost, 3) +
                        " significant digits lost to cancellation by the shift between the "
                        "origin of frame '" +
                        p.frame + "' and the center of mass (m|c|^2 = " +
                        Number(p.mass * p.com.squaredNorm(), 3) + " against trace " +
                        Number(I.trace(), 3) + ")");
      }
    }
    out << " mass, center of mass, inertia about the center of mass (in the named frame):\n";
    WriteTable(out, a, 3);
    out << " principal moments (ascending), principal axes (in the frame), equivalent box sides "
           "(along the axes):\n";
    WriteTable(out, b, 2);
    if (!report.unreachable_links.empty()) {
      std::string list;
      for (const std::string& name : report.unreachable_links) list += " " + name;
      notes.push_back("left out of the total (not connected to the root link):" + list);
    }
    const std::vector<std::vector<std::string>> g = GeometryRows(report, &notes);
    if (g.size() > 1) {
      out << " inertia implied by the geometry for the declared mass (link frame), relative "
             "difference of the declared principal moments, angle between principal axes:\n";
      WriteTable(out, g, 2);
    }
    for (const std::string& note : notes) out << " note: " << note << "\n";
  }
}

}  // namespace

ModelTargetReport MakeTargetReport(const Model& model, Target target, const std::string& text) {
  ModelTargetReport out;
  out.target = target;
  auto names = [&](const std::vector<int>& links) {
    std::vector<std::string> v;
    for (int l : links) v.push_back(model.links[l].name);
    return v;
  };
  if (target == Target::kMujoco) {
    const MujocoPrediction p = PredictMujoco(model, ReadMujocoCompilerOptions(text));
    for (const MujocoBody& b : p.bodies) {
      TargetBody body;
      body.name = b.name;
      body.links = names(b.fused_links);
      body.links.insert(body.links.begin(), b.name);
      body.moving = b.moving;
      body.mass = b.mass;
      body.mujoco_moments = b.inertia;
      out.bodies.push_back(std::move(body));
    }
    out.accepted = p.accepted();
    if (!p.accepted()) {
      out.refusal_message = p.errors.front().message;
      out.refusal_body = p.errors.front().body;
    }
    out.not_predicted = p.unsupported;
  } else if (target == Target::kGazebo) {
    for (const GazeboBody& b : GazeboBodies(model, text)) {
      const std::string& frame = model.links[b.links.front()].name;
      out.bodies.push_back(
          {frame, names(b.links),
           MakeBodyMassProperties(frame, b.inertia.mass, b.inertia.p_RoScm_R, b.inertia.I_SScm_R)});
    }
  } else if (target == Target::kDrake) {
    for (std::size_t l = 0; l < model.links.size(); ++l) {
      const Link& link = model.links[l];
      if (model.format == Model::Format::kUrdf && link.name == "world" &&
          model.root_link == "world") {
        continue;
      }
      const MassProperties m = LinkMassProperties(link, model.format);
      out.bodies.push_back({link.name,
                            {link.name},
                            MakeBodyMassProperties(link.name, m.mass, m.p_FoScm_F, m.I_SScm_F)});
    }
  }
  return out;
}

void WriteMassReport(std::ostream& out, MassReportFormat format,
                     const std::vector<ModelMassReport>& reports,
                     const std::vector<MassReportError>& errors, double digits_lost_threshold,
                     const std::vector<ModelTargetReport>& targets) {
  switch (format) {
    case MassReportFormat::kJson:
      WriteJson(out, reports, errors, targets);
      break;
    case MassReportFormat::kCsv:
      WriteCsv(out, reports, targets);
      break;
    case MassReportFormat::kText:
      WriteText(out, reports, digits_lost_threshold);
      break;
  }
}

}  // namespace massprops
