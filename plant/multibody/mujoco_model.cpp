#include "plant/multibody/mujoco_model.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <utility>

#include <fmt/format.h>

namespace chaser::plant::multibody {

namespace {

int bad_state_warnings(const mjData& d) {
  return d.warning[mjWARN_BADQPOS].number + d.warning[mjWARN_BADQVEL].number + d.warning[mjWARN_BADQACC].number;
}

// The VFS holds the text as a file "scene.xml" (2.2.2 compiles from files only).
struct Vfs {
  std::unique_ptr<mjVFS> vfs = std::make_unique<mjVFS>();
  Vfs() { mj_defaultVFS(vfs.get()); }
  ~Vfs() { mj_deleteVFS(vfs.get()); }
};

}  // namespace

MujocoModel::MujocoModel(const std::string& mjcf) {
  constexpr const char* kName = "scene.xml";
  Vfs files;
  if (mj_makeEmptyFileVFS(files.vfs.get(), kName, static_cast<int>(mjcf.size())) != 0)
    throw MujocoError("MuJoCo: the model's text does not fit the virtual file system");
  const int file = mj_findFileVFS(files.vfs.get(), kName);
  std::memcpy(files.vfs->filedata[file], mjcf.data(), mjcf.size());
  std::array<char, 1024> error{};
  mjModel* model = nullptr;
  guarded("loading the model", [&] { model = mj_loadXML(kName, files.vfs.get(), error.data(), static_cast<int>(error.size())); });
  if (model == nullptr) throw MujocoError(fmt::format("MuJoCo refused the model: {}", error.data()));
  model_ = model;
  mjData* data = nullptr;
  guarded("allocating the data", [&] { data = mj_makeData(model_); });
  if (data == nullptr) {
    mj_deleteModel(model_);
    throw MujocoError("MuJoCo: could not allocate the model's data");
  }
  data_ = data;
}

MujocoModel::~MujocoModel() {
  if (data_ != nullptr) mj_deleteData(data_);
  if (model_ != nullptr) mj_deleteModel(model_);
}

MujocoModel::MujocoModel(const MujocoModel& other) {
  mjModel* model = nullptr;
  mjData* data = nullptr;
  const mjModel* src_model = other.model_;
  const mjData* src_data = other.data_;
  guarded("copying the model", [&] {
    model = mj_copyModel(nullptr, src_model);
    data = mj_makeData(model);
    mj_copyData(data, model, src_data);
  });
  model_ = model;
  data_ = data;
}

MujocoModel& MujocoModel::operator=(const MujocoModel& other) {
  if (this != &other) {
    MujocoModel copy(other);
    *this = std::move(copy);
  }
  return *this;
}

MujocoModel::MujocoModel(MujocoModel&& other) noexcept : model_(other.model_), data_(other.data_) {
  other.model_ = nullptr;
  other.data_ = nullptr;
}

MujocoModel& MujocoModel::operator=(MujocoModel&& other) noexcept {
  std::swap(model_, other.model_);
  std::swap(data_, other.data_);
  return *this;
}

namespace {

// MuJoCo resets the state when a position, velocity or acceleration is not finite (or too large)
// and only counts a warning: that is a diverged step, never a state to fly on.
void throw_if_diverged(const mjData& d, int bad_before, double t_s) {
  if (bad_state_warnings(d) != bad_before)
    throw MujocoError(fmt::format("MuJoCo: the multibody step diverged at t = {} s (a non-finite or runaway state)", t_s));
}

}  // namespace

void MujocoModel::step() {
  const double t_s = data_->time;
  const int bad_before = bad_state_warnings(*data_);
  mjModel* m = model_;
  mjData* d = data_;
  guarded("stepping", [m, d] { mj_step(m, d); });
  throw_if_diverged(*data_, bad_before, t_s);
}

int MujocoModel::begin_step() {
  const int bad_before = bad_state_warnings(*data_);
  mjModel* m = model_;
  mjData* d = data_;
  guarded("stepping", [m, d] {
    mj_checkPos(m, d);
    mj_checkVel(m, d);
    mj_fwdPosition(m, d);  // mj_forwardSkip's position and velocity stages (MuJoCo 2.2.2)
    mj_sensorPos(m, d);
    if (mjENABLED(mjENBL_ENERGY)) mj_energyPos(m, d);
    mj_fwdVelocity(m, d);
    mj_sensorVel(m, d);
    if (mjENABLED(mjENBL_ENERGY)) mj_energyVel(m, d);
  });
  return bad_before;
}

bool MujocoModel::finish_evaluation() {
  mjModel* m = model_;
  mjData* d = data_;
  if (m->opt.integrator != mjINT_RK4 && m->opt.integrator != mjINT_EULER) return false;
  guarded("stepping", [m, d] {
    mj_forwardSkip(m, d, mjSTAGE_VEL, 0);  // the rest of mj_forward: actuation, accelerations, constraints
    mj_checkAcc(m, d);
    if (mjENABLED(mjENBL_FWDINV)) mj_compareFwdInv(m, d);
  });
  return true;
}

void MujocoModel::integrate(int bad_before) {
  const double t_s = data_->time;
  mjModel* m = model_;
  mjData* d = data_;
  guarded("stepping", [m, d] {
    switch (m->opt.integrator) {
      case mjINT_RK4:
        mj_RungeKutta(m, d, 4);
        break;
      case mjINT_EULER:
        mj_Euler(m, d);
        break;
      default:  // 2.2.2 does not export its implicit integrator: the whole step, evaluated anew
        mj_step(m, d);
    }
  });
  throw_if_diverged(*data_, bad_before, t_s);
}

void MujocoModel::forward() {
  mjModel* m = model_;
  mjData* d = data_;
  guarded("computing the state", [m, d] { mj_forward(m, d); });
}

Eigen::MatrixXd MujocoModel::mass_matrix() const {
  const int nv = model_->nv;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> M(nv, nv);
  const mjModel* m = model_;
  const mjData* d = data_;
  double* out = M.data();
  guarded("the mass matrix", [m, d, out] { mj_fullM(m, out, d->qM); });
  return M;
}

Momentum MujocoModel::momentum() {
  mjModel* m = model_;
  mjData* d = data_;
  guarded("the momentum", [m, d] { mj_subtreeVel(m, d); });
  // Body 0 (the world) is the whole scene's subtree: its CoM velocity times its mass, and its
  // angular momentum about its CoM.
  Momentum p;
  p.linear_kgmps = model_->body_subtreemass[0] * Vec3(d->subtree_linvel[0], d->subtree_linvel[1], d->subtree_linvel[2]);
  p.angular_kgm2ps = Vec3(d->subtree_angmom[0], d->subtree_angmom[1], d->subtree_angmom[2]);
  return p;
}

int MujocoModel::index(int type, const char* name, const char* what) const {
  const int id = mj_name2id(model_, type, name);
  if (id < 0) throw MujocoError(fmt::format("MuJoCo: the model has no {} named '{}'", what, name));
  return id;
}

int MujocoModel::body(const char* name) const { return index(mjOBJ_BODY, name, "body"); }
int MujocoModel::joint(const char* name) const { return index(mjOBJ_JOINT, name, "joint"); }
int MujocoModel::actuator(const char* name) const { return index(mjOBJ_ACTUATOR, name, "actuator"); }

}  // namespace chaser::plant::multibody
