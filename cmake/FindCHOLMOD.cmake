# Finds SuiteSparse CHOLMOD (Debian: libsuitesparse-dev). SuiteSparse 5.x ships no CMake config,
# so we look for the header and the libraries CHOLMOD links against (AMD, COLAMD, CAMD, CCOLAMD,
# SuiteSparse_config) and expose one imported target, CHOLMOD::CHOLMOD.
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY cholmod)
find_library(SUITESPARSE_CONFIG_LIBRARY suitesparseconfig)
foreach(_lib amd colamd camd ccolamd)
  string(TOUPPER ${_lib} _LIB)
  find_library(${_LIB}_LIBRARY ${_lib})
endforeach()

if(CHOLMOD_INCLUDE_DIR AND EXISTS "${CHOLMOD_INCLUDE_DIR}/cholmod_core.h")
  file(STRINGS "${CHOLMOD_INCLUDE_DIR}/cholmod_core.h" _main REGEX "#define CHOLMOD_MAIN_VERSION")
  file(STRINGS "${CHOLMOD_INCLUDE_DIR}/cholmod_core.h" _sub REGEX "#define CHOLMOD_SUB_VERSION")
  file(STRINGS "${CHOLMOD_INCLUDE_DIR}/cholmod_core.h" _sv REGEX "#define CHOLMOD_SUBSUB_VERSION")
  string(REGEX MATCH "[0-9]+" _main "${_main}")
  string(REGEX MATCH "[0-9]+" _sub "${_sub}")
  string(REGEX MATCH "[0-9]+" _sv "${_sv}")
  set(CHOLMOD_VERSION "${_main}.${_sub}.${_sv}")
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CHOLMOD
  REQUIRED_VARS CHOLMOD_LIBRARY CHOLMOD_INCLUDE_DIR SUITESPARSE_CONFIG_LIBRARY AMD_LIBRARY COLAMD_LIBRARY
  VERSION_VAR CHOLMOD_VERSION)

if(CHOLMOD_FOUND AND NOT TARGET CHOLMOD::CHOLMOD)
  add_library(CHOLMOD::CHOLMOD UNKNOWN IMPORTED)
  set_target_properties(CHOLMOD::CHOLMOD PROPERTIES
    IMPORTED_LOCATION "${CHOLMOD_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${AMD_LIBRARY};${COLAMD_LIBRARY};${CAMD_LIBRARY};${CCOLAMD_LIBRARY};${SUITESPARSE_CONFIG_LIBRARY}")
endif()
mark_as_advanced(CHOLMOD_INCLUDE_DIR CHOLMOD_LIBRARY SUITESPARSE_CONFIG_LIBRARY AMD_LIBRARY
                 COLAMD_LIBRARY CAMD_LIBRARY CCOLAMD_LIBRARY)
