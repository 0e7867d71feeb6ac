// MpiTransport and MpiSession: par/mpi_transport.hpp.
#include "par/mpi_transport.hpp"

#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace pdr::par {
namespace {

constexpr int kTag = 1;

void check(int rc, const char* what) {
  if (rc == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int len = 0;
  MPI_Error_string(rc, text, &len);
  throw std::runtime_error(std::string("mpi: ") + what + ": " + std::string(text, static_cast<std::size_t>(len)));
}

}  // namespace

const char* single_host_pml() {
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  if (size == nullptr || local == nullptr || std::getenv("OMPI_MCA_pml") != nullptr) return nullptr;
  return std::atoi(size) > 0 && std::atoi(size) == std::atoi(local) ? "ob1" : nullptr;
}

MpiSession::MpiSession(int* argc, char*** argv) {
  if (const char* pml = single_host_pml()) setenv("OMPI_MCA_pml", pml, 0);
  int provided = 0;
  check(MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

void MpiSession::abort(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::abort();  // MPI_Abort does not return; if it did, do not go on
}

int launcher_world_size() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "SLURM_STEP_NUM_TASKS"})
    if (const char* n = std::getenv(v); n != nullptr && std::atoi(n) > 0) return std::atoi(n);
  return 0;
}

bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE",
                        "MPI_LOCALNRANKS", "SLURM_STEP_NUM_TASKS"})
    if (std::getenv(v) != nullptr) return true;
  return false;
}

MpiTransport::MpiTransport(std::chrono::microseconds latency) : latency_(latency) {
  check(MPI_Comm_dup(MPI_COMM_WORLD, &messages_), "MPI_Comm_dup");
  check(MPI_Comm_dup(MPI_COMM_WORLD, &reductions_), "MPI_Comm_dup");
  MPI_Comm_set_errhandler(messages_, MPI_ERRORS_RETURN);
  MPI_Comm_set_errhandler(reductions_, MPI_ERRORS_RETURN);
  MPI_Comm_rank(messages_, &rank_);
  MPI_Comm_size(messages_, &size_);
}

MpiTransport::~MpiTransport() {
  for (Outgoing& o : sending_) MPI_Wait(&o.request, MPI_STATUS_IGNORE);
  if (reduction_ != MPI_REQUEST_NULL) MPI_Wait(&reduction_, MPI_STATUS_IGNORE);
  MPI_Comm_free(&messages_);
  MPI_Comm_free(&reductions_);
}

void MpiTransport::do_send(int to, Bytes message) {
  if (message.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error("mpi: a message of " + std::to_string(message.size()) +
                            " bytes exceeds MPI's int count");
  Outgoing& o = sending_.emplace_back();
  o.bytes = std::move(message);
  check(MPI_Isend(o.bytes.data(), static_cast<int>(o.bytes.size()), MPI_BYTE, to, kTag,
                  messages_, &o.request),
        "MPI_Isend");
  reap();
}

void MpiTransport::reap() {
  // Every completed send, not only a prefix: a large message to a busy peer must not keep
  // the buffers behind it alive. Moving an Outgoing keeps its bytes where they are.
  for (std::size_t i = 0; i < sending_.size();) {
    int done = 0;
    check(MPI_Test(&sending_[i].request, &done, MPI_STATUS_IGNORE), "MPI_Test");
    if (!done) {
      ++i;
      continue;
    }
    if (i + 1 != sending_.size()) sending_[i] = std::move(sending_.back());
    sending_.pop_back();
  }
}

std::size_t MpiTransport::do_poll(const Deliver& deliver, std::size_t max) {
  if (polling_) throw std::logic_error("mpi: poll() called from a message handler");
  polling_ = true;
  struct Done {
    bool& flag;
    ~Done() { flag = false; }
  } done{polling_};
  reap();
  std::size_t n = 0;
  const bool hold = latency_.count() > 0;
  const auto now = hold ? Clock::now() : Clock::time_point{};
  while (n < max) {
    int found = 0;
    MPI_Message msg;
    MPI_Status status;
    check(MPI_Improbe(MPI_ANY_SOURCE, kTag, messages_, &found, &msg, &status), "MPI_Improbe");
    if (!found) break;
    int count = 0;
    MPI_Get_count(&status, MPI_BYTE, &count);
    Bytes& into = hold ? held_.emplace_back(Held{status.MPI_SOURCE, {}, now + latency_}).bytes
                       : incoming_;
    into.resize(static_cast<std::size_t>(count));
    check(MPI_Mrecv(into.data(), count, MPI_BYTE, &msg, MPI_STATUS_IGNORE), "MPI_Mrecv");
    if (hold) continue;  // delivered below, when its time has come
    deliver(status.MPI_SOURCE, incoming_);
    ++n;
  }
  // Held messages in arrival order: their times are too, so FIFO per pair is kept.
  while (hold && n < max && !held_.empty() && held_.front().due <= now) {
    incoming_ = std::move(held_.front().bytes);
    const int from = held_.front().from;
    held_.pop_front();
    deliver(from, incoming_);
    ++n;
  }
  return n;
}

void MpiTransport::start_reduction(const Reduction& mine) {
  if (reduction_ != MPI_REQUEST_NULL)
    throw std::logic_error("mpi: a reduction round is already open on this rank");
  mine_ = mine;
  check(MPI_Iallreduce(mine_.data(), sum_.data(), static_cast<int>(mine_.size()),
                       MPI_UINT64_T, MPI_SUM, reductions_, &reduction_),
        "MPI_Iallreduce");
}

std::optional<Reduction> MpiTransport::reduction_done() {
  if (reduction_ == MPI_REQUEST_NULL) return std::nullopt;
  int done = 0;
  check(MPI_Test(&reduction_, &done, MPI_STATUS_IGNORE), "MPI_Test");
  if (!done) return std::nullopt;
  return sum_;
}

}  // namespace pdr::par
