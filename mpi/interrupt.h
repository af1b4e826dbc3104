#pragma once
// SIGINT, SIGTERM and SIGUSR1 ask the render to stop. Open MPI's mpirun passes SIGINT and SIGTERM
// on to every rank but then ends itself with status 1 whatever the ranks return (and kills ranks
// still running after odls_base_sigkill_timeout, 1 s by default); SIGUSR1 it forwards and then
// returns the ranks' status, 0. Batch systems signal every rank directly. The handler only sets
// a flag, the render loops read it at their next round or pass and agree on it with the other
// ranks, so all stop after the same round, reduce and write the image so far. A second signal ends
// the process at once.
//
// Open MPI's mpirun, asked to stop (SIGINT or SIGTERM), first sends the ranks SIGCONT, a second
// later SIGTERM and another second later SIGKILL (odls_base_sigkill_timeout); batch systems do
// likewise. So SIGCONT asks the ranks to save: they agree on it like a stop, and write the image
// so far and a checkpoint after the same round, then go on. A SIGCONT that resumes a stopped
// process asks the same: it costs one write.
namespace relt::mpi {

void installStopHandlers();
// This rank received a stop signal.
bool stopSignalled();
// This rank received SIGCONT since it last took the request (takes it: true once per signal).
bool takeSaveRequest();
// The ranks agreed to stop (set by agree() in comm.h); the render writes what it has and exits 0.
bool stopAgreed();
void markStopAgreed();

}  // namespace relt::mpi
