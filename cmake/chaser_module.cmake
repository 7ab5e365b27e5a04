# chaser_module(NAME DEPS...): a static library from every .cpp of the current folder.
# One library per folder keeps the dependency rules of docs/architecture.md visible in the build.
function(chaser_module name)
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(sources)
    add_library(${name} STATIC ${sources})
    target_link_libraries(${name} PUBLIC chaser_options ${ARGN})
    # The Python module (python/module/) links these libraries into a shared object, which needs
    # position-independent code. -fno-semantic-interposition keeps the calls inside a library
    # inlinable as under the compiler's default -fPIE (a library's symbols are never interposed).
    set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    target_compile_options(${name} PRIVATE -fno-semantic-interposition)
    # Compiled in unity batches of eight, as the tests (below); -ffp-contract=off (CMakeLists.txt)
    # keeps every result bit-identical to the file-by-file build, whatever the batches inline.
    set_target_properties(${name} PROPERTIES UNITY_BUILD ${CHASER_UNITY_LIBS} UNITY_BUILD_BATCH_SIZE 8)
  else()  # a header-only folder
    add_library(${name} INTERFACE)
    target_link_libraries(${name} INTERFACE chaser_options ${ARGN})
  endif()
endfunction()

# chaser_test(NAME LIBS...): one GoogleTest binary from every .cpp of the current test folder.
function(chaser_test name)
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(NOT sources)
    return()
  endif()
  add_executable(${name} ${sources})
  # The suite's files compiled in batches of eight (CMake's unity build): each batch parses
  # GoogleTest, Eigen and our headers once instead of eight times: the suites build in about
  # two thirds of the time (docs/performance.md, "Build and test").
  # A file's helpers live in its own namespace where another file of the suite has the same names.
  set_target_properties(${name} PROPERTIES UNITY_BUILD ${CHASER_UNITY_TESTS} UNITY_BUILD_BATCH_SIZE 8)
  target_link_libraries(${name} PRIVATE ${ARGN} GTest::gtest GTest::gtest_main)
  add_test(NAME ${name} COMMAND ${name} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
endfunction()
