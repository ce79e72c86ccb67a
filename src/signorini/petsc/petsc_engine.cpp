#include "signorini/petsc/petsc_engine.hpp"

#include <fmt/format.h>
#include <petscmat.h>
#include <petscsys.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <thread>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "signorini/core/error.hpp"
#include "signorini/petsc/petsc_active_set_solver.hpp"
#include "signorini/petsc/petsc_algebra.hpp"
#include "signorini/petsc/petsc_check.hpp"
#include "signorini/petsc/petsc_newton_space.hpp"

namespace signorini {

PetscEngine::PetscEngine() {
  // PT-Scotch (7.0) partitions with several threads by default, and its threads make another
  // partition from one run to the next: other numbers, sums in another order, answers that
  // differ in the last digits and at times by an Uzawa step. One thread makes the same partition
  // every time (docs/distributed.md, "The partition"); a user's own setting is kept.
  setenv("SCOTCH_PTHREAD_NUMBER", "1", /*overwrite=*/0);
  petsc::check(PetscInitialize(nullptr, nullptr, nullptr, nullptr), "initialisation");
  // Errors come back as codes that petsc::check turns into one-line exceptions; PETSc's own
  // handler would print a traceback on every rank first.
  petsc::check(PetscPushErrorHandler(petsc::recording_error_handler, nullptr), "error handler");
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
  MPI_Comm_dup(PETSC_COMM_WORLD, &meeting_comm_);
  MPI_Comm_size(PETSC_COMM_WORLD, &size_);
  share_the_cores();
}

void PetscEngine::share_the_cores() const {
#ifdef _OPENMP
  // The OpenMP loops of each rank (the assembly, the sparsity pattern, the products of its CG
  // and multigrid: petsc/threaded_product.hpp) on its share of the node's cores: ranks that each
  // started one thread per core would oversubscribe the node, and OpenMP's waiting threads spin.
  // OMP_NUM_THREADS, where set, is kept (docs/distributed.md).
  if (std::getenv("OMP_NUM_THREADS") != nullptr) return;
  MPI_Comm node = MPI_COMM_NULL;
  MPI_Comm_split_type(PETSC_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  int on_node = 1;
  if (node != MPI_COMM_NULL) {
    MPI_Comm_size(node, &on_node);
    MPI_Comm_free(&node);
  }
  omp_set_num_threads(std::max(1, omp_get_num_procs() / on_node));
#endif
}

PetscEngine::~PetscEngine() {
  if (meeting_ == MPI_REQUEST_NULL) MPI_Comm_free(&meeting_comm_);  // else a rank is missing
  PetscPopErrorHandler();
  PetscFinalize();
}

std::string PetscEngine::description() const {
  std::string d =
      fmt::format("PETSc {}.{}.{} on {} MPI rank{}", PETSC_VERSION_MAJOR, PETSC_VERSION_MINOR,
                  PETSC_VERSION_SUBMINOR, size_, size_ == 1 ? "" : "s");
  if (!partitioner_.empty()) d += ", nodes partitioned by " + partitioner_;
  return d;
}

std::vector<int> PetscEngine::partition(const NodeGraph& graph, const std::string& engine_options) {
  petsc::insert_petsc_options(engine_options);  // -mat_partitioning_type may name another one
  const auto local = static_cast<PetscInt>(graph.last - graph.first);
  // MatCreateMPIAdj and the vertex weights take arrays from PetscMalloc, and free them.
  PetscInt* ia = nullptr;
  PetscInt* ja = nullptr;
  PetscInt* weights = nullptr;
  petsc::check(PetscMalloc1(local + 1, &ia), "the node graph");
  petsc::check(PetscMalloc1(static_cast<PetscInt>(graph.neighbours.size()) + 1, &ja),
               "the node graph");
  petsc::check(PetscMalloc1(local + 1, &weights), "the node graph");
  for (PetscInt i = 0; i <= local; ++i)
    ia[i] = static_cast<PetscInt>(graph.offsets[static_cast<std::size_t>(i)]);
  for (std::size_t e = 0; e < graph.neighbours.size(); ++e)
    ja[e] = static_cast<PetscInt>(graph.neighbours[e]);
  for (PetscInt i = 0; i < local; ++i)
    weights[i] = static_cast<PetscInt>(graph.weights[static_cast<std::size_t>(i)]);
  Mat adjacency = nullptr;
  petsc::check(MatCreateMPIAdj(PETSC_COMM_WORLD, local, static_cast<PetscInt>(graph.vertices), ia,
                               ja, nullptr, &adjacency),
               "the node graph");
  MatPartitioning part = nullptr;
  petsc::check(MatPartitioningCreate(PETSC_COMM_WORLD, &part), "the partitioner");
  petsc::check(MatPartitioningSetAdjacency(part, adjacency), "the partitioner");
  // PT-Scotch where PETSc has it (Debian's does), else ParMETIS, else PETSc's own split.
  PetscBool has = PETSC_FALSE;
  petsc::check(PetscHasExternalPackage("ptscotch", &has), "the partitioner");
  MatPartitioningType type = MATPARTITIONINGAVERAGE;
  if (has) {
    type = MATPARTITIONINGPTSCOTCH;
  } else {
    petsc::check(PetscHasExternalPackage("parmetis", &has), "the partitioner");
    if (has) type = MATPARTITIONINGPARMETIS;
  }
  petsc::check(MatPartitioningSetType(part, type), "the partitioner");
  petsc::check(MatPartitioningSetNParts(part, size_), "the partitioner");
  petsc::check(MatPartitioningSetVertexWeights(part, weights), "the partitioner");
  petsc::check(MatPartitioningSetFromOptions(part), "the partitioner options");
  IS owners = nullptr;
  petsc::check(MatPartitioningApply(part, &owners), "partitioning the nodes");
  MatPartitioningType used = nullptr;
  petsc::check(MatPartitioningGetType(part, &used), "the partitioner");
  partitioner_ = used != nullptr ? used : "?";

  // Every rank gets every vertex's rank.
  const PetscInt* mine = nullptr;
  petsc::check(ISGetIndices(owners, &mine), "partitioning the nodes");
  std::vector<int> local_owner(mine, mine + local);
  petsc::check(ISRestoreIndices(owners, &mine), "partitioning the nodes");
  std::vector<int> counts(static_cast<std::size_t>(size_)), displs(static_cast<std::size_t>(size_));
  for (int r = 0; r < size_; ++r) {
    const Index first = vertex_share_start(graph.vertices, r, size_);
    const Index last = vertex_share_start(graph.vertices, r + 1, size_);
    counts[static_cast<std::size_t>(r)] = static_cast<int>(last - first);
    displs[static_cast<std::size_t>(r)] = static_cast<int>(first);
  }
  std::vector<int> owner(static_cast<std::size_t>(graph.vertices));
  MPI_Allgatherv(local_owner.data(), static_cast<int>(local), MPI_INT, owner.data(), counts.data(),
                 displs.data(), MPI_INT, PETSC_COMM_WORLD);
  ISDestroy(&owners);
  MatPartitioningDestroy(&part);
  MatDestroy(&adjacency);
  return owner;
}

std::unique_ptr<DistributedNewtonSpace> PetscEngine::newton_space(
    const ContactProblem& problem, const ContactSolverOptions& options, const Vector& x0,
    TimingTable& timings) {
  return std::make_unique<PetscNewtonSpace>(problem, options, x0, timings, PETSC_COMM_WORLD);
}

std::unique_ptr<DistributedActiveSetSolver> PetscEngine::active_set_solver(
    const ContactProblem& problem, const ContactSolverOptions& options, const Vector& x0,
    TimingTable& timings) {
  return std::make_unique<PetscActiveSetSolver>(problem, options, x0, timings, PETSC_COMM_WORLD);
}

void PetscEngine::sum(double* values, Index count) const {
  if (count > 0)
    MPI_Allreduce(MPI_IN_PLACE, values, static_cast<int>(count), MPI_DOUBLE, MPI_SUM,
                  PETSC_COMM_WORLD);
}

double PetscEngine::max(double value) const {
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  return value;
}

bool PetscEngine::any(bool flag) const {
  int local = flag ? 1 : 0, global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_LOR, PETSC_COMM_WORLD);
  return global != 0;
}

namespace {

// MPI counts are ints: a message longer than 2 GiB goes in pieces of at most 1 GiB.
constexpr std::size_t kPiece = std::size_t{1} << 30;

int piece_size(std::size_t total, std::size_t at) {
  return static_cast<int>(std::min(kPiece, total - at));
}

}  // namespace

void PetscEngine::broadcast(std::vector<char>& bytes) const {
  auto size = static_cast<std::uint64_t>(bytes.size());
  MPI_Bcast(&size, 1, MPI_UINT64_T, 0, PETSC_COMM_WORLD);
  bytes.resize(static_cast<std::size_t>(size));
  for (std::size_t at = 0; at < bytes.size(); at += kPiece)
    MPI_Bcast(bytes.data() + at, piece_size(bytes.size(), at), MPI_CHAR, 0, PETSC_COMM_WORLD);
}

void PetscEngine::send_from_root(int to, const std::vector<char>& bytes) const {
  auto size = static_cast<std::uint64_t>(bytes.size());
  MPI_Send(&size, 1, MPI_UINT64_T, to, 0, PETSC_COMM_WORLD);
  for (std::size_t at = 0; at < bytes.size(); at += kPiece)
    MPI_Send(bytes.data() + at, piece_size(bytes.size(), at), MPI_CHAR, to, 0, PETSC_COMM_WORLD);
}

std::vector<char> PetscEngine::receive_from_root() const {
  std::uint64_t size = 0;
  MPI_Recv(&size, 1, MPI_UINT64_T, 0, 0, PETSC_COMM_WORLD, MPI_STATUS_IGNORE);
  std::vector<char> bytes(static_cast<std::size_t>(size));
  for (std::size_t at = 0; at < bytes.size(); at += kPiece)
    MPI_Recv(bytes.data() + at, piece_size(bytes.size(), at), MPI_CHAR, 0, 0, PETSC_COMM_WORLD,
             MPI_STATUS_IGNORE);
  return bytes;
}

std::vector<std::vector<char>> PetscEngine::allgather(const std::vector<char>& bytes) const {
  // (MPI_Allgatherv's counts and offsets are ints: up to 2 GiB in all, checked.)
  const auto mine = static_cast<std::uint64_t>(bytes.size());
  std::vector<std::uint64_t> sizes(static_cast<std::size_t>(size_));
  MPI_Allgather(&mine, 1, MPI_UINT64_T, sizes.data(), 1, MPI_UINT64_T, PETSC_COMM_WORLD);
  std::vector<int> counts, offsets;
  std::uint64_t total = 0;
  for (const std::uint64_t s : sizes) {
    offsets.push_back(static_cast<int>(total));
    counts.push_back(static_cast<int>(s));
    total += s;
  }
  if (total >= (std::uint64_t{1} << 31))
    throw std::runtime_error("allgather: more than 2 GiB from the ranks together");
  std::vector<char> all(static_cast<std::size_t>(total));
  MPI_Allgatherv(bytes.data(), static_cast<int>(mine), MPI_CHAR, all.data(), counts.data(),
                 offsets.data(), MPI_CHAR, PETSC_COMM_WORLD);
  std::vector<std::vector<char>> out;
  for (int r = 0; r < size_; ++r) {
    const auto at = all.begin() + offsets[static_cast<std::size_t>(r)];
    out.emplace_back(at, at + counts[static_cast<std::size_t>(r)]);
  }
  return out;
}

std::vector<std::vector<char>> PetscEngine::exchange(
    const std::vector<std::vector<char>>& to_each) const {
  if (static_cast<int>(to_each.size()) != size_)
    throw std::logic_error("exchange: expected one message per rank");
  std::vector<std::uint64_t> out_sizes, in_sizes(static_cast<std::size_t>(size_));
  for (const std::vector<char>& m : to_each) out_sizes.push_back(m.size());
  MPI_Alltoall(out_sizes.data(), 1, MPI_UINT64_T, in_sizes.data(), 1, MPI_UINT64_T,
               PETSC_COMM_WORLD);
  std::vector<std::vector<char>> from(static_cast<std::size_t>(size_));
  std::vector<MPI_Request> requests;
  // Each message in pieces of at most 1 GiB, tagged by their number.
  for (int r = 0; r < size_; ++r) {
    std::vector<char>& in = from[static_cast<std::size_t>(r)];
    in.resize(static_cast<std::size_t>(in_sizes[static_cast<std::size_t>(r)]));
    int tag = 0;
    for (std::size_t at = 0; at < in.size(); at += kPiece, ++tag)
      MPI_Irecv(in.data() + at, piece_size(in.size(), at), MPI_CHAR, r, tag, PETSC_COMM_WORLD,
                &requests.emplace_back());
  }
  for (int r = 0; r < size_; ++r) {
    const std::vector<char>& out = to_each[static_cast<std::size_t>(r)];
    int tag = 0;
    for (std::size_t at = 0; at < out.size(); at += kPiece, ++tag)
      MPI_Isend(out.data() + at, piece_size(out.size(), at), MPI_CHAR, r, tag, PETSC_COMM_WORLD,
                &requests.emplace_back());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  return from;
}

bool PetscEngine::meet_within(double seconds) const {
  if (meeting_ == MPI_REQUEST_NULL) MPI_Ibarrier(meeting_comm_, &meeting_);
  // MPI_Test drives the barrier on (Open MPI progresses non-blocking collectives in MPI calls);
  // a millisecond's sleep between tests keeps a waiting rank off the core.
  const double end = MPI_Wtime() + seconds;
  for (;;) {
    int done = 0;
    MPI_Test(&meeting_, &done, MPI_STATUS_IGNORE);
    if (done != 0) return true;
    if (MPI_Wtime() >= end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

void PetscEngine::abort(int status) const {
  MPI_Abort(PETSC_COMM_WORLD, status);
  std::exit(status);  // not reached: MPI_Abort ends the process
}

}  // namespace signorini
