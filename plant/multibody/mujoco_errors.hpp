#pragma once
// MuJoCo's errors as C++ exceptions. MuJoCo 2.2.2's default error handler prints and ends the
// process, and a user handler that returns lets MuJoCo go on with a broken state; inside a campaign
// or the Python module an error must be a clear exception instead. guarded() runs MuJoCo calls
// with Chaser's handler installed: on an error the handler jumps back to the guard (setjmp /
// longjmp, as MuJoCo's own Python bindings do: no C++ exception unwinds MuJoCo's C frames) and the
// guard throws MujocoError with MuJoCo's message. An error outside any guard aborts with the message.
#include <csetjmp>
#include <stdexcept>
#include <string>

namespace chaser::plant::multibody {

class MujocoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

namespace detail {
// The guard in force on this thread (campaigns fly runs on worker threads) and the last message.
std::jmp_buf*& guard_on_this_thread();
// Installs Chaser's error and warning handlers (idempotent).
void install_mujoco_handlers();
[[noreturn]] void throw_mujoco_error(const char* what);
}  // namespace detail

// Runs `call`, which must make plain MuJoCo calls only (the jump back skips its frames, so nothing
// in them may need a destructor); throws MujocoError("MuJoCo, <what>: <message>") if MuJoCo raised
// an error. Guards nest.
template <class Call>
void guarded(const char* what, Call call) {
  detail::install_mujoco_handlers();
  std::jmp_buf here;
  std::jmp_buf* const outer = detail::guard_on_this_thread();
  detail::guard_on_this_thread() = &here;
  if (setjmp(here) == 0) {
    call();
    detail::guard_on_this_thread() = outer;
    return;
  }
  detail::guard_on_this_thread() = outer;
  detail::throw_mujoco_error(what);
}

}  // namespace chaser::plant::multibody
