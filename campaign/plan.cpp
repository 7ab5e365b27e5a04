#include "campaign/plan.hpp"

#include "campaign/dispersion.hpp"
#include "campaign/fault_sampling.hpp"
#include "core/random.hpp"

namespace chaser::campaign {

double run_duration_s(const model::Scenario& nominal) {
  return nominal.campaign.onset_s + nominal.campaign.horizon_after_onset_s;
}

RunSetup make_run_setup(const CampaignPlan& plan, std::int64_t run) {
  const model::CampaignParams& params = plan.nominal.campaign;
  RunSetup setup;
  setup.run = run;
  setup.seed = run_seed(params.seed, static_cast<std::uint64_t>(run));
  setup.fault_case = plan.layout.case_of(run);
  setup.fault = sample_fault(setup.fault_case, params, model::initial_active_set(plan.nominal.thrusters), setup.seed);
  setup.truth = plan.nominal;
  setup.truth.seed = setup.seed;  // the plant draws its own noises (thrust dispersion included) from it
  setup.truth.duration_s = run_duration_s(plan.nominal);
  setup.truth.chaser = disperse_chaser(plan.nominal.chaser, params, setup.seed);
  setup.truth.target = disperse_target_spin(plan.nominal.target, params, setup.seed);
  disperse_initial(setup.truth.initial, params, setup.seed);
  setup.truth.faults.clear();
  if (setup.fault) setup.truth.faults.push_back(*setup.fault);
  return setup;
}

}  // namespace chaser::campaign
