// The per-step histories of `chaser fmea` for python/plot_invsim.py (cli/fmea_report.hpp).
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "cli/fmea_report.hpp"
#include "core/constants.hpp"

namespace chaser::cli {
namespace {

// "d1/d2~+e2/e1~" -> "d1-d2n+e2-e1n": portable file names ('~' reads as "negative").
std::string file_stem(std::size_t index, const std::string& label) {
  std::string stem = fmt::format("{:02d}_", index);
  for (char c : label) stem += c == '/' ? '-' : (c == '~' ? 'n' : c);
  return stem;
}

std::string history_csv(const std::vector<invsim::InvSimSample>& samples) {
  std::string csv;
  for (std::string_view column : kHistoryColumns) csv += fmt::format("{}{}", csv.empty() ? "" : ",", column);
  csv += '\n';
  for (const invsim::InvSimSample& s : samples) {
    const auto v = history_values(s);
    csv += fmt::format("{:.1f},{:.5f},{:.5f},{:.5f},{:.6f},{:.6f},{:.6f},{:.5f},{:.5f},{:.5f},", v[0], v[1], v[2], v[3],
                       v[4], v[5], v[6], v[7], v[8], v[9]);
    csv += fmt::format("{:.5f},{:.5f},{:.5f},{:.5f},{:.5f},{:.6e},{:.6e},{:.6e},", v[10], v[11], v[12], v[13], v[14],
                       v[15], v[16], v[17]);
    csv += fmt::format("{},{},{},{},{},{}\n", s.pulse_direction[0], s.pulse_direction[1], s.pulse_direction[2],
                       s.pulse_count[0], s.pulse_count[1], s.pulse_count[2]);
  }
  return csv;
}

bool write(const std::filesystem::path& path, const std::string& text, std::string& error) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (out) return true;
  error = "cannot write " + path.string();
  return false;
}

}  // namespace

std::array<double, kHistoryColumns.size()> history_values(const invsim::InvSimSample& s) {
  return {s.t_s,
          s.r_hill_m.x(),
          s.r_hill_m.y(),
          s.r_hill_m.z(),
          s.v_hill_mps.x(),
          s.v_hill_mps.y(),
          s.v_hill_mps.z(),
          s.r_desired_hill_m.x(),
          s.r_desired_hill_m.y(),
          s.r_desired_hill_m.z(),
          s.euler_rad.x() / kDegToRad,
          s.euler_rad.y() / kDegToRad,
          s.euler_rad.z() / kDegToRad,
          s.azimuth_rad / kDegToRad,
          s.elevation_rad / kDegToRad,
          s.u_body_mps2.x(),
          s.u_body_mps2.y(),
          s.u_body_mps2.z(),
          static_cast<double>(s.pulse_direction[0]),
          static_cast<double>(s.pulse_direction[1]),
          static_cast<double>(s.pulse_direction[2]),
          static_cast<double>(s.pulse_count[0]),
          static_cast<double>(s.pulse_count[1]),
          static_cast<double>(s.pulse_count[2])};
}

bool write_fmea_histories(const std::filesystem::path& dir, const std::vector<FmeaLayout>& layouts,
                          const std::vector<std::vector<invsim::FmeaHistory>>& histories,
                          std::string& error) {
  const std::filesystem::path root = dir / "history";
  std::string index = "configuration,mode,file,draws,draw_seed\n";
  for (std::size_t l = 0; l < layouts.size() && l < histories.size(); ++l) {
    std::error_code ec;
    std::filesystem::create_directories(root / layouts[l].name, ec);
    if (ec) {
      error = fmt::format("cannot create {}: {}", (root / layouts[l].name).string(), ec.message());
      return false;
    }
    for (std::size_t i = 0; i < layouts[l].rows.size() && i < histories[l].size(); ++i) {
      const std::string& label = layouts[l].rows[i].fmea_case.mode.label;
      const std::string file = layouts[l].name + "/" + file_stem(i, label) + ".csv";
      const invsim::FmeaHistory& h = histories[l][i];
      if (!write(root / file, history_csv(h.samples), error)) return false;
      index += fmt::format("{},{},{},{},{}\n", layouts[l].name, label, file, h.draws,
                           h.seed ? std::to_string(*h.seed) : std::string());
    }
  }
  return write(root / "index.csv", index, error);
}

}  // namespace chaser::cli
