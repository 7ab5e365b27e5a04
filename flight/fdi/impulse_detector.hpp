#pragma once
// Thruster fault detection by impulses (docs/fdi.md, "Turning flight: the impulse statistic"): the
// deficit detector's statistic where the tanks' liquid fills the torque rows. In COMRADE's turning
// hold the slosh masses strike their tank walls and give the chaser torque spikes of a few N m that
// last about a second; the GLR gain on single rows (deficit_detector.hpp) reads them as a thruster's,
// and an on-board copy of the pendulums cannot time the strikes well enough to remove them (docs/fdi.md).
// But the liquid only exchanges momentum with the chaser: its torque's impulse over any interval is
// the change of its own angular momentum, bounded by twice the largest it can hold, whatever the
// interval's length. A thruster fault has a lasting torque: a stuck-open thruster of COMRADE's
// chaser gives ~20 N m for as long as it lasts, 400 N m s in 20 s.
//
// The torque rows y(k) (deficit_isolation.hpp) are summed in blocks of about a second; every
// block, the change of their mean over the last W seconds against the L seconds before, as the
// impulse over W,
//   d = T (sum over the last W of y  -  (W / L) sum over the L before of y)     [N m s, body axes]
// and the statistic is d's excess over what the model errors can make (below). The alarm is raised
// when the statistic exceeds the threshold.
// The suspect is the watched thruster whose torque direction lies closest to d's (|cos|): a deficit
// along -M_C,i (stuck closed, loss) or an excess along +M_C,i (stuck open, leak); the deficit bank
// names the thruster after the alarm, as for the gain detector.
//
// A change statistic, not a level: what is constant over W + L cancels, such as a centre of mass
// off its nominal place under a steady thrust. What the model errors make of a CHANGE of the
// commanded wrench does not: the centre of mass's error delta_c under the force's change, and the
// inertia's relative error delta_I under the torque's (the bounds the deficit bank weighs its rows
// with, fdi.deficit.com_uncertainty_m and inertia_uncertainty). With dF and dtau the same change
// statistic of the commanded force and torque (N s, N m s), per axis a (j, k the other two)
//   bound_a = delta_c (|dF_j| + |dF_k|) + delta_I |dtau_a|
// bounds it (the torque error delta_c x F is linear in F, so its change is delta_c x dF), and the
// statistic is the largest excess, max_a (|d_a| - bound_a), floored at zero. Without it the hold's
// transfer, 47 N on a centre of mass 1.3 cm off, read 35 N m s in a fault-free run.
// The threshold, in N m s, is sized from fault-free campaigns (docs/fdi.md). The detector needs
// W + L seconds of rows after it is armed before it can alarm.
//
// Cost: nine additions and the commanded wrench a period, and W + L blocks' additions per block.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "flight/fdi/deficit_isolation.hpp"
#include "model/fdi.hpp"

namespace chaser::flight::fdi {

struct ImpulseDetectorParams {
  int block = 10;             // [periods] rows per block (model::impulse_block_periods)
  int window_blocks = 20;     // [blocks] W
  int baseline_blocks = 100;  // [blocks] L
  double threshold_Nms = 40.0;  // [N m s] on the largest axis of d
};

// Problems with the parameters (empty when valid), each naming the field.
std::vector<std::string> validate(const ImpulseDetectorParams& params);

// Sums over one block of periods.
struct ImpulseBlock {
  Vec3 row_Nm = Vec3::Zero();     // [N m] the torque rows
  Vec3 force_N = Vec3::Zero();    // [N] the commanded force, body axes
  Vec3 torque_Nm = Vec3::Zero();  // [N m] the commanded torque
};

struct ImpulseDetectorState {
  std::array<ImpulseBlock, model::kMaxImpulseBlocks> ring{};  // complete blocks; the oldest at `slot`
  ImpulseBlock open_block;         // the rows of the block being summed
  int phase = 0;                   // rows in open_block
  int slot = 0;                    // ring slot of the next complete block
  std::int64_t blocks = 0;         // complete blocks so far
  Vec3 change_Nms = Vec3::Zero();  // [N m s] d at the last evaluation
  Vec3 bound_Nms = Vec3::Zero();   // [N m s] what the model errors can make of the wrench's change
  double statistic = 0;            // [N m s] the largest excess of |d| over the bound, >= 0
  int suspect = -1;                // lane, -1: none yet
  bool alarm = false;              // latched
  std::int64_t alarm_sample = -1;  // the deficit bank's sample index at the alarm
};

// Call after push_deficit_sample: adds the torque row of the previous sample and, when a block is
// complete, evaluates.
void step_impulse_detector(const ImpulseDetectorParams& params, const DeficitIsolationParams& bank_params,
                           const DeficitBankState& bank, ImpulseDetectorState& state);

}  // namespace chaser::flight::fdi
