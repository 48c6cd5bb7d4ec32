#include "experiments/model.hpp"

namespace fspm::experiments {

void RunContext::check() const {
  if (interrupted_ != nullptr && interrupted_->load(std::memory_order_relaxed)) {
    throw RunStopped("interrupted", false);
  }
  if (deadline_ && Clock::now() > *deadline_) throw RunStopped("time limit exceeded", true);
}

}  // namespace fspm::experiments
