// MpiTransport: the Transport of par/transport.hpp over Open MPI, plus the MPI session.
//
// Messages: MPI_Isend of the bytes on a private duplicate of MPI_COMM_WORLD, one tag, so
// MPI's non-overtaking rule gives FIFO per pair; poll() receives with MPI_Improbe +
// MPI_Mrecv (any size, no pre-posted buffers) into one buffer, so a handler may not poll
// again (refused); a send's buffer is kept until MPI_Test reports that send complete. Nothing blocks: a blocking send of a large message could deadlock
// against a peer doing the same.
// Reductions: MPI_Iallreduce (sum) on a second duplicate, so they never meet messages.
// Teardown waits for the outstanding sends (every message was received by then: the
// caller tears down only after termination detection).
#pragma once

#include <mpi.h>

#include <chrono>
#include <deque>
#include <vector>

#include "par/transport.hpp"

namespace pdr::par {

// MPI_Init / MPI_Finalize around a scope (MPI_THREAD_FUNNELED: a rank has other threads,
// its writers', its checker's, the closer of replaced files, but only the thread that
// started MPI calls it). A transport must not outlive it. A rank that fails must call
// abort() (MPI_Abort) rather than unwind into MPI_Finalize, which would wait for peers
// that never come.
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  [[noreturn]] static void abort(int code);

 private:
  int rank_ = 0, size_ = 1;
};

// Open MPI's messaging layer for a run whose ranks all share one host (the launcher's
// OMPI_COMM_WORLD_LOCAL_SIZE equals OMPI_COMM_WORLD_SIZE): "ob1", whose shared-memory
// transport is what such a run uses anyway, unless the user chose one (OMPI_MCA_pml set,
// even empty). Left to Open MPI's own choice, MPI_Init first starts UCX, which then finds
// no network to use: about 0.2 s of every run on one host. MpiSession sets it in the
// environment before MPI_Init; runs over several hosts keep Open MPI's choice. Returns
// nullptr where nothing is to be set.
const char* single_host_pml();

// True when this process was started by an MPI launcher (mpirun, mpiexec, srun): the
// launchers' environment variables are set.
bool launched_by_mpi();
// The number of ranks the launcher started, from its environment (0: not said).
int launcher_world_size();

class MpiTransport final : public Transport {
 public:
  // Precondition: MPI is initialised. `latency` > 0: every message is held that long after
  // it arrives before poll() delivers it (latency injection, --inject-latency; a held
  // message is still in flight for termination detection).
  explicit MpiTransport(std::chrono::microseconds latency = {});
  ~MpiTransport() override;
  MpiTransport(const MpiTransport&) = delete;
  MpiTransport& operator=(const MpiTransport&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void start_reduction(const Reduction& mine) override;
  std::optional<Reduction> reduction_done() override;

  std::size_t sends_in_progress() const { return sending_.size(); }

 private:
  struct Outgoing {
    Bytes bytes;
    MPI_Request request = MPI_REQUEST_NULL;
  };
  void do_send(int to, Bytes message) override;
  std::size_t do_poll(const Deliver& deliver, std::size_t max) override;
  void reap();  // frees the buffers of completed sends

  MPI_Comm messages_ = MPI_COMM_NULL, reductions_ = MPI_COMM_NULL;
  int rank_ = 0, size_ = 1;
  std::vector<Outgoing> sending_;
  bool polling_ = false;
  Bytes incoming_;
  using Clock = std::chrono::steady_clock;
  struct Held {
    int from = 0;
    Bytes bytes;
    Clock::time_point due;
  };
  std::chrono::microseconds latency_;
  std::deque<Held> held_;
  Reduction mine_{}, sum_{};
  MPI_Request reduction_ = MPI_REQUEST_NULL;
};

}  // namespace pdr::par
