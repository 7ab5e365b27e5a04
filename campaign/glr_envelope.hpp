#pragma once
// Threshold selection (Fonod 2015, Fig. 8): the envelope of the GLR statistic S of each scheme over
// every fault-free run, per whole second, and the threshold it suggests, J_th = margin x max.
//
// Each fault-free run leaves one line in DIR/glr_runs.csv (kept so that resume and merge rebuild
// the envelope from files, like the summary): "run,p0,a0,p1,a1,..." with p_t, a_t the largest S of
// the position and attitude scheme in [t, t+1), as floats written with 9 significant digits
// (exact for a float). The envelope is a maximum, so the order of the runs does not change it.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace chaser::campaign {

inline constexpr std::string_view kGlrRunsHeader = "run,position_max_s0,attitude_max_s0,...";

std::string format_glr_line(std::int64_t run, const std::vector<std::array<float, 2>>& glr_max_per_s);

struct GlrLine {
  std::int64_t run = 0;
  std::vector<std::array<float, 2>> per_second;
};
std::optional<GlrLine> parse_glr_line(std::string_view line);

class GlrEnvelope {
 public:
  void add(const std::vector<std::array<float, 2>>& per_second);
  bool empty() const { return runs_ == 0; }
  std::int64_t runs() const { return runs_; }
  const std::vector<std::array<float, 2>>& per_second() const { return max_; }
  std::array<double, 2> overall_max() const;  // [position, attitude]

 private:
  std::vector<std::array<float, 2>> max_;
  std::int64_t runs_ = 0;
};

// Builds the envelope from a glr_runs.csv file (nullopt if it cannot be read).
std::optional<GlrEnvelope> read_glr_envelope(const std::string& glr_runs_path);
// glr_envelope.csv: "t_s,position_max,attitude_max", one row per whole second.
bool write_glr_envelope(const GlrEnvelope& envelope, const std::string& path);

}  // namespace chaser::campaign
