#include "view/replay_page.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "view/replay_events.hpp"

namespace chaser::view {

namespace {

std::string base64(const std::vector<unsigned char>& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned b0 = bytes[i], b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0, b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
    const unsigned v = (b0 << 16) | (b1 << 8) | b2;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[v & 63] : '=';
  }
  return out;
}

// A number for JSON: NaN and infinities as null.
void number(std::string& out, double v, int decimals) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  fmt::format_to(std::back_inserter(out), "{:.{}f}", v, decimals);
}

// The kept rows' values, `width` a row, as a flat JSON array (after "key": when a key is given).
template <class Get>
void array(std::string& out, const char* key, const std::vector<std::size_t>& kept, int width, int decimals, Get get) {
  if (*key) fmt::format_to(std::back_inserter(out), "\"{}\":", key);
  out += '[';
  bool first = true;
  for (std::size_t r : kept)
    for (int k = 0; k < width; ++k) {
      if (!first) out += ',';
      first = false;
      number(out, get(r, k), decimals);
    }
  out += ']';
}

double quat_component(const Quat& q, int k) { return k == 0 ? q.w() : q.vec()(k - 1); }

std::string track_json(const ReplayTrack& k, const std::vector<std::size_t>& kept) {
  std::string out = "{";
  fmt::format_to(std::back_inserter(out), "\"t\":[");
  for (std::size_t i = 0; i < kept.size(); ++i) fmt::format_to(std::back_inserter(out), "{}{}", i ? "," : "", k.t_s[kept[i]]);
  out += "],";
  array(out, "r", kept, 3, 4, [&](std::size_t r, int c) { return k.r_lvlh_m[r](c); });
  out += ',';
  array(out, "qb", kept, 4, 7, [&](std::size_t r, int c) { return quat_component(k.q_lvlh_from_body[r], c); });
  out += ',';
  array(out, "qt", kept, 4, 7, [&](std::size_t r, int c) { return quat_component(k.q_lvlh_from_target[r], c); });
  out += ',';
  array(out, "ref", kept, 3, 4, [&](std::size_t r, int c) { return k.r_ref_lvlh_m[r](c); });
  out += ',';
  array(out, "att_err_deg", kept, 1, 4, [&](std::size_t r, int) { return k.attitude_error_rad[r] * 180.0 / 3.14159265358979323846; });
  out += ",\"arm\":";
  if (k.arm.empty()) {
    out += "null";
  } else {
    // The points flat, 27 a row; null where the arm sleeps.
    array(out, "", kept, 3 * kArmPoints, 4, [&](std::size_t r, int c) {
      return k.arm[r] ? (*k.arm[r])[static_cast<std::size_t>(c / 3)](c % 3) : std::nan("");
    });
  }
  out += '}';
  return out;
}

// Every period's realised on-times (ton_real_i; ton_cmd_i without them) as bytes, row-major.
nlohmann::json on_times(const sim::TelemetryRows& rows, int thrusters) {
  std::vector<int> cols;
  for (const char* base : {"ton_real_", "ton_cmd_"}) {
    cols.clear();
    for (int i = 1; i <= thrusters; ++i) {
      const auto it = std::find(rows.channels.begin(), rows.channels.end(), fmt::format("{}{}", base, i));
      if (it == rows.channels.end()) break;
      cols.push_back(static_cast<int>(it - rows.channels.begin()));
    }
    if (static_cast<int>(cols.size()) == thrusters && thrusters > 0) {
      std::vector<unsigned char> bytes;
      bytes.reserve(rows.rows() * cols.size());
      for (std::size_t r = 0; r < rows.rows(); ++r)
        for (int c : cols) {
          const double v = rows.values[r * rows.channels.size() + static_cast<std::size_t>(c)];
          bytes.push_back(static_cast<unsigned char>(std::lround(std::clamp(std::isfinite(v) ? v : 0.0, 0.0, 1.0) * 255.0)));
        }
      return {{"channel", std::string(base) + "N"}, {"rows", rows.rows()}, {"thrusters", thrusters}, {"base64", base64(bytes)}};
    }
  }
  return nullptr;
}

// The rows nearest each event (the one at or after it and the one before), kept by the decimation.
std::vector<std::size_t> event_rows(const std::vector<double>& t_s, const std::vector<ReplayEvent>& events) {
  std::vector<std::size_t> rows;
  for (const ReplayEvent& e : events) {
    const auto at = static_cast<std::size_t>(std::lower_bound(t_s.begin(), t_s.end(), e.t_s) - t_s.begin());
    if (at < t_s.size()) rows.push_back(at);
    if (at > 0) rows.push_back(at - 1);
  }
  return rows;
}

