#include "plant/multibody/mujoco_errors.hpp"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <fmt/format.h>
#include <mujoco/mujoco.h>

namespace chaser::plant::multibody::detail {

namespace {

thread_local std::jmp_buf* t_guard = nullptr;
thread_local std::array<char, 1024> t_message{};

void on_mujoco_error(const char* message) {
  std::strncpy(t_message.data(), message, t_message.size() - 1);
  t_message.back() = '\0';
  if (t_guard != nullptr) std::longjmp(*t_guard, 1);
  // MuJoCo would go on after this handler returns: stop rather than compute on a broken state.
  std::fprintf(stderr, "chaser: MuJoCo error outside a guarded call: %s\n", message);
  std::abort();
}

// Warnings MuJoCo also counts in mjData::warning, where the callers read the ones that matter (a
// non-finite state); printing them would only clutter a campaign's output.
void on_mujoco_warning(const char*) {}

}  // namespace

std::jmp_buf*& guard_on_this_thread() { return t_guard; }

void install_mujoco_handlers() {
  mju_user_error = on_mujoco_error;
  mju_user_warning = on_mujoco_warning;
}

void throw_mujoco_error(const char* what) { throw MujocoError(fmt::format("MuJoCo, {}: {}", what, t_message.data())); }

}  // namespace chaser::plant::multibody::detail
