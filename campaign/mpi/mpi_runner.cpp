// chaser-mpi's campaign runner over MPI (campaign/mpi_runner.hpp).
#include "campaign/mpi_runner.hpp"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "campaign/progress.hpp"
#include "campaign/run_one.hpp"
#include "campaign/run_schedule.hpp"

namespace chaser::campaign {

namespace {

// Protocol. To rank 0: kTagReady (int32: the sender's worker threads, one request each) once, then
// kTagResult (a packed RunOutput, which is also the next request). From rank 0: kTagRun (int64 run
// index) or kTagStop, one answer per request. A rank is done when each of its requests got a stop.
enum Tag : int { kTagReady = 1, kTagResult = 2, kTagRun = 3, kTagStop = 4 };
constexpr std::int64_t kNoMoreRuns = RunSchedule::kNoMoreRuns;
constexpr std::int64_t kWindowFull = RunSchedule::kWindowFull;
// Idle pause of the polling main threads: short against a run (milliseconds to seconds), long
// enough not to steal a core from the workers.
constexpr auto kPollPause = std::chrono::microseconds(300);

// RunOutput as bytes: run (int64), diverged (1 byte), row length (uint64), row, glr line. Ranks of
// one job share the byte order (homogeneous cluster).
std::string pack(const RunOutput& out) {
  std::string bytes(17, '\0');
  const std::uint64_t row_size = out.row.size();
  std::memcpy(bytes.data(), &out.run, 8);
  bytes[8] = out.diverged ? 1 : 0;
  std::memcpy(bytes.data() + 9, &row_size, 8);
  return bytes + out.row + out.glr_line;
}

RunOutput unpack(const std::vector<char>& bytes) {
  RunOutput out;
  std::uint64_t row_size = 0;
  std::memcpy(&out.run, bytes.data(), 8);
  out.diverged = bytes[8] != 0;
  std::memcpy(&row_size, bytes.data() + 9, 8);
  out.row.assign(bytes.data() + 17, row_size);
  out.glr_line.assign(bytes.data() + 17 + row_size, bytes.size() - 17 - row_size);
  return out;
}

[[noreturn]] void abort_job(int rank, const std::string& message) {
  // One write per line: the ranks share stderr, and a line written piecewise tears.
  std::cerr << ("chaser campaign: MPI rank " + std::to_string(rank) + ": " + message + "; aborting the job\n");
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::terminate();  // MPI_Abort does not return
}

// Rank 0's main thread: takes one message if any. A result goes to `finished`; the message's
// requests join `waiting`.
struct Requests {
  std::deque<int> waiting;  // ranks, one entry per unanswered request
  int heard = 0;            // ranks whose kTagReady arrived
  std::int64_t live = 0;    // requests not yet answered with a stop
};

bool receive_one(Requests& r, const std::function<void(RunOutput)>& finished) {
  int flag = 0;
  MPI_Status status;
  MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
  if (!flag) return false;
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::vector<char> bytes(static_cast<std::size_t>(std::max(count, 1)));
  MPI_Recv(bytes.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  std::int32_t requests = 1;
  if (status.MPI_TAG == kTagReady) {
    std::memcpy(&requests, bytes.data(), sizeof requests);
    ++r.heard;
    r.live += requests;
  } else {
    finished(unpack(bytes));
  }
  r.waiting.insert(r.waiting.end(), static_cast<std::size_t>(requests), status.MPI_SOURCE);
  return true;
}

// Answers the waiting requests in order while runs can be handed out.
bool answer(Requests& r, const std::function<std::int64_t()>& next_run) {
  bool answered = false;
  while (!r.waiting.empty()) {
    const std::int64_t run = next_run();
    if (run == kWindowFull) break;
    MPI_Send(&run, 1, MPI_INT64_T, r.waiting.front(), run < 0 ? kTagStop : kTagRun, MPI_COMM_WORLD);
    r.live -= run < 0;
    r.waiting.pop_front();
    answered = true;
  }
  return answered;
}

// Serves the other ranks until each of them has been told to stop (at once when world_size is 1).
void coordinate(int world_size, const std::function<std::int64_t()>& next_run,
                const std::function<void(RunOutput)>& finished) {
  Requests r;
  while (r.heard < world_size - 1 || r.live > 0) {
    const bool received = receive_one(r, finished);
    const bool answered = answer(r, next_run);
    if (!received && !answered) std::this_thread::sleep_for(kPollPause);
  }
}

// Rank 0's RunsExecutor: its worker threads and the other ranks share one schedule.
ExecuteResult execute_mpi(int world_size, const CampaignPlan& plan, const flight::FlightParams& flight,
                          const RunRange& todo, RowsWriter& writer, const ExecuteOptions& options) {
  const int threads = std::max(1, options.threads);
  RunSchedule s(todo.begin, todo.end, static_cast<std::int64_t>(threads) * world_size * kReorderWindowPerThread);
  Progress progress(todo.size(), options.progress, options.show_progress);
  const auto worker = [&] {
    for (std::int64_t run = s.claim(); run >= 0; run = s.claim())
      s.deliver(run_one(plan, flight, run, telemetry_dir(options.telemetry_root, options.keep_telemetry, run)),
                writer, progress);
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  coordinate(world_size, [&] { return s.try_claim(); },
             [&](RunOutput out) { s.deliver(std::move(out), writer, progress); });
  for (std::thread& t : pool) t.join();
  ExecuteResult result = s.result();
  progress.finish(result.runs, result.diverged);
  result.wall_s = progress.elapsed_s();
  return result;
}

// Another rank: its worker threads take runs from `inbox` and leave rows in `outbox`; the main
// thread alone talks to rank 0.
struct Mailbox {
  std::mutex mutex;
  std::condition_variable arrived;
  std::deque<std::int64_t> inbox;
  std::deque<RunOutput> outbox;
  bool closed = false;
  std::string error;
};

void fly_from(Mailbox& box, const CampaignPlan& plan, const flight::FlightParams& flight, const CampaignOptions& o) {
  const std::string root = (std::filesystem::path(o.out_dir) / "runs").string();
  for (;;) {
    std::unique_lock lock(box.mutex);
    box.arrived.wait(lock, [&] { return box.closed || !box.inbox.empty(); });
    if (box.inbox.empty()) return;
    const std::int64_t run = box.inbox.front();
    box.inbox.pop_front();
    lock.unlock();
    try {
      RunOutput out = run_one(plan, flight, run, telemetry_dir(root, o.keep_telemetry, run));
      lock.lock();
      box.outbox.push_back(std::move(out));
    } catch (const std::exception& e) {
      if (!lock.owns_lock()) lock.lock();
      box.error = "run " + std::to_string(run) + ": " + e.what();
      return;
    }
  }
}

// One pass of the main thread: sends finished rows, takes rank 0's answers. False when idle.
bool relay(Mailbox& box, int& stops, std::int64_t& flown, int rank) {
  std::deque<RunOutput> done;
  {
    std::lock_guard lock(box.mutex);
    if (!box.error.empty()) abort_job(rank, box.error);
    done.swap(box.outbox);
  }
  for (const RunOutput& out : done) {
    const std::string bytes = pack(out);
    MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
    ++flown;
  }
  int flag = 0;
  MPI_Status status;
  MPI_Iprobe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
  if (flag) {
    std::int64_t run = kNoMoreRuns;
    MPI_Recv(&run, 1, MPI_INT64_T, 0, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    std::lock_guard lock(box.mutex);
    if (status.MPI_TAG == kTagRun) box.inbox.push_back(run);
    else ++stops;
    box.arrived.notify_one();
  }
  return flag || !done.empty();
}

std::int64_t serve_runs(const CampaignPlan& plan, const CampaignOptions& options, int rank) {
  std::int32_t threads = std::max(1, options.threads);
  std::optional<flight::FlightParams> flight;
  try {
    flight = flight::make_flight_params(plan.nominal);  // designed once per rank, as the thread pool does
  } catch (const std::exception& e) {
    abort_job(rank, std::string("cannot design the flight software: ") + e.what());
  }
  Mailbox box;
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back([&] { fly_from(box, plan, *flight, options); });
  MPI_Send(&threads, sizeof threads, MPI_CHAR, 0, kTagReady, MPI_COMM_WORLD);
  int stops = 0;
  std::int64_t flown = 0;
  while (stops < threads)
    if (!relay(box, stops, flown, rank)) std::this_thread::sleep_for(kPollPause);
  {
    std::lock_guard lock(box.mutex);
    box.closed = true;
  }
  box.arrived.notify_all();
  for (std::thread& t : pool) t.join();
  return flown;
}

}  // namespace

bool mpi_built() { return true; }

MpiSession::MpiSession(int& argc, char**& argv) {
  int provided = 0;
  if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    error_ = "--mpi: MPI_Init_thread failed";
    return;
  }
  initialized_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  if (provided < MPI_THREAD_FUNNELED) error_ = "--mpi: this MPI library does not support MPI_THREAD_FUNNELED";
}

MpiSession::~MpiSession() {
  if (initialized_) MPI_Finalize();
}

int mpi_rank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

bool mpi_all_agree(const std::string& campaign, int rank) {
  std::uint64_t size = campaign.size();
  MPI_Bcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  std::string root = rank == 0 ? campaign : std::string(size, '\0');
  MPI_Bcast(root.data(), static_cast<int>(size), MPI_CHAR, 0, MPI_COMM_WORLD);
  const bool same = !campaign.empty() && campaign == root;
  if (!campaign.empty() && !root.empty() && !same)
    std::cerr << ("chaser campaign: MPI rank " + std::to_string(rank) +
                  " prepared another campaign than rank 0 (a scenario file, --set or option differs between the ranks)\n");
  int mine = same ? 1 : 0, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return all == 1;
}

CampaignOutcome run_campaign_mpi(const CampaignPlan& plan, const CampaignOptions& options, int rank) {
  if (rank != 0) {
    CampaignOutcome served;
    served.executed.runs = serve_runs(plan, options, rank);
    return served;
  }
  int world_size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &world_size);
  bool executed = false;
  const auto executor = [&](const CampaignPlan& p, const flight::FlightParams& flight, const RunRange& todo,
                            RowsWriter& writer, const ExecuteOptions& execute) {
    executed = true;
    return execute_mpi(world_size, p, flight, todo, writer, execute);
  };
  CampaignOutcome outcome = run_campaign(plan, options, executor);
  if (!executed)  // bad input or an unwritable --out: release the other ranks
    coordinate(world_size, [] { return kNoMoreRuns; }, [](RunOutput) {});
  return outcome;
}

}  // namespace chaser::campaign
