#include "interrupt.h"

#include <csignal>

namespace relt::mpi {
namespace {

volatile std::sig_atomic_t signalled = 0;
volatile std::sig_atomic_t continued = 0;  // SIGCONTs received
std::sig_atomic_t continuedTaken = 0;
bool agreed = false;

extern "C" void onStopSignal(int sig) {
  if (signalled) {  // the second one: the user insists
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  signalled = sig;
}

extern "C" void onContinue(int) { continued = continued + 1; }

}  // namespace

void installStopHandlers() {
  struct sigaction sa = {};
  sa.sa_handler = onStopSignal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;  // MPI's own system calls continue
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGUSR1, &sa, nullptr);
  struct sigaction cont = {};
  cont.sa_handler = onContinue;
  sigemptyset(&cont.sa_mask);
  cont.sa_flags = SA_RESTART;
  sigaction(SIGCONT, &cont, nullptr);
}

bool stopSignalled() { return signalled != 0; }

bool takeSaveRequest() {
  const std::sig_atomic_t now = continued;
  if (now == continuedTaken) return false;
  continuedTaken = now;
  return true;
}
bool stopAgreed() { return agreed; }
void markStopAgreed() { agreed = true; }

}  // namespace relt::mpi
