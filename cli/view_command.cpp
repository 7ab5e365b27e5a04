// chaser view RUN_DIR [--out FILE.html]: the run replayed in 3D in one HTML file (docs/view.md).
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/output_file.hpp"
#include "view/replay_page.hpp"
#include "view/run_files.hpp"

namespace chaser::cli {

int view_command(const ViewArgs& args) {
  const std::filesystem::path run_dir(args.run_dir);
  const std::filesystem::path out = args.out_path.empty() ? run_dir / "view.html" : std::filesystem::path(args.out_path);
  view::ViewPage page;
  try {
    page = view::view_page(view::read_run_files(run_dir));
  } catch (const view::ViewInputError& e) {
    std::cerr << fmt::format("chaser view: {}; no page written\n", e.what());
    return kExitBadInput;
  } catch (const nlohmann::json::exception& e) {  // a key of summary.json or geometry.json of the wrong type
    std::cerr << fmt::format("chaser view: {}: summary.json or geometry.json does not read ({}); no page written\n",
                             run_dir.string(), e.what());
    return kExitBadInput;
  }
  if (!write_output_file(out, page.html)) return kExitFailure;
  std::cout << fmt::format("wrote {} ({:.1f} MB): {} of {} telemetry rows drawn, every period's thruster on-times, {} events\n",
                           out.string(), static_cast<double>(page.html.size()) / 1e6, page.kept_rows, page.telemetry_rows,
                           page.events);
  return kExitOk;
}

}  // namespace chaser::cli
