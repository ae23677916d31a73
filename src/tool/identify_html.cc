#include "identify_html.h"

#include <nlohmann/json.hpp>
#include <string>

#include "html_text.h"
#include "massprops/dynamics/torque_regressor.h"
#include "view_assets.h"

namespace massprops::cli {

namespace {

constexpr Eigen::Index kIdentifyHtmlMaxPoints = 4000;

// The page's own script: one line chart per joint from the data block; the charts are left in
// window.identifyCharts (the browser test reads them).
constexpr const char* kIdentifyPageJs = R"js(
(function () {
  const data = JSON.parse(document.getElementById('identify-data').textContent);
  const host = document.getElementById('charts');
  const charts = [];
  const series = (label, values, color, dash) => ({
    label, data: values, borderColor: color, backgroundColor: color, borderWidth: 1.2,
    borderDash: dash, pointRadius: 0, tension: 0 });
  data.joints.forEach((joint, index) => {
    const section = document.createElement('section');
    const title = document.createElement('h2');
    title.textContent = "joint '" + joint.joint + "': held-out torque RMS " +
        joint.rms_file.toPrecision(4) + " (file) -> " + joint.rms_identified.toPrecision(4) +
        " (identified)";
    const canvas = document.createElement('canvas');
    canvas.id = 'joint-' + index;
    section.append(title, canvas);
    host.append(section);
    const labels = joint.measured.map((_, k) => data.first_sample + k * data.stride);
    charts.push(new Chart(canvas, {
      type: 'line',
      data: { labels, datasets: [
        series('measured', joint.measured, '#222222', []),
        series('identified', joint.identified, '#d62728', []),
        series("file's values", joint.file, '#1f77b4', [5, 4]) ] },
      options: { animation: false, responsive: true, interaction: { mode: 'index', intersect: false },
        scales: { x: { title: { display: true, text: 'sample' } },
                  y: { title: { display: true, text: 'torque (N·m or N)' } } } }
    }));
  });
  window.identifyCharts = charts;
})();
)js";

nlohmann::json IdentifyHtmlSeries(const Eigen::VectorXd& stacked, Eigen::Index n, Eigen::Index j,
                                  Eigen::Index stride) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index k = 0; k * n + j < stacked.size(); k += stride)
    out.push_back(stacked[k * n + j]);
  return out;
}

}  // namespace

bool IdentifyHtmlAvailable() { return embedded::kChartJsSize > 0; }

std::string RenderIdentifyHtml(const std::string& robot, const std::string& data,
                               const KinematicTree& tree, const OrderedTrajectory& data_rows,
                               const IdentifyOptions& options, const IdentifyResult& r) {
  const Eigen::Index rows = data_rows.q.rows();
  const Eigen::Index held = r.validation_samples > 0 ? r.validation_samples : rows;
  const Eigen::Index first = rows - held;
  const Eigen::MatrixXd W =
      StackTorqueRegressor(tree, data_rows.q.bottomRows(held), data_rows.dq.bottomRows(held),
                           data_rows.ddq.bottomRows(held), options.regressor);
  const Eigen::VectorXd file = W * r.file, identified = W * r.identified;
  const Eigen::Index n = tree.size();
  const Eigen::Index stride = (held + kIdentifyHtmlMaxPoints - 1) / kIdentifyHtmlMaxPoints;
  nlohmann::json joints = nlohmann::json::array();
  for (Eigen::Index j = 0; j < n; ++j) {
    nlohmann::json measured = nlohmann::json::array();
    for (Eigen::Index k = 0; k < held; k += stride) measured.push_back(data_rows.tau(first + k, j));
    joints.push_back({{"joint", tree.bodies[static_cast<std::size_t>(j)].joint},
                      {"measured", measured},
                      {"file", IdentifyHtmlSeries(file, n, j, stride)},
                      {"identified", IdentifyHtmlSeries(identified, n, j, stride)},
                      {"rms_file", r.rms_file[j]},
                      {"rms_identified", r.rms_identified[j]},
                      {"rms_least_squares", r.rms_least_squares[j]}});
  }
  const nlohmann::json block = {{"robot", robot},
                                {"data", data},
                                {"first_sample", first},
                                {"stride", stride},
                                {"joints", joints}};
  std::string data_text = block.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string escaped;  // '<' only occurs inside JSON strings: escaped, nothing ends the block
  for (const char c : data_text) escaped += c == '<' ? std::string("\\u003c") : std::string(1, c);
  const std::string title = EscapeHtml(robot + " with " + data);
  std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<title>massprops identify: " + title + "</title>\n";
  page +=
      "<style>body{font-family:sans-serif;margin:1em 2em}section{max-width:1100px;"
      "margin-bottom:2em}h2{font-size:1.05em}</style>\n</head>\n<body>\n";
  page += "<h1>massprops identify</h1>\n<p>" + title + ": torques measured on the " +
          std::to_string(held) + (r.validation_samples > 0 ? " held-out" : " fitted") +
          " samples against those the file's values and the identified ones predict.</p>\n";
  page += "<div id=\"charts\"></div>\n";
  page += "<script id=\"identify-data\" type=\"application/json\">" + escaped + "</script>\n";
  page +=
      "<script>" +
      ScriptElementText(std::string(embedded::AsText(embedded::kChartJs, embedded::kChartJsSize))) +
      "</script>\n";
  page += "<script>" + ScriptElementText(kIdentifyPageJs) + "</script>\n</body>\n</html>\n";
  return page;
}

}  // namespace massprops::cli
