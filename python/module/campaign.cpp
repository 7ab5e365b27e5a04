// chaser.campaign: the Monte Carlo campaign of `chaser campaign` (docs/campaigns.md), from Python.
// The campaign library flies the runs and writes its directory exactly as for the command; this file
// turns the arguments into its plan and options, shows the progress, and reads the directory back:
// runs.csv as a NumPy structured array, summary.csv and campaign.json as dicts.
#include <signal.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "campaign/campaign.hpp"
#include "campaign/csv.hpp"
#include "campaign/plan.hpp"
#include "campaign/run_row.hpp"
#include "campaign/target.hpp"
#include "core/worker_threads.hpp"
#include "flight/flight_software.hpp"
#include "sim/run.hpp"
#include "sim/summary.hpp"
#include "python/module/module.hpp"

namespace chaser::python {

namespace {

// The width of runs.csv's words in the structured array: "stuck_closed", the longest it writes.
constexpr std::size_t kTextWidth = 12;

struct CampaignResult {
  py::object runs;         // runs.csv: a NumPy structured array, one field per column
  py::dict summary;        // summary.csv: scheme -> case -> column -> value
  py::dict campaign;       // campaign.json's content
  std::string summary_md;  // summary.md's text
  py::object out;          // the campaign directory; None when it was a temporary one, now removed
  double wall_s = 0;       // [s] the runs' wall-clock time
};

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// --runs' text from N, "N", "case=N,..." or {case: N}.
std::string runs_text(const py::handle& runs) {
  if (runs.is_none()) return "";
  if (py::isinstance<py::bool_>(runs)) throw py::type_error("runs: an int, a 'case=N,case=N' str or a dict {case: N}");
  if (py::isinstance<py::int_>(runs)) return std::to_string(runs.cast<long long>());
  if (py::isinstance<py::str>(runs)) return runs.cast<std::string>();
  if (py::isinstance<py::dict>(runs)) {
    std::vector<std::string> pairs;
    for (const auto& [name, count] : runs.cast<py::dict>())
      pairs.push_back(fmt::format("{}={}", py::str(name).cast<std::string>(), py::str(count).cast<std::string>()));
    return fmt::format("{}", fmt::join(pairs, ","));
  }
  throw py::type_error("runs: an int, a 'case=N,case=N' str or a dict {case: N}");
}

// --cases' text from "none,leak" or ["none", "leak"].
std::string cases_text(const py::handle& cases) {
  if (cases.is_none()) return "";
  if (py::isinstance<py::str>(cases)) return cases.cast<std::string>();
  return fmt::format("{}", fmt::join(cases.cast<std::vector<std::string>>(), ","));
}

// Where the progress goes: a line on sys.stderr, or the caller's progress(done, total, diverged).
// Called from the campaign's worker threads, which hold no GIL: each call takes it for the call only.
// An exception from the caller's function stops the calls (the runs go on, their results are the
// same) and is raised once the campaign is over.
class ProgressShow {
 public:
  explicit ProgressShow(py::object callback) : callback_(std::move(callback)) {}

  void operator()(const campaign::ProgressCounts& counts) {
    py::gil_scoped_acquire gil;
    if (error_) return;
    try {
      if (callback_.is_none()) {
        const py::object stderr_ = py::module_::import("sys").attr("stderr");
        stderr_.attr("write")("\r" + campaign::progress_line(counts) + (counts.final ? "\n" : ""));
        stderr_.attr("flush")();
      } else {
        callback_(counts.done, counts.total, counts.diverged);
      }
    } catch (py::error_already_set& e) {
      error_ = std::move(e);
    }
  }
  void raise_if_failed() {
    if (error_) throw *error_;
  }

