#include "model/invsim_study.hpp"

namespace chaser::model {

InvSimParams apply_configuration(const InvSimParams& base, const InvSimConfiguration& c) {
  InvSimParams p = base;
  for (const InvSimThrusterChange& change : c.changes) {
    InvSimThruster& t = p.thrusters.at(change.thruster);
    if (change.thrust_N) t.thrust_N = *change.thrust_N;
    if (change.position_body_m) t.position_body_m = *change.position_body_m;
    if (change.direction_body) t.direction_body = change.direction_body->normalized();
  }
  return p;
}

std::size_t candidate_count(const std::vector<InvSimFreeChoice>& choices) {
  std::size_t n = 1;
  for (const InvSimFreeChoice& choice : choices) {
    n *= choice.options.size();
    if (n > kMaxOptimizeCandidates) return kMaxOptimizeCandidates + 1;
  }
  return n;
}

InvSimConfiguration candidate(const std::vector<InvSimFreeChoice>& choices, std::size_t index) {
  // Digits from the last choice (fastest) to the first.
  std::vector<std::size_t> digit(choices.size(), 0);
  for (std::size_t k = choices.size(); k-- > 0;) {
    digit[k] = index % choices[k].options.size();
    index /= choices[k].options.size();
  }
  InvSimConfiguration c;
  for (std::size_t k = 0; k < choices.size(); ++k) {
    const InvSimConfiguration& option = choices[k].options[digit[k]];
    if (!c.name.empty()) c.name += ", ";
    c.name += choices[k].name + "=" + option.name;
    if (!option.description.empty()) {
      if (!c.description.empty()) c.description += "; ";
      c.description += option.description;
    }
    c.changes.insert(c.changes.end(), option.changes.begin(), option.changes.end());
  }
  return c;
}

}  // namespace chaser::model
