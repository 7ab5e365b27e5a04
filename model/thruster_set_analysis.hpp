#pragma once
// Thruster-set analysis: the force/moment direction and fault compensability analysis of
// COMRADE 2018, sec. 6 (6.3). Before a fault-tolerant allocator can be trusted, one asks of the
// thruster set (a) along which body directions it can push at all, and how hard, and (b) whether
// it still can after any one thruster is lost, i.e. whether a single failure can be compensated
// by the remaining thrusters or leaves a direction in which the vehicle is no longer controllable.
//
// "How hard" is measured per signed body axis (+Fx, -Fx, ..., +Cz, -Cz): the largest PURE force
// (or torque) along that axis that on-times u in [0, 1] can produce,
//     max t  s.t.  M u = t e_axis,  0 <= u <= 1,
// the other five wrench components held at zero. This is a linear programme, solved with CLP.
// It is always feasible (u = 0, t = 0) and bounded (t <= sum_j |M(axis, j)|).
//
// Not the hot path: these functions allocate freely and are meant for design-time tools and tests.
#include <Eigen/Core>
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace chaser::model {

// Configuration matrix of any thruster set: column j = [force [N]; torque about the centre of mass
// [N m]], body axes, of thruster j open for a whole period, per unit on-time. 1..32 columns.
using ThrusterSetMatrix = Eigen::Matrix<double, 6, Eigen::Dynamic>;

inline constexpr int kMaxAnalysedThrusters = 32;
inline constexpr int kSignedAxes = 12;

// Signed axis k is wrench component k / 2 (0-2 force x, y, z; 3-5 torque x, y, z), positive
// direction for even k, negative for odd k:
// +Fx, -Fx, +Fy, -Fy, +Fz, -Fz, +Cx, -Cx, +Cy, -Cy, +Cz, -Cz.
std::string_view signed_axis_name(int axis);
// Unit of signed axis k's figures: "N" for forces, "N m" for torques.
std::string_view signed_axis_unit(int axis);

// An attained value below this fraction of the largest column norm is reported as 0
// (unattainable). It matches kPositiveSpanTolerance: CLP leaves residuals of order 1e-12 of the
// column scale, so a true zero never shows above it, and a real thruster set that can push along
// an axis does so with a sizeable fraction of one thruster, far above it.
inline constexpr double kAttainableZeroTolerance = 1e-9;

struct AttainableAxes {
  // Largest pure force [N] (axes 0-5) or torque [N m] (axes 6-11) along each signed axis; 0 where
  // unattainable. The other five components are zero to within ~1e-12 of the column scale.
  std::array<double, kSignedAxes> value{};
  // On-times attaining each value (one entry per column of M, each in [0, 1] to within ~1e-12).
  std::array<Eigen::VectorXd, kSignedAxes> on_times;
};

// The twelve LPs for M. Thruster `lost` (if in [0, cols)) is held closed (u_lost = 0), which is
// the same as removing its column; lost = -1 keeps every thruster. Throws std::invalid_argument
// for 0 or more than kMaxAnalysedThrusters columns or non-finite entries, std::runtime_error if
// CLP fails to prove an optimum (it cannot fail on a feasible bounded LP unless numerically stuck).
AttainableAxes attainable_axes(const ThrusterSetMatrix& m, int lost = -1);

struct SingleLossAnalysis {
  int lost = -1;        // index of the lost thruster (column of M)
  std::string name;     // its name
  AttainableAxes axes;  // the twelve values with it held closed
  bool spans = false;   // the remaining thrusters positively span R^6
  // Smallest attained_after / attained_before over the axes attainable before the loss (1 when
  // none is), and the signed axis where it occurs (-1 when none is): 0 means a lost direction.
  double shrink_ratio = 1.0;  // [-]
  int shrink_axis = -1;
};

struct ThrusterSetAnalysis {
  std::vector<std::string> names;  // one per column of M
  AttainableAxes axes;             // all thrusters available
  // The columns of M positively span R^6 (model::positive_span): force and torque in every
  // direction. Equivalent to every value of `axes` being positive (the cone then holds +-e_k).
  bool spans = false;
  std::vector<SingleLossAnalysis> single_losses;  // one per thruster, in column order
  bool tolerates_single_loss = false;             // every single loss still spans
};

// The full analysis: attainable axes and span of M and of every N-1 subset. `names` empty means
// "T1".."TN"; otherwise one per column (std::invalid_argument if not).
ThrusterSetAnalysis analyse_thruster_set(const ThrusterSetMatrix& m,
                                         std::vector<std::string> names = {});

// Human-readable report: the verdicts, the force table [N] and torque table [N m] (rows: the full
// set, then without each thruster), and the per-loss shrink table.
std::string format_thruster_set_analysis(const ThrusterSetAnalysis& analysis);

// JSON report (indent 2). Keys:
//   "thrusters": [names], "axes": ["+Fx", ..., "-Cz"] (the order of every 12-number array),
//   "units": {"force": "N", "torque": "N m"},
//   "attainable": [12 numbers, all thrusters], "spans": bool, "tolerates_single_loss": bool,
//   "single_loss": [{"lost": name, "index": column, "attainable": [12 numbers], "spans": bool,
//                    "shrink_ratio": number, "shrink_axis": "+Fx".. or null}, ...].
std::string thruster_set_analysis_json(const ThrusterSetAnalysis& analysis);

}  // namespace chaser::model
