# Finds Debian's FAISS (libfaiss-dev), which ships only a static library without a CMake config.
# Defines the imported target FAISS::faiss, which links the OpenMP runtime, BLAS and LAPACK it needs
# (the runtime only: code that includes FAISS is not compiled with -fopenmp).
find_path(FAISS_INCLUDE_DIR faiss/IndexIVFFlat.h)
find_library(FAISS_LIBRARY NAMES faiss)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(FAISS REQUIRED_VARS FAISS_LIBRARY FAISS_INCLUDE_DIR)
if(FAISS_FOUND AND NOT TARGET FAISS::faiss)
  find_package(OpenMP REQUIRED COMPONENTS CXX)
  find_package(BLAS REQUIRED)
  find_package(LAPACK REQUIRED)
  add_library(FAISS::faiss UNKNOWN IMPORTED)
  set_target_properties(FAISS::faiss PROPERTIES
    IMPORTED_LOCATION "${FAISS_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${FAISS_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${OpenMP_CXX_LIBRARIES};LAPACK::LAPACK;BLAS::BLAS")
endif()
mark_as_advanced(FAISS_INCLUDE_DIR FAISS_LIBRARY)
