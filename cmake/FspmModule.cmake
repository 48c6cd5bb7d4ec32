# fspm_add_module(NAME DEPS target...): one library per module folder, built from every .cpp in
# it, with headers beside the sources and included from the repository root
# (#include "lsystem/parser.hpp"). The alias is fspm::NAME.
function(fspm_add_module name)
  cmake_parse_arguments(ARG "" "" "DEPS;PRIVATE_DEPS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(NOT sources)
    # A module without sources yet is still a static library, so targets can link to it and
    # add sources conditionally.
    set(sources ${CMAKE_CURRENT_BINARY_DIR}/fspm_${name}_empty.cpp)
    file(WRITE ${sources} "// empty module\n")
  endif()
  add_library(fspm_${name} STATIC ${sources})
  target_include_directories(fspm_${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(fspm_${name} PUBLIC ${ARG_DEPS} PRIVATE fspm_warnings ${ARG_PRIVATE_DEPS})
  add_library(fspm::${name} ALIAS fspm_${name})
endfunction()

# fspm_add_test_suite(MODULE DEPS target...): one GoogleTest executable per module from every
# tests/MODULE/*_test.cpp, registered with CTest test by test.
function(fspm_add_test_suite module)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${module}/*_test.cpp)
  if(NOT sources)
    return()
  endif()
  add_executable(fspm_${module}_tests ${sources})
  target_link_libraries(fspm_${module}_tests PRIVATE ${ARG_DEPS} fspm_warnings GTest::gtest
                                                     GTest::gtest_main GTest::gmock)
  target_compile_definitions(fspm_${module}_tests PRIVATE
                             FSPM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(fspm_${module}_tests DISCOVERY_TIMEOUT 60
                       PROPERTIES ENVIRONMENT "FSPM_SOURCE_DIR=${PROJECT_SOURCE_DIR}")
endfunction()
