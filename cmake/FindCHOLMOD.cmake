# Finds SuiteSparse CHOLMOD and exposes one imported target, CHOLMOD::CHOLMOD.
# SuiteSparse 7 and newer install a CMake package (target SuiteSparse::CHOLMOD): it is used when
# present. SuiteSparse 5.x (Debian 12: libsuitesparse-dev) ships none, so we look for the header
# and the libraries CHOLMOD links against: AMD, COLAMD and SuiteSparse_config are required, CAMD
# and CCOLAMD are linked only where they exist.
find_package(CHOLMOD CONFIG QUIET)
if(TARGET SuiteSparse::CHOLMOD)
  if(NOT TARGET CHOLMOD::CHOLMOD)
    add_library(CHOLMOD::CHOLMOD INTERFACE IMPORTED)
    set_target_properties(CHOLMOD::CHOLMOD PROPERTIES INTERFACE_LINK_LIBRARIES SuiteSparse::CHOLMOD)
  endif()
  set(CHOLMOD_FOUND TRUE)
  return()
endif()

find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY cholmod)
find_library(SUITESPARSE_CONFIG_LIBRARY suitesparseconfig)
foreach(_lib amd colamd camd ccolamd)
  string(TOUPPER ${_lib} _LIB)
  find_library(${_LIB}_LIBRARY ${_lib})
endforeach()

# The version is in cholmod_core.h up to SuiteSparse 6 and in cholmod.h from 7 on.
foreach(_header cholmod_core.h cholmod.h)
  if(NOT CHOLMOD_VERSION AND CHOLMOD_INCLUDE_DIR AND EXISTS "${CHOLMOD_INCLUDE_DIR}/${_header}")
    file(STRINGS "${CHOLMOD_INCLUDE_DIR}/${_header}" _main REGEX "#define CHOLMOD_MAIN_VERSION")
    file(STRINGS "${CHOLMOD_INCLUDE_DIR}/${_header}" _sub REGEX "#define CHOLMOD_SUB_VERSION")
    file(STRINGS "${CHOLMOD_INCLUDE_DIR}/${_header}" _sv REGEX "#define CHOLMOD_SUBSUB_VERSION")
    string(REGEX MATCH "[0-9]+" _main "${_main}")
    string(REGEX MATCH "[0-9]+" _sub "${_sub}")
    string(REGEX MATCH "[0-9]+" _sv "${_sv}")
    if(NOT "${_main}" STREQUAL "")
      set(CHOLMOD_VERSION "${_main}.${_sub}.${_sv}")
    endif()
  endif()
endforeach()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CHOLMOD
  REQUIRED_VARS CHOLMOD_LIBRARY CHOLMOD_INCLUDE_DIR SUITESPARSE_CONFIG_LIBRARY AMD_LIBRARY COLAMD_LIBRARY
  VERSION_VAR CHOLMOD_VERSION)

if(CHOLMOD_FOUND AND NOT TARGET CHOLMOD::CHOLMOD)
  set(_cholmod_links ${AMD_LIBRARY} ${COLAMD_LIBRARY})
  foreach(_optional CAMD_LIBRARY CCOLAMD_LIBRARY)
    if(${_optional})
      list(APPEND _cholmod_links ${${_optional}})
    endif()
  endforeach()
  list(APPEND _cholmod_links ${SUITESPARSE_CONFIG_LIBRARY})
  add_library(CHOLMOD::CHOLMOD UNKNOWN IMPORTED)
  set_target_properties(CHOLMOD::CHOLMOD PROPERTIES
    IMPORTED_LOCATION "${CHOLMOD_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${_cholmod_links}")
endif()
mark_as_advanced(CHOLMOD_INCLUDE_DIR CHOLMOD_LIBRARY SUITESPARSE_CONFIG_LIBRARY AMD_LIBRARY
                 COLAMD_LIBRARY CAMD_LIBRARY CCOLAMD_LIBRARY)
