# Sanitizer and fuzzing builds (docs/reliability.md). The flags reach every target of ours through
# chaser_options; system libraries (yaml-cpp, fmt, GoogleTest) stay uninstrumented.
#
# CHASER_SANITIZE=address,undefined (make sanitize, build-sanitize): the test suite with
# AddressSanitizer and UndefinedBehaviorSanitizer; undefined behaviour aborts the test at once.
# CHASER_FUZZ=ON (make fuzz, build-fuzz, clang only): coverage for libFuzzer plus both sanitizers,
# and the harnesses of fuzz/.
set(CHASER_SANITIZE "" CACHE STRING "Sanitizers for our code, e.g. address,undefined")
option(CHASER_FUZZ "Build the libFuzzer harnesses of fuzz/ (clang)" OFF)

# The sanitizer build compiles our code at -O1 with line tables only (-g1), after the build type's
# flags so that these win: a report still names file and line, and the build takes half the time of
# -O2 -g (36 s against 17 s for plant/multibody_motion.cpp on this machine), which is most of CI.
if(CHASER_SANITIZE)
  target_compile_options(chaser_options INTERFACE -fsanitize=${CHASER_SANITIZE}
                         -fno-sanitize-recover=undefined -fno-omit-frame-pointer -O1 -g1)
  target_link_options(chaser_options INTERFACE -fsanitize=${CHASER_SANITIZE})
endif()

if(CHASER_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "CHASER_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  target_compile_options(chaser_options INTERFACE -fsanitize=fuzzer-no-link,address,undefined
                         -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g)
  target_link_options(chaser_options INTERFACE -fsanitize=address,undefined)
endif()
