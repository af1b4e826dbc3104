#include "mpi_job.h"

#include "interrupt.h"
#include "request_channel.h"

namespace relt::mpi {

bool MpiJob::stopRequested() const { return stopSignalled(); }
bool MpiJob::takeSaveRequest() { return mpi::takeSaveRequest(); }
bool MpiJob::stopAgreed() const { return mpi::stopAgreed(); }
void MpiJob::markStopAgreed() { mpi::markStopAgreed(); }
std::unique_ptr<RequestChannel> MpiJob::openRequestChannel() { return std::make_unique<MpiRequestChannel>(); }

}  // namespace relt::mpi
