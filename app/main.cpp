// signorini: the command-line tool (tool.cpp). Started by an MPI launcher (mpirun), it hands over
// to signorini-mpi, the same tool with the PETSc engine (mpi_handover.hpp, docs/distributed.md).

#include "commands.hpp"
#include "mpi_handover.hpp"
#include "process_tuning.hpp"

int main(int argc, char** argv) {
  signorini::app::hand_over_to_mpi_tool(argv);  // under mpirun: becomes signorini-mpi
  signorini::app::tune_process(argc, argv);     // may re-execute the program (process_tuning.hpp)
  return signorini::app::run_tool(argc, argv);
}
