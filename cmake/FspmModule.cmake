include(GNUInstallDirs)
if(FSPM_SHARED_LIBS)
  # Installed executables and libraries find the fspm libraries beside them, wherever the tree is
  # installed or unpacked.
  set(CMAKE_INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")
endif()

# fspm_add_module(NAME DEPS target... PRIVATE_DEPS target... INTERNAL_HEADERS file...): one
# library per module folder (static, or shared with FSPM_SHARED_LIBS), built from every .cpp in it, with headers beside the sources and
# included from the repository root (#include "lsystem/parser.hpp"). The alias is fspm::NAME.
# The library and its headers are installed (headers under include/fspm/<folder>/, so the same
# #include lines work with -I<prefix>/include/fspm), except the INTERNAL_HEADERS: implementation
# headers that name a private dependency (docs/architecture.md, "Public and internal headers").
# The fspm modules among DEPS and PRIVATE_DEPS are recorded for the CMake package (cmake/Packaging).
function(fspm_add_module name)
  cmake_parse_arguments(ARG "" "" "DEPS;PRIVATE_DEPS;INTERNAL_HEADERS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(NOT sources)
    # A module without sources yet is still a static library, so targets can link to it and
    # add sources conditionally.
    set(sources ${CMAKE_CURRENT_BINARY_DIR}/fspm_${name}_empty.cpp)
    file(WRITE ${sources} "// empty module\n")
  endif()
  if(FSPM_SHARED_LIBS)
    # Shared, with the SONAME of the minor version (0.y: a new minor version may break the ABI).
    # No fspm_NAME_EXPORTS define (DEFINE_SYMBOL), so the objects are those of the static build and
    # come from ccache; --no-undefined makes a dependency missing from DEPS a link error.
    add_library(fspm_${name} SHARED ${sources})
    set_target_properties(fspm_${name} PROPERTIES
                          VERSION ${PROJECT_VERSION}
                          SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
                          DEFINE_SYMBOL "")
    target_link_options(fspm_${name} PRIVATE -Wl,--no-undefined)
  else()
    add_library(fspm_${name} STATIC ${sources})
  endif()
  target_include_directories(fspm_${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                                 $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/fspm>)
  target_link_libraries(fspm_${name} PUBLIC ${ARG_DEPS}
                                     PRIVATE $<BUILD_INTERFACE:fspm_warnings> ${ARG_PRIVATE_DEPS})
  set_target_properties(fspm_${name} PROPERTIES EXPORT_NAME ${name})
  add_library(fspm::${name} ALIAS fspm_${name})

  set(module_deps "")
  foreach(dep IN LISTS ARG_DEPS ARG_PRIVATE_DEPS)
    if(dep MATCHES "^fspm::(.+)$")
      list(APPEND module_deps ${CMAKE_MATCH_1})
    endif()
  endforeach()
  set_property(GLOBAL APPEND PROPERTY FSPM_MODULES ${name})
  set_property(GLOBAL PROPERTY FSPM_MODULE_DEPS_${name} "${module_deps}")

  file(RELATIVE_PATH folder ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})
  file(GLOB headers CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.hpp)
  foreach(internal IN LISTS ARG_INTERNAL_HEADERS)
    if(NOT EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${internal})
      message(FATAL_ERROR "fspm_add_module(${name}): INTERNAL_HEADERS names ${internal}, "
                          "which is not in ${folder}/")
    endif()
    list(REMOVE_ITEM headers ${CMAKE_CURRENT_SOURCE_DIR}/${internal})
  endforeach()
  install(TARGETS fspm_${name} EXPORT fspm_${name}_targets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev)
  install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/fspm/${folder} COMPONENT dev)
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
