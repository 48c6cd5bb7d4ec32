# Installation and packages: the CMake package (fspmConfig.cmake, one exported target file per
# module, found with find_package(fspm)), a pkg-config file for the model libraries, the Python
# module, docs and examples, and CPack's Debian package (scripts/package.sh).
#
# The modules are static libraries (position-independent) by default: the executables and the
# Python module carry the code they use, and `pip install .` needs nothing beside the extension.
# A static library's private dependencies are part of its link interface, so fspmConfig.cmake
# finds every package the requested modules link (Ceres, TBB, Highway, VTK, ...). With
# FSPM_SHARED_LIBS (the Debian package) they are shared, and only their public dependencies are
# needed downstream.
include(CMakePackageConfigHelpers)

set(FSPM_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/fspm)
get_property(fspm_modules GLOBAL PROPERTY FSPM_MODULES)
set(FSPM_MODULE_DEPS_LINES "")
foreach(module IN LISTS fspm_modules)
  install(EXPORT fspm_${module}_targets NAMESPACE fspm:: FILE fspm-${module}-targets.cmake
          DESTINATION ${FSPM_CMAKE_INSTALL_DIR} COMPONENT dev)
  get_property(deps GLOBAL PROPERTY FSPM_MODULE_DEPS_${module})
  string(APPEND FSPM_MODULE_DEPS_LINES "set(_fspm_deps_${module} \"${deps}\")\n")
endforeach()
set(FSPM_MODULES "${fspm_modules}")
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/fspmConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/fspmConfig.cmake
                              INSTALL_DESTINATION ${FSPM_CMAKE_INSTALL_DIR})
# 0.y.z: a new minor version may change the API (semantic versioning), so only the same minor
# version satisfies a request.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/fspmConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/fspmConfig.cmake ${PROJECT_BINARY_DIR}/fspmConfigVersion.cmake
        DESTINATION ${FSPM_CMAKE_INSTALL_DIR} COMPONENT dev)

# pkg-config: the model libraries only (core, lsystem, greenlab, environment, stages); the others
# link VTK, CGAL and assimp, which have no pkg-config files, and are used through find_package.
# Static libraries need what they link privately too; shared ones only their headers' packages.
if(FSPM_SHARED_LIBS)
  set(FSPM_PC_REQUIRES "eigen3 nlohmann_json tomlplusplus")
  set(FSPM_PC_EXTRA_LIBS "")
else()
  set(FSPM_PC_REQUIRES "eigen3 nlohmann_json tomlplusplus tbb libhwy libglog")
  set(FSPM_PC_EXTRA_LIBS " -lceres")
endif()
# The prefix is found from the file's own place, so the file works wherever the tree is installed.
file(RELATIVE_PATH FSPM_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(REGEX REPLACE "/$" "" FSPM_PC_TO_PREFIX "${FSPM_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/fspm.pc.in ${PROJECT_BINARY_DIR}/fspm.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/fspm.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
        COMPONENT dev)

# The Python module where Debian's python3 looks for it: lib/python3/dist-packages under /usr (the
# Debian package), lib/python3.X/dist-packages under another prefix (/usr/local by default).
if(CMAKE_INSTALL_PREFIX STREQUAL "/usr" OR NOT Python_VERSION_MINOR)
  set(python_dir lib/python3/dist-packages)
else()
  set(python_dir lib/python${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}/dist-packages)
endif()
set(FSPM_PYTHON_INSTALL_DIR ${python_dir} CACHE STRING
    "Where the Python module fspm is installed, relative to the prefix")
if(TARGET _fspm)
  install(TARGETS _fspm LIBRARY DESTINATION ${FSPM_PYTHON_INSTALL_DIR}/fspm COMPONENT python)
  if(FSPM_SHARED_LIBS)
    file(RELATIVE_PATH python_to_lib /prefix/${FSPM_PYTHON_INSTALL_DIR}/fspm
         /prefix/${CMAKE_INSTALL_LIBDIR})
    set_target_properties(_fspm PROPERTIES INSTALL_RPATH "$ORIGIN/${python_to_lib}")
  endif()
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/python/fspm/ DESTINATION ${FSPM_PYTHON_INSTALL_DIR}/fspm
          COMPONENT python FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
endif()

install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT doc)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT doc)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples
        COMPONENT doc)

# CPack: fspm_VERSION_amd64.deb (scripts/package.sh). Depends comes from dpkg-shlibdeps on the
# installed executables and Python module.
set(CPACK_PACKAGE_NAME fspm)
set(CPACK_PACKAGE_VENDOR "fspm")
set(CPACK_PACKAGE_CONTACT "fspm developers <fspm@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(FSPM_SHARED_LIBS)
  # The package's own libraries: a shlibs file for packages built against them, and
  # dpkg-shlibdeps finds them in the package.
  set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${CPACK_PACKAGING_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR})
endif()
# The Python module is built for one Python minor version and imports numpy.
if(TARGET _fspm)
  math(EXPR python_next_minor "${Python_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
      "python3 (>= ${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}), python3 (<< ${Python_VERSION_MAJOR}.${python_next_minor}), python3-numpy")
endif()
# Building against the installed C++ package needs a compiler and the headers its public headers
# include (static libraries: also the packages they link).
set(CPACK_DEBIAN_PACKAGE_SUGGESTS
    "g++, cmake, pkg-config, libeigen3-dev, libboost-dev, nlohmann-json3-dev, libtomlplusplus-dev")
if(NOT FSPM_SHARED_LIBS)
  string(APPEND CPACK_DEBIAN_PACKAGE_SUGGESTS ", libceres-dev, libtbb-dev, libhwy-dev")
endif()
# The optional parts are in the one package (fspm-full links the viewer and MPI); what they need
# at run time beyond libraries is recommended: mpirun for `fspm run --mpi`, Xvfb for renders and
# the viewer on a machine without a display.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "openmpi-bin, xvfb, xauth")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "${PROJECT_DESCRIPTION}\n The fspm and fspm-full commands, the Python module fspm, the C++\n libraries with headers and CMake package (find_package(fspm)), docs and examples.")
set(CPACK_OUTPUT_FILE_PREFIX ${PROJECT_BINARY_DIR}/packages)
include(CPack)
