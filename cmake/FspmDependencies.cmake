# Finds the Debian 12 packages fspm needs. A missing required package stops configure with the
# package to install; a missing optional one turns its part off with one message.
macro(fspm_require pkg debian)
  find_package(${pkg} ${ARGN} QUIET)
  if(NOT ${pkg}_FOUND)
    message(FATAL_ERROR "fspm needs ${pkg}: install the Debian package '${debian}' "
                        "(or run scripts/deps.sh)")
  endif()
endmacro()

macro(fspm_optional option pkg debian)
  if(${option})
    find_package(${pkg} ${ARGN} QUIET)
    if(NOT ${pkg}_FOUND)
      message(STATUS "fspm: ${pkg} not found, ${option} turned off "
                     "(install the Debian package '${debian}' to enable it)")
      set(${option} OFF)
    endif()
  endif()
endmacro()

fspm_require(Eigen3 libeigen3-dev 3.3 NO_MODULE)
fspm_require(Boost libboost-graph-dev 1.74)
fspm_require(fmt libfmt-dev)
fspm_require(spdlog libspdlog-dev)
fspm_require(nlohmann_json nlohmann-json3-dev)
fspm_require(tomlplusplus libtomlplusplus-dev)
fspm_require(CLI11 libcli11-dev)
fspm_require(SQLite3 libsqlite3-dev)
fspm_require(Threads libc6-dev)
fspm_require(TBB libtbb-dev)
fspm_require(Ceres libceres-dev)
# Google Highway: the light kernels' SIMD code, one source for every x86-64 target, picked at run
# time (environment/sky_occlusion_kernel.cpp).
fspm_require(hwy libhwy-dev)
if(FSPM_BUILD_TESTS)
  fspm_require(GTest libgtest-dev)
endif()
if(FSPM_BUILD_BENCH AND NOT FSPM_CORE_ONLY)
  fspm_optional(FSPM_BUILD_BENCH benchmark libbenchmark-dev)
endif()

if(FSPM_CORE_ONLY)
  set(FSPM_WITH_VTK OFF)
  set(FSPM_WITH_VIEWER OFF)
  set(FSPM_WITH_MPI OFF)
  set(FSPM_WITH_PYTHON OFF)
endif()
# Debian's VTK links VTK::mpi against MPI::MPI_C, so MPI's C part must be known first.
find_package(MPI QUIET COMPONENTS C CXX)
fspm_optional(FSPM_WITH_VTK VTK libvtk9-dev 9 COMPONENTS CommonCore CommonDataModel IOXML
              RenderingCore RenderingOpenGL2 RenderingAnnotation InteractionStyle ChartsCore
              ViewsContext2D RenderingContextOpenGL2 RenderingFreeType)
fspm_optional(FSPM_WITH_VTK OpenImageIO libopenimageio-dev)
if(TARGET OpenImageIO::OpenImageIO)
  # Debian 12's OpenImageIO config lists /usr/include/opencv4 even when OpenCV is not installed;
  # drop include directories that do not exist so targets linking it can be generated.
  get_target_property(_oiio_inc OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
  set(_oiio_existing "")
  foreach(_dir IN LISTS _oiio_inc)
    if(EXISTS "${_dir}" OR _dir MATCHES "^\\$<")
      list(APPEND _oiio_existing "${_dir}")
    endif()
  endforeach()
  set_target_properties(OpenImageIO::OpenImageIO PROPERTIES
                        INTERFACE_INCLUDE_DIRECTORIES "${_oiio_existing}")
endif()
if(FSPM_WITH_VIEWER)
  find_package(glfw3 QUIET)
  find_package(glm QUIET)
  find_package(OpenGL QUIET COMPONENTS OpenGL)
  if(NOT glfw3_FOUND OR NOT glm_FOUND OR NOT OpenGL_FOUND)
    message(STATUS "fspm: GLFW, GLM or OpenGL not found, FSPM_WITH_VIEWER turned off "
                   "(install libglfw3-dev libglm-dev libgl-dev to enable it)")
    set(FSPM_WITH_VIEWER OFF)
  endif()
endif()
# The viewer's controls panel: Dear ImGui (Debian's static library with the GLFW and OpenGL 3 back
# ends, found through pkg-config); without it the viewer runs without the panel.
set(FSPM_HAVE_IMGUI OFF)
if(FSPM_WITH_VIEWER)
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(IMGUI QUIET IMPORTED_TARGET imgui)
  endif()
  if(IMGUI_FOUND)
    set(FSPM_HAVE_IMGUI ON)
  else()
    message(STATUS "fspm: Dear ImGui not found, the viewer has no controls panel "
                   "(install libimgui-dev to add it)")
  endif()
endif()
if(FSPM_WITH_MPI AND NOT MPI_CXX_FOUND)
  message(STATUS "fspm: MPI not found, FSPM_WITH_MPI turned off "
                 "(install libopenmpi-dev openmpi-bin to enable it)")
  set(FSPM_WITH_MPI OFF)
endif()
if(FSPM_WITH_PYTHON)
  set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Debian's Python 3")
  find_package(Python 3 QUIET COMPONENTS Interpreter Development.Module)
  if(Python_FOUND)
    find_package(pybind11 CONFIG QUIET)
  endif()
  if(NOT Python_FOUND OR NOT pybind11_FOUND)
    message(STATUS "fspm: Python 3 development files or pybind11 not found, FSPM_WITH_PYTHON "
                   "turned off (install python3-dev pybind11-dev to enable it)")
    set(FSPM_WITH_PYTHON OFF)
  endif()
endif()
