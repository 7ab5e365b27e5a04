#include "flight/diagnosis_schemes.hpp"

#include <algorithm>

#include "core/plain_name.hpp"
#include "flight/fdir.hpp"

namespace chaser::flight {

namespace {

std::vector<DiagnosisScheme>& table() {
  static std::vector<DiagnosisScheme> schemes = {
      {.name = "position", .residual_channels = 3, .enabled = [](const FdirParams& p) { return p.position_enabled; },
       .deficit = [](const FdirState& f) { return &f.position_deficit.decision; }},
      {.name = "attitude", .residual_channels = 3, .enabled = [](const FdirParams& p) { return p.attitude_enabled; },
       .deficit = [](const FdirState& f) { return &f.attitude_deficit.decision; }},
      {.name = "deficit", .residual_channels = 0, .enabled = [](const FdirParams& p) { return p.deficit_detection; },
       .deficit = [](const FdirState& f) { return &f.detector_deficit.decision; }},
      // residual_bank_1: the nominal observer's mean residual, _2: the smallest observer's [rad/s]
      {.name = "bank", .residual_channels = 2, .enabled = [](const FdirParams& p) { return p.bank_enabled; },
       .step = step_bank_scheme, .deficit = [](const FdirState& f) { return &f.bank_deficit.decision; }},
      // residual_rate_check_1: the latest check's reading, the missing share of its pulse [-]
      {.name = "rate_check", .residual_channels = 1, .enabled = [](const FdirParams& p) { return p.rate_check_enabled; },
       .step = step_rate_check_scheme, .deficit = [](const FdirState& f) { return &f.rate_check_decision; }},
  };
  return schemes;
}

}  // namespace

const std::vector<DiagnosisScheme>& diagnosis_schemes() { return table(); }

int register_diagnosis_scheme(DiagnosisScheme scheme) {
  std::vector<DiagnosisScheme>& schemes = table();
  const bool taken = std::any_of(schemes.begin(), schemes.end(), [&](const DiagnosisScheme& s) { return s.name == scheme.name; });
  if (taken || !is_plain_name(scheme.name) || !scheme.enabled || !scheme.step ||
      static_cast<int>(schemes.size()) >= kMaxDiagnosisSchemes)
    return -1;
  schemes.push_back(std::move(scheme));
  return static_cast<int>(schemes.size()) - 1;
}

}  // namespace chaser::flight
