# FindSuiteSparse.cmake -- imported targets for the SuiteSparse pieces fsi uses.
#
# Debian 12 ships SuiteSparse 5.12 without CMake package files, so we look the
# headers and libraries up ourselves. Provides:
#   SuiteSparse::config  SuiteSparse::AMD  SuiteSparse::COLAMD  SuiteSparse::BTF
#   SuiteSparse::CHOLMOD SuiteSparse::UMFPACK  SuiteSparse::KLU
# and SuiteSparse_FOUND / SuiteSparse_INCLUDE_DIR.

find_path(SuiteSparse_INCLUDE_DIR NAMES umfpack.h
  PATH_SUFFIXES suitesparse
  DOC "Directory holding umfpack.h")

include(FindPackageHandleStandardArgs)

# name of the imported target -> library base name, in link order (users first)
set(_fsi_ss_components
  UMFPACK umfpack
  KLU klu
  CHOLMOD cholmod
  BTF btf
  COLAMD colamd
  AMD amd
  config suitesparseconfig)

set(_fsi_ss_required_vars SuiteSparse_INCLUDE_DIR)
list(LENGTH _fsi_ss_components _n)
math(EXPR _last "${_n} - 1")
foreach(_i RANGE 0 ${_last} 2)
  math(EXPR _j "${_i} + 1")
  list(GET _fsi_ss_components ${_i} _target)
  list(GET _fsi_ss_components ${_j} _lib)
  find_library(SuiteSparse_${_target}_LIBRARY NAMES ${_lib})
  list(APPEND _fsi_ss_required_vars SuiteSparse_${_target}_LIBRARY)
endforeach()

find_package_handle_standard_args(SuiteSparse REQUIRED_VARS ${_fsi_ss_required_vars})

if(SuiteSparse_FOUND)
  foreach(_i RANGE 0 ${_last} 2)
    list(GET _fsi_ss_components ${_i} _target)
    if(NOT TARGET SuiteSparse::${_target})
      add_library(SuiteSparse::${_target} UNKNOWN IMPORTED)
      set_target_properties(SuiteSparse::${_target} PROPERTIES
        IMPORTED_LOCATION "${SuiteSparse_${_target}_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${SuiteSparse_INCLUDE_DIR}")
    endif()
  endforeach()
  # Inter-library dependencies (SuiteSparse 5.x layout).
  set_property(TARGET SuiteSparse::AMD PROPERTY INTERFACE_LINK_LIBRARIES SuiteSparse::config)
  set_property(TARGET SuiteSparse::COLAMD PROPERTY INTERFACE_LINK_LIBRARIES SuiteSparse::config)
  set_property(TARGET SuiteSparse::BTF PROPERTY INTERFACE_LINK_LIBRARIES SuiteSparse::config)
  set_property(TARGET SuiteSparse::CHOLMOD PROPERTY INTERFACE_LINK_LIBRARIES
    SuiteSparse::AMD SuiteSparse::COLAMD SuiteSparse::config)
  set_property(TARGET SuiteSparse::UMFPACK PROPERTY INTERFACE_LINK_LIBRARIES
    SuiteSparse::CHOLMOD SuiteSparse::AMD SuiteSparse::config)
  set_property(TARGET SuiteSparse::KLU PROPERTY INTERFACE_LINK_LIBRARIES
    SuiteSparse::BTF SuiteSparse::AMD SuiteSparse::COLAMD SuiteSparse::config)
endif()
mark_as_advanced(SuiteSparse_INCLUDE_DIR)
