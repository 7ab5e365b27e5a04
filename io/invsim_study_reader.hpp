#pragma once
// Internal to io: the layout-study sections of an inverse-simulation scenario (`configurations`,
// `optimize`; model/invsim_study.hpp), read after the thrusters, and the thruster-layout check
// they share with the scenario's own layout (io/invsim_reader.cpp).
#include "io/yaml_reader.hpp"
#include "model/invsim.hpp"
#include "model/invsim_study.hpp"

namespace chaser::io {

// Reports at `key_path` every way the layout cannot fly the approach: a translation group that does
// not push along its axis, attitude thrusters that do not turn about theirs, repeated names.
void check_invsim_layout(const model::InvSimParams& p, const std::string& key_path, Diagnostics& diag);

// Reads the optional sections `configurations` and `optimize` of the root mapping; `p` holds the
// scenario's thrusters (names resolve against it) and must be valid.
void read_invsim_study(MapReader& root, const model::InvSimParams& p, model::InvSimStudy& out);

}  // namespace chaser::io