 private:
  py::object callback_;  // None: the stderr line
  std::optional<py::error_already_set> error_;
};

// Ctrl-C during a campaign. With the GIL released, Python's SIGINT handler would run only once the
// campaign returned. While one runs on Python's main thread under the default handler, a handler
// of ours records the signal instead; the workers then take no more runs (stop_requested), the
// rows written stay a prefix that resume=True finishes, and the call raises KeyboardInterrupt.
std::atomic<bool> interrupt_seen = false;
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");
extern "C" void record_interrupt(int) { interrupt_seen = true; }

class InterruptWatch {
 public:
  InterruptWatch() {
    const py::module_ signal = py::module_::import("signal"), threading = py::module_::import("threading");
    watching_ = threading.attr("current_thread")().is(threading.attr("main_thread")()) &&
                signal.attr("getsignal")(SIGINT).is(signal.attr("default_int_handler"));
    if (!watching_) return;
    interrupt_seen = false;
    struct sigaction ours {};
    ours.sa_handler = record_interrupt;
    sigemptyset(&ours.sa_mask);
    sigaction(SIGINT, &ours, &previous_);
  }
  ~InterruptWatch() {
    if (watching_) sigaction(SIGINT, &previous_, nullptr);
  }
  InterruptWatch(const InterruptWatch&) = delete;
  InterruptWatch& operator=(const InterruptWatch&) = delete;
  bool seen() const { return watching_ && interrupt_seen; }