// The parts of summary.json the side panel shows.
nlohmann::json panel_summary(const nlohmann::json& s) {
  nlohmann::json out = nlohmann::json::object();
  for (const char* key : {"scenario", "seed", "duration_s", "simulated_s", "control_period_s", "capture_achieved", "mission_met",
                          "faults", "phases_flown", "phase_verdicts", "phases", "approach_axis_lvlh", "corridor_half_angle_deg",
                          "capture_distance_m", "propellant_used_kg", "chaser_version", "min_target_clearance_m"})
    if (s.contains(key)) out[key] = s[key];
  return out;
}

}  // namespace

nlohmann::json::string_t replay_data_json(const RunFiles& files, const DecimationTolerance& tol, ViewPage& figures) {
  const std::string file = files.telemetry_path.string();
  const double n = files.geometry.value("/lvlh/mean_motion_radps"_json_pointer, 0.0);
  const ReplayTrack track = replay_track(files.telemetry, n, file);
  const std::vector<ReplayEvent> events = replay_events(files.telemetry, files.summary);
  const std::vector<std::size_t> kept = decimate(track, tol, event_rows(track.t_s, events));
  const int thrusters = static_cast<int>(files.geometry.value("/chaser/thrusters"_json_pointer, nlohmann::json::array()).size());

  nlohmann::json event_list = nlohmann::json::array();
  for (const ReplayEvent& e : events)
    event_list.push_back({{"t", e.t_s}, {"kind", e.kind}, {"label", e.label}, {"thruster", e.thruster < 0 ? nlohmann::json(nullptr) : nlohmann::json(e.thruster)}});
  nlohmann::json active = nlohmann::json::array();
  for (const ActiveSetChange& a : active_set_changes(files.telemetry)) active.push_back({a.t_s, a.mask});
  const nlohmann::json meta = {{"telemetry_file", files.telemetry_path.filename().string()},
                               {"telemetry_rows", files.telemetry.rows()},
                               {"kept_rows", kept.size()},
                               {"t0_s", track.t_s.front()},
                               {"t_end_s", track.t_s.back()},
                               {"tolerance", {{"position_m", tol.position_m}, {"attitude_deg", tol.attitude_rad * 180.0 / 3.14159265358979323846}, {"max_gap_s", tol.max_gap_s}}}};
  std::string out = "{\"meta\":" + meta.dump() + ",\"geometry\":" + files.geometry.dump() +
                    ",\"summary\":" + panel_summary(files.summary).dump() + ",\"track\":" + track_json(track, kept) +
                    ",\"ontimes\":" + on_times(files.telemetry, thrusters).dump() + ",\"active\":" + active.dump() +
                    ",\"events\":" + event_list.dump() + "}";
  figures.telemetry_rows = files.telemetry.rows();
  figures.kept_rows = kept.size();
  figures.events = events.size();
  return out;
}

namespace {

// Text placed inside a <script> element: "</" would end it early.
std::string script_safe(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') {
      out += "<\\/";
      ++i;
    } else {
      out += text[i];
    }
  }
  return out;
}

// The template with each @NAME@ marker replaced by its text, in one pass: no inserted text is
// searched for markers.
std::string fill(std::string_view tmpl, const std::vector<std::pair<std::string_view, std::string_view>>& parts) {
  std::string out;
  std::size_t at = 0;
  while (at < tmpl.size()) {
    const std::size_t open = tmpl.find('@', at);
    if (open == std::string_view::npos) break;
    const std::size_t close = tmpl.find('@', open + 1);
    if (close == std::string_view::npos) break;
    const std::string_view name = tmpl.substr(open + 1, close - open - 1);
    const auto part = std::find_if(parts.begin(), parts.end(), [&](const auto& p) { return p.first == name; });
    if (part == parts.end()) {  // not a marker: the '@' is text
      out.append(tmpl.substr(at, open + 1 - at));
      at = open + 1;
      continue;
    }
    out.append(tmpl.substr(at, open - at));
    out.append(part->second);
    at = close + 1;
  }
  out.append(tmpl.substr(at));
  return out;
}

std::string html_escaped(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

}  // namespace

ViewPage view_page(const RunFiles& files, const DecimationTolerance& tol) {
  ViewPage page;
  const std::string data = script_safe(replay_data_json(files, tol, page));
  const PageAssets assets = page_assets();
  const std::string title = html_escaped(files.summary.value("scenario", std::string("run")));
  const std::string three = script_safe(assets.three), js = script_safe(assets.js);
  page.html = fill(assets.html, {{"TITLE", title},
                                 {"STYLE", assets.css},
                                 {"THREE_VERSION", assets.three_version},
                                 {"THREE_LICENCE", assets.three_licence},
                                 {"THREE", three},
                                 {"APP", js},
                                 {"DATA", data}});
  return page;
}

}  // namespace chaser::view
