/* Fault injection for tests, loaded with LD_PRELOAD into every rank of an mpirun job:
 * shifts one rank's MPI_Wtime by a constant, the way Open MPI's per-process clock origins
 * differ between ranks (MPI_WTIME_IS_GLOBAL is false). A collective decision taken from
 * rank-local clock readings then differs between ranks and the job deadlocks; Catena must
 * take such decisions once and share them.
 *
 *   CATENA_TEST_WTIME_SKEW="RANK:SECONDS"   e.g. "1:-5": rank 1's clock runs 5 s behind.
 *
 * The rank is read from OMPI_COMM_WORLD_RANK (set by Open MPI's launcher). */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

static double skew_seconds(void) {
  static int known = 0;
  static double skew = 0.0;
  if (!known) {
    const char* spec = getenv("CATENA_TEST_WTIME_SKEW");
    const char* rank = getenv("OMPI_COMM_WORLD_RANK");
    int skewed_rank = -1;
    double seconds = 0.0;
    if (spec && rank && sscanf(spec, "%d:%lf", &skewed_rank, &seconds) == 2 &&
        skewed_rank == atoi(rank))
      skew = seconds;
    known = 1;
  }
  return skew;
}

double MPI_Wtime(void) { return PMPI_Wtime() + skew_seconds(); }
