#include "request_channel.h"

#include "comm.h"
#include "replica/round_loop.h"

namespace relt::mpi {
namespace {
constexpr int kNoticeTag = 41;  // + the epoch's parity: a rank drains an epoch before the next is sent
}

MpiRequestChannel::MpiRequestChannel() {
  MPI_Comm_dup(MPI_COMM_WORLD, &comm_);
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
  all_.resize(mine_.size() * size_t(size_));
  listen();
}

MpiRequestChannel::~MpiRequestChannel() {
  if (notice_ != MPI_REQUEST_NULL) {
    MPI_Cancel(&notice_);
    MPI_Wait(&notice_, MPI_STATUS_IGNORE);
  }
  MPI_Comm_free(&comm_);
}

void MpiRequestChannel::listen() {
  noticeFrom_ = -1;
  MPI_Irecv(&noticeWord_, 1, MPI_INT, MPI_ANY_SOURCE, kNoticeTag + int(epoch_ & 1u), comm_, &notice_);
}

// Offers the next round this rank reaches (and its requests); with `notify` first tells the others.
void MpiRequestChannel::offer(bool notify) {
  if (notify)
    for (int r = 0; r < size_; ++r) {
      if (r == rank_) continue;
      sends_.emplace_back();
      MPI_Isend(&sendWord_, 1, MPI_INT, r, kNoticeTag + int(epoch_ & 1u), comm_, &sends_.back());
    }
  mine_ = {double(rounds_ + 1), wantStop_ ? 1.0 : 0.0, wantSave_ ? 1.0 : 0.0, notify ? 1.0 : 0.0};
  wantStop_ = wantSave_ = false;
  MPI_Iallgather(mine_.data(), int(mine_.size()), MPI_DOUBLE, all_.data(), int(mine_.size()), MPI_DOUBLE, comm_,
                 &agreement_);
  offered_ = true;
}

// Waits for every rank's offer, takes the agreement, receives the notices of this epoch that have
// not arrived (one from every rank that sent them) and listens for the next epoch's.
void MpiRequestChannel::complete() {
  waitTimed(agreement_);
  offered_ = false;
  std::vector<RequestOffer> offers;
  std::vector<int> senders;
  for (int r = 0; r < size_; ++r) {
    const double* offered = all_.data() + mine_.size() * size_t(r);
    offers.push_back({uint64_t(offered[0]), offered[1] > 0.0, offered[2] > 0.0});
    if (offered[3] > 0.0 && r != rank_) senders.push_back(r);
  }
  const RequestAgreement agreed = agreeOnOffers(offers);
  const int tag = kNoticeTag + int(epoch_ & 1u);
  if (noticeFrom_ < 0 && !senders.empty()) {
    MPI_Status status;
    MPI_Wait(&notice_, &status);
    noticeFrom_ = status.MPI_SOURCE;
  } else if (noticeFrom_ < 0) {
    MPI_Cancel(&notice_);
    MPI_Wait(&notice_, MPI_STATUS_IGNORE);
  }
  for (int r : senders)
    if (r != noticeFrom_) MPI_Recv(&noticeWord_, 1, MPI_INT, r, tag, comm_, MPI_STATUS_IGNORE);
  MPI_Waitall(int(sends_.size()), sends_.data(), MPI_STATUSES_IGNORE);
  sends_.clear();
  ++epoch_;
  listen();
  due_ = agreed;
}

void MpiRequestChannel::poll() {
  if (offered_) {  // let it advance; it is taken at the round offered (a finished wait returns at once)
    int done = 0;
    MPI_Test(&agreement_, &done, MPI_STATUS_IGNORE);
    return;
  }
  if (due_) return;
  int got = 0;
  MPI_Status status;
  MPI_Test(&notice_, &got, &status);
  if (!got) return;
  noticeFrom_ = status.MPI_SOURCE;
  offer(false);
}

std::optional<RequestAgreement> MpiRequestChannel::at(uint64_t rounds, bool stop, bool save) {
  rounds_ = rounds;
  wantStop_ |= stop;
  wantSave_ |= save;
  if (offered_) {
    if (uint64_t(mine_[0]) <= rounds) complete();
  } else if (!due_ && (wantStop_ || wantSave_)) {
    offer(true);
  } else {
    poll();
  }
  if (!due_ || due_->round != rounds) return std::nullopt;
  const RequestAgreement agreed = *due_;
  due_.reset();
  return agreed;
}

void MpiRequestChannel::close() {
  due_.reset();
  if (!offered_) offer(false);
  complete();
  due_.reset();
}

void MpiRequestChannel::barrier() {
  MPI_Request request;
  MPI_Ibarrier(comm_, &request);
  waitTimed(request, [this] { poll(); });
}

}  // namespace relt::mpi
