#pragma once
// cuBLAS and cuSPARSE, loaded when a GPU solve first needs them (dlopen), not when the program
// starts: linked in, they cost every run of the tool 0.3-0.4 s and some 24,000 page faults to
// load and relocate (cuBLAS pulls in the 540 MB cuBLASLt), GPU or not. The CUDA runtime itself
// (0.7 MB) stays linked, shared: the libraries opened later use that same runtime. Private to
// the CUDA backend.

#include <cublas_v2.h>
#include <cusparse.h>

#include <string>

namespace signorini::cuda {

// The functions the backend calls, each named once: (member, function of the library's header).
// cublas_v2.h maps the names to their _v2 symbols, which are what is looked up.
#define SIGNORINI_CUBLAS_FUNCTIONS(X)       \
  X(create, cublasCreate)                   \
  X(destroy, cublasDestroy)                 \
  X(set_stream, cublasSetStream)            \
  X(set_workspace, cublasSetWorkspace)      \
  X(set_pointer_mode, cublasSetPointerMode) \
  X(ddot, cublasDdot_64)                    \
  X(dgemv, cublasDgemv_64)                  \
  X(status_string, cublasGetStatusString)

#define SIGNORINI_CUSPARSE_FUNCTIONS(X)            \
  X(create, cusparseCreate)                        \
  X(destroy, cusparseDestroy)                      \
  X(set_stream, cusparseSetStream)                 \
  X(create_csr, cusparseCreateCsr)                 \
  X(destroy_sp_mat, cusparseDestroySpMat)          \
  X(create_dn_vec, cusparseCreateDnVec)            \
  X(create_const_dn_vec, cusparseCreateConstDnVec) \
  X(destroy_dn_vec, cusparseDestroyDnVec)          \
  X(spmv_buffer_size, cusparseSpMV_bufferSize)     \
  X(spmv_preprocess, cusparseSpMV_preprocess)      \
  X(spmv, cusparseSpMV)                            \
  X(error_string, cusparseGetErrorString)

#define SIGNORINI_FUNCTION_POINTER(member, function) decltype(&::function) member = nullptr;

struct CublasFunctions {
  SIGNORINI_CUBLAS_FUNCTIONS(SIGNORINI_FUNCTION_POINTER)
};

struct CusparseFunctions {
  SIGNORINI_CUSPARSE_FUNCTIONS(SIGNORINI_FUNCTION_POINTER)
};

#undef SIGNORINI_FUNCTION_POINTER

struct CudaLibraries {
  CublasFunctions cublas;
  CusparseFunctions cusparse;
  std::string cublas_path;  ///< where each was found (dlinfo), for reports
  std::string cusparse_path;
};

/// Loads both libraries on the first call (the sonames of the toolkit this was built with, on the
/// library path, then in the toolkit's folder) and resolves every function; later calls return
/// the same table. Throws InputError naming the library and dlerror()'s reason if one is missing
/// or lacks a function: a GPU solve cannot start without them.
const CudaLibraries& cuda_libraries();

}  // namespace signorini::cuda
