// The faults list (Fonod 2015, section II.D): at most one fault per thruster, each with the keys of
// its kind only.
#include <array>

#include <fmt/format.h>

#include "io/scenario_sections.hpp"

namespace chaser::io {
namespace {

using model::FaultKind;

constexpr std::array<FaultKind, 4> kKinds = {FaultKind::kStuckOpen, FaultKind::kStuckClosed,
                                             FaultKind::kLeak, FaultKind::kLoss};

std::optional<FaultKind> fault_kind(const std::string& text) {
  for (FaultKind k : kKinds)
    if (text == model::to_string(k)) return k;
  return std::nullopt;
}

// A size key that belongs to another kind is an error, not silently ignored.
void reject_key(MapReader& m, std::string_view key, std::string_view owner, std::string_view kind) {
  if (!m.has(key)) return;
  m.accept(key);
  m.diagnostics().add(m.path_of(key), fmt::format("only allowed when kind is {} (kind here is {})",
                                                  owner, kind));
}

// Reads one fault; returns its thruster index if that was valid.
std::optional<int> read_fault(const YAML::Node& node, const std::string& path, model::FaultParams& out,
                              Diagnostics& diag) {
  MapReader m(node, path, diag);
  std::string name, kind_text;
  std::optional<int> index;
  if (m.text("thruster", name) && !(index = model::thruster_index(name)))
    diag.add(m.path_of("thruster"), fmt::format("must be a thruster name T1..TN, N the number of thrusters.list entries (got '{}')", name));
  std::optional<FaultKind> kind;
  if (m.text("kind", kind_text) && !(kind = fault_kind(kind_text)))
    diag.add(m.path_of("kind"),
             fmt::format("must be one of stuck_open, stuck_closed, leak, loss (got '{}')", kind_text));
  m.number("onset_s", Range::non_negative(), out.onset_s);  // <= duration: validate_scenario
  if (kind) {
    out.kind = *kind;
    if (*kind == FaultKind::kLeak) {
      m.number("leak_size", Range::left_open(0.0, 1.0), out.leak_size);
      m.number("leak_slope_per_s", Range::positive(), out.leak_slope_per_s);
    } else {
      reject_key(m, "leak_size", "leak", kind_text);
      reject_key(m, "leak_slope_per_s", "leak", kind_text);
    }
    if (*kind == FaultKind::kLoss)
      m.number("loss_size", Range::left_open(0.0, 1.0), out.loss_size);
    else
      reject_key(m, "loss_size", "loss", kind_text);
  } else {  // unknown kind: its keys cannot be judged
    for (const char* key : {"leak_size", "leak_slope_per_s", "loss_size"}) m.accept(key);
  }
  m.finish();
  if (index) out.thruster = *index;
  return index;
}

}  // namespace

void read_faults(MapReader& root, std::vector<model::FaultParams>& out) {
  const auto list = root.child("faults", "a list of faults (may be empty: [])");
  if (!list) return;
  Diagnostics& diag = root.diagnostics();
  // At most one fault per thruster, so a longer list cannot be valid: it is refused before its
  // entries are read.
  if (!list->IsSequence() || list->size() > static_cast<std::size_t>(model::kMaxThrusters)) {
    diag.add("faults", fmt::format("must be a list of faults, at most {} (one per thruster; may be empty: []) (got {})",
                                   model::kMaxThrusters, describe_node(*list)));
    return;
  }
  std::array<int, model::kMaxThrusters> first_fault;
  first_fault.fill(-1);
  out.assign(list->size(), model::FaultParams{});
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string path = join_path("faults", std::to_string(i));
    const std::optional<int> index = read_fault((*list)[i], path, out[i], diag);
    if (!index) continue;
    if (first_fault[*index] >= 0)
      diag.add(join_path(path, "thruster"),
               fmt::format("duplicate fault on T{} (also faults.{}): at most one fault per thruster",
                           *index + 1, first_fault[*index]));
    else
      first_fault[*index] = static_cast<int>(i);
  }
}

}  // namespace chaser::io
