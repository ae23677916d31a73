#pragma once
// The files of the HTML view, embedded into the `massprops` tool at build time by
// cmake/embed_file.cmake (nothing is read at run time): the page template, its style and script
// (src/tool/view/), and three.js with its OrbitControls from Debian's libjs-three (r111); and
// Chart.js 3.9 from Debian's libjs-chart.js for `identify --html` (empty when not installed).
#include <cstddef>
#include <string_view>

namespace massprops::cli::embedded {

extern const unsigned char kViewHtml[];
extern const std::size_t kViewHtmlSize;
extern const unsigned char kViewCss[];
extern const std::size_t kViewCssSize;
extern const unsigned char kViewJs[];
extern const std::size_t kViewJsSize;
extern const unsigned char kThreeJs[];
extern const std::size_t kThreeJsSize;
extern const unsigned char kOrbitControlsJs[];
extern const std::size_t kOrbitControlsJsSize;
extern const unsigned char kChartJs[];
extern const std::size_t kChartJsSize;

/// The bytes of an embedded file as text.
inline std::string_view AsText(const unsigned char* bytes, std::size_t size) {
  return {reinterpret_cast<const char*>(bytes), size};
}

}  // namespace massprops::cli::embedded
