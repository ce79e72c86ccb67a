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

/// The functions of cuBLAS that the backend calls (cublas_v2.h maps the names to their _v2
/// symbols, which are what is looked up).
struct CublasFunctions {
  decltype(&::cublasCreate) create = nullptr;
  decltype(&::cublasDestroy) destroy = nullptr;
  decltype(&::cublasSetStream) set_stream = nullptr;
  decltype(&::cublasSetWorkspace) set_workspace = nullptr;
  decltype(&::cublasSetPointerMode) set_pointer_mode = nullptr;
  decltype(&::cublasDdot_64) ddot = nullptr;
  decltype(&::cublasDgemv_64) dgemv = nullptr;
  decltype(&::cublasGetStatusString) status_string = nullptr;
};

/// The functions of cuSPARSE that the backend calls.
struct CusparseFunctions {
  decltype(&::cusparseCreate) create = nullptr;
  decltype(&::cusparseDestroy) destroy = nullptr;
  decltype(&::cusparseSetStream) set_stream = nullptr;
  decltype(&::cusparseCreateCsr) create_csr = nullptr;
  decltype(&::cusparseDestroySpMat) destroy_sp_mat = nullptr;
  decltype(&::cusparseCreateDnVec) create_dn_vec = nullptr;
  decltype(&::cusparseCreateConstDnVec) create_const_dn_vec = nullptr;
  decltype(&::cusparseDestroyDnVec) destroy_dn_vec = nullptr;
  decltype(&::cusparseSpMV_bufferSize) spmv_buffer_size = nullptr;
  decltype(&::cusparseSpMV_preprocess) spmv_preprocess = nullptr;
  decltype(&::cusparseSpMV) spmv = nullptr;
  decltype(&::cusparseGetErrorString) error_string = nullptr;
};

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
