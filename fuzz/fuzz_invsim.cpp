// libFuzzer harness: inverse-simulation scenario text -> io::load_invsim_text (limits, parse, read,
// layout and study checks). Findings as in fuzz_scenario.cpp.
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/invsim_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const chaser::io::InvSimLoadResult r = chaser::io::load_invsim_text(text);
  if (r.params.has_value() == !r.errors.empty()) __builtin_trap();
  return 0;
}