 private:
  bool watching_ = false;
  struct sigaction previous_ {};
};

// progress=None: the line when sys.stderr is a terminal, as the command line decides.
bool progress_wanted(const py::handle& progress) {
  if (py::isinstance<py::bool_>(progress)) return progress.cast<bool>();
  if (!progress.is_none()) {
    if (!PyCallable_Check(progress.ptr()))
      throw py::type_error("progress: None, True, False or a function progress(done, total, diverged)");
    return true;
  }
  const py::object stderr_ = py::module_::import("sys").attr("stderr");
  return !stderr_.is_none() && py::hasattr(stderr_, "isatty") && stderr_.attr("isatty")().cast<bool>();
}

// One runs.csv field as its column's kind reads it; nullopt when it does not read.
std::optional<py::object> field_value(campaign::ColumnKind kind, std::string_view field) {
  switch (kind) {
    case campaign::ColumnKind::kInteger:
      if (const auto v = campaign::parse_integer(field)) return py::int_(*v);
      return std::nullopt;
    case campaign::ColumnKind::kUnsigned: {
      std::uint64_t v = 0;
      const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
      if (field.empty() || ec != std::errc() || end != field.data() + field.size()) return std::nullopt;
      return py::int_(v);
    }
    case campaign::ColumnKind::kText:
      if (field.empty() || field.size() > kTextWidth) return std::nullopt;
      return py::str(std::string(field));
    case campaign::ColumnKind::kNumber:
      if (const auto v = campaign::parse_number(field)) return py::float_(*v);
      return std::nullopt;
    case campaign::ColumnKind::kFlag:
      if (field != "0" && field != "1") return std::nullopt;
      return py::bool_(field == "1");
  }
  return std::nullopt;
}

// The NumPy type of each kind.
std::string numpy_type(campaign::ColumnKind kind) {
  switch (kind) {
    case campaign::ColumnKind::kInteger: return "<i8";
    case campaign::ColumnKind::kUnsigned: return "<u8";
    case campaign::ColumnKind::kText: return fmt::format("<U{}", kTextWidth);
    case campaign::ColumnKind::kNumber: return "<f8";
    case campaign::ColumnKind::kFlag: return "?";
  }
  return "";
}

// runs.csv's rows as a structured array, each column typed by its ColumnKind.
py::object runs_array(const std::string& text) {
  const std::vector<std::string> lines = lines_of(text);
  const std::optional<campaign::RunColumnSet> set =
      lines.empty() ? std::nullopt : campaign::run_column_set_of(lines.front());
  if (!set) throw std::runtime_error("runs.csv: not this version's header");
  const std::vector<campaign::RunColumn>& columns = campaign::run_columns(*set);
  std::vector<std::vector<std::string_view>> rows;
  for (std::size_t r = 1; r < lines.size(); ++r) {
    rows.push_back(campaign::split_fields(lines[r]));
    if (rows.back().size() != columns.size()) throw std::runtime_error(fmt::format("runs.csv: row {} is malformed", r));
  }
  py::list fields;
  for (const campaign::RunColumn& c : columns) fields.append(py::make_tuple(std::string(c.name), numpy_type(c.kind)));
  const py::module_ np = py::module_::import("numpy");
  py::object array = np.attr("zeros")(rows.size(), np.attr("dtype")(fields));
  for (std::size_t c = 0; c < columns.size(); ++c) {
    py::list values;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const std::optional<py::object> value = field_value(columns[c].kind, rows[r][c]);
      if (!value)
        throw std::runtime_error(fmt::format("runs.csv: row {}, {}: '{}'", r + 1, columns[c].name, rows[r][c]));
      values.append(*value);
    }
    array[py::str(std::string(columns[c].name))] = values;
  }
  return array;
}

// summary.csv as summary[scheme][case][column]: runs and detected as int, the rest as float.
py::dict summary_dict(const std::string& text) {
  const std::vector<std::string> lines = lines_of(text);
  if (lines.empty()) throw std::runtime_error("summary.csv is empty");
  const std::vector<std::string_view> header = campaign::split_fields(lines.front());
  py::dict summary;
  for (std::size_t r = 1; r < lines.size(); ++r) {
    const std::vector<std::string_view> cells = campaign::split_fields(lines[r]);
    if (cells.size() != header.size() || header.size() < 2)
      throw std::runtime_error(fmt::format("summary.csv: row {} is malformed", r));
    py::dict row;
    for (std::size_t c = 2; c < cells.size(); ++c) {
      const bool count = header[c] == "runs" || header[c] == "detected";
      const auto integer = count ? campaign::parse_integer(cells[c]) : std::nullopt;
      const auto number = count ? std::nullopt : campaign::parse_number(cells[c]);
      if (!integer && !number)
        throw std::runtime_error(fmt::format("summary.csv: row {}, {}: '{}'", r, header[c], cells[c]));
      row[py::str(std::string(header[c]))] = integer ? py::object(py::int_(*integer)) : py::object(py::float_(*number));
    }
    const py::str scheme{std::string(cells[0])}, fault_case{std::string(cells[1])};
    if (!summary.contains(scheme)) summary[scheme] = py::dict();
    summary[scheme].cast<py::dict>()[fault_case] = row;
  }
  return summary;
}

CampaignResult read_result(const std::filesystem::path& dir, double wall_s) {
  CampaignResult result;
  result.runs = runs_array(read_text(dir / "runs.csv"));
  result.summary = summary_dict(read_text(dir / "summary.csv"));
  result.campaign = py::module_::import("json").attr("loads")(read_text(dir / "campaign.json"));
  result.summary_md = read_text(dir / "summary.md");
  result.wall_s = wall_s;
  return result;
}

// A directory from tempfile.mkdtemp, removed with what is in it when this goes out of scope.
class TemporaryDirectory {
 public:
  TemporaryDirectory()
      : path_(py::str(py::module_::import("tempfile").attr("mkdtemp")(py::arg("prefix") = "chaser-campaign-"))) {}
  ~TemporaryDirectory() { py::module_::import("shutil").attr("rmtree")(path_, py::arg("ignore_errors") = true); }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

[[noreturn]] void raise_outcome(const campaign::CampaignOutcome& outcome) {
  if (outcome.status == campaign::CampaignStatus::kBadInput) throw py::value_error(outcome.message);
  PyErr_SetString(PyExc_OSError, outcome.message.c_str());
  throw py::error_already_set();
}

// --target's requirements, every one checked.
std::vector<campaign::Target> targets_of(const std::vector<std::string>& texts) {
  std::vector<campaign::Target> targets;
  for (const std::string& text : texts) {
    const campaign::TargetParse parsed = campaign::parse_target(text);
    if (!parsed.target) throw py::value_error(parsed.error);
    targets.push_back(*parsed.target);
  }
  return targets;
}

// What the command line's options say beyond the layout, checked as prepare() checks them.
struct Extras {
  campaign::Shard shard;
  bool resume = false;
  std::int64_t keep_telemetry = 0;
  std::vector<campaign::Target> targets;
};

Extras extras_of(const std::optional<std::string>& shard_text, bool resume, std::int64_t keep_telemetry,
                 const std::vector<std::string>& targets) {
  const campaign::ShardParse shard = campaign::parse_shard(shard_text.value_or("0/1"));
  if (!shard.shard) throw py::value_error(shard.error);
  if (keep_telemetry < 0) throw py::value_error(fmt::format("keep_telemetry: must be >= 0 (got {})", keep_telemetry));
  return Extras{*shard.shard, resume, keep_telemetry, targets_of(targets)};
}

// The campaign of a loaded scenario with --runs and --cases (its layout checked as prepare() checks it).
campaign::CampaignPlan plan_of(const Scenario& scenario, const py::object& runs, const py::object& cases) {
  const campaign::LayoutParse layout = campaign::parse_layout(
      cases_text(cases), runs_text(runs), static_cast<std::int64_t>(scenario.scenario.campaign.runs_per_case));
  if (!layout.error.empty()) throw py::value_error(layout.error);
  return campaign::CampaignPlan{scenario.scenario, scenario.hash, campaign::RunLayout(layout.cases)};
}

// `chaser campaign SCENARIO --runs --cases --threads --seed --out --shard --resume --keep-telemetry
// --target` (cli/campaign_command.cpp, prepare).
CampaignResult run_campaign(const py::object& scenario_arg, const py::object& runs, const py::object& cases,
                            std::optional<int> threads, std::optional<std::uint64_t> seed,
                            const py::object& out_arg, const py::object& progress,
                            const std::optional<std::string>& shard, bool resume, std::int64_t keep_telemetry,
                            const std::vector<std::string>& target_texts) {
  const std::optional<std::string> out =
      out_arg.is_none() ? std::nullopt : std::optional(py::str(py::module_::import("os").attr("fspath")(out_arg)));
  Scenario scenario = scenario_argument(scenario_arg);
  if (seed) scenario = with_overrides(scenario, {fmt::format("campaign.seed={}", *seed)});
  if (threads && *threads < 1) throw py::value_error(fmt::format("threads: must be >= 1 (got {})", *threads));
  const Extras extras = extras_of(shard, resume, keep_telemetry, target_texts);
  if (!out && (resume || keep_telemetry > 0))
    throw py::value_error("resume and keep_telemetry need out=DIR (without it the directory is a temporary one)");
  const campaign::CampaignPlan plan = plan_of(scenario, runs, cases);
  const bool show = progress_wanted(progress);

  std::optional<TemporaryDirectory> temporary;
  if (!out) temporary.emplace();
  const std::string dir = out ? *out : temporary->path();
  ProgressShow shown(py::isinstance<py::bool_>(progress) ? py::none() : progress);
  campaign::CampaignOptions options{
      .out_dir = dir,
      .shard = extras.shard,
      .threads = threads.value_or(default_worker_threads()),
      .resume = extras.resume,
      .keep_telemetry = extras.keep_telemetry,
      .progress = show,
      .show_progress = [&shown](const campaign::ProgressCounts& counts) { shown(counts); },
      .stop_requested = {},
      .targets = extras.targets};
  campaign::CampaignOutcome outcome;
  bool interrupted = false;
  {
    const InterruptWatch interrupt;
    options.stop_requested = [&interrupt] { return interrupt.seen(); };
    {
      py::gil_scoped_release released;
      outcome = campaign::run_campaign(plan, options);
    }
    interrupted = interrupt.seen();  // also after the last run was taken: the Ctrl-C is not lost
  }
  if (interrupted) {
    const std::string when = outcome.status == campaign::CampaignStatus::kStopped ? outcome.message : "after every run";
    PyErr_SetString(PyExc_KeyboardInterrupt, ("chaser.campaign: " + when).c_str());
    throw py::error_already_set();
  }
  if (outcome.status != campaign::CampaignStatus::kOk) raise_outcome(outcome);
  shown.raise_if_failed();
  CampaignResult result = read_result(dir, outcome.executed.wall_s);
  result.out = out ? py::object(py::str(*out)) : py::object(py::none());
  return result;
}

// `chaser campaign SCENARIO --runs --cases --seed --rerun I`: run I of that campaign alone, with the
// truth the campaign gives it (dispersions, fault) and the flight software designed for the nominal
// scenario, as chaser.run gives a run: summary.json's content and the telemetry in memory.
RunResult campaign_run(const py::object& scenario_arg, std::int64_t run, const py::object& runs, const py::object& cases,
                       std::optional<std::uint64_t> seed) {
  Scenario scenario = scenario_argument(scenario_arg);
  if (seed) scenario = with_overrides(scenario, {fmt::format("campaign.seed={}", *seed)});
  const campaign::CampaignPlan plan = plan_of(scenario, runs, cases);
  const std::int64_t total = plan.layout.total_runs();
  if (run < 0 || run >= total)
    throw py::value_error(fmt::format("run: must be in [0, {}] for this campaign (got {})", total - 1, run));
  sim::TelemetryRows memory;
  std::string summary_json, report;
  {
    py::gil_scoped_release released;
    const campaign::RunSetup setup = campaign::make_run_setup(plan, run);
    sim::RunOptions options;
    options.telemetry_rows = &memory;
    const sim::RunResult result = sim::run_scenario(setup.truth, flight::make_flight_params(plan.nominal), options);
    summary_json = sim::run_summary(setup.truth, plan.scenario_hash, result).dump(2) + "\n";
    report = sim::summary_text(setup.truth, result);
  }
  return run_result(summary_json, report, memory);
}

py::object to_pandas(const CampaignResult& result) {
  py::module_ pandas;
  try {
    pandas = py::module_::import("pandas");
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ImportError)) throw;
    throw py::import_error("to_pandas needs pandas (Debian: python3-pandas); .runs is the same table as a NumPy "
                           "structured array");
  }
  return pandas.attr("DataFrame")(result.runs);
}

}  // namespace

