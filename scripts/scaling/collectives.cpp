// Latency and bandwidth of the collectives relt's round loop uses, on this machine's ranks:
// MPI_Allgatherv (the round message) and MPI_Allreduce (the end-of-render sums) for several
// message sizes. Prints one JSON object per size on rank 0. Inputs of scripts/scaling/model.py.
// Usage: mpirun -np P relt_bench_collectives [REPEATS]
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

// Mean seconds of one call, after a warm-up, synchronised start.
template <class F>
double timeCalls(int repeats, F&& call) {
  for (int i = 0; i < 10; ++i) call();
  MPI_Barrier(MPI_COMM_WORLD);
  const double t0 = MPI_Wtime();
  for (int i = 0; i < repeats; ++i) call();
  double t = (MPI_Wtime() - t0) / repeats, worst = 0.0;
  MPI_Allreduce(&t, &worst, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 2000;
  for (int n : {1, 8, 64, 512, 4096, 32768}) {  // doubles per rank
    std::vector<double> mine(size_t(n), 1.0), all(size_t(n) * size_t(size));
    std::vector<int> counts(static_cast<size_t>(size), n), offsets(static_cast<size_t>(size));
    for (int r = 0; r < size; ++r) offsets[size_t(r)] = r * n;
    const int reps = n >= 4096 ? repeats / 10 : repeats;
    const double gather = timeCalls(reps, [&] {
      MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, MPI_COMM_WORLD);
    });
    const double reduce = timeCalls(reps, [&] {
      MPI_Allreduce(MPI_IN_PLACE, mine.data(), n, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    });
    if (rank == 0)
      std::printf("{\"ranks\": %d, \"doubles_per_rank\": %d, \"allgatherv_seconds\": %.9g, \"allreduce_seconds\": %.9g}\n",
                  size, n, gather, reduce);
  }
  MPI_Finalize();
  return 0;
}
