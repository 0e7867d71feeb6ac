// run_tasks: the writers' concurrency. Each task writes a file of its own (a format, or one
// of TetGen's three files) from the same read-only mesh, so the tasks share nothing but
// that mesh; they run on their own threads (inline when no thread can be started) and the
// caller waits for all of them. The first exception (in task order) is rethrown once every
// task has ended, so no thread outlives the call. Each writer commits its own files or
// none: after a failure the other formats are written all the same (run one after the
// other, the formats after the failing one were not), and the caller reports the failure.
#pragma once

#include <exception>
#include <functional>
#include <system_error>
#include <thread>
#include <vector>

namespace pdr::io {

inline void run_tasks(const std::vector<std::function<void()>>& tasks) {
  std::vector<std::exception_ptr> errors(tasks.size());
  {
    std::vector<std::jthread> threads;
    for (std::size_t i = 1; i < tasks.size(); ++i) {
      const auto run = [&, i] {
        try {
          tasks[i]();
        } catch (...) {
          errors[i] = std::current_exception();
        }
      };
      try {
        threads.emplace_back(run);
      } catch (const std::system_error&) {
        run();  // no thread to be had: run it here
      }
    }
    if (!tasks.empty()) {
      try {
        tasks[0]();
      } catch (...) {
        errors[0] = std::current_exception();
      }
    }
  }  // joins
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace pdr::io
