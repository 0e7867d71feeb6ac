// Termination detection: the two-round state machine of par/termination.hpp.
#include "par/termination.hpp"

namespace pdr::par {

bool TerminationDetector::step(bool idle) {
  switch (state_) {
    case State::Quiet:
      if (idle) {
        dirty_ = false;
        sent_at_snapshot_ = t_.sent();
        received_at_snapshot_ = t_.received();
        t_.start_reduction({sent_at_snapshot_, received_at_snapshot_, 0});
        ++rounds_;
        state_ = State::Counting;
      }
      break;
    case State::Counting:
      if (const auto r = t_.reduction_done()) {
        balanced_ = (*r)[0] == (*r)[1];
        const bool changed =
            t_.sent() != sent_at_snapshot_ || t_.received() != received_at_snapshot_;
        t_.start_reduction({0, 0, (dirty_ || !idle || changed) ? 1u : 0u});
        ++rounds_;
        state_ = State::Confirming;
      }
      break;
    case State::Confirming:
      if (const auto r = t_.reduction_done())
        state_ = (balanced_ && (*r)[2] == 0) ? State::Done : State::Quiet;
      break;
    case State::Done:
      break;
  }
  return state_ == State::Done;
}

}  // namespace pdr::par
