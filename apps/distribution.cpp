// join_distributed_job without MPI in the build, and how every build tells
// whether a launcher started it: Open MPI's mpirun sets
// OMPI_COMM_WORLD_SIZE, PMI launchers (MPICH's mpiexec, Slurm's srun)
// PMI_SIZE, so a plain run never touches MPI.
#include "distribution.h"

#include <cstdlib>

namespace lancer::app {

#ifdef LANCER_HAVE_MPI
std::unique_ptr<Distribution> join_mpi_job(std::string& problem);  // apps/mpi/mpi_distribution.cpp
#endif

namespace {

int launcher_world_size() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
        if (const char* value = std::getenv(name)) return std::atoi(value);
    }
    return 0;
}

}  // namespace

std::unique_ptr<Distribution> join_distributed_job(std::string& problem) {
    problem.clear();
    if (launcher_world_size() <= 1) return nullptr;
#ifdef LANCER_HAVE_MPI
    return join_mpi_job(problem);
#else
    problem = "this lancer was built without MPI, but mpirun started " + std::to_string(launcher_world_size()) +
              " copies of it: each would render the whole job. Rebuild with -DLANCER_MPI=ON (docs/distributed.md)";
    return nullptr;
#endif
}

}  // namespace lancer::app
