# Warnings are errors on our own code only; generated and third-party code is left alone.
# (Not in the clang fuzz build: a clang-only warning must not break it for gcc-only authors.)
function(semnav_strict target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic $<$<NOT:$<BOOL:${SEMNAV_FUZZ}>>:-Werror>)
endfunction()

# semnav_library(NAME SOURCES ... DEPS ...): a static library of our own code.
function(semnav_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${CMAKE_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_DEPS})
  semnav_strict(${name})
endfunction()

# semnav_executable(NAME SOURCES ... DEPS ...); the global property SEMNAV_EXECUTABLES lists them
# all (tests/cli checks each one's command line).
function(semnav_executable name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  set_property(GLOBAL APPEND PROPERTY SEMNAV_EXECUTABLES ${name})
  target_include_directories(${name} PRIVATE ${CMAKE_SOURCE_DIR})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS})
  semnav_strict(${name})
endfunction()

# semnav_test(NAME SOURCES ... DEPS ... [LABELS ...]): a GoogleTest binary run by ctest.
# Tests see SEMNAV_SHARED_DATA_DIR, SEMNAV_SOURCE_DIR and SEMNAV_BIN_DIR (where the service binaries are).
function(semnav_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_include_directories(${name} PRIVATE ${CMAKE_SOURCE_DIR})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gmock GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    SEMNAV_SHARED_DATA_DIR="${SEMNAV_SHARED_DATA_DIR}"
    SEMNAV_SOURCE_DIR="${CMAKE_SOURCE_DIR}"
    SEMNAV_BIN_DIR="${CMAKE_RUNTIME_OUTPUT_DIRECTORY}")
  semnav_strict(${name})
  # Each test process gets its own TEST_TMPDIR/TMPDIR (see run-isolated.sh).
  set_target_properties(${name} PROPERTIES
    CROSSCOMPILING_EMULATOR ${CMAKE_SOURCE_DIR}/cmake/run-isolated.sh)
  gtest_discover_tests(${name} DISCOVERY_MODE PRE_TEST DISCOVERY_TIMEOUT 30
    PROPERTIES LABELS "${ARG_LABELS}" TIMEOUT 300)
endfunction()
