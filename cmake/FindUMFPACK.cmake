# Finds SuiteSparse UMFPACK (sparse LU, the same package as CHOLMOD: libsuitesparse-dev) and
# exposes one imported target, UMFPACK::UMFPACK. SuiteSparse 7 and newer install a CMake package
# (target SuiteSparse::UMFPACK), used when present; SuiteSparse 5.x (Debian 12) ships none, so we
# look for the header and the library, which links CHOLMOD's (AMD, SuiteSparse_config) itself.
find_package(UMFPACK CONFIG QUIET)
if(TARGET SuiteSparse::UMFPACK)
  if(NOT TARGET UMFPACK::UMFPACK)
    add_library(UMFPACK::UMFPACK INTERFACE IMPORTED)
    set_target_properties(UMFPACK::UMFPACK PROPERTIES INTERFACE_LINK_LIBRARIES SuiteSparse::UMFPACK)
  endif()
  set(UMFPACK_FOUND TRUE)
  return()
endif()

find_path(UMFPACK_INCLUDE_DIR umfpack.h PATH_SUFFIXES suitesparse)
find_library(UMFPACK_LIBRARY umfpack)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(UMFPACK REQUIRED_VARS UMFPACK_LIBRARY UMFPACK_INCLUDE_DIR)

if(UMFPACK_FOUND AND NOT TARGET UMFPACK::UMFPACK)
  add_library(UMFPACK::UMFPACK UNKNOWN IMPORTED)
  set_target_properties(UMFPACK::UMFPACK PROPERTIES
    IMPORTED_LOCATION "${UMFPACK_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${UMFPACK_INCLUDE_DIR}")
endif()
mark_as_advanced(UMFPACK_INCLUDE_DIR UMFPACK_LIBRARY)
