#pragma once
// The HTML report of `massprops identify --html FILE` (docs/identify.md): per joint, the torques
// measured on the held-out samples against those the file's values and the identified ones
// predict, drawn by Chart.js (Debian's libjs-chart.js, embedded at build time: view_assets.h),
// one self-contained page that asks for nothing over the network.

#include <string>

#include "massprops/analysis/identify.h"

namespace massprops::cli {

/// Whether this build carries Chart.js (false: built without libjs-chart.js).
bool IdentifyHtmlAvailable();

/// The page. `robot` and `data` name the files (shown, HTML-escaped); `data_rows` are the
/// samples Identify was given and `options` its options (the held-out rows are the last
/// r.validation_samples; all rows when none is held out). The plotted numbers are in a JSON block
/// `<script id="identify-data" type="application/json">`: {"robot", "data", "first_sample",
/// "stride", "joints": [{"joint", "measured", "file", "identified", "rms_file", "rms_identified",
/// "rms_least_squares"}]}, every stride-th sample (stride 1 up to 4 000 samples).
std::string RenderIdentifyHtml(const std::string& robot, const std::string& data,
                               const KinematicTree& tree, const OrderedTrajectory& data_rows,
                               const IdentifyOptions& options, const IdentifyResult& r);

}  // namespace massprops::cli
