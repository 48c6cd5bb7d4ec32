# Compiler settings for project code: warnings (as errors), sanitizers, ccache.
find_program(FSPM_CCACHE ccache)
if(FSPM_CCACHE)
  set(CMAKE_CXX_COMPILER_LAUNCHER ${FSPM_CCACHE})
endif()

add_library(fspm_warnings INTERFACE)
target_compile_options(fspm_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  # GCC 12 at -O3 reports impossible memcpy overlaps inside std::string's operator+
  # (GCC bug 105651), in every file that concatenates strings; the warning is noise there.
  target_compile_options(fspm_warnings INTERFACE -Wno-restrict)
endif()
if(FSPM_WERROR)
  target_compile_options(fspm_warnings INTERFACE -Werror)
endif()

if(FSPM_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
