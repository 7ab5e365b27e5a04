#pragma once
// The chaser of one campaign run: mass, principal moments of inertia and centre of mass dispersed
// about the nominal (Fonod 2015, Table 1 and section V). Each value is a normal draw truncated at
// 3 sigma, with the scenario's 3-sigma value; thruster forces are dispersed by the plant itself.
#include <cstdint>

#include "core/random.hpp"
#include "model/campaign.hpp"
#include "model/scenario.hpp"
#include "model/spacecraft.hpp"

namespace chaser::campaign {

// Redraws of the three moments allowed before the nominal moments are kept (a triangle-inequality
// failure needs moments dispersed by about their 3-sigma at once; 100 misses never happen in
// practice, the bound only keeps the loop finite).
inline constexpr int kMaxInertiaDraws = 100;

// Draws from the stream "campaign/dispersion" of the run seed, in a fixed order: mass, the three
// principal moments (all three redrawn together until I1 + I2 >= I3 holds for every ordering),
// then the three centre-of-mass offsets. Principal axes stay those of the nominal tensor.
model::SpacecraftParams disperse_chaser(const model::SpacecraftParams& nominal, const model::CampaignParams& params,
                                        std::uint64_t run_seed);

// The tumbling target's initial attitude and rate with campaign.target_spin_*: the rate scaled by a
// dispersed factor, then the target and its rate turned together by a tilt (angle normal, 3-sigma
// given, truncated at 3 sigma) about a direction perpendicular to the rate, uniform in angle; so a
// spin about a body axis stays about it. Stream "campaign/target_spin"; the result has spin_case
// given. Unchanged without target.body or with both dispersions zero.
model::TargetParams disperse_target_spin(const model::TargetParams& nominal, const model::CampaignParams& params,
                                         std::uint64_t run_seed);

// The start's offsets (model::InitialState::offset_*) with campaign.initial_*: per LVLH axis,
// normal, truncated at 3 sigma, position then velocity; stream "campaign/initial".
void disperse_initial(model::InitialState& initial, const model::CampaignParams& params, std::uint64_t run_seed);

// One draw of a relative factor 1 + x, x normal with 3-sigma `three_sigma`, truncated at 3 sigma.
double dispersed_factor(RandomStream& rng, double three_sigma);

}  // namespace chaser::campaign
