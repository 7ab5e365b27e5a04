#pragma once
// A residual generator design as JSON (for `chaser fdi design --out FILE.json`): the inputs that
// matter, the matrices the runtime observer needs (A_bar, B_bar, C, L, Q), and the design figures.
// Matrices are arrays of rows; complex numbers are [re, im].
#include <nlohmann/json.hpp>

#include "flight/fdi/design/rate_model.hpp"
#include "flight/fdi/design/residual_design.hpp"
#include "flight/fdi/design/uio_bank.hpp"

namespace chaser::flight::fdi {

nlohmann::json to_json(const ResidualDesign& design);

// The body-rate model (`chaser fdi design --model rate --out FILE.json`): full and reduced
// matrices, the state names and each slosh mode's figures.
nlohmann::json to_json(const RateModel& model);

// The observer bank (`chaser fdi design --model uio-bank --out FILE.json`): the discrete model, the
// nominal observer and per thruster its observer (matrices and figures), the steady fault gains and
// each thruster's blind and least moved observers.
nlohmann::json to_json(const UioBank& bank);

}  // namespace chaser::flight::fdi
