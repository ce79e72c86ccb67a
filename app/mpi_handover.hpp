#pragma once
// `mpirun -n N signorini solve ...` (docs/distributed.md): the serial tool does not link PETSc
// and MPI (107 shared libraries, 20 ms at every start, 0.3 s more to initialise MPI), so when an
// MPI launcher started it, it re-executes itself as signorini-mpi, which lies beside it in a
// build with PETSc, with the same arguments and environment.

namespace signorini::app {

/// Under an MPI launcher (Open MPI's OMPI_COMM_WORLD_SIZE, or PMI_SIZE / PMIX_RANK of other
/// launchers), replaces the process by signorini-mpi from the folder of this executable. Where
/// there is none, and the launcher started more than one rank, prints an error and exits with
/// status 2; with one rank it returns and the tool runs serially. Returns at once otherwise, and
/// when this program is signorini-mpi.
void hand_over_to_mpi_tool(char** argv);

}  // namespace signorini::app
