# FindMUMPS.cmake -- the sequential MUMPS (double precision) as the imported target
# MUMPS::dmumps_seq.
#
# Debian 12's libmumps-seq-dev ships no CMake package files: dmumps_c.h lies in the
# include directory, the MPI stub's mpi.h in include/mumps_seq, and the libraries are
# dmumps_seq, mumps_common_seq, pord_seq (the PORD ordering) and mpiseq_seq (the stub).
# Provides MUMPS_FOUND and MUMPS::dmumps_seq.

find_path(MUMPS_INCLUDE_DIR NAMES dmumps_c.h DOC "Directory holding dmumps_c.h")
find_path(MUMPS_MPISEQ_INCLUDE_DIR NAMES mpi.h PATH_SUFFIXES mumps_seq NO_DEFAULT_PATH
  PATHS /usr/include /usr/local/include DOC "Directory holding the sequential MUMPS' mpi.h stub")
find_library(MUMPS_DMUMPS_LIBRARY NAMES dmumps_seq)
find_library(MUMPS_COMMON_LIBRARY NAMES mumps_common_seq)
find_library(MUMPS_PORD_LIBRARY NAMES pord_seq)
find_library(MUMPS_MPISEQ_LIBRARY NAMES mpiseq_seq)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MUMPS REQUIRED_VARS MUMPS_DMUMPS_LIBRARY MUMPS_COMMON_LIBRARY
  MUMPS_PORD_LIBRARY MUMPS_MPISEQ_LIBRARY MUMPS_INCLUDE_DIR MUMPS_MPISEQ_INCLUDE_DIR)

if(MUMPS_FOUND AND NOT TARGET MUMPS::dmumps_seq)
  add_library(MUMPS::dmumps_seq UNKNOWN IMPORTED)
  set_target_properties(MUMPS::dmumps_seq PROPERTIES
    IMPORTED_LOCATION "${MUMPS_DMUMPS_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${MUMPS_INCLUDE_DIR};${MUMPS_MPISEQ_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${MUMPS_COMMON_LIBRARY};${MUMPS_PORD_LIBRARY};${MUMPS_MPISEQ_LIBRARY}")
endif()
mark_as_advanced(MUMPS_INCLUDE_DIR MUMPS_MPISEQ_INCLUDE_DIR MUMPS_DMUMPS_LIBRARY MUMPS_COMMON_LIBRARY
  MUMPS_PORD_LIBRARY MUMPS_MPISEQ_LIBRARY)
