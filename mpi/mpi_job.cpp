#include "mpi_job.h"

#include "interrupt.h"

namespace relt::mpi {

bool MpiJob::stopRequested() const { return stopSignalled(); }
bool MpiJob::takeSaveRequest() { return mpi::takeSaveRequest(); }
bool MpiJob::stopAgreed() const { return mpi::stopAgreed(); }

}  // namespace relt::mpi
