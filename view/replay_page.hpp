#pragma once
// `chaser view`'s page: one HTML file that replays a run in 3D with no network and no server
// (docs/view.md). The page's template, style and script (view/page/) and three.js with its licence
// are built into the program (view/CMakeLists.txt); the run's data goes into the page as JSON.
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "view/replay_track.hpp"
#include "view/run_files.hpp"

namespace chaser::view {

struct ViewPage {
  std::string html;
  std::size_t telemetry_rows = 0;
  std::size_t kept_rows = 0;  // the decimated track's
  std::size_t events = 0;
};

// The data the page reads (its "chaser-data" script): meta, geometry, summary, the decimated track,
// every period's thruster on-times (uint8 per thruster, on-time x 255, base64), the active set's
// changes and the events. Throws ViewInputError for telemetry the view cannot draw.
nlohmann::json::string_t replay_data_json(const RunFiles& files, const DecimationTolerance& tol, ViewPage& figures);

// The whole page.
ViewPage view_page(const RunFiles& files, const DecimationTolerance& tol = {});

// The built-in assets (view_assets.cpp, generated at build time).
struct PageAssets {
  std::string_view html, css, js, three, three_licence, three_version;
};
PageAssets page_assets();

}  // namespace chaser::view