void add_campaign(py::module_& m) {
  py::class_<CampaignResult>(m, "CampaignResult", "What a campaign gives: its runs table and its summary.")
      .def_readonly("runs", &CampaignResult::runs, "runs.csv as a NumPy structured array, one field per column")
      .def_readonly("summary", &CampaignResult::summary,
                    "summary.csv as a dict: summary[scheme][case][column] (scheme: position, attitude, deficit, fdir)")
      .def_readonly("campaign", &CampaignResult::campaign, "campaign.json's content, as a dict")
      .def_readonly("summary_md", &CampaignResult::summary_md, "summary.md's text")
      .def_readonly("out", &CampaignResult::out, "the campaign directory (None: a temporary one, removed)")
      .def_readonly("wall_s", &CampaignResult::wall_s, "wall-clock time of the runs [s]")
      .def("to_pandas", &to_pandas, "The runs table as a pandas DataFrame (needs pandas).")
      .def("__repr__", [](const CampaignResult& r) {
        return "<chaser.CampaignResult " + py::str(r.campaign["scenario"]).cast<std::string>() + ", " +
               std::to_string(py::len(r.runs)) + " runs>";
      });

  m.def("campaign", &run_campaign, py::arg("scenario"), py::arg("runs") = py::none(), py::arg("cases") = py::none(),
        py::arg("threads") = py::none(), py::arg("seed") = py::none(), py::arg("out") = py::none(),
        py::arg("progress") = py::none(), py::kw_only(), py::arg("shard") = py::none(), py::arg("resume") = false,
        py::arg("keep_telemetry") = 0, py::arg("targets") = std::vector<std::string>{},
        "A Monte Carlo campaign, as `chaser campaign` (docs/campaigns.md): runs as --runs (N, 'case=N,...' or "
        "{case: N}), cases as --cases ('none,leak' or a list), threads as --threads (default: every core), seed as "
        "--seed (campaign.seed), out as --out (None: a temporary directory, removed after reading). progress: None "
        "shows a line on stderr when it is a terminal, True always, False never; or a function "
        "progress(done, total, diverged), called at most every 0.25 s and once at the end. Keywords as the "
        "command's options: shard='I/M' (--shard), resume=True (--resume, with out), keep_telemetry=K "
        "(--keep-telemetry, with out), targets=['P_nd<=1e-3@0.95', ...] (--target, judged in summary.md).");
  m.def("campaign_run", &campaign_run, py::arg("scenario"), py::arg("run"), py::arg("runs") = py::none(),
        py::arg("cases") = py::none(), py::arg("seed") = py::none(),
        "Run `run` of the campaign that chaser.campaign(scenario, runs, cases, seed=seed) flies, alone, as "
        "`chaser campaign ... --rerun I`: its dispersed truth and fault, the flight software designed for the "
        "nominal scenario; a RunResult as chaser.run gives (summary, telemetry in memory, report). Its figures "
        "are the campaign's row for that run.");
}

}  // namespace chaser::python
