#pragma once
// Stop and save requests agreed apart from the round messages, for local decisions (packed
// placement), whose messages come back lag rounds (up to 256) late. A rank asked to stop or save
// tells every other at once, point to point; each then offers, by a nonblocking allgather, the next
// round it will reach, and all act at the largest of those: within the ranks' spread of rounds
// (their drift, usually a few rounds) of the request, however long the lag. A rank that offered
// waits at the round it offered until all have; so every wait of the round loop for other ranks
// calls poll(), which notices a request and offers.
#include <mpi.h>

#include <array>
#include <optional>
#include <vector>

#include "parallel/job.h"

namespace relt::mpi {

class MpiRequestChannel final : public RequestChannel {
 public:
  MpiRequestChannel();  // collective (on its own communicator)
  MpiRequestChannel(const MpiRequestChannel&) = delete;
  MpiRequestChannel& operator=(const MpiRequestChannel&) = delete;
  ~MpiRequestChannel() override;

  std::optional<RequestAgreement> at(uint64_t rounds, bool stop, bool save) override;
  void poll() override;
  void close() override;
  // A rank ahead would otherwise wait in a snapshot's collectives while another waits for its offer.
  void barrier() override;

 private:
  void listen();
  void offer(bool notify);
  void complete();

  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0, size_ = 1;
  unsigned epoch_ = 0;  // agreements completed; their notices are tagged by its parity
  MPI_Request notice_ = MPI_REQUEST_NULL, agreement_ = MPI_REQUEST_NULL;
  int noticeFrom_ = -1;  // the sender of the notice received this epoch (-1: none yet)
  int noticeWord_ = 0, sendWord_ = 1;
  std::vector<MPI_Request> sends_;
  std::array<double, 4> mine_{};  // next round, stop, save, notified the others
  std::vector<double> all_;
  uint64_t rounds_ = 0;                // the last round at() was told of
  bool wantStop_ = false, wantSave_ = false;  // this rank's requests not offered yet
  bool offered_ = false;                      // an offer of this epoch is out
  std::optional<RequestAgreement> due_;       // agreed, for a round not reached yet
};

}  // namespace relt::mpi
