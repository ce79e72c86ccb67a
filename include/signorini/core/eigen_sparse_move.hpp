// Included inside the class Eigen::SparseMatrix (EIGEN_SPARSEMATRIX_PLUGIN, which the signorini
// target sets for itself and for everything that links it, so that every translation unit sees
// one definition of the class). Eigen 3.4.0 declares no move constructor and no move assignment
// for sparse matrices, so std::move(A), a returned member or a moved struct holding A copied the
// whole matrix: for a moment twice the memory of the largest matrix of a solve (the stiffness
// into the model, the prolongations into the hierarchy). Eigen's later versions swap, as here.
// No include guard: the file is meant to be included inside the class body.

inline SparseMatrix(SparseMatrix&& other) noexcept : SparseMatrix() {
  this->swap(other);
}
inline SparseMatrix& operator=(SparseMatrix&& other) noexcept {
  this->swap(other);
  return *this;
}
