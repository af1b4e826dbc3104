#pragma once
// SIGINT, SIGTERM and SIGUSR1 ask the render to stop. Open MPI's mpirun passes SIGINT and SIGTERM
// on to every rank but then ends itself with status 1 whatever the ranks return (and kills ranks
// still running after odls_base_sigkill_timeout, 1 s by default); SIGUSR1 it forwards and then
// returns the ranks' status, 0. Batch systems signal every rank directly. The handler only sets
// a flag, the render loops read it at their next round or pass and agree on it with the other
// ranks, so all stop after the same round, reduce and write the image so far. A second signal ends
// the process at once.
namespace relt::mpi {

void installStopHandlers();
// This rank received a stop signal.
bool stopSignalled();
// The ranks agreed to stop (set by agree() in comm.h); the render writes what it has and exits 0.
bool stopAgreed();
void markStopAgreed();

}  // namespace relt::mpi
