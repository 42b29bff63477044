# FindSuiteSparseQR: SuiteSparse's sparse QR (SPQR) with the CHOLMOD and SuiteSparse_config
# libraries it needs, as the imported target SuiteSparseQR::SPQR. Debian 12's libsuitesparse-dev
# (SuiteSparse 5.12) ships neither a CMake config nor a pkg-config file for SPQR, hence this
# module; it is installed beside foldkitConfig.cmake, which uses it for foldkit::geometry. The
# target is not SuiteSparse::SPQR, the name Ceres's own FindSuiteSparse defines differently.
find_path(SuiteSparseQR_INCLUDE_DIR SuiteSparseQR.hpp PATH_SUFFIXES suitesparse)
find_library(SuiteSparseQR_LIBRARY spqr)
find_library(SuiteSparseQR_CHOLMOD_LIBRARY cholmod)
find_library(SuiteSparseQR_CONFIG_LIBRARY suitesparseconfig)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparseQR
  REQUIRED_VARS SuiteSparseQR_LIBRARY SuiteSparseQR_CHOLMOD_LIBRARY SuiteSparseQR_CONFIG_LIBRARY
                SuiteSparseQR_INCLUDE_DIR)
if(SuiteSparseQR_FOUND AND NOT TARGET SuiteSparseQR::SPQR)
  add_library(SuiteSparseQR::SPQR INTERFACE IMPORTED)
  set_target_properties(SuiteSparseQR::SPQR PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${SuiteSparseQR_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${SuiteSparseQR_LIBRARY};${SuiteSparseQR_CHOLMOD_LIBRARY};${SuiteSparseQR_CONFIG_LIBRARY}")
endif()
mark_as_advanced(SuiteSparseQR_INCLUDE_DIR SuiteSparseQR_LIBRARY SuiteSparseQR_CHOLMOD_LIBRARY
                 SuiteSparseQR_CONFIG_LIBRARY)
