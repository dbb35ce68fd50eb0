# Warn loudly when the reference BLAS is the active libblas.so.3: UMFPACK is
# 2-3x slower with it than with OpenBLAS (measured on the 2-core CI machines).
function(fsi_check_blas)
  set(_candidates
    /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/libblas.so.3
    /usr/lib/libblas.so.3)
  foreach(_c IN LISTS _candidates)
    if(EXISTS "${_c}")
      get_filename_component(_real "${_c}" REALPATH)
      if(_real MATCHES "openblas")
        message(STATUS "BLAS behind UMFPACK: OpenBLAS (${_real})")
      else()
        message(WARNING
          "\n*** The active BLAS is NOT OpenBLAS: ${_real}\n"
          "*** UMFPACK will be 2-3x slower. Fix: apt-get install libopenblas0-pthread\n"
          "*** and 'update-alternatives --config libblas.so.3-${CMAKE_LIBRARY_ARCHITECTURE}'.\n")
      endif()
      return()
    endif()
  endforeach()
  message(WARNING "Could not find libblas.so.3; cannot tell which BLAS UMFPACK will use.")
endfunction()
