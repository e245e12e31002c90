# Small helpers so every target gets the same language level and warnings without global flags.

function(swarm_target_defaults target)
  target_compile_features(${target} PUBLIC cxx_std_20)
  # -ffp-contract=off: no fused multiply-add, so floating-point results (K-Means, RNG draws) are
  # bit-identical on x86 and ARM; lockstep determinism promises that.
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wno-unused-parameter -ffp-contract=off)
  # A folder may lower Release's -O3 (SWARM_RELEASE_OPT, set in its CMakeLists.txt): the algorithms
  # (planner_core, comm) and the benchmarks keep -O3; the roles' glue takes -O2, and the tests and
  # the command line -O1, which compile in a third less time and run as fast where it matters
  # (their loops are the libraries'). Other build types keep their own flags.
  if(SWARM_RELEASE_OPT)
    target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-O${SWARM_RELEASE_OPT}>)
  endif()
endfunction()

# swarm_add_gtest(NAME <name> SOURCES <files...> LIBS <targets...> [LABELS <labels...>] [COST <n>])
# One GoogleTest executable registered with ctest; tests are discovered at build time. COST: what
# ctest schedules first when it has no timings yet (a clean clone): the longest tests, so that
# they do not end the run alone.
function(swarm_add_gtest)
  cmake_parse_arguments(T "" "NAME;TIMEOUT;COST" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${T_NAME} ${T_SOURCES})
  swarm_target_defaults(${T_NAME})
  target_link_libraries(${T_NAME} PRIVATE ${T_LIBS} swarm::test_support GTest::gtest GTest::gtest_main)
  set_target_properties(${T_NAME} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  if(NOT T_LABELS)
    set(T_LABELS unit)
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 120)
  endif()
  if(NOT T_COST)
    set(T_COST 0)
  endif()
  gtest_discover_tests(${T_NAME} TEST_LIST ${T_NAME}_TESTS DISCOVERY_TIMEOUT 30)
  # gtest_discover_tests flattens list-valued PROPERTIES (LABELS "unit;dds" would become the
  # words "unit dds", i.e. label unit and a stray argument), so labels and timeout are set from a
  # file ctest includes after the discovered tests.
  set(props ${CMAKE_CURRENT_BINARY_DIR}/${T_NAME}_properties.cmake)
  file(WRITE ${props}
       "foreach(t IN LISTS ${T_NAME}_TESTS)\n"
       "  set_tests_properties(\"\${t}\" PROPERTIES LABELS \"${T_LABELS}\" TIMEOUT ${T_TIMEOUT} COST ${T_COST})\n"
       "endforeach()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${props})
endfunction()

# swarm_library(<name> SOURCES <files...> [PUBLIC <targets...>] [PRIVATE <targets...>])
# A static library swarm_<name>, alias swarm::<name>, with the folder's include/ as its public
# include directory (headers live in include/swarm/<name>/).
function(swarm_library name)
  cmake_parse_arguments(L "" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  add_library(swarm_${name} STATIC ${L_SOURCES})
  add_library(swarm::${name} ALIAS swarm_${name})
  swarm_target_defaults(swarm_${name})
  target_include_directories(swarm_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:include>)
  target_link_libraries(swarm_${name} PUBLIC ${L_PUBLIC} PRIVATE ${L_PRIVATE})
endfunction()

# swarm_role(<executable> <library>...): a role process, main.cpp beside its library.
function(swarm_role exe)
  add_executable(${exe} main.cpp)
  swarm_target_defaults(${exe})
  target_link_libraries(${exe} PRIVATE ${ARGN})
endfunction()
