#pragma once
// The supervisor in the flight software (fdi.supervisor; flight/fdi/mode_supervisor.hpp): its
// estimators designed from the scenario when a run starts, and, with `accommodate`, each mode's
// allocation, COMRADE 2018's virtual actuator (Fig. 15) for thruster faults:
//   nominal             every starting thruster flies;
//   j stuck closed      the allocation flies without j (the paper's u_max,j = 0);
//   j stuck open        the same, and asks the others for the demand less j's full thrust, so that
//                       the two together give the demand (ours: the paper is silent).
// The nominal controller runs on unchanged: the mode reshapes only how its demand is met. Where the
// remaining thrusters can meet it (every single-thruster set of a validated layout), the faulty
// plant under the mode's allocation gives the wrench the healthy one gives under the nominal's, so
// the loop the controller sees is the same in every matched mode, and its virtual actuator state
// (Lunze and Steffen's x_v, the part of the demand the reallocation cannot give) stays zero.
#include <optional>

#include "flight/fdi/mode_supervisor.hpp"
#include "flight/thruster_management.hpp"
#include "model/recovery.hpp"
#include "model/scenario.hpp"

namespace chaser::flight {

// The supervisor's estimators for the scenario (absent with fdi.supervisor.enabled false).
std::optional<fdi::SupervisorParams> make_flight_supervisor(const model::Scenario& scenario);

// The active set and the cancelled thrust of `mode`: the starting set without the mode's thruster,
// whose full thrust is cancelled when the mode says it is stuck open.
void fly_supervisor_mode(const fdi::SupervisorParams& supervisor, int mode, const ThrusterManagementParams& management,
                         ThrusterManagementState& state, model::ThrusterConfiguration& thrusters);

}  // namespace chaser::flight
