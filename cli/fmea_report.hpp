#pragma once
// The files of `chaser fmea` (docs/invsim.md, "chaser fmea"): fmea.csv, one row per mode, and
// fmea.md, Zhou 2018's Tables 4, 5 and 6 in the paper's layout followed by the ranking by risk.
#include <string>
#include <vector>

#include "invsim/fmea.hpp"
#include "model/invsim.hpp"

namespace chaser::cli {

std::string fmea_csv(const model::InvSimParams& p, const std::vector<invsim::FmeaRow>& rows);
std::string fmea_markdown(const model::InvSimParams& p, const std::vector<invsim::FmeaRow>& rows);

}  // namespace chaser::cli
