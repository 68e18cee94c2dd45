# Small helpers shared by every folder's CMakeLists.

# The fuzz build (fuzz/, GEARSIM_FUZZ) needs clang's libFuzzer; GCC has none.
if(GEARSIM_FUZZ AND NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "GEARSIM_FUZZ needs clang (libFuzzer), not ${CMAKE_CXX_COMPILER_ID}: configure a "
                      "fresh build folder with CC=clang CXX=clang++ (scripts/fuzz.sh does)")
endif()

# Warnings (and sanitizers when asked) on one of our targets.
function(gearsim_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion)
  # No fused multiply-adds the source does not write: a contracted a·b − c·d is no longer the
  # negation of c·d − a·b, which geometry/triangulate.cpp's orientation test relies on (built
  # with -march=native, the paper's ring failed to triangulate: "no visible bridge vertex"), and
  # results would differ between machines that have FMA and those without (GCC contracts by
  # default where the target has FMA: aarch64, -march=native on x86-64).
  target_compile_options(${target} PRIVATE -ffp-contract=off)
  # No errno from the math functions (no code here reads it): std::sqrt and friends inline
  # without their error-path call. The same results bit for bit (the paper run's logs compared);
  # the paper run's step ≈ 1 % faster.
  target_compile_options(${target} PRIVATE -fno-math-errno)
  if(CMAKE_POSITION_INDEPENDENT_CODE AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # The libraries are position-independent when the Python module links them; GCC then takes
    # every non-inline function as replaceable at load time and calls it instead of inlining it
    # (FlankTable::direction() from flank_jet(), …). Nothing here relies on interposing a symbol.
    # The same results bit for bit (golden hashes); the paper run's step 0.9 % fewer instructions.
    target_compile_options(${target} PRIVATE -fno-semantic-interposition)
  endif()
  if(GEARSIM_PGO STREQUAL "generate")
    # One thread writes the counters (a run steps on one): no atomic updates needed.
    target_compile_options(${target} PRIVATE -fprofile-generate -fprofile-update=single -fprofile-dir=${GEARSIM_PGO_DIR})
  elseif(GEARSIM_PGO STREQUAL "use")
    # Code the training runs never reached is optimised as without a profile
    # (-fprofile-partial-training), and so is a function whose source changed since the profile
    # was made (-Wno-coverage-mismatch: GCC then leaves its profile out). The optimisation moves
    # code, not arithmetic: the same results bit for bit (the golden-hash tests).
    target_compile_options(${target} PRIVATE -fprofile-use -fprofile-partial-training -fprofile-dir=${GEARSIM_PGO_DIR}
                                             -Wno-missing-profile -Wno-coverage-mismatch)
  endif()
  if(GEARSIM_UNITY AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # A unity batch #includes the sources, so GCC no longer sees an Impl's anonymous-namespace
    # members as belonging to the main file and warns; the warning is only about that inclusion.
    target_compile_options(${target} PRIVATE -Wno-subobject-linkage)
  endif()
  if(GEARSIM_FUZZ)
    # Every library a fuzz target links carries libFuzzer's coverage hooks and the sanitizers;
    # the fuzz targets themselves add -fsanitize=fuzzer (libFuzzer's main). Undefined behaviour
    # aborts, so that libFuzzer keeps a reproducer.
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link,address,undefined
                                             -fno-sanitize-recover=undefined -fno-omit-frame-pointer
                                             -fsanitize-coverage-ignorelist=${PROJECT_SOURCE_DIR}/fuzz/coverage_ignore.txt)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  elseif(GEARSIM_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()

# Test code itself (assertions, fixtures, GoogleTest's macros) builds at -O1: the code under test
# is the libraries, built as released; -O3 on the tests only doubled their compile time.
function(gearsim_test_optimisation target)
  if(CMAKE_BUILD_TYPE STREQUAL "Release")
    target_compile_options(${target} PRIVATE -O1)
  endif()
endfunction()

# A library of one folder: gearsim_add_library(NAME SOURCES a.cpp b.cpp DEPS x y).
function(gearsim_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_DEPS})
  gearsim_target_defaults(${name})
endfunction()

# One test executable: gearsim_add_test(NAME SOURCES a.cpp DEPS geometry).
function(gearsim_add_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE GEARSIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                             GEARSIM_BINARY_DIR="${PROJECT_BINARY_DIR}")
  gearsim_target_defaults(${name})
  gearsim_test_optimisation(${name})
  # One label per executable, its name without _tests: geometry, physics, …, fe and fe_ccx.
  # ctest's -L/-LE take regular expressions: `-L fe` runs both fe executables, `-LE ccx` leaves
  # out the CalculiX runs.
  string(REGEX REPLACE "_tests$" "" label ${name})
  set(props ENVIRONMENT "GEARSIM_SOURCE_DIR=${PROJECT_SOURCE_DIR}" LABELS ${label})
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES ${props})
endfunction()
