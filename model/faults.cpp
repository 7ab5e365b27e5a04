#include "model/faults.hpp"

namespace chaser::model {

std::string_view to_string(FaultKind kind) {
  switch (kind) {
    case FaultKind::kStuckOpen: return "stuck_open";
    case FaultKind::kStuckClosed: return "stuck_closed";
    case FaultKind::kLeak: return "leak";
    case FaultKind::kLoss: return "loss";
  }
  return "unknown";
}

}  // namespace chaser::model
