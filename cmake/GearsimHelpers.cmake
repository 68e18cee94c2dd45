# Small helpers shared by every folder's CMakeLists.

# Warnings (and sanitizers when asked) on one of our targets.
function(gearsim_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion)
  if(GEARSIM_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
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

# One test executable: gearsim_add_test(NAME SOURCES a.cpp DEPS geometry [LABELS ccx]).
function(gearsim_add_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE GEARSIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                             GEARSIM_BINARY_DIR="${PROJECT_BINARY_DIR}")
  gearsim_target_defaults(${name})
  set(props ENVIRONMENT "GEARSIM_SOURCE_DIR=${PROJECT_SOURCE_DIR}")
  if(ARG_LABELS)
    list(APPEND props LABELS "${ARG_LABELS}")
  endif()
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES ${props})
endfunction()
