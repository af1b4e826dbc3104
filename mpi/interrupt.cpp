#include "interrupt.h"

#include <csignal>

namespace relt::mpi {
namespace {

volatile std::sig_atomic_t signalled = 0;
bool agreed = false;

extern "C" void onStopSignal(int sig) {
  if (signalled) {  // the second one: the user insists
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  signalled = sig;
}

}  // namespace

void installStopHandlers() {
  struct sigaction sa = {};
  sa.sa_handler = onStopSignal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;  // MPI's own system calls continue
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGUSR1, &sa, nullptr);
}

bool stopSignalled() { return signalled != 0; }
bool stopAgreed() { return agreed; }
void markStopAgreed() { agreed = true; }

}  // namespace relt::mpi
